#pragma once

#include <string_view>
#include <vector>

namespace kerf::fagor {

// The IBn variables (spec part 2 §6.8) an ordinary program reads, in increasing n, each once:
// the values the operator gives before a run (docs/fagor.md, "Operator inputs"). Comments (';'
// to the end of the line) and quoted texts do not count.
std::vector<int> operatorInputsRead(std::string_view programText);

}  // namespace kerf::fagor
