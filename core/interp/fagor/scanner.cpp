#include "core/interp/fagor/scanner.h"

namespace kerf::fagor {

bool Scanner::unsignedNumber(ScannedNumber& out) {
    skipBlanks();
    const char* const begin = m_text.data() + m_pos;
    const char* const end = m_text.data() + m_text.size();
    const char* p = begin;
    while (p != end && *p == '0')
        ++p;  // leading zeros are not significant digits
    uint64_t mantissa = 0;
    const char* digitsStart = p;
    while (p != end && isDigit(*p)) {
        if (p - digitsStart < 18) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
        ++p;
    }
    const auto intDigits = static_cast<size_t>(p - digitsStart);
    const bool anyInt = p != begin;
    size_t decimals = 0;
    double scale = 1.0;
    if (p != end && *p == '.') {
        const char* q = p + 1;
        while (q != end && isDigit(*q)) {
            if (intDigits + decimals < 18) {
                mantissa = mantissa * 10 + static_cast<unsigned>(*q - '0');
                scale *= 10.0;
            }
            ++decimals;
            ++q;
        }
        if (decimals == 0 && !anyInt) return false;  // a lone '.'
        p = q;
    } else if (!anyInt) {
        return false;
    }
    double value = static_cast<double>(mantissa);
    // Digits beyond 18 significant ones only matter for absurd lengths; they scale the value.
    for (size_t i = 18; i < intDigits; ++i)
        value *= 10.0;
    out.value = value / scale;
    out.intDigits = static_cast<uint8_t>(intDigits > 255 ? 255 : intDigits);
    out.decDigits = static_cast<uint8_t>(decimals > 255 ? 255 : decimals);
    m_pos += static_cast<size_t>(p - begin);
    return true;
}

bool Scanner::unsignedInteger(int64_t& out, uint8_t& digits) {
    skipBlanks();
    size_t i = m_pos;
    int64_t value = 0;
    while (i < m_text.size() && isDigit(m_text[i])) {
        if (i - m_pos >= 18) return false;
        value = value * 10 + (m_text[i] - '0');
        ++i;
    }
    if (i == m_pos) return false;
    digits = static_cast<uint8_t>(i - m_pos);
    out = value;
    m_pos = i;
    return true;
}

std::string_view Scanner::letters() {
    skipBlanks();
    size_t start = m_pos;
    while (m_pos < m_text.size() && isUpper(m_text[m_pos]))
        ++m_pos;
    return m_text.substr(start, m_pos - start);
}

}  // namespace kerf::fagor
