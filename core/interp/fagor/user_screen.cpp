#include "core/interp/fagor/user_screen.h"

#include <cmath>
#include <cstdio>

#include "core/base/translate.h"

namespace kerf::fagor {

void UserScreen::showPage(int page) {
    m_page = page;
    m_symbols.clear();
    m_windows = {};
    ++m_revision;
}

void UserScreen::drawSymbol(const ScreenSymbol& symbol) {
    m_symbols.push_back(symbol);
    ++m_revision;
}

void UserScreen::defineWindow(int window, int row, int column) {
    m_windows[static_cast<size_t>(window)] = DataWindow{row, column, {}};
    ++m_revision;
}

bool UserScreen::showInWindow(int window, std::string text) {
    auto& w = m_windows[static_cast<size_t>(window)];
    if (!w) return false;
    if (w->text != text) {
        w->text = std::move(text);
        ++m_revision;
    }
    return true;
}

void UserScreen::setSoftkeys(const std::vector<std::pair<int, std::string>>& keys) {
    if (!m_userMenu) m_softkeys = {};
    m_userMenu = true;
    for (const auto& [key, text] : keys)
        m_softkeys[static_cast<size_t>(key - 1)] = text;
    ++m_revision;
}

void UserScreen::showPrompt(std::string text) {
    m_prompt = std::move(text);
    ++m_revision;
}

void UserScreen::askNumber(int input, std::string prompt, InputFormat format) {
    m_prompt = std::move(prompt);
    m_format = format;
    m_input = input;
    m_answer.reset();
    m_waiting = Waiting::Number;
    ++m_revision;
}

void UserScreen::askKey() {
    m_key.reset();
    m_waiting = Waiting::Key;
    ++m_revision;
}

std::optional<double> UserScreen::takeNumber() {
    if (!m_answer) return std::nullopt;
    const double value = *m_answer;
    m_answer.reset();
    m_inputs[static_cast<size_t>(m_input)] = value;
    m_waiting = Waiting::Nothing;
    ++m_revision;
    return value;
}

std::optional<int> UserScreen::takeKey() {
    if (!m_key) return std::nullopt;
    const int key = *m_key;
    m_key.reset();
    if (m_waiting == Waiting::Key) m_waiting = Waiting::Nothing;
    ++m_revision;
    return key;
}

void UserScreen::appendToBlock(std::string_view text) {
    m_editBuffer += text;
    ++m_revision;
}

void UserScreen::insertBlock() {
    m_inserted.push_back(m_editBuffer);
    m_editBuffer.clear();
    ++m_revision;
}

void UserScreen::leave() {
    m_left = true;
    m_waiting = Waiting::Nothing;
    m_userMenu = false;
    m_softkeys = {};
    ++m_revision;
}

bool UserScreen::pressKey(int code) {
    if (m_keySource != 0 || m_waiting != Waiting::Key) return false;
    m_key = code;
    ++m_revision;
    return true;
}

std::optional<std::string> UserScreen::enterNumber(std::string_view text) {
    if (m_waiting != Waiting::Number) return std::string(KERF_TR_NOOP("no input is asked for"));
    while (!text.empty() && text.front() == ' ')
        text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ')
        text.remove_suffix(1);
    bool negative = false;
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    if (negative && !m_format.negative) {
        return std::string(KERF_TR_NOOP("only positive values are accepted here"));
    }
    int integerDigits = 0;
    int decimals = 0;
    bool point = false;
    for (char c : text) {
        if (c == '.' && !point) {
            point = true;
        } else if (c >= '0' && c <= '9') {
            (point ? decimals : integerDigits) += 1;
        } else {
            return std::string(KERF_TR_NOOP("a number is expected"));
        }
    }
    if (integerDigits + decimals == 0) return std::string(KERF_TR_NOOP("a number is expected"));
    if (integerDigits > m_format.integerDigits || decimals > m_format.decimals) {
        return std::string(KERF_TR_NOOP("the number does not fit the input format"));
    }
    const double value = std::stod(std::string(text));
    m_answer = negative ? -value : value;
    ++m_revision;
    return std::nullopt;
}

std::vector<std::string> UserScreen::takeInsertedBlocks() {
    std::vector<std::string> blocks(
        m_inserted.begin() + static_cast<std::ptrdiff_t>(m_insertedTaken), m_inserted.end());
    m_insertedTaken = m_inserted.size();
    return blocks;
}

std::string UserScreen::describe() const {
    std::string out = "page " + (m_page < 0 ? std::string("-") : std::to_string(m_page)) + "\n";
    for (const ScreenSymbol& s : m_symbols) {
        out += "symbol " + std::to_string(s.number) + " at column " + std::to_string(s.column) +
               ", row " + std::to_string(s.row) + "\n";
    }
    for (size_t i = 0; i < m_windows.size(); ++i) {
        if (!m_windows[i]) continue;
        out += "window " + std::to_string(i) + " (row " + std::to_string(m_windows[i]->row) +
               ", column " + std::to_string(m_windows[i]->column) + "): " + m_windows[i]->text +
               "\n";
    }
    for (size_t i = 0; i < m_softkeys.size(); ++i) {
        if (!m_softkeys[i].empty()) {
            out += "softkey F" + std::to_string(i + 1) + ": \"" + m_softkeys[i] + "\"\n";
        }
    }
    if (!m_prompt.empty()) out += "input: " + m_prompt + "\n";
    if (!m_editBuffer.empty()) out += "edit buffer: " + m_editBuffer + "\n";
    for (const std::string& block : m_inserted)
        out += "inserted block: " + block + "\n";
    return out;
}

std::string decimalText(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.5f", value);
    std::string s = text;
    while (s.back() == '0')
        s.pop_back();
    if (s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string hexadecimalText(double value) {
    // Negative values as 32-bit two's complement.
    const auto bits = static_cast<uint32_t>(static_cast<int64_t>(std::llround(value)));
    char text[16];
    std::snprintf(text, sizeof text, "%X", bits);
    return text;
}

std::string binaryText(double value) {
    const long long n = std::llround(value);
    if (n > 255) return "11111111";
    if (n < -127) return "10000000";
    const auto bits = static_cast<uint8_t>(n);
    std::string s(8, '0');
    for (int i = 0; i < 8; ++i) {
        if ((bits & (1u << i)) != 0) s[static_cast<size_t>(7 - i)] = '1';
    }
    return s;
}

std::pair<std::string, std::string> softkeyLines(std::string_view text) {
    if (text.size() < 10) {
        const size_t left = (10 - text.size()) / 2;
        std::string upper(left, ' ');
        upper += text;
        upper.append(10 - upper.size(), ' ');
        return {upper, std::string()};
    }
    return {std::string(text.substr(0, 10)), std::string(text.substr(10))};
}

std::string keyName(int code) {
    if (code >= UserScreen::kSoftkeyF1 && code < UserScreen::kSoftkeyF1 + UserScreen::kSoftkeys) {
        return "F" + std::to_string(code - UserScreen::kSoftkeyF1 + 1);
    }
    if (code > 32 && code < 127) return std::string(1, static_cast<char>(code));
    char text[16];
    std::snprintf(text, sizeof text, "$%04X", static_cast<unsigned>(code));
    return text;
}

std::optional<int> keyCode(std::string_view name) {
    if (name.size() == 2 && (name[0] == 'F' || name[0] == 'f') && name[1] >= '1' &&
        name[1] <= '7') {
        return UserScreen::kSoftkeyF1 + (name[1] - '1');
    }
    if (name.size() >= 2 && name[0] == '$' && name.size() <= 5) {
        int code = 0;
        for (char c : name.substr(1)) {
            const int digit = c >= '0' && c <= '9'   ? c - '0'
                              : c >= 'A' && c <= 'F' ? c - 'A' + 10
                              : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                                     : -1;
            if (digit < 0) return std::nullopt;
            code = code * 16 + digit;
        }
        return code;
    }
    if (name.size() == 1 && name[0] > 32 && name[0] < 127) return name[0];
    return std::nullopt;
}

}  // namespace kerf::fagor
