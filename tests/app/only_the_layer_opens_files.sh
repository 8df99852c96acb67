#!/bin/sh
# docs/files.md: only the file-access layer (core/base/atomic_file.cpp under program::NcRoot, and
# core/program/mapped_copy.cpp, which copies a long program to an unnamed file) opens files. The other matches allowed here are the run's outputs, which the output guard
# (app/runner/output_guard.h) checks: --trace, --samples, --can-trace.
# Usage: only_the_layer_opens_files.sh SOURCE_DIR
cd "$1" || exit 2
found=$(grep -rnE '\bfopen\(|std::[io]?fstream|[^_a-zA-Z]::open\(|\bmmap\(|\bQFile\b|QSaveFile' \
    core app ui graphics motion drivers --include='*.cpp' --include='*.h' |
  grep -vE '^core/base/(atomic_file|open_beneath)\.cpp:' |
  grep -vE '^core/program/mapped_copy\.cpp:' |
  grep -vE '^app/runner/headless_run\.cpp:.*traceFile' |
  grep -vE '^motion/sim/motion_recorder\.h:.*m_csv' |
  grep -vE '^drivers/can/candump_log\.cpp:.*m_file = std::fopen')
if [ -n "$found" ]; then
  echo "files opened outside the file-access layer (docs/files.md):"
  echo "$found"
  exit 1
fi
echo "only the file-access layer opens files"
