#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/base/translate.h"

namespace kerf {

enum class Severity : uint8_t { Note, Warning, Error };

std::string_view severityName(Severity severity);

// A message for the user: a stable code, an English template with {1}, {2} ... placeholders (the UI
// translates the template, then substitutes the arguments) and the place it refers to.
struct Diagnostic {
    Severity severity = Severity::Error;
    std::string code;
    std::string messageTemplate;
    std::vector<std::string> args;
    std::string file;
    uint32_t line = 0;
    uint32_t column = 0;

    // The template with its arguments substituted.
    std::string message() const;
    // "file:line:column: severity: message", as compilers print it.
    std::string format() const;

    template <typename... Args>
    static Diagnostic make(Severity severity, std::string code, std::string file, uint32_t line,
                           uint32_t column, std::string messageTemplate, Args&&... args) {
        Diagnostic d;
        d.severity = severity;
        d.code = std::move(code);
        d.file = std::move(file);
        d.line = line;
        d.column = column;
        d.messageTemplate = std::move(messageTemplate);
        (d.args.emplace_back(std::forward<Args>(args)), ...);
        return d;
    }
};

// Substitutes {1}..{9} in a template; "{{" is a literal brace.
std::string substituteArgs(std::string_view messageTemplate, const std::vector<std::string>& args);

using DiagnosticList = std::vector<Diagnostic>;

// A list keeps at most this many diagnostics; one more entry ("and N more diagnostics") counts the
// rest, with the highest severity among them, so that a program of a million bad lines cannot
// exhaust memory and hasErrors() stays true when an error was left out.
inline constexpr size_t kMaxDiagnostics = 1000;

// Appends `diagnostic` within the limit (see kMaxDiagnostics).
void appendDiagnostic(DiagnosticList& list, Diagnostic diagnostic);
void appendDiagnostics(DiagnosticList& list, const DiagnosticList& more);

bool hasErrors(const DiagnosticList& list);

}  // namespace kerf
