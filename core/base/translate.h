#pragma once

// Marks an English message template for translation without translating it here: core is Qt-free,
// lupdate extracts these strings (-tr-function-alias QT_TRANSLATE_NOOP+=KERF_TR_NOOP) and the UI
// translates them when it shows them.
#define KERF_TR_NOOP(text) text
