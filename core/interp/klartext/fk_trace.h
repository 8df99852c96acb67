#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/source_location.h"
#include "core/geometry/offset_contour.h"
#include "core/geometry/plane.h"

// What the FK solver made of a program's FK blocks while it ran, for the programming graphics
// (docs/hmi.md, "FK programming graphics"): every FK element with its geometry once it is
// determined, and every choice between several solutions.
namespace kerf::klartext {

struct FkTrace {
    struct Element {
        SourceLocation at;                     // the FK block
        std::optional<PlanarSegment> segment;  // empty: not determined (yet)
        std::optional<Vec2> givenEnd;          // X and Y given absolutely: where it ends
        std::optional<Vec2> sequenceStart;     // the first of an FK sequence: where it starts
        // Determined only by taking solution 1 of an element whose FSELECT is missing: the
        // graphics go on with it, drawn as an assumption.
        bool tentative = false;
    };
    struct Ambiguity {
        SourceLocation at;     // the element that has several solutions
        SourceLocation after;  // the block that made it so: FSELECT must follow this one
        std::vector<PlanarSegment> alternatives;  // FSELECT n picks alternatives[n - 1]
        std::optional<SourceLocation> selectAt;   // the FSELECT that chose
        int selected = 0;                         // its n; 0: none yet
    };
    std::vector<Element> elements;
    std::vector<Ambiguity> ambiguities;
    // The working plane of the elements: their coordinates are its first and second axes.
    Plane plane = Plane::XY;
};

}  // namespace kerf::klartext
