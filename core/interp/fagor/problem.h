#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace kerf::fagor {

// What is wrong with a block and where (byte offset in the block's text); becomes a Diagnostic.
struct Problem {
    size_t offset = 0;
    std::string code;
    std::string messageTemplate;
    std::vector<std::string> args;
};

// Fills `problem` (code, message, arguments; the offset stays) and returns false, so a check
// can `return problemOf(...)`.
inline bool problemOf(Problem& problem, const char* code, const char* text,
                      std::vector<std::string> args = {}) {
    problem.code = code;
    problem.messageTemplate = text;
    problem.args = std::move(args);
    return false;
}

// Where parameter values come from while a block is read. Without a source (program check) every
// parameter reads as 0 and range checks that depend on values are left to execution.
class ParameterSource {
public:
    virtual ~ParameterSource() = default;
    // P<number> for an ISO word; false with `problem` filled (code, message) if it cannot be read.
    virtual bool parameter(int number, double& out, Problem& problem) = 0;
};

}  // namespace kerf::fagor
