// Cycle 14 CONTOUR and the contour subprograms of the SL cycles (spec §6.1): at a cycle call
// each listed label is read with the interpreter's own path functions (CC, C, CR, CT, RND, CHF,
// polar), its moves kept instead of sent on, and turned into a closed chain of lines and arcs.
#include <cmath>
#include <type_traits>

#include "core/base/translate.h"
#include "core/geometry/contour_region.h"
#include "core/interp/klartext/contour_labels.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

constexpr size_t kMaxContourBlocks = 16384;  // spec: contour elements of one SL cycle
const char* const kNoContourInSubprogram =
    KERF_TR_NOOP("the contour subprogram {1} has no contour");

// Keeps what a contour subprogram would have sent to the canonical stream.
class MoveCapture final : public canon::Sink {
public:
    void consume(const canon::Command& command) override { commands.push_back(command); }
    std::vector<canon::Command> commands;
};

// Coordinate transformations (datum shift, mirror image, rotation, scaling) may be programmed in
// a contour subprogram (spec §8: they act on the following subprograms of the same call).
bool isTransformation(const Statement& s) {
    const auto* cycle = std::get_if<CycleDefinition>(&s);
    if (cycle == nullptr || cycle->probe || cycle->subNumber < 0) return false;
    return cycle->number == 7 || cycle->number == 8 || cycle->number == 10 || cycle->number == 11 ||
           cycle->number == 26;
}

// Blocks a contour subprogram may hold: path functions, parameter calculations and
// transformations.
bool allowedInContour(const Statement& s) {
    return std::holds_alternative<Empty>(s) || std::holds_alternative<LinearBlock>(s) ||
           std::holds_alternative<CircleCenter>(s) || std::holds_alternative<CircleBlock>(s) ||
           std::holds_alternative<CircleRadiusBlock>(s) ||
           std::holds_alternative<CircleTangentBlock>(s) || std::holds_alternative<RoundBlock>(s) ||
           std::holds_alternative<ChamferBlock>(s) || std::holds_alternative<LinePolarBlock>(s) ||
           std::holds_alternative<CirclePolarBlock>(s) ||
           std::holds_alternative<CircleTangentPolarBlock>(s) ||
           std::holds_alternative<QAssign>(s) || std::holds_alternative<QStringAssign>(s) ||
           std::holds_alternative<FkBlock>(s) || std::holds_alternative<FkPole>(s) ||
           std::holds_alternative<FkSelect>(s) || isTransformation(s);
}

// M functions of a contour subprogram have no effect (spec §8: "F and M are ignored"): the
// machine state the cycle runs with stays as it was.
Statement withoutMFunctions(const Statement& s) {
    Statement copy = s;
    std::visit(
        [](auto& b) {
            if constexpr (requires { b.words.m; }) b.words.m = MWords{};
        },
        copy);
    return copy;
}

const Coordinates* coordinatesOf(const Statement& s) {
    return std::visit(
        [](const auto& b) -> const Coordinates* {
            if constexpr (requires { b.coords; }) {
                if constexpr (std::is_same_v<std::decay_t<decltype(b.coords)>, Coordinates>) {
                    return &b.coords;
                }
            }
            return nullptr;
        },
        s);
}

bool movesInPlane(const Statement& s) {
    return std::holds_alternative<LinearBlock>(s) || std::holds_alternative<CircleBlock>(s) ||
           std::holds_alternative<CircleRadiusBlock>(s) ||
           std::holds_alternative<CircleTangentBlock>(s) ||
           std::holds_alternative<LinePolarBlock>(s) ||
           std::holds_alternative<CirclePolarBlock>(s) ||
           std::holds_alternative<CircleTangentPolarBlock>(s) || std::holds_alternative<FkBlock>(s);
}

}  // namespace

// "CYCL DEF 14.1 CONTOUR LABEL 1/2/3" (KONTURLABEL1 /2, LABEL CONTORNO1/2 ...): the keyword is
// language-dependent, the numbers after it are the labels.
// The single-block form "CYCL DEF 14 CONTOUR LABEL 1/2/3" has the same text after the number.
void KlartextInterpreter::contourLabels(const CycleDefinition& def) {
    if (def.subNumber != 1 && def.subNumber >= 0) return;
    const ContourLabelList list = parseContourLabels(def.subNumber == 1 ? def.rest : def.name);
    if (list.error != nullptr) {
        fail("cycle-syntax", list.error);
        return;
    }
    m_contourLabels.clear();
    for (const ContourLabel& label : list.labels)
        m_contourLabels.push_back(label.number);
    m_contourSource = ContourSource::Labels;
}

