// The profile of G66/G68/G69 (spec part 2 §1.6): the blocks from label S to label E of program Q
// (or the program with the cycle) read as geometry from the cycle's X, Z: lines, arcs (I/K, R,
// G06 absolute centre, G08 tangent, G09 through a point), the corners G36 rounds and G39
// chamfers, points relative to machine zero (G53), inch or mm (G70/G71), and polar coordinates
// about the polar origin G93 presets.
#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/geometry/contour_element.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

namespace {

constexpr size_t kMaxProfileElements = 10000;

std::string gName(int n) {
    return "G" + std::string(n < 10 ? "0" : "") + std::to_string(n);
}

}  // namespace

bool FagorInterpreter::readProfile(const CycleWords& w, const Vec2& start,
                                   std::vector<cycles::lathe::ProfileElement>& finished,
                                   RawProfile& raw) {
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
    // G70/G71 hold for the rest of the profile only: the program goes on in its own units.
    struct UnitsRestorer {
        bool& inch;
        const bool saved;
        ~UnitsRestorer() { inch = saved; }
    } unitsRestorer{m_modal.inch, m_modal.inch};
    Vec2 polarOrigin = m_polarOrigin;  // G93 in the profile moves it for the profile only
    int motion = 1;
    Vec2 at = start;
    // The finished profile, then from its G00 block on the raw-stock profile (§1.6).
    std::vector<cycles::lathe::ProfileElement>* target = &finished;
    std::vector<ProfileCorner> corners;  // G36/G39 at the end of an element
    std::vector<ProfileCorner> rawCorners;
    bool rawStarts = false;
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
        int arcForm = 0;                    // G06, G08 or G09 in this block
        std::optional<size_t> machineZero;  // G53's offset: the block is in machine coordinates
        bool presetsPolarOrigin = false;
        std::optional<ProfileCorner> corner;
        std::vector<cycles::lathe::ProfileElement>& out = *target;
        for (uint8_t i = 0; i < iso.gCount; ++i) {
            const int g = static_cast<int>(iso.g[i].value);
            switch (g) {
                case 1:
                case 2:
                case 3:
                    motion = g;
                    break;
                case 6:
                case 8:
                case 9:
                    arcForm = g;
                    break;
                case 36:
                case 39:
                    if (!(iso.cornerR.present && iso.cornerR.value > 0.0)) {
                        return refuse(iso.g[i].offset,
                                      KERF_TR_NOOP("{1} needs R greater than 0 right after it"),
                                      {gName(g)});
                    }
                    corner = ProfileCorner{0, g == 36, length(iso.cornerR.value), line.firstLine,
                                           program::columnOf(line.text, iso.g[i].offset)};
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
                    if (target != &finished) {
                        return refuse(iso.g[i].offset,
                                      KERF_TR_NOOP("a profile has one raw-stock part (one G00)"),
                                      {});
                    }
                    rawStarts = true;
                    motion = 0;
                    break;
                case 53:
                    machineZero = iso.g[i].offset;
                    break;
                case 70:
                case 71:
                    m_modal.inch = g == 70;
                    break;
                case 93:
                    presetsPolarOrigin = true;
                    break;
                default:
                    return refuse(iso.g[i].offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                                  {gName(g)});
            }
        }
        if (presetsPolarOrigin) {
            // G93 is alone in its block: I, J the origin, or the profile's point without them.
            polarOrigin = polarOriginOf(iso, at);
            continue;
        }
        // Lines and arcs of the plane only: the words besides are refused at their column.
        const std::pair<const WordValue*, char> others[] = {
            {&iso.j, 'J'}, {&iso.l, 'L'}, {&iso.i2, 'I'}};
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
        const bool straight = motion == 0 || motion == 1;
        const bool polarPoint = straight && (iso.r.present || iso.q.present);
        // Q is the angle of a polar point, or the end angle of a G02/G03 arc (I/K, G06 or none).
        const bool polarArc = !straight && iso.q.present && (arcForm == 0 || arcForm == 6);
        if (iso.q.present && ((straight && arcForm != 0) || (!straight && !polarArc))) {
            return refuse(iso.q.offset, KERF_TR_NOOP("{1} is not allowed in a profile"), {"Q"});
        }
        if (machineZero) {
            // G53 names machine positions, so it needs Cartesian points of a line (as in a
            // program); alone it would cancel the zero offset, which a profile may not.
            const bool cartesianLine = straight && arcForm == 0 && !polarPoint &&
                                       (iso.has(plane.abscissa) || iso.has(plane.ordinate));
            if (!cartesianLine) {
                return refuse(*machineZero,
                              KERF_TR_NOOP("G53 in a profile needs a G00 or G01 point in X, Z"),
                              {});
            }
        }
        if (!iso.has(plane.abscissa) && !iso.has(plane.ordinate) && !polarPoint && !iso.q.present) {
            if (rawStarts) {
                return refuse(0,
                              KERF_TR_NOOP("the G00 block starts the raw-stock profile: it "
                                           "needs its point"),
                              {});
            }
            continue;
        }
        Vec2 end = at;
        const auto coordinate = [&](Axis axis, double& value) {
            if (!iso.has(axis)) return;
            const double v = axisValue(axis, iso.axes[static_cast<size_t>(axisIndex(axis))].value);
            value = incremental ? value + v : v;
        };
        if (machineZero) {
            Pose from = programmedPosition();
            plane.setPoint(from, at);
            end = plane.point(fromStream(machineTarget(iso, toStream(from))));
        } else if (polarPoint) {
            if (iso.has(plane.abscissa) || iso.has(plane.ordinate)) {
                return refuse(iso.r.present ? iso.r.offset : iso.q.offset,
                              KERF_TR_NOOP("polar coordinates (R, Q) and Cartesian coordinates "
                                           "of the plane in one block"),
                              {});
            }
            // About the polar origin: R and Q absolute (G90) or added to the point's (G91).
            const Vec2 rel = at - polarOrigin;
            const double r0 = rel.norm();
            const double q0 = r0 > 1e-12 ? angleDeg(rel) : 0.0;
            const double r = iso.r.present ? length(iso.r.value) : (incremental ? 0.0 : r0);
            const double q = iso.q.present ? iso.q.value : (incremental ? 0.0 : q0);
            const double radius = incremental ? r0 + r : r;
            if (radius < 0.0) {
                return refuse(iso.r.offset, KERF_TR_NOOP("the polar radius becomes negative"), {});
            }
            end = polarOrigin + radius * unitAtDeg(incremental ? q0 + q : q);
        } else {
            coordinate(plane.abscissa, end.x());
            coordinate(plane.ordinate, end.y());
        }
        if (rawStarts) {
            // The raw-stock profile starts here; G00 is modal, so its blocks name G01-G03.
            raw.start = end;
            target = &raw.elements;
            rawStarts = false;
            at = end;
            continue;
        }
        if (motion == 0) {
            return refuse(0, KERF_TR_NOOP("after G00 the raw-stock profile needs G01, G02 or G03"),
                          {});
        }
        cycles::lathe::ProfileElement element;
        element.end = end;
        element.line = line.firstLine;
        if (arcForm == 8 || arcForm == 9) {
            // G08 tangent to the previous element; G09 through the point I, K.
            std::optional<Vec2> centre;
            double sweep = 0.0;
            if (arcForm == 8) {
                if (out.empty()) {
                    return refuse(0,
                                  KERF_TR_NOOP("G08 needs a previous path in the plane to be "
                                               "tangent to"),
                                  {});
                }
                const Vec2 from = out.size() > 1 ? out[out.size() - 2].end : start;
                const cycles::lathe::ProfileElement& previous = out.back();
                const Vec2 tangent =
                    previous.centre
                        ? arcTangentAt(*previous.centre, previous.end,
                                       arcSweep(from, previous.end, *previous.centre, previous.ccw))
                        : (previous.end - from).normalized();
                if (const auto arc = tangentArc(at, tangent, end)) {
                    centre = arc->center;
                    sweep = arc->sweep;
                }
            } else {
                Vec2 middle = at;
                const auto through = [&](Axis axis, const WordValue& word, double& value) {
                    if (!word.present) return;
                    const double v = axisValue(axis, word.value);
                    value = incremental ? value + v : v;
                };
                through(plane.abscissa, iso.k, middle.x());
                through(plane.ordinate, iso.i1, middle.y());
                if (const auto circle = circleThrough(at, middle, end)) {
                    centre = circle->center;
                    sweep = arcSweep(at, end, circle->center, cross2(middle - at, end - at) > 0.0);
                }
            }
            if (!centre || (end - at).norm() < 1e-9) {
                return refuse(0, KERF_TR_NOOP("{1} cannot make an arc to this end point"),
                              {gName(arcForm)});
            }
            element.centre = centre;
            element.ccw = sweep > 0.0;
        } else if (motion == 2 || motion == 3) {
            element.ccw = motion == 3;
            if (polarArc) {
                // To the angle Q about the centre I, K (G06: absolute), else the polar origin.
                Vec2 centre = polarOrigin;
                if (iso.i1.present || iso.k.present) {
                    centre = arcForm == 6 ? Vec2(axisValue(plane.abscissa, iso.k.value),
                                                 axisValue(plane.ordinate, iso.i1.value))
                                          : at + Vec2(length(iso.k.value), length(iso.i1.value));
                }
                const double radius = (at - centre).norm();
                if (radius < 1e-9) {
                    return refuse(iso.q.offset, KERF_TR_NOOP("the arc has no radius"), {});
                }
                const double angle =
                    incremental ? angleDeg(at - centre) + iso.q.value : iso.q.value;
                element.end = centre + radius * unitAtDeg(angle);
                element.centre = centre;
                end = element.end;
            } else if (arcForm == 6) {
                // G06: the centre I, K in absolute coordinates (I as X: diameter or radius).
                element.centre = Vec2(axisValue(plane.abscissa, iso.k.value),
                                      axisValue(plane.ordinate, iso.i1.value));
            } else if (iso.r.present) {
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
        } else if ((iso.r.present && !polarPoint) || iso.i1.present || iso.k.present) {
            const WordValue& word = iso.r.present ? iso.r : iso.i1.present ? iso.i1 : iso.k;
            return refuse(word.offset, KERF_TR_NOOP("{1} is not allowed in a profile"),
                          {iso.r.present    ? "R"
                           : iso.i1.present ? "I"
                                            : "K"});
        }
        if (out.size() >= kMaxProfileElements) {
            return refuse(0, KERF_TR_NOOP("the profile has more than 10000 elements"), {});
        }
        if (element.centre && m_settings.polarOriginFollowsArcs && arcForm != 8 && arcForm != 9) {
            polarOrigin = *element.centre;  // PORGMOVE
        }
        out.push_back(element);
        if (corner) {
            corner->element = out.size() - 1;
            (target == &finished ? corners : rawCorners).push_back(*corner);
        }
        at = end;
    }
    const bool here = program == m_program;
    return shapeProfileCorners(start, corners, finished, here) &&
           (raw.elements.empty() || shapeProfileCorners(raw.start, rawCorners, raw.elements, here));
}

