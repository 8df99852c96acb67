#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace kerf::cycles {

// A resolved feed: mm/min, mm/rev or rapid traverse.
struct Feed {
    enum class Kind : uint8_t { PerMinute, PerRevolution, Rapid };
    Kind kind = Kind::PerMinute;
    double value = 0.0;

    static Feed perMinute(double mmPerMin) { return {Kind::PerMinute, mmPerMin}; }
    static Feed perRevolution(double mmPerRev) { return {Kind::PerRevolution, mmPerRev}; }
    static Feed rapid() { return {Kind::Rapid, 0.0}; }
    bool isRapid() const { return kind == Kind::Rapid; }
    bool isZero() const { return kind != Kind::Rapid && value == 0.0; }
};

// The parameter values of one cycle definition, captured when the definition is processed
// (lengths and feeds already in mm). Missing parameters read as 0.
class CycleValues {
public:
    void set(uint16_t q, double value);
    void setFeed(uint16_t q, Feed feed);
    void setText(uint16_t q, std::string text);

    bool has(uint16_t q) const { return m_entries.count(q) != 0; }
    double number(uint16_t q) const;
    // A feed parameter; a plain number is mm/min.
    Feed feed(uint16_t q) const;
    // Feed `q`, or feed `fallback` when `q` is 0 (e.g. Q208 = 0: retract at the plunging feed).
    Feed feedOr(uint16_t q, uint16_t fallback) const;
    const std::string& text(uint16_t q) const;
    int integer(uint16_t q) const;

private:
    struct Entry {
        double number = 0.0;
        Feed feed;
        std::string text;
    };
    std::map<uint16_t, Entry> m_entries;
};

}  // namespace kerf::cycles
