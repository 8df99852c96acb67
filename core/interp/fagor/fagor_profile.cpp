// The profile of G68/G69 (spec part 2 §1.6): the blocks from label S to label E of program Q (or
// the program with the cycle) read as geometry, lines and arcs from the cycle's X, Z.
#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

namespace {

constexpr size_t kMaxProfileElements = 10000;

std::string gName(int n) {
    return "G" + std::string(n < 10 ? "0" : "") + std::to_string(n);
}

}  // namespace

bool FagorInterpreter::readProfile(const CycleWords& w, const Vec2& start,
                                   std::vector<cycles::lathe::ProfileElement>& out) {
    if (!waitForCheck()) return false;
    FagorProgram* program = m_program;
    if (w.has('Q')) {
        Problem problem;
        program = programByNumber(static_cast<int>(w['Q'].value), true, problem);
        if (program == nullptr) {
            failAt(w['Q'].offset, problem);
            return false;
        }
    }
    auto label = [&](char letter, BlockPosition& at) {
        const auto number = static_cast<int64_t>(w[letter].value);
        const BlockPosition* found = program->findLabel(number);
        if (found == nullptr) {
            m_at.column = program::columnOf(m_line.text, w[letter].offset);
            fail("cycle-profile", KERF_TR_NOOP("label N{1} of the profile is not in the program"),
                 {std::to_string(number)});
            return false;
        }
        at = *found;
        return true;
    };
    BlockPosition first;
    BlockPosition last;
    if (!label('S', first) || !label('E', last)) return false;
    if (last.offset < first.offset) {
        m_at.column = program::columnOf(m_line.text, w['E'].offset);
        fail("cycle-profile", KERF_TR_NOOP("the profile ends (E) before it starts (S)"));
        return false;
    }
    const PlaneFrame& plane = m_modal.plane;
    std::string_view text = program->source->text();
    program::LineReader reader(text.substr(0, std::min(text.size(), program->end)));
    reader.seek(first.offset, first.line);
    BlockParser parser(this);
    ParsedBlock block;
    program::LogicalLine line;
    bool incremental = m_modal.incremental;
    int motion = 1;
    Vec2 at = start;
    // A problem in a profile block is reported at that block.
    auto refuse = [&](size_t offset, const char* message, std::vector<std::string> args) {
        if (program == m_program) {
            m_at.line = line.firstLine;
            m_at.column = program::columnOf(line.text, offset);
        }
        fail("cycle-profile", message, std::move(args));
        return false;
    };
    while (reader.offset() <= last.offset && reader.next(line, false)) {
        if (!parser.parse(line.text, false, block)) {
            const Problem& p = parser.problem();
            return refuse(p.offset, p.messageTemplate.c_str(), p.args);
        }
        if (block.kind == ParsedBlock::Kind::HighLevel) {
            return refuse(block.highLevelOffset,
                          KERF_TR_NOOP("a profile holds no high-level blocks"), {});
        }
        if (block.kind != ParsedBlock::Kind::Iso) continue;
        const IsoBlock& iso = block.iso;
        for (uint8_t i = 0; i < iso.gCount; ++i) {
            const int g = static_cast<int>(iso.g[i].value);
            switch (g) {
                case 1:
                case 2:
                case 3:
                    motion = g;
                    break;
                case 90:
                case 91:
                    incremental = g == 91;
                    break;
                case 5:
                case 7:
                case 50:
                    break;  // accepted and ignored (§1.6)
                case 0:
                case 6:
                case 8:
                case 9:
                case 36:
                case 39:
                case 53:
                case 70:
                case 71:
                case 93:
                    return refuse(iso.g[i].offset,
                                  KERF_TR_NOOP("{1} in a profile is not supported yet"),
                                  {gName(g)});
                default:
                    return refuse(iso.g[i].offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                                  {gName(g)});
            }
        }
        // Lines and arcs of the plane only: the words besides are refused at their column.
        const std::pair<const WordValue*, char> others[] = {
            {&iso.q, 'Q'}, {&iso.j, 'J'}, {&iso.l, 'L'}, {&iso.i2, 'I'}};
        for (const auto& [word, letter] : others) {
            if (word->present) {
                return refuse(word->offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                              {std::string(1, letter)});
            }
        }
        if (iso.cycle.g >= 0) {
            return refuse(iso.cycle.offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                          {gName(iso.cycle.g)});
        }
        for (uint8_t i = 0; i < iso.axisCount; ++i) {
            const Axis axis = iso.axisOrder[i];
            if (axis != plane.abscissa && axis != plane.ordinate) {
                return refuse(iso.axes[static_cast<size_t>(axisIndex(axis))].offset,
                              KERF_TR_NOOP("{1} is not allowed in a profile"),
                              {std::string(1, axisLetter(axis))});
            }
        }
        if (!iso.has(plane.abscissa) && !iso.has(plane.ordinate)) continue;
        Vec2 end = at;
        const auto coordinate = [&](Axis axis, double& value) {
            if (!iso.has(axis)) return;
            const double v = axisValue(axis, iso.axes[static_cast<size_t>(axisIndex(axis))].value);
            value = incremental ? value + v : v;
        };
        coordinate(plane.abscissa, end.x());
        coordinate(plane.ordinate, end.y());
        cycles::lathe::ProfileElement element;
        element.end = end;
        if (motion == 2 || motion == 3) {
            element.ccw = motion == 3;
            if (iso.r.present) {
                const auto c = arcCenterFromRadius(at, end, length(iso.r.value), element.ccw);
                if (!c) {
                    return refuse(iso.r.offset,
                                  KERF_TR_NOOP("the arc radius R is too small for the end point"),
                                  {});
                }
                element.centre = *c;
            } else {
                // I and K relative to the start, always radius (K of the abscissa, I of X).
                element.centre = at + Vec2(length(iso.k.value), length(iso.i1.value));
            }
        } else if (iso.r.present || iso.i1.present || iso.k.present) {
            const WordValue& word = iso.r.present ? iso.r : iso.i1.present ? iso.i1 : iso.k;
            return refuse(word.offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                          {iso.r.present    ? "R"
                           : iso.i1.present ? "I"
                                            : "K"});
        }
        if (out.size() >= kMaxProfileElements) {
            return refuse(0, KERF_TR_NOOP("the profile has more than 10000 elements"), {});
        }
        out.push_back(element);
        at = end;
    }
    return true;
}

}  // namespace kerf::fagor