bool FagorInterpreter::shapeProfileCorners(const Vec2& start,
                                           const std::vector<ProfileCorner>& corners,
                                           std::vector<cycles::lathe::ProfileElement>& out,
                                           bool here) {
    // From the last corner back, so that inserting keeps the earlier indices.
    for (auto c = corners.rbegin(); c != corners.rend(); ++c) {
        auto refuse = [&](const char* message) {
            if (here) {
                m_at.line = c->line;
                m_at.column = c->column;
            }
            fail("cycle-profile", message, {});
            return false;
        };
        const size_t i = c->element;
        if (i + 1 >= out.size()) {
            return refuse(KERF_TR_NOOP("the next block must be a contour element in the plane"));
        }
        // The two elements as contour elements of the plane (z, x) -> (X, Y).
        auto element = [&](size_t k) {
            const Vec2 from = k == 0 ? start : out[k - 1].end;
            Pose a;
            Pose b;
            a[Axis::X] = from.x();
            a[Axis::Y] = from.y();
            b[Axis::X] = out[k].end.x();
            b[Axis::Y] = out[k].end.y();
            if (!out[k].centre) return ContourElement::line(Plane::XY, a, b);
            return ContourElement::arc(Plane::XY, a, b, *out[k].centre,
                                       arcSweep(from, out[k].end, *out[k].centre, out[k].ccw));
        };
        const ContourElement a = element(i);
        const ContourElement b = element(i + 1);
        cycles::lathe::ProfileElement inserted;
        inserted.line = c->line;
        if (c->round) {
            const auto f = fillet(a, b, c->size);
            if (!f) {
                return refuse(
                    KERF_TR_NOOP("G36: the rounding radius does not fit between the elements"));
            }
            out[i].end = a.pointAt(f->paramOnA);
            inserted.end = b.pointAt(f->paramOnB);
            inserted.centre = f->center;
            inserted.ccw = f->sweep > 0.0;
        } else {
            if (a.kind != ContourElement::Kind::Line || b.kind != ContourElement::Kind::Line) {
                return refuse(KERF_TR_NOOP("G39 needs straight lines on both sides"));
            }
            const double la = a.planarLength();
            const double lb = b.planarLength();
            if (c->size >= la - 1e-9 || c->size >= lb - 1e-9) {
                return refuse(KERF_TR_NOOP("G39: the chamfer is longer than an adjacent line"));
            }
            out[i].end = a.pointAt(1.0 - c->size / la);
            inserted.end = b.pointAt(c->size / lb);
        }
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(i) + 1, inserted);
    }
    return true;
}

}  // namespace kerf::fagor
