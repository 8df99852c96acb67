#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace kerf::fagor {

// What is wrong with a block and where (byte offset in the block's text); becomes a Diagnostic.
struct Problem {
    size_t offset = 0;
    std::string code;
    std::string messageTemplate;
    std::vector<std::string> args;
};

// Where parameter values come from while a block is read. Without a source (program check) every
// parameter reads as 0 and range checks that depend on values are left to execution.
class ParameterSource {
public:
    virtual ~ParameterSource() = default;
    // P<number> for an ISO word; false with `problem` filled (code, message) if it cannot be read.
    virtual bool parameter(int number, double& out, Problem& problem) = 0;
};

}  // namespace kerf::fagor
