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
// Concave arcs tighter than the nose are left as they are. Returns the profile unchanged when
// the geometry is unknown (CUTA or NOSEA 0) or the profile turns back against `feed`.
std::vector<ProfileElement> reachableProfile(const Vec2& start,
                                             const std::vector<ProfileElement>& profile,
                                             const Vec2& feed, const Vec2& outward,
                                             const InsertGeometry& insert);

}  // namespace kerf::cycles::lathe
