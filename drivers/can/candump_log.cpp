#include "drivers/can/candump_log.h"

#include <cerrno>
#include <cinttypes>
#include <cstring>
#include <string>

namespace kerf::drivers::can {

namespace {

constexpr char kHex[] = "0123456789ABCDEF";

int hexDigit(char c) noexcept {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

bool parseHex(std::string_view text, uint32_t& value) noexcept {
    if (text.empty() || text.size() > 8) return false;
    value = 0;
    for (char c : text) {
        int d = hexDigit(c);
        if (d < 0) return false;
        value = value << 4 | static_cast<uint32_t>(d);
    }
    return true;
}

bool parseDecimal(std::string_view text, uint64_t& value) noexcept {
    if (text.empty() || text.size() > 19) return false;
    value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        value = value * 10 + static_cast<uint64_t>(c - '0');
    }
    return true;
}

}  // namespace

size_t formatCandumpLine(char* out, std::chrono::nanoseconds time, std::string_view interface,
                         const CanFrame& frame) noexcept {
    auto micros =
        static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(time).count());
    int n = std::snprintf(out, kCandumpLineMax, "(%010" PRIu64 ".%06" PRIu64 ") %.*s ",
                          micros / 1'000'000u, micros % 1'000'000u,
                          static_cast<int>(interface.size() > 15 ? 15 : interface.size()),
                          interface.data());
    auto pos = static_cast<size_t>(n < 0 ? 0 : n);
    int digits = frame.extended ? 8 : 3;
    for (int i = digits - 1; i >= 0; --i)
        out[pos++] = kHex[(frame.id >> (4 * i)) & 0xF];
    out[pos++] = '#';
    if (frame.remote) {
        out[pos++] = 'R';
    } else {
        for (uint8_t i = 0; i < frame.length && i < kMaxDataLength; ++i) {
            out[pos++] = kHex[frame.data[i] >> 4];
            out[pos++] = kHex[frame.data[i] & 0xF];
        }
    }
    out[pos] = '\0';
    return pos;
}

bool parseCandumpLine(std::string_view line, CandumpRecord& out) noexcept {
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.remove_suffix(1);
    if (line.size() < 3 || line.front() != '(') return false;
    size_t close = line.find(')');
    size_t dot = line.find('.');
    if (close == std::string_view::npos || dot == std::string_view::npos || dot > close) {
        return false;
    }
    uint64_t seconds = 0;
    uint64_t micros = 0;
    if (!parseDecimal(line.substr(1, dot - 1), seconds) ||
        !parseDecimal(line.substr(dot + 1, close - dot - 1), micros) || close - dot - 1 != 6) {
        return false;
    }
    out.time = std::chrono::microseconds(static_cast<int64_t>(seconds * 1'000'000u + micros));
    std::string_view rest = line.substr(close + 1);
    if (rest.empty() || rest.front() != ' ') return false;
    rest.remove_prefix(1);
    size_t space = rest.find(' ');
    if (space == std::string_view::npos || space == 0) return false;
    out.interface = rest.substr(0, space);
    rest = rest.substr(space + 1);
    // candump may append " T" / " R" (transmitted / received) after the frame.
    if (size_t tail = rest.find(' '); tail != std::string_view::npos) rest = rest.substr(0, tail);
    size_t hash = rest.find('#');
    if (hash == std::string_view::npos || (hash != 3 && hash != 8)) return false;
    CanFrame frame;
    if (!parseHex(rest.substr(0, hash), frame.id)) return false;
    frame.extended = hash == 8;
    if (frame.id > (frame.extended ? kExtendedIdMask : kStandardIdMask)) return false;
    std::string_view data = rest.substr(hash + 1);
    if (!data.empty() && (data.front() == 'R' || data.front() == 'r')) {
        frame.remote = true;
    } else {
        if (data.size() % 2 != 0 || data.size() > 2 * kMaxDataLength) return false;
        for (size_t i = 0; i < data.size(); i += 2) {
            int hi = hexDigit(data[i]);
            int lo = hexDigit(data[i + 1]);
            if (hi < 0 || lo < 0) return false;
            frame.data[frame.length++] = static_cast<uint8_t>(hi << 4 | lo);
        }
    }
    out.frame = frame;
    return true;
}

CandumpWriter::~CandumpWriter() {
    close();
}

std::error_code CandumpWriter::open(const std::filesystem::path& path) {
    close();
    m_file = std::fopen(path.c_str(), "w");
    if (!m_file) return {errno, std::generic_category()};
    m_failed = false;
    m_written = 0;
    m_truncated = false;
    return {};
}

std::error_code CandumpWriter::close() {
    if (!m_file) return {};
    bool failed = m_failed || std::ferror(m_file) != 0;
    int result = std::fclose(m_file);
    m_file = nullptr;
    if (failed || result != 0) return std::make_error_code(std::errc::io_error);
    return {};
}

void CandumpWriter::onFrame(std::chrono::nanoseconds time, const CanFrame& frame) noexcept {
    if (!m_file || m_truncated) return;
    char line[kCandumpLineMax + 1];
    size_t length = formatCandumpLine(line, time, m_interface, frame);
    line[length] = '\n';
    if (m_written + length + 1 > m_limit) {
        m_truncated = true;
        return;
    }
    m_written += length + 1;
    if (std::fwrite(line, 1, length + 1, m_file) != length + 1) m_failed = true;
}

}  // namespace kerf::drivers::can
