#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "drivers/can/frame_observer.h"

// The candump log format of can-utils (`candump -l`, read by canplayer and log2asc):
//   (0000000001.002000) can0 601#4000100000000000
// seconds with ten digits, microseconds with six, the interface, then ID#DATA in upper-case hex
// (three digits for 11-bit, eight for 29-bit identifiers; "R" marks a remote frame).
namespace kerf::drivers::can {

inline constexpr size_t kCandumpLineMax = 64;

// Writes one line without the newline into `out` (at least kCandumpLineMax bytes); returns its
// length. No allocation.
size_t formatCandumpLine(char* out, std::chrono::nanoseconds time, std::string_view interface,
                         const CanFrame& frame) noexcept;

struct CandumpRecord {
    std::chrono::microseconds time{0};
    std::string_view interface;  // points into the parsed line
    CanFrame frame;
};

// Parses one line; false when it is not a classical-CAN candump log line.
bool parseCandumpLine(std::string_view line, CandumpRecord& out) noexcept;

// Appends every observed frame to a file, up to a size limit: the first line that would pass
// it and every later one are left out (truncated() says so), whole lines only. Writing goes
// through stdio's buffer (allocated once by open()); a full disk shows up in close()'s result.
class CandumpWriter final : public FrameObserver {
public:
    explicit CandumpWriter(std::string_view interface = "can0") : m_interface(interface) {}
    void setLimit(uint64_t bytes) noexcept { m_limit = bytes; }
    bool truncated() const noexcept { return m_truncated; }
    uint64_t bytesWritten() const noexcept { return m_written; }
    ~CandumpWriter() override;
    CandumpWriter(const CandumpWriter&) = delete;
    CandumpWriter& operator=(const CandumpWriter&) = delete;

    std::error_code open(const std::filesystem::path& path);
    std::error_code close();
    bool isOpen() const noexcept { return m_file != nullptr; }
    void onFrame(std::chrono::nanoseconds time, const CanFrame& frame) noexcept override;

private:
    std::string_view m_interface;
    std::FILE* m_file = nullptr;
    bool m_failed = false;
    uint64_t m_limit = UINT64_MAX;
    uint64_t m_written = 0;
    bool m_truncated = false;
};

}  // namespace kerf::drivers::can
