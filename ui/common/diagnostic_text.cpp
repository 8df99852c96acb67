#include "ui/common/diagnostic_text.h"

#include <QCoreApplication>

#include "ui/common/message_cause.h"

namespace kerf::ui {

QString translatedMessage(const Diagnostic& diagnostic) {
    const QString translated =
        QCoreApplication::translate("kerf", diagnostic.messageTemplate.c_str());
    const std::string filled = substituteArgs(translated.toStdString(), diagnostic.args);
    return QString::fromStdString(filled);
}

void registerDiagnosticMetaTypes() {
    qRegisterMetaType<kerf::Severity>();
    qRegisterMetaType<kerf::Diagnostic>();
    qRegisterMetaType<kerf::DiagnosticList>();
    qRegisterMetaType<kerf::ui::MessageCause>();
}

QString severityText(Severity severity) {
    switch (severity) {
        case Severity::Note:
            return QCoreApplication::translate("kerf", "Note");
        case Severity::Warning:
            return QCoreApplication::translate("kerf", "Warning");
        case Severity::Error:
            return QCoreApplication::translate("kerf", "Error");
    }
    return {};
}

}  // namespace kerf::ui
