#!/bin/sh
# Refreshes the translation sources (every translations/kerf_<lang>.ts) from the code:
# - the HMI's tr() texts from ui/, in one context per class;
# - core's operator messages, marked KERF_TR_NOOP("..."), into the context "kerf", where
#   ui/common/diagnostic_text.cpp looks them up at run time.
# lupdate 5.15 cannot take a one-argument macro as QT_TRANSLATE_NOOP (it finds nothing) and
# QT_TR_NOOP would name the context after each class, so a copy of the sources with
# KERF_TR_NOOP( rewritten to QT_TRANSLATE_NOOP("kerf", is scanned instead (KERF_TR_NOOP3( with a
# disambiguation to QT_TRANSLATE_NOOP3("kerf",).
# lupdate 5.15 does not understand C++17 nested namespaces ("namespace kerf::ui {") either: it
# names contexts "MainWindow" where Qt looks for "kerf::ui::MainWindow", so the last step puts
# the namespace back.
# A new language: copy the header of an existing .ts to kerf_<lang>.ts with language="xx_YY",
# an empty <TS> body, and run this script.
set -e
cd "$(dirname "$0")/.."
ts_files=$(ls translations/kerf_*.ts)
# ui/ marks diagnostics with KERF_TR_NOOP as well, and so does motion/ (the planner's refusals and
# the simulated machine's errors reach the operator), so all three are scanned as rewritten copies.
source_copy=$(mktemp -d)
trap 'rm -rf "$source_copy"' EXIT
find core ui motion -name '*.h' -o -name '*.cpp' | while read -r file; do
  mkdir -p "$source_copy/$(dirname "$file")"
  sed 's/KERF_TR_NOOP(/QT_TRANSLATE_NOOP("kerf", /g; s/KERF_TR_NOOP3(/QT_TRANSLATE_NOOP3("kerf", /g' \
    "$file" >"$source_copy/$file"
done
# Back to lupdate's names first, so that it keeps the existing translations; classes declared
# with Q_DECLARE_TR_FUNCTIONS(kerf::ui::Name) are named in full by lupdate too.
# shellcheck disable=SC2086
sed -i -E 's#<name>kerf::ui::([A-Za-z]+)</name>#<name>\1</name>#' $ts_files
for name in $(grep -rhoE 'Q_DECLARE_TR_FUNCTIONS\(kerf::ui::[A-Za-z]+\)' ui | sed -E 's/.*::([A-Za-z]+)\)/\1/' | sort -u); do
  # shellcheck disable=SC2086
  sed -i "s#<name>$name</name>#<name>kerf::ui::$name</name>#" $ts_files
done
# shellcheck disable=SC2086
/usr/lib/qt5/bin/lupdate -no-obsolete -locations none "$source_copy/ui" "$source_copy/core" \
  "$source_copy/motion" -ts $ts_files
# shellcheck disable=SC2086
sed -i -E 's#<name>([A-Za-z]+)</name>#<name>kerf::ui::\1</name>#; s#<name>kerf::ui::kerf</name>#<name>kerf</name>#' \
  $ts_files
