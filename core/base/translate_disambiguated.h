#pragma once

// KERF_TR_NOOP (core/base/translate.h) with a disambiguation, for a word whose translation
// depends on what it describes (Portuguese "pronto" for a program, "pronta" for a machine):
// translations/update_ts.sh has lupdate extract it as QT_TRANSLATE_NOOP3, and the UI translates
// it with the same disambiguation.
#define KERF_TR_NOOP3(text, disambiguation) text
