#pragma once

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/program/dialect.h"

// The special functions the SPEC FCT softkey writes (docs/hmi.md, "Special functions"): the
// tilted working plane (PLANE), tool centre point management (FUNCTION TCPM, M128/M129) and
// program calls (SEL PGM, CALL SELECTED PGM, CALL PGM). Conversational and TNC ISO programs
// write them with the same conversational words (docs/tnciso.md, "Special functions"), except
// CALL PGM, which ISO writes "%NAME".
namespace kerf::ui {

// The PLANE forms come first (isPlane relies on it).
enum class SpecialFunction {
    PlaneSpatial,
    PlaneProjected,
    PlaneEuler,
    PlaneVector,
    PlanePoints,
    PlaneRelative,
    PlaneAxial,
    PlaneReset,
    Tcpm,
    ResetTcpm,
    M128,
    M129,
    SelectProgram,
    CallSelectedProgram,
    CallProgram,
};

enum class SpecialFieldKind {
    Number,       // "+45", "-0.5", "Q3"; written after the word with its sign
    Choice,       // one of `choices`; an empty choice writes nothing
    Length,       // positive number or empty (MB, DIST)
    Retract,      // MB: a positive number, MAX or empty
    Feed,         // F: a feed rate, FMAX or empty
    ProgramName,  // a program name or path inside the NC root
};

struct SpecialField {
    QString word;  // "SPA", "MB", "F" ...; empty for a choice written as it is
    SpecialFieldKind kind;
    bool required = false;
    QStringList choices;
    const char* description;  // English, translated in the "kerf" context
};

// The block's first words ("PLANE SPATIAL", "FUNCTION TCPM", "SEL PGM" ...), the dialog's title.
QString specialFunctionTitle(SpecialFunction function);
// The dialog's fields; none: the block is written without a dialog.
std::vector<SpecialField> specialFields(SpecialFunction function);
QString specialFieldDescription(const SpecialField& field);

// Checks one entry; the message is in the UI language.
std::optional<QString> checkSpecialField(const SpecialField& field, const QString& text);
// Checks all entries (the message in the UI language), including the rules across fields
// (PLANE AXIAL needs an angle; STAY moves nothing, so it takes no MB, DIST or F).
std::optional<QString> checkSpecialFunction(SpecialFunction function, const QStringList& values);
// The block without number (and without ISO's '*') in `dialect`; values must have passed.
QString writeSpecialFunction(SpecialFunction function, const QStringList& values,
                             program::Dialect dialect);

}  // namespace kerf::ui
