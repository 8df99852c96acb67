#pragma once

#include <QString>
#include <filesystem>

namespace kerf::ui {

// Where the program being edited lies, so that a program call chosen from the file list can be
// written as the TNC writes it. An empty root: no file list is offered.
struct ProgramPlace {
    std::filesystem::path ncRoot;
    std::filesystem::path folder;  // the edited program's folder; empty: the NC root
};

// The name a CALL PGM or SEL PGM block writes for the chosen file, or why it cannot be called.
struct ProgramReference {
    QString name;     // "PART.H", "SUB\PART.H" or "TNC:\DIR\PART.H"
    QString refusal;  // in the UI language; empty when `name` is set
};

// As the TNC (spec: tnc-machining-cycles, "Program name"): a file in the calling program's
// folder, or below it, by its name relative to that folder; any other file of the NC root by its
// full path, `TNC:\DIR\PART.H`. Folders are separated by backslashes, the extension is kept (a
// DIN/ISO program needs its `.I`). Refused: a file outside the NC root once its links are
// resolved, a folder or anything but a regular file.
ProgramReference programReference(const std::filesystem::path& chosen, const ProgramPlace& place);

}  // namespace kerf::ui
