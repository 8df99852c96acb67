#pragma once

#include <vector>

#include "core/cycles/lathe/tool_reach.h"

namespace kerf::cycles::lathe {

// The closest profile the insert reaches (spec part 2 §1.6: "the CNC builds a modified profile in
// the zones the tool cannot reach"), for a profile that advances steadily along `feed` (a unit
// vector; the material on the side opposite `outward`). A descent into the material steeper than
// the trailing edge allows (180° - CUTA - NOSEA) is bridged by the line that leaves the profile
// at that angle until it meets the profile again; with CUTA below 90° a wall rising steeper than
// CUTA is bridged the same way from the far side. Bridges start and end exactly on the
// profile's lines and arcs (an arc may be shortened, never replaced); the rest is unchanged.
// Before that, a concave arc tighter than the nose radius R is replaced by what the nose
// reaches: its neighbours up to where the nose rests on them, joined by an arc of radius R
// (this needs R only). The angle rules are skipped when CUTA or NOSEA is 0 or the profile
// turns back against `feed`.
std::vector<ProfileElement> reachableProfile(const Vec2& start,
                                             const std::vector<ProfileElement>& profile,
                                             const Vec2& feed, const Vec2& outward,
                                             const InsertGeometry& insert);

}  // namespace kerf::cycles::lathe
