#!/bin/sh
# Refreshes the translation sources from the HMI code. lupdate 5.15 does not understand C++17
# nested namespaces ("namespace kerf::ui {"), so it names contexts "MainWindow" where Qt looks
# for "kerf::ui::MainWindow" at run time: the last step puts the namespace back.
set -e
cd "$(dirname "$0")/.."
# Back to lupdate's names first, so that it keeps the existing translations.
sed -i -E 's#<name>kerf::ui::([A-Za-z]+)</name>#<name>\1</name>#' translations/kerf_pt.ts translations/kerf_pl.ts
/usr/lib/qt5/bin/lupdate -no-obsolete -locations none ui/common ui/editor ui/files ui/tables ui/shell \
  -ts translations/kerf_pt.ts translations/kerf_pl.ts
sed -i -E 's#<name>([A-Za-z]+)</name>#<name>kerf::ui::\1</name>#; s#<name>kerf::ui::kerf</name>#<name>kerf</name>#' \
  translations/kerf_pt.ts translations/kerf_pl.ts
