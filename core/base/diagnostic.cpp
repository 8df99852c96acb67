#include "core/base/diagnostic.h"

#include <algorithm>
#include <string>

namespace kerf {

std::string_view severityName(Severity severity) {
    switch (severity) {
        case Severity::Note:
            return "note";
        case Severity::Warning:
            return "warning";
        case Severity::Error:
            return "error";
    }
    return "error";
}

std::string substituteArgs(std::string_view messageTemplate, const std::vector<std::string>& args) {
    std::string out;
    out.reserve(messageTemplate.size() + 32);
    for (size_t i = 0; i < messageTemplate.size(); ++i) {
        char c = messageTemplate[i];
        if (c == '{' && i + 1 < messageTemplate.size() && messageTemplate[i + 1] == '{') {
            out += '{';
            ++i;
        } else if (c == '{' && i + 2 < messageTemplate.size() && messageTemplate[i + 2] == '}' &&
                   messageTemplate[i + 1] >= '1' && messageTemplate[i + 1] <= '9') {
            size_t index = static_cast<size_t>(messageTemplate[i + 1] - '1');
            if (index < args.size()) out += args[index];
            i += 2;
        } else {
            out += c;
        }
    }
    return out;
}

std::string Diagnostic::message() const {
    return substituteArgs(messageTemplate, args);
}

std::string Diagnostic::format() const {
    std::string out = file.empty() ? std::string("kerf") : file;
    if (line > 0) {
        out += ':' + std::to_string(line);
        if (column > 0) out += ':' + std::to_string(column);
    }
    out += ": ";
    out += severityName(severity);
    out += ": ";
    out += message();
    return out;
}

namespace {

constexpr const char* kOmittedCode = "too-many-diagnostics";

bool endsWithOmitted(const DiagnosticList& list) {
    return !list.empty() && list.back().code == kOmittedCode;
}

// Counts `count` left-out diagnostics in the list's last entry.
void addOmitted(DiagnosticList& list, unsigned long long count, Severity severity) {
    if (!endsWithOmitted(list)) {
        list.push_back(Diagnostic::make(severity, kOmittedCode, "", 0, 0,
                                        KERF_TR_NOOP("and {1} more diagnostics"), "0"));
    }
    Diagnostic& omitted = list.back();
    omitted.args.front() = std::to_string(std::stoull(omitted.args.front()) + count);
    omitted.severity = std::max(omitted.severity, severity);
}

}  // namespace

void appendDiagnostic(DiagnosticList& list, Diagnostic diagnostic) {
    if (list.size() < kMaxDiagnostics && !endsWithOmitted(list)) {
        list.push_back(std::move(diagnostic));
    } else {
        addOmitted(list, 1, diagnostic.severity);
    }
}

void appendDiagnostics(DiagnosticList& list, const DiagnosticList& more) {
    for (const Diagnostic& d : more) {
        if (d.code == kOmittedCode) {
            addOmitted(list, std::stoull(d.args.front()), d.severity);
        } else {
            appendDiagnostic(list, d);
        }
    }
}

bool hasErrors(const DiagnosticList& list) {
    return std::any_of(list.begin(), list.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

}  // namespace kerf
