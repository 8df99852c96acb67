#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/fk/fk_carrier.h"
#include "core/geometry/fk/fk_element.h"
#include "core/geometry/offset_contour.h"

// Resolves a sequence of FK elements into lines and arcs as soon as the data given so far
// determine them (docs/klartext.md, "FK free contour programming"). Pure: no interpreter state,
// the caller feeds elements, FSELECT choices and the end of the sequence, and emits what comes
// back in order.
namespace kerf::fk {

struct FkProblem {
    size_t tag = 0;         // the element whose block is to blame
    bool atCaller = false;  // the block being executed instead (FSELECT, the end of the sequence)
    const char* messageTemplate = "";
    std::vector<std::string> args;
};

struct FkResolved {
    size_t tag = 0;
    PlanarSegment segment;
};

struct FkStep {
    std::vector<FkResolved> resolved;  // newly determined elements, in contour order
    std::optional<FkProblem> problem;  // the sequence cannot go on
    size_t choices = 0;                // > 1: FSELECT 1..choices must follow
};

// One alternative of an ambiguous element, for the programming graphics.
struct FkAlternative {
    size_t tag = 0;
    PlanarSegment segment;
};

class FkSolver {
public:
    // Most elements that may wait for data of later blocks (the TNC allows 64 blocks back for
    // relative data; the solver looks at most two elements ahead).
    static constexpr size_t kMaxWaiting = 3;

    // The contour continues from `start`; `tangent` is the end direction of the element before
    // (FLT and FCT need it), empty at the start of a program.
    void begin(const Vec2& start, std::optional<Vec2> tangent);
    bool idle() const { return m_window.empty() && m_alternatives.empty(); }
    bool awaitingChoice() const { return !m_alternatives.empty(); }
    const std::vector<FkAlternative>& alternatives() const { return m_alternatives; }

    // A block's end point, direction and centre for R.. data of later blocks (conventional
    // blocks too). FK elements are remembered when they are resolved.
    void remember(int64_t blockNumber, const Vec2& end, const Vec2& endTangent,
                  std::optional<Vec2> centre);

    // `tag` is the caller's name for the element; `pole` is FPOL (empty: none).
    FkStep add(const FkElement& element, size_t tag, std::optional<Vec2> pole);
    FkStep select(int choice);  // FSELECT n, 1-based
    // The FK sequence ends: every element must be determined.
    FkStep finish();

private:
    struct Pending {
        FkElement element;
        size_t tag = 0;
        std::optional<Vec2> pole;
        std::optional<Carrier> fixed;  // carrier chosen while resolving the element before
    };
    struct Choice {
        PlanarSegment segment;
        Carrier carrier;
        std::optional<Carrier> next;  // the following element's carrier, if it was chosen too
    };
    struct Reference {
        int64_t block = -1;
        Vec2 end{0.0, 0.0};
        Vec2 tangent{1.0, 0.0};
        std::optional<Vec2> centre;
    };
    enum class Outcome : uint8_t { Waiting, Resolved, Ambiguous, Failed };

    Outcome advance(FkStep& step);
    static void addChoice(std::vector<Choice>& choices, Choice choice);
    void commit(const Choice& choice, FkStep& step);
    bool resolveReferences(FkElement& element, size_t tag, const std::optional<Vec2>& pole,
                           FkStep& step) const;
    const Reference* reference(int64_t block) const;

    std::deque<Pending> m_window;
    std::vector<Choice> m_choices;
    std::vector<FkAlternative> m_alternatives;
    size_t m_ambiguousTag = 0;
    Vec2 m_start{0.0, 0.0};
    std::optional<Vec2> m_tangent;
    std::optional<Vec2> m_contourStart;  // where the CLSD+ element starts
    bool m_closing = false;              // a CLSD+ element was given
    std::deque<Reference> m_references;
};

}  // namespace kerf::fk
