#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

// Where the parameters of a cycle block stand on one physical line. The control writes one
// `Qnnn=value ;comment` per line, but CAM post-processors and hand-written programs also put
// several side by side, or on the CYCL DEF line itself: `CYCL DEF 200 DRILLING Q200=2 Q201=-20`.
// Conversational and ISO programs read them alike (docs/klartext.md, "Cycle parameters").
namespace kerf::klartext {

struct CycleParameterSpans {
    std::vector<size_t> starts;  // offsets of each "Qnnn=" / "QSnnn =", in order
    size_t commentAt = 0;        // the ';' that ends the line's parameters, or the line's end
};

// The parameters of text[from, to): each starts at `from` or after a blank with Q or QS, digits
// and '=' (blanks allowed before it), outside quotes; a ';' outside quotes ends them.
CycleParameterSpans cycleParameterSpans(std::string_view text, size_t from, size_t to);

}  // namespace kerf::klartext
