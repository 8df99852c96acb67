#include "core/cycles/cycle_values.h"

#include <cmath>

#include "core/base/saturating.h"

namespace kerf::cycles {

void CycleValues::set(uint16_t q, double value) {
    Entry& e = m_entries[q];
    e.number = value;
    e.feed = Feed::perMinute(value);
}

void CycleValues::setFeed(uint16_t q, Feed feed) {
    Entry& e = m_entries[q];
    e.feed = feed;
    e.number = feed.value;
}

void CycleValues::setText(uint16_t q, std::string text) {
    m_entries[q].text = std::move(text);
}

double CycleValues::number(uint16_t q) const {
    auto it = m_entries.find(q);
    return it == m_entries.end() ? 0.0 : it->second.number;
}

Feed CycleValues::feed(uint16_t q) const {
    auto it = m_entries.find(q);
    return it == m_entries.end() ? Feed::perMinute(0.0) : it->second.feed;
}

Feed CycleValues::feedOr(uint16_t q, uint16_t fallback) const {
    Feed f = feed(q);
    return f.isZero() ? feed(fallback) : f;
}

const std::string& CycleValues::text(uint16_t q) const {
    static const std::string kEmpty;
    auto it = m_entries.find(q);
    return it == m_entries.end() ? kEmpty : it->second.text;
}

int CycleValues::integer(uint16_t q) const {
    return saturatingInt(std::round(number(q)));
}

}  // namespace kerf::cycles
