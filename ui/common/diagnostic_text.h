#pragma once

#include <QMetaType>
#include <QString>

#include "core/base/diagnostic.h"

namespace kerf::ui {

// The diagnostic's message in the UI language: core writes English templates marked with
// KERF_TR_NOOP; they are translated in the "kerf" context, then the arguments are filled in.
QString translatedMessage(const Diagnostic& diagnostic);

// Registers the diagnostic types for signals; widgets that emit them call it once.
void registerDiagnosticMetaTypes();

// "Error", "Warning", "Note" in the UI language.
QString severityText(Severity severity);

}  // namespace kerf::ui

// Diagnostics travel in signals (and queued connections between threads).
Q_DECLARE_METATYPE(kerf::Severity)
Q_DECLARE_METATYPE(kerf::Diagnostic)
Q_DECLARE_METATYPE(kerf::DiagnosticList)
