#include "ui/shell/ui_language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <memory>

// Q_INIT_RESOURCE must be called outside any namespace; the resources live in a static library.
static void initTranslationResources() {
    Q_INIT_RESOURCE(kerf_translations);
}

namespace kerf::ui {

namespace {

// The compiled translations are built into the program as resources (see translations/).
const QString kTranslationFolder = QStringLiteral(":/translations");

std::unique_ptr<QTranslator>& installedTranslator() {
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

// Qt's own texts (the standard buttons: Cancel, Save, Discard ...) from Debian's
// qttranslations5-l10n; without it they stay English.
std::unique_ptr<QTranslator>& qtTranslator() {
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

void switchQtTexts(const QString& code) {
    if (qtTranslator()) QCoreApplication::removeTranslator(qtTranslator().get());
    qtTranslator().reset();
    if (code == QLatin1String("en")) return;
    auto translator = std::make_unique<QTranslator>();
    if (translator->load(QLocale(code), QStringLiteral("qtbase"), QStringLiteral("_"),
                         QLibraryInfo::location(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(translator.get());
        qtTranslator() = std::move(translator);
    }
}

QString& languageCode() {
    static QString code = QStringLiteral("en");
    return code;
}

}  // namespace

QStringList availableLanguages() {
    initTranslationResources();
    QStringList codes{QStringLiteral("en")};
    const QStringList files =
        QDir(kTranslationFolder).entryList({QStringLiteral("kerf_*.qm")}, QDir::Files, QDir::Name);
    for (const QString& file : files)
        codes << file.mid(5, file.size() - 8);
    return codes;
}

bool switchLanguage(const QString& code) {
    initTranslationResources();
    auto translator = std::make_unique<QTranslator>();
    if (code != QLatin1String("en") &&
        !translator->load(QStringLiteral("kerf_") + code, kTranslationFolder)) {
        return false;
    }
    switchQtTexts(code);
    if (installedTranslator()) QCoreApplication::removeTranslator(installedTranslator().get());
    installedTranslator().reset();
    if (code != QLatin1String("en")) {
        QCoreApplication::installTranslator(translator.get());
        installedTranslator() = std::move(translator);
    } else {
        // Removing the last translator sends LanguageChange too; make sure widgets retranslate.
        QEvent change(QEvent::LanguageChange);
        QCoreApplication::sendEvent(QCoreApplication::instance(), &change);
    }
    languageCode() = code;
    return true;
}

QString currentLanguage() {
    return languageCode();
}

}  // namespace kerf::ui
