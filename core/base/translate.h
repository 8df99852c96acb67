#pragma once

// Marks an English message template for translation without translating it here: core is Qt-free,
// lupdate extracts these strings (-tr-function-alias QT_TRANSLATE_NOOP+=KERF_TR_NOOP) and the UI
// translates them when it shows them.
#define KERF_TR_NOOP(text) text
// The same with a disambiguation, for a word whose translation depends on what it describes
// (Portuguese "pronto" for a program, "pronta" for a machine): lupdate extracts it as
// QT_TRANSLATE_NOOP3, and the UI translates it with the same disambiguation.
#define KERF_TR_NOOP3(text, disambiguation) text