bool KlartextInterpreter::captureContours(std::vector<cycles::SubContour>& out) {
    out.clear();
    if (m_contourSource != ContourSource::Labels) return true;
    m_subcontourFrame = cycles::CoordinateFrame{};
    for (int label : m_contourLabels) {
        LabelTarget target;
        target.number = label;
        const LabelPosition* position = resolveLabel(target);
        if (position == nullptr) return false;
        cycles::SubContour sub;
        if (!captureContour(*position, label, sub)) return false;
        out.push_back(std::move(sub));
    }
    return true;
}

bool KlartextInterpreter::captureTrain(int cycle, cycles::ContourTrain& out) {
    out = cycles::ContourTrain{};
    out.labelCount = m_contourLabels.size();
    if (m_contourLabels.empty()) return true;  // the cycle asks for cycle 14
    m_subcontourFrame = cycles::CoordinateFrame{};
    // Spec §6.1: cycle 25 uses the first label only, 275 and 276 need exactly one (they check).
    LabelTarget target;
    target.number = m_contourLabels.front();
    const LabelPosition* position = resolveLabel(target);
    if (position == nullptr) return false;
    CapturedChain chain;
    ChainRules rules;
    rules.approach = cycle == 275;
    rules.toolAxis = cycle == 276;
    if (!captureChain(*m_levels.back().program, *position, rules, chain)) return false;
    if (!checkContourReach(chain.segments, "LBL " + std::to_string(*target.number),
                           kNoContourInSubprogram)) {
        return false;
    }
    out.segments = std::move(chain.segments);
    out.side = chain.side == CompWord::Left ? 1 : chain.side == CompWord::Right ? -1 : 0;
    out.approach = chain.approach;
    if (rules.toolAxis) out.heights = std::move(chain.heights);
    out.label = *target.number;
    const Vec2 start = out.segments.front().start;
    out.closed = (out.segments.back().end - start).norm() <= 1e-6;
    if (out.closed) out.segments.back().end = start;
    return true;
}

