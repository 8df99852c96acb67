#pragma once

#include <optional>
#include <vector>

#include "core/cycles/lathe/lathe_path.h"
#include "core/cycles/lathe/turning_chain.h"

namespace kerf::cycles::lathe {

// The channels of a G68/G69 profile (spec part 2 §2 G68, step 2): the stretches where the profile
// dips back under a level, left by the main passes and roughed afterwards one by one.
struct ChannelRoughing {
    const Chain* chain = nullptr;   // the profile plus its allowances, in the (cut, step) frame
    const Chain* raw = nullptr;     // the raw-stock profile, if any
    std::vector<double> levels;     // the pass levels, from the first below the call point down
    Vec2 call{0.0, 0.0};            // the call point in the frame
    double side = 1.0;              // +1 when the material lies above the profile (towards call)
    double passDirection = -1.0;    // the sign of the passes' travel along the frame's x
    std::optional<double> retract;  // D
    double feed = 0.0;              // the roughing passes (0: the feed active at the call)
    double plungeFeed = 0.0;        // K: down the channel's wall (0: the roughing feed)
    bool facing = false;            // the frame is swapped (G69)
};

// Each channel from its entry at the level the main passes left it: down its wall along the
// profile at K, a pass at the feed to the opposite wall, the retract D (absent: up that wall
// along the profile), back to the entry, down to the next level; channels inside channels
// afterwards, the same way. Between channels the tool leaves straight up to the call level.
// False when the profile has no channel.
bool roughChannels(const ChannelRoughing& job, LathePath& path);

}  // namespace kerf::cycles::lathe
