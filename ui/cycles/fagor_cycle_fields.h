#pragma once

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/interp/fagor/cycle_syntax.h"

namespace kerf::ui {

// The FAGOR 8035 T canned cycles G66-G89 as the panel writes them: one field per parameter of
// the interpreter's table (core/interp/fagor/cycle_syntax), checked by the interpreter's own
// block reader, so that the dialog refuses exactly what the program check would.

// The cycles in the order of the manual's chapter 9.
const std::vector<int>& fagorCycleNumbers();
// "stock removal cycle along X", in the UI language.
QString fagorCycleName(int g);

// What a parameter means for its cycle (spec part 2 §2) and its unit. RadiusLength: a length the
// manual gives in radius whatever the diameter mode of X (allowances, pass steps, depths).
enum class FagorUnit { None, Length, RadiusLength, Feed, Degrees, Hundredths };
struct FagorField {
    const fagor::CycleParameter* parameter = nullptr;
    const char* meaning = "";  // English, translated in the "kerf" context
    FagorUnit unit = FagorUnit::None;

    QString label() const { return QString(QLatin1Char(parameter->letter)); }
    bool required() const { return parameter->required; }
};

std::vector<FagorField> fagorCycleFields(int g);
QString fagorUnitText(FagorUnit unit);
// "digits 5.5, signed", "whole, at most 9999": the format the interpreter accepts.
QString fagorFormatText(const fagor::CycleParameter& parameter);

// Why the text of one field is refused (message in the UI language), or nothing: a value the
// interpreter reads for that parameter alone, or empty for an optional one.
std::optional<QString> checkFagorField(int g, const FagorField& field, const QString& text);

// The cycle block of the values (in fagorCycleFields order; empty ones are left out):
// "G68 X0 Z0 C2 S10 E20".
QString writeFagorCycleBlock(int g, const std::vector<FagorField>& fields,
                             const QStringList& values);

// The whole block as the interpreter reads it: the refusal and the field it points at.
struct FagorBlockRefusal {
    int field = -1;  // -1: the block as a whole
    QString message;
};
std::optional<FagorBlockRefusal> checkFagorCycleBlock(int g, const std::vector<FagorField>& fields,
                                                      const QStringList& values);

// A cycle block found in a program line: the cycle, the values of its fields and where the
// cycle's words are in the line (the block number before and a comment after stay).
struct FagorCycleInLine {
    int g = -1;
    QStringList values;
    int first = 0;   // offset of the G word
    int length = 0;  // up to the end of the last parameter
};
std::optional<FagorCycleInLine> readFagorCycleLine(const QString& line);

}  // namespace kerf::ui