bool KlartextInterpreter::captureChain(const ProgramFile& program, const LabelPosition& position,
                                       ChainRules rules, CapturedChain& out) {
    // The subprogram runs in program coordinates (the cycle's moves are transformed later),
    // without compensation (RL/RR only tell pocket from island), from the current position.
    const Pose programmed = m_programmed;
    const CompWord comp = m_comp;
    const std::optional<Vec2> lastTangent = m_lastTangent;
    const Plane lastTangentPlane = m_lastTangentPlane;
    const Direction direction = m_direction;
    const cycles::CoordinateFrame frame = m_frame;
    const SourceLocation callAt = m_at;
    const canon::FeedMode feedMode = m_feedMode;
    const double feed = m_feed;
    const bool feedSet = m_feedSet;
    const int lastCycle = m_lastCycleDefined;
    // Feeds of a contour subprogram do not matter (the cycle has its own): any will do.
    if (!m_feedSet) {
        m_feed = 1.0;
        m_feedSet = true;
    }
    // Transformations of earlier subprograms of this call still act (m_subcontourFrame).
    m_frame = m_subcontourFrame;
    m_comp = CompWord::Off;
    MoveCapture capture;
    interp::PathBuilder builder(capture);
    builder.reset(m_programmed);
    builder.setToolRadius(0.0);
    m_capturePath = &builder;
    // The subprogram's FK sequence is its own: the caller's FPOL stays valid in it.
    FkState outerFk = std::move(m_fk);
    m_fk = FkState{};
    m_fk.pole = outerFk.pole;

    const Plane plane = workingPlane();
    const PlaneAxes axes = planeAxes(plane);
    // A DIN/ISO contour program is read with a parser of its own: its modal path function
    // is not the running program's.
    std::unique_ptr<BlockSyntax> ownParser;
    BlockSyntax& parser = parserFor(program, ownParser);
    BlockReader reader(program.source->text(), &parser);
    reader.seek(position.offset, position.line);
    program::LogicalLine line;
    ParsedBlock parsed;
    bool firstBlock = true;
    bool firstMove = true;
    std::optional<CompWord> side;
    out.approach = false;
    size_t count = 0;
    bool stop = false;
    while (!stop && m_status != interp::RunStatus::Failed && reader.next(line)) {
        m_at = SourceLocation{program.fileId, line.firstLine, 1, -1};
        if (!parser.parse(line, parsed)) {
            const ParseProblem& p = parser.problem();
            m_at.line = line.lineAt(p.offset);
            m_at.column = line.columnAt(p.offset);
            fail(p.code.c_str(), p.messageTemplate.c_str(), p.args);
            break;
        }
        m_at.blockNumber = parsed.blockNumber;
        // An ISO block may mean several conversational ones ("I+5 J+5 G02 X+10": CC, then C).
        for (size_t k = 0; k <= parsed.more.size() && !stop; ++k) {
            const Statement& s = k == 0 ? parsed.statement : parsed.more[k - 1];
            if (rules.formula && std::holds_alternative<BeginPgm>(s)) continue;
            if (rules.formula && std::holds_alternative<EndPgm>(s)) {
                stop = true;
                break;
            }
            if (std::holds_alternative<Label>(s)) {
                if (firstBlock) {
                    firstBlock = false;
                    continue;
                }
                stop = true;  // LBL 0, or the next subprogram
                break;
            }
            firstBlock = false;
            const bool approach = std::holds_alternative<ApproachBlock>(s);
            if (!allowedInContour(s) && !(approach && rules.approach)) {
                fail("contour", KERF_TR_NOOP("this block is not allowed in a contour subprogram"));
                stop = true;
                break;
            }
            if (const Coordinates* c = coordinatesOf(s);
                c != nullptr && c->has(axes.normal) && !rules.toolAxis && !rules.formula) {
                fail("contour",
                     KERF_TR_NOOP("a contour subprogram must not move in the tool axis"));
                stop = true;
                break;
            }
            if (firstMove && approach) out.approach = true;
            if (firstMove && movesInPlane(s) && !out.approach) {
                const auto* l = std::get_if<LinearBlock>(&s);
                const bool polarLine = rules.formula && std::holds_alternative<LinePolarBlock>(s);
                if (!polarLine &&
                    (l == nullptr || !l->coords.has(axes.first) || !l->coords.has(axes.second))) {
                    fail("contour",
                         KERF_TR_NOOP("the first block of a contour subprogram must be a "
                                      "straight line with both working-plane axes"));
                    stop = true;
                    break;
                }
                if (rules.toolAxis && l != nullptr && !l->coords.has(axes.normal)) {
                    fail("contour", KERF_TR_NOOP("the first block of a 3-D contour subprogram must "
                                                 "give the tool axis too"));
                    stop = true;
                    break;
                }
            }
            if (++count > kMaxContourBlocks) {
                fail("contour", KERF_TR_NOOP("a contour subprogram has more than 16384 blocks"));
                stop = true;
                break;
            }
            execute(withoutMFunctions(s));
            if (firstMove && (movesInPlane(s) || approach)) {
                firstMove = false;
                side = m_comp;
                // A mirror image in the subprogram turns the contour: RL and RR swap with it.
                if (m_frame.flipsOrientation(plane) &&
                    (side == CompWord::Left || side == CompWord::Right))
                    side = side == CompWord::Left ? CompWord::Right : CompWord::Left;
            }
        }
    }
    finishFk();
    if (m_status != interp::RunStatus::Failed) checkPathError(builder.flush());
    m_capturePath = nullptr;
    m_subcontourFrame = m_frame;
    m_fk = std::move(outerFk);
    m_programmed = programmed;
    m_comp = comp;
    m_lastTangent = lastTangent;
    m_lastTangentPlane = lastTangentPlane;
    m_direction = direction;
    m_frame = frame;
    m_at = callAt;
    m_feedMode = feedMode;
    m_feed = feed;
    m_feedSet = feedSet;
    m_lastCycleDefined = lastCycle;
    if (m_status == interp::RunStatus::Failed) return false;

    // The moves after the first (which leads to the start point) are the contour.
    std::vector<PlanarSegment>& contour = out.segments;
    contour.clear();
    out.heights.clear();
    std::optional<Vec2> from;
    double fromW = 0.0;
    for (const canon::Command& command : capture.commands) {
        const Pose* target = nullptr;
        const canon::ArcMove* arc = std::get_if<canon::ArcMove>(&command.body);
        if (const auto* r = std::get_if<canon::RapidMove>(&command.body)) target = &r->target;
        if (const auto* l = std::get_if<canon::LinearMove>(&command.body)) target = &l->target;
        if (arc != nullptr) target = &arc->target;
        if (target == nullptr) continue;
        const Vec2 to{(*target)[axes.first], (*target)[axes.second]};
        const double toW = (*target)[axes.normal];
        const size_t before = contour.size();
        if (from && (to - *from).norm() > 1e-9) {
            if (arc != nullptr) {
                const Vec2 centre{arc->center[axisIndex(axes.first)],
                                  arc->center[axisIndex(axes.second)]};
                contour.push_back({PlanarSegment::Kind::Arc, *from, to, centre, arc->sweepRad});
            } else {
                contour.push_back(PlanarSegment::line(*from, to));
            }
        } else if (from && arc != nullptr && std::fabs(arc->sweepRad) > 1e-9) {
            const Vec2 centre{arc->center[axisIndex(axes.first)],
                              arc->center[axisIndex(axes.second)]};
            contour.push_back(PlanarSegment::arc(*from, centre, arc->sweepRad));
        }
        if (contour.size() > before) out.heights.emplace_back(fromW, toW);
        from = to;
        fromW = toW;
    }
    out.side = side.value_or(CompWord::Off);
    return true;
}

