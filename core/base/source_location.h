#pragma once

#include <cstdint>

namespace kerf {

// Where a block or token came from: a file registered in program::SourceRegistry, a 1-based line
// and column, and the NC block number written in the file (-1 when the block has none). A block
// that runs in several single-block steps (the points of a pattern cycle) numbers them from 1;
// 0: the block is one step.
struct SourceLocation {
    uint32_t fileId = 0;
    uint32_t line = 0;
    uint32_t column = 0;
    int64_t blockNumber = -1;
    uint32_t step = 0;

    friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

}  // namespace kerf
