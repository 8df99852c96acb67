#include "core/interp/klartext/fprint_formatter.h"

#include <cstdio>
#include <vector>

#include "core/base/saturating.h"
#include "core/base/translate.h"

namespace kerf::klartext {

namespace {

struct Value {
    bool isString = false;
    double number = 0.0;
    std::string text;
};

std::optional<Value> dateValue(std::string_view word, const std::tm& now) {
    if (word == "DAY") return Value{false, static_cast<double>(now.tm_mday), {}};
    if (word == "MONTH") return Value{false, static_cast<double>(now.tm_mon + 1), {}};
    if (word == "YEAR2") return Value{false, static_cast<double>((now.tm_year + 1900) % 100), {}};
    if (word == "YEAR4") return Value{false, static_cast<double>(now.tm_year + 1900), {}};
    if (word == "HOUR") return Value{false, static_cast<double>(now.tm_hour), {}};
    if (word == "MIN") return Value{false, static_cast<double>(now.tm_min), {}};
    if (word == "SEC") return Value{false, static_cast<double>(now.tm_sec), {}};
    return std::nullopt;
}

Diagnostic maskError(const std::string& name, uint32_t line, const char* text,
                     std::string arg = {}) {
    return Diagnostic::make(Severity::Error, "fprint", name, line, 1, text, std::move(arg));
}

// Applies one printf field to one value, converting the TNC letters to C ones.
std::string formatField(std::string spec, const Value& value) {
    char conversion = static_cast<char>(spec.back());
    spec.pop_back();
    if (!spec.empty() && (spec.back() == 'L' || spec.back() == 'l')) spec.pop_back();
    char buffer[512];
    int n = 0;
    if (conversion == 'S' || conversion == 's') {
        spec += 's';
        std::string text = value.isString ? value.text : std::to_string(value.number);
        n = std::snprintf(buffer, sizeof buffer, spec.c_str(), text.c_str());
    } else if (conversion == 'D' || conversion == 'd' || conversion == 'I' || conversion == 'i') {
        spec += 'd';
        n = std::snprintf(buffer, sizeof buffer, spec.c_str(),
                          saturatingInt(value.isString ? 0.0 : value.number));
    } else {
        spec += 'f';
        n = std::snprintf(buffer, sizeof buffer, spec.c_str(), value.isString ? 0.0 : value.number);
    }
    if (n < 0) return {};
    return std::string(buffer, std::min(static_cast<size_t>(n), sizeof buffer - 1));
}

}  // namespace

Expected<FPrintOutput> formatFPrint(std::string_view mask, const std::string& maskName,
                                    FormulaEnvironment& environment, const std::tm& now) {
    FPrintOutput out;
    bool languageActive = true;
    uint32_t lineNumber = 0;
    size_t start = 0;
    while (start < mask.size()) {
        size_t end = mask.find('\n', start);
        if (end == std::string_view::npos) end = mask.size();
        std::string_view line = mask.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        Cursor c(line);
        if (c.atEnd()) continue;
        if (c.peek() != '"') {
            std::string_view keyword = c.word();
            if (keyword == "M_APPEND") {
                out.append = true;
            } else if (keyword == "L_ALL" || keyword == "L_ENGLISH") {
                languageActive = true;
            } else if (keyword.substr(0, 2) == "L_") {
                languageActive = false;
            } else if (keyword != "M_CLOSE" && keyword != "M_EMPTY_HIDE" &&
                       keyword != "M_EMPTY_SHOW" && keyword != "M_TRUNCATE") {
                return maskError(maskName, lineNumber, KERF_TR_NOOP("unknown keyword '{1}'"),
                                 std::string(keyword));
            }
            continue;
        }
        auto format = c.quoted();
        if (!format) {
            return maskError(maskName, lineNumber, KERF_TR_NOOP("the format has no closing quote"));
        }
        std::vector<Value> values;
        while (c.acceptChar(',')) {
            FormulaParser parser(c, &environment);
            if (auto ref = parser.parameter(true)) {
                if (ref->kind == QKind::QS) {
                    values.push_back({true, 0.0, environment.string(ref->index)});
                } else {
                    values.push_back({false, environment.number(*ref), {}});
                }
                continue;
            }
            std::string_view word = c.word();
            auto date = dateValue(word, now);
            if (!date) {
                return maskError(maskName, lineNumber, KERF_TR_NOOP("unknown value '{1}'"),
                                 std::string(word));
            }
            values.push_back(*date);
        }
        c.acceptChar(';');
        if (!languageActive) continue;
        std::string text;
        size_t next = 0;
        for (size_t i = 0; i < format->size(); ++i) {
            char ch = (*format)[i];
            if (ch == '\\' && i + 1 < format->size() && (*format)[i + 1] == 'n') {
                text += '\n';
                ++i;
                continue;
            }
            if (ch != '%') {
                text += ch;
                continue;
            }
            if (i + 1 < format->size() && (*format)[i + 1] == '%') {
                text += '%';
                ++i;
                continue;
            }
            size_t j = i + 1;
            while (j < format->size() && std::string_view("-+ #0123456789.lL").find((*format)[j]) !=
                                             std::string_view::npos) {
                ++j;
            }
            if (j >= format->size() ||
                std::string_view("FfDdIiSs").find((*format)[j]) == std::string_view::npos) {
                return maskError(maskName, lineNumber, KERF_TR_NOOP("bad format field"));
            }
            if (next >= values.size()) {
                return maskError(maskName, lineNumber, KERF_TR_NOOP("more fields than values"));
            }
            text += formatField(std::string(format->substr(i, j - i + 1)), values[next++]);
            i = j;
        }
        out.text += text;
        out.text += '\n';
    }
    return out;
}

}  // namespace kerf::klartext
