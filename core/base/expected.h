#pragma once

#include <optional>
#include <utility>
#include <variant>

#include "core/base/diagnostic.h"

namespace kerf {

// A value or the diagnostic that explains why there is none. (std::expected is C++23 and the
// clang 14 used for fuzzing cannot compile libstdc++'s <expected>.)
template <typename T>
class Expected {
public:
    Expected(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Expected(Diagnostic error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(m_state); }
    const T& value() const& { return std::get<0>(m_state); }
    T&& value() && { return std::get<0>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Diagnostic& error() const { return std::get<1>(m_state); }

private:
    std::variant<T, Diagnostic> m_state;
};

// Result of an operation that returns nothing: empty on success.
using MaybeError = std::optional<Diagnostic>;

}  // namespace kerf