// Contour coordinates beyond any machine's reach would overflow the contour engine's grid.
bool KlartextInterpreter::checkContourReach(const std::vector<PlanarSegment>& segments,
                                            const std::string& name, const char* noContour) {
    const std::vector<std::string> args{name};
    if (segments.empty()) {
        fail("contour", noContour, args);
        return false;
    }
    for (const PlanarSegment& s : segments) {
        for (const Vec2& p : {s.start, s.end, s.center}) {
            if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxContourCoordinateMm) {
                fail("contour",
                     KERF_TR_NOOP("the contour of {1} lies beyond 1,000,000 mm from the origin"),
                     args);
                return false;
            }
        }
    }
    return true;
}

// The control closes a contour that ends elsewhere with a straight line (the islands of the
// seed's chapter 7 example end one side short of their start).
bool KlartextInterpreter::closeContour(std::vector<PlanarSegment> segments, const std::string& name,
                                       ClosedContour& out) {
    const std::vector<std::string> args{name};
    out.segments = std::move(segments);
    const Vec2 start = out.segments.front().start;
    if ((out.segments.back().end - start).norm() > 1e-6) {
        out.segments.push_back(PlanarSegment::line(out.segments.back().end, start));
    }
    out.segments.back().end = start;
    if (std::fabs(out.signedArea()) < 1e-9) {
        fail("contour", KERF_TR_NOOP("the contour of {1} encloses no area"), args);
        return false;
    }
    if (selfIntersects(out)) {
        fail("contour", KERF_TR_NOOP("the contour of {1} intersects itself"), args);
        return false;
    }
    return true;
}

bool KlartextInterpreter::captureContour(const LabelPosition& position, int label,
                                         cycles::SubContour& out) {
    CapturedChain chain;
    if (!captureChain(*m_levels.back().program, position, ChainRules{}, chain)) return false;
    const std::string name = "LBL " + std::to_string(label);
    if (!checkContourReach(chain.segments, name, kNoContourInSubprogram)) return false;
    const std::optional<CompWord> side = chain.side;
    const std::vector<std::string> args{std::to_string(label)};
    ClosedContour contour;
    if (!closeContour(std::move(chain.segments), name, contour)) return false;
    if (side != CompWord::Left && side != CompWord::Right) {
        fail("contour",
             KERF_TR_NOOP("the contour subprogram LBL {1} needs radius compensation RL or RR "
                          "(pocket or island)"),
             args);
        return false;
    }
    // Spec §6.1: the tool inside the loop makes a pocket: clockwise with RR, counter-clockwise
    // with RL. A mirror image of the subprogram keeps that relation, so program coordinates do.
    const bool counterClockwise = contour.signedArea() > 0.0;
    out.island = counterClockwise == (side == CompWord::Right);
    out.contour = std::move(contour);
    out.label = label;
    return true;
}

}  // namespace kerf::klartext
