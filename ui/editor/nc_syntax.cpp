#include "ui/editor/nc_syntax.h"

#include <QString>

#include "core/interp/fagor/cycle_syntax.h"

namespace kerf::ui {

namespace {

bool is(QStringView word, const char* text) {
    return word.compare(QLatin1String(text)) == 0;
}
bool isDigit(QChar c) {
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}
bool isUpper(QChar c) {
    return (c >= QLatin1Char('A') && c <= QLatin1Char('Z')) || c == QLatin1Char('_');
}
bool isNumberChar(QChar c) {
    return isDigit(c) || c == QLatin1Char('.');
}

// Letters that start a coordinate or an address word when a number, sign or parameter follows.
bool isAxisLetter(QChar c) {
    return QStringView(u"XYZABCUVWIJKRH").contains(c);
}
// Letters of function words: feed, speed, tool, miscellaneous and G functions.
bool isFunctionLetter(QChar c, program::Dialect dialect) {
    if (dialect == program::Dialect::Klartext)
        return c == QLatin1Char('F') || c == QLatin1Char('S') || c == QLatin1Char('M');
    return QStringView(u"GMFSTD").contains(c);
}

class LineScanner {
public:
    LineScanner(QStringView line, program::Dialect dialect) : m_line(line), m_dialect(dialect) {}

    std::vector<NcSpan> scan() {
        skipSpaces();
        scanBlockNumber();
        while (m_pos < m_line.size()) {
            const QChar c = m_line[m_pos];
            if (c == QLatin1Char(';')) {
                add(m_pos, m_line.size() - m_pos, NcToken::Comment);
                break;
            }
            if (isUpper(c)) {
                scanWord();
            } else if (isNumberChar(c) ||
                       ((c == QLatin1Char('+') || c == QLatin1Char('-')) &&
                        m_pos + 1 < m_line.size() && isNumberChar(m_line[m_pos + 1]))) {
                const qsizetype start = m_pos++;
                while (m_pos < m_line.size() && isNumberChar(m_line[m_pos]))
                    ++m_pos;
                add(start, m_pos - start, NcToken::Number);
            } else {
                ++m_pos;
            }
        }
        return std::move(m_spans);
    }

private:
    void scanBlockNumber() {
        const qsizetype start = m_pos;
        if (m_dialect != program::Dialect::Klartext) {
            if (m_pos < m_line.size() && m_line[m_pos] == QLatin1Char('N'))
                ++m_pos;
            else
                return;
        }
        const qsizetype digits = m_pos;
        while (m_pos < m_line.size() && isDigit(m_line[m_pos]))
            ++m_pos;
        if (m_pos == digits) {
            m_pos = start;
            return;
        }
        add(start, m_pos - start, NcToken::BlockNumber);
    }

    void scanWord() {
        const qsizetype start = m_pos;
        while (m_pos < m_line.size() && isUpper(m_line[m_pos]))
            ++m_pos;
        const QStringView word = m_line.mid(start, m_pos - start);
        const QChar next = m_pos < m_line.size() ? m_line[m_pos] : QChar();
        const bool valueFollows =
            isNumberChar(next) || next == QLatin1Char('+') || next == QLatin1Char('-');
        if (word.size() == 1 && m_cycle != nullptr && m_cycle->find(word[0].toLatin1())) {
            add(start, 1, NcToken::Parameter);
        } else if (isParameter(word) && isDigit(next)) {
            while (m_pos < m_line.size() && isDigit(m_line[m_pos]))
                ++m_pos;
            add(start, m_pos - start, NcToken::Parameter);
        } else if (word.size() == 1 && isFunctionLetter(word[0], m_dialect) &&
                   (valueFollows || is(word, "F"))) {
            takeValue();
            add(start, m_pos - start, NcToken::Function);
            if (m_dialect == program::Dialect::Fagor && is(word, "G"))
                m_cycle = fagor::cycleSyntax(m_line.mid(start + 1, m_pos - start - 1).toInt());
        } else if (word.size() == 1 && isAxisLetter(word[0]) &&
                   (valueFollows || next == QLatin1Char('Q'))) {
            add(start, 1, NcToken::Address);
        } else if (is(word, "FMAX") || is(word, "FAUTO")) {
            add(start, m_pos - start, NcToken::Function);
        } else {
            add(start, m_pos - start, NcToken::Keyword);
        }
    }

    bool isParameter(QStringView word) const {
        if (m_dialect == program::Dialect::Fagor) return is(word, "P");
        return is(word, "Q") || is(word, "QL") || is(word, "QR") || is(word, "QS");
    }

    void takeValue() {
        if (m_pos < m_line.size() &&
            (m_line[m_pos] == QLatin1Char('+') || m_line[m_pos] == QLatin1Char('-')))
            ++m_pos;
        while (m_pos < m_line.size() && isNumberChar(m_line[m_pos]))
            ++m_pos;
    }

    void skipSpaces() {
        while (m_pos < m_line.size() && m_line[m_pos].isSpace())
            ++m_pos;
    }

    void add(qsizetype start, qsizetype length, NcToken token) {
        m_spans.push_back({static_cast<int>(start), static_cast<int>(length), token});
    }

    QStringView m_line;
    program::Dialect m_dialect;
    qsizetype m_pos = 0;
    // After a FAGOR canned cycle G66-G89 the block's letters are that cycle's parameters, as
    // the block parser reads them (an X is still the cycle's X, an M no M function).
    const fagor::CycleSyntax* m_cycle = nullptr;
    std::vector<NcSpan> m_spans;
};

}  // namespace

std::vector<NcSpan> scanNcLine(QStringView line, program::Dialect dialect) {
    return LineScanner(line, dialect).scan();
}

}  // namespace kerf::ui
