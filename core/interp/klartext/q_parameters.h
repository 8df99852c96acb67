#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/base/expected.h"

namespace kerf::klartext {

// Q parameter families of the TNC 320: global Q, program-local QL, remanent QR (kept across power
// off) and string QS.
enum class QKind : uint8_t { Q, QL, QR, QS };

struct QRef {
    QKind kind = QKind::Q;
    uint16_t index = 0;
    friend bool operator==(const QRef&, const QRef&) = default;
};

inline constexpr int kQCount = 2000;
inline constexpr int kQlCount = 500;
inline constexpr int kQrCount = 500;
inline constexpr int kQsCount = 2000;

int qLimit(QKind kind);
const char* qPrefix(QKind kind);

// All Q values of a run. QL values live per program level (a CALL PGM gets fresh ones). An unset
// parameter reads as 0 (strings as empty), as on the control.
class QParameters {
public:
    QParameters();

    double get(QRef ref) const;
    void set(QRef ref, double value);
    // Whether the run (or the remanent file) gave the parameter a value; QL of the current level.
    bool isSet(QRef ref) const;
    const std::string& getString(uint16_t index) const { return m_strings[index]; }
    bool stringDefined(uint16_t index) const { return m_stringSet[index]; }
    void setString(uint16_t index, std::string value);

    void pushLocalLevel();
    void popLocalLevel();

    // Remanent values: read from and saved (atomically) to a small text file "QRn=value" per line.
    MaybeError loadRemanent(const std::filesystem::path& file);
    MaybeError saveRemanent(const std::filesystem::path& file) const;
    bool remanentChanged() const { return m_remanentChanged; }

private:
    std::vector<double> m_q;
    std::vector<std::array<double, kQlCount>> m_local;
    std::array<double, kQrCount> m_remanent{};
    std::bitset<kQCount> m_qSet;
    std::vector<std::bitset<kQlCount>> m_localSet;
    std::bitset<kQrCount> m_remanentSet;
    std::vector<std::string> m_strings;
    std::vector<bool> m_stringSet;
    bool m_remanentChanged = false;
};

}  // namespace kerf::klartext
