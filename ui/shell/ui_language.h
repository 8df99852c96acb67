#pragma once

#include <QString>
#include <QStringList>

namespace kerf::ui {

// The languages the HMI ships, as ISO 639-1 codes; "en" is the source language.
QStringList availableLanguages();

// Switches the whole application to `code` at run time: the translator of the previous language
// is removed and every widget receives QEvent::LanguageChange. False if there is no such
// translation (the current language stays).
bool switchLanguage(const QString& code);
QString currentLanguage();

}  // namespace kerf::ui
