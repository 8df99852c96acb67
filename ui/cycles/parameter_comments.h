#pragma once

#include <QString>

#include "core/cycles/cycle_parameter.h"

namespace kerf::ui {

// The TNC writes a short upper-case comment after each cycle parameter ("Q200=+2 ;SET-UP
// CLEARANCE"); it is only for the reader, in the UI language.
constexpr int kMaxCommentLength = 24;

// The comment for `parameter` of `cycle`, translated ("kerf" context).
QString parameterComment(int cycle, const cycles::ParameterDescriptor& parameter);
// True when the spec's examples give the comment (else it is made from the description).
bool hasSpecComment(int cycle, int q);

}  // namespace kerf::ui
