#pragma once

// Both formula parsers descend recursively; each level of nesting (parentheses, a function, a
// sign) is counted so that a program nesting deeper than the parser's limit gets an error at its
// column instead of overflowing the stack.
namespace kerf::interp {

// Enters one level of nesting for as long as it lives.
class NestingLevel {
public:
    explicit NestingLevel(int& depth) : m_depth(depth) { ++m_depth; }
    ~NestingLevel() { --m_depth; }
    NestingLevel(const NestingLevel&) = delete;
    NestingLevel& operator=(const NestingLevel&) = delete;

private:
    int& m_depth;
};

}  // namespace kerf::interp
