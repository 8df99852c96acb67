#pragma once

#include <cstdint>

namespace kerf {

// Where a block or token came from: a file registered in program::SourceRegistry, a 1-based line
// and column, and the NC block number written in the file (-1 when the block has none).
struct SourceLocation {
    uint32_t fileId = 0;
    uint32_t line = 0;
    uint32_t column = 0;
    int64_t blockNumber = -1;

    friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

}  // namespace kerf
