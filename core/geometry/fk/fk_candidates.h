#pragma once

#include <optional>
#include <vector>

#include "core/geometry/fk/fk_carrier.h"
#include "core/geometry/fk/fk_element.h"

// What one FK element's data say about its carrier and its end point, given what is known
// around it. Incremental data (IX, IPA, IAN ...) need the element's start point.
namespace kerf::fk {

struct CandidateContext {
    std::optional<Vec2> start;
    std::optional<Vec2> startTangent;  // end direction of the element before, when start is known
    std::optional<Vec2> pole;          // FPOL
    // The carrier of the element before, for a tangential element whose start is not known yet.
    std::optional<Carrier> previous;
    // The carrier of the next element if it is tangential and determined by its own data.
    std::optional<Carrier> next;
    std::optional<Vec2> contourStart;  // where CLSD- ends
};

enum class Found : uint8_t { Undetermined, Some, Contradiction };

struct CarrierCandidates {
    Found found = Found::Undetermined;
    std::vector<Carrier> carriers;
};

// The carriers the element's data allow, in the order of the FSELECT numbering.
CarrierCandidates carrierCandidates(const FkElement& element, const CandidateContext& context);

struct EndCandidates {
    Found found = Found::Undetermined;  // Undetermined: the end is where the next element starts
    std::vector<Vec2> ends;
};

// The end points the element's data give on `carrier` from `start`.
EndCandidates endCandidates(const FkElement& element, const Carrier& carrier, const Vec2& start,
                            const CandidateContext& context);

// Whether an element from start to end on its carrier runs the carrier's way (lines; an arc may
// end anywhere on its circle, its start too).
bool runsForward(const Carrier& carrier, const Vec2& start, const Vec2& end);

}  // namespace kerf::fk
