#include "core/interp/fagor/tables/table_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

bool isUpper(char c) {
    return c >= 'A' && c <= 'Z';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

// Reads "[+-]digits[.digits]" and nothing else.
bool parseNumber(std::string_view text, double& out) {
    if (text.empty()) return false;
    size_t i = (text[0] == '+' || text[0] == '-') ? 1 : 0;
    size_t digits = 0;
    bool point = false;
    for (size_t j = i; j < text.size(); ++j) {
        if (isDigit(text[j])) {
            ++digits;
        } else if (text[j] == '.' && !point) {
            point = true;
        } else {
            return false;
        }
    }
    if (digits == 0) return false;
    std::string copy(text.substr(i));
    auto result = std::from_chars(copy.data(), copy.data() + copy.size(), out);
    if (result.ec != std::errc()) return false;
    if (text[0] == '-') out = -out;
    return true;
}

}  // namespace

const TableField* TableRow::field(std::string_view name) const {
    for (const TableField& f : fields) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

std::string formatTableNumber(double value, int decimals) {
    std::string text = formatFixed(value, decimals);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text = "0";
    return text;
}

Diagnostic TableText::error(size_t line, size_t column, const char* messageTemplate,
                            std::vector<std::string> args) const {
    Diagnostic d =
        Diagnostic::make(Severity::Error, "table", m_fileName, static_cast<uint32_t>(line + 1),
                         static_cast<uint32_t>(column + 1), messageTemplate);
    d.args = std::move(args);
    return d;
}

Expected<TableText> TableText::parse(std::string_view bytes, std::string fileName) {
    TableText table;
    table.m_fileName = std::move(fileName);
    size_t at = 0;
    while (at < bytes.size()) {
        size_t end = at;
        while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r')
            ++end;
        Line line;
        line.text = std::string(bytes.substr(at, end - at));
        if (end < bytes.size()) {
            const bool crlf =
                bytes[end] == '\r' && end + 1 < bytes.size() && bytes[end + 1] == '\n';
            line.ending = crlf ? "\r\n" : std::string(1, bytes[end]);
            end += line.ending.size();
        }
        table.m_lines.push_back(std::move(line));
        at = end;
    }
    for (size_t i = 0; i < table.m_lines.size(); ++i) {
        if (auto problem = table.parseLine(i)) return *problem;
    }
    return table;
}

TableText TableText::create(std::string_view header, std::string_view comment) {
    TableText table;
    table.appendLine(std::string(header));
    table.appendLine("; " + std::string(comment));
    return table;
}

MaybeError TableText::parseLine(size_t index) {
    const std::string& text = m_lines[index].text;
    m_rows.erase(std::remove_if(m_rows.begin(), m_rows.end(),
                                [&](const TableRow& r) { return r.line == index; }),
                 m_rows.end());
    if (index == 0 && !text.empty() && text[0] == '%') return std::nullopt;  // header
    size_t end = std::min(text.find(';'), text.size());
    size_t i = 0;
    auto token = [&](size_t& start) {
        while (i < end && isBlank(text[i]))
            ++i;
        start = i;
        while (i < end && !isBlank(text[i]))
            ++i;
        return std::string_view(text).substr(start, i - start);
    };
    size_t start = 0;
    std::string_view key = token(start);
    if (key.empty()) return std::nullopt;  // blank or comment line
    for (char c : key) {
        if (!isUpper(c) && !isDigit(c)) {
            return error(index, start, KERF_TR_NOOP("'{1}' is not a row key"), {std::string(key)});
        }
    }
    TableRow row;
    row.key = std::string(key);
    row.line = index;
    for (;;) {
        std::string_view word = token(start);
        if (word.empty()) break;
        size_t letters = 0;
        while (letters < word.size() && isUpper(word[letters]))
            ++letters;
        TableField field;
        field.name = std::string(word.substr(0, letters));
        field.offset = start;
        field.length = word.size();
        if (letters == 0 || !parseNumber(word.substr(letters), field.value)) {
            return error(index, start, KERF_TR_NOOP("'{1}' is not a field (letters and a number)"),
                         {std::string(word)});
        }
        row.fields.push_back(std::move(field));
    }
    for (const TableRow& other : m_rows) {
        if (other.key == row.key) {
            return error(index, 0, KERF_TR_NOOP("row {1} appears twice"), {row.key});
        }
    }
    auto position = std::find_if(m_rows.begin(), m_rows.end(),
                                 [&](const TableRow& r) { return r.line > index; });
    m_rows.insert(position, std::move(row));
    return std::nullopt;
}

std::string TableText::serialize() const {
    std::string out;
    for (const Line& line : m_lines) {
        out += line.text;
        out += line.ending;
    }
    return out;
}

const TableRow* TableText::row(std::string_view key) const {
    for (const TableRow& r : m_rows) {
        if (r.key == key) return &r;
    }
    return nullptr;
}

void TableText::appendLine(std::string text) {
    std::string ending = "\n";
    if (!m_lines.empty()) {
        Line& last = m_lines.back();
        // Keep the file's line ending; a last line without one gets it now.
        for (const Line& l : m_lines) {
            if (!l.ending.empty()) {
                ending = l.ending;
                break;
            }
        }
        if (last.ending.empty()) last.ending = ending;
    }
    m_lines.push_back(Line{std::move(text), ending});
}

void TableText::set(std::string_view key, std::string_view name, double value, int decimals) {
    std::string number = formatTableNumber(value, decimals);
    const TableRow* existing = row(key);
    if (existing == nullptr) {
        appendLine(std::string(key) + " " + std::string(name) + number);
        (void)parseLine(m_lines.size() - 1);
        return;
    }
    const size_t index = existing->line;
    std::string& text = m_lines[index].text;
    if (const TableField* f = existing->field(name)) {
        // Keep an explicit '+' the way the file wrote it.
        const bool plus =
            text.size() > f->offset + name.size() && text[f->offset + name.size()] == '+';
        if (plus && value >= 0.0) number.insert(0, "+");
        text.replace(f->offset, f->length, std::string(name) + number);
    } else {
        size_t insertAt = text.size();
        if (!existing->fields.empty()) {
            const TableField& last = existing->fields.back();
            insertAt = last.offset + last.length;
        } else {
            insertAt = text.find(existing->key) + existing->key.size();
        }
        text.insert(insertAt, " " + std::string(name) + number);
    }
    (void)parseLine(index);
}

bool TableText::removeRow(std::string_view key) {
    const TableRow* existing = row(key);
    if (existing == nullptr) return false;
    m_lines.erase(m_lines.begin() + static_cast<std::ptrdiff_t>(existing->line));
    // The lines after it moved up: index the rows again.
    m_rows.clear();
    for (size_t i = 0; i < m_lines.size(); ++i)
        (void)parseLine(i);
    return true;
}

void TableText::replaceRow(std::string_view key, std::string_view fields) {
    std::string text = std::string(key);
    if (!fields.empty()) text += " " + std::string(fields);
    if (const TableRow* existing = row(key)) {
        const size_t index = existing->line;
        std::string& line = m_lines[index].text;
        const size_t comment = line.find(';');
        std::string tail =
            comment == std::string::npos ? std::string() : "  " + line.substr(comment);
        line = text + tail;
        (void)parseLine(index);
        return;
    }
    appendLine(text);
    (void)parseLine(m_lines.size() - 1);
}

}  // namespace kerf::fagor
