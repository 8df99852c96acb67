// CYCL CALL, CYCL CALL PAT, CYCL CALL POS, M99, M89 and the pattern cycles 220/221: the last
// defined machining cycle expanded into ordinary moves at the calling block's location.
#include <algorithm>
#include <cmath>
#include <ctime>

#include "core/base/translate.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/geometry/spatial_arc.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {
constexpr size_t kCycleMovesPerBlock = 2000000;

cycles::DateTime localNow() {
    const std::time_t now = std::time(nullptr);
    std::tm t{};
    localtime_r(&now, &t);
    return {t.tm_year + 1900, t.tm_mon + 1, t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec};
}
}  // namespace

// Feeds the moves of an expanded cycle into the interpreter's path pipeline, where the
// coordinate transformations apply to them as to programmed moves.
class KlartextInterpreter::CycleOutput final : public CycleFunctions {
public:
    explicit CycleOutput(KlartextInterpreter& owner) : CycleFunctions(owner) {}

    void rapid(const Vec3& target) override {
        if (ok()) m.moveProgrammed(m.fromLocal(target), true, m.m_feed);
    }
    void line(const Vec3& target, const cycles::Feed& feed) override {
        if (ok()) m.moveProgrammed(m.fromLocal(target), false, feedValue(feed));
    }
    void arc(const Vec3& target, const Vec2& center, double sweepRad,
             const cycles::Feed& feed) override {
        if (!ok()) return;
        const double f = feedValue(feed);
        m.submitMove(ContourElement::arc(m.workingPlane(), m.m_programmed, m.fromLocal(target),
                                         center, sweepRad),
                     false, f, CommonWords{});
    }
    // An arc in one of the planes XY, YZ, ZX that the transformations keep is written as such;
    // any other as straight pieces within the tolerance after scaling.
    void spatialArc(const Vec3& from, const Vec3& target, const Vec3& centre,
                    const cycles::Feed& feed) override {
        if (!ok()) return;
        const double f = feedValue(feed);
        const std::optional<Plane> plane = planeOfLocalArc(from, target, centre);
        if (plane && m.pathKeepsArcs(*plane)) {
            const Pose end = m.fromLocal(target);
            const PlaneAxes axes = planeAxes(*plane);
            const Pose c = m.fromLocal(centre);
            const Vec2 centre2(c[axes.first], c[axes.second]);
            const Vec2 a = Vec2(m.m_programmed[axes.first], m.m_programmed[axes.second]) - centre2;
            const Vec2 b = Vec2(end[axes.first], end[axes.second]) - centre2;
            const double sweep = std::atan2(cross2(a, b), a.dot(b));
            m.submitMove(ContourElement::arc(*plane, m.m_programmed, end, centre2, sweep), false, f,
                         CommonWords{});
            return;
        }
        double scale = m.m_frame.scale();
        for (double s : m.m_frame.axisScale())
            scale = std::max(scale, m.m_frame.scale() * s);
        const double tolerance = cycles::kSpatialArcTolerance / std::max(1.0, std::fabs(scale));
        for (const Vec3& p : arcChordPoints(from, target, centre, tolerance))
            m.moveProgrammed(m.fromLocal(p), false, f);
    }
    void threadMove(const Vec3& target, double leadMm, double startAngleDeg) override {
        if (!ok() || !m.checkPathError(m.m_path.flush())) return;
        // The spindle-synchronised move is one straight move of the axes along the tool; TCPM
        // counts tip positions on the part, which the tables may have turned away from it.
        if (m.m_tcpm) {
            m.fail("tcpm", KERF_TR_NOOP("tapping and thread cutting follow the spindle along "
                                        "the tool axis: switch TCPM off first (M129 or "
                                        "FUNCTION RESET TCPM)"));
            return;
        }
        const Pose end = m.fromLocal(target);
        const Plane plane = m.workingPlane();
        // A mirror image reverses the hand of the thread; scaling scales its pitch.
        double lead = leadMm * m.m_frame.scale();
        if (m.m_frame.flipsOrientation(plane)) lead = -lead;
        const Pose work = m.m_frame.toWorkpiece(end);
        canon::SpindleSyncedMove move;
        move.target = work;
        move.leadMmPerRev = lead;
        move.startAngleDeg = startAngleDeg;
        m.emit(move);
        m.m_path.resetToMachine(work);
        m.m_programmed = end;
    }

private:
    double feedValue(const cycles::Feed& feed) { return m.cycleFeed(feed); }
    // The plane of the machine's axes an arc given in (u, v, w) lies in: the one whose normal
    // coordinate its start, end and centre share.
    std::optional<Plane> planeOfLocalArc(const Vec3& from, const Vec3& to, const Vec3& c) const {
        const PlaneAxes a = planeAxes(m.workingPlane());
        const Axis local[] = {a.first, a.second, a.normal};
        for (int k = 0; k < 3; ++k) {
            if (std::fabs(from[k] - c[k]) > 1e-9 || std::fabs(to[k] - c[k]) > 1e-9) continue;
            return planeFromAxes(local[(k + 1) % 3], local[(k + 2) % 3]);
        }
        return std::nullopt;
    }
};

void KlartextInterpreter::CycleFunctions::dwell(double seconds) {
    if (ok()) m.emit(canon::Dwell{seconds});
}

void KlartextInterpreter::CycleFunctions::spindle(canon::SpindleDirection direction, double rpm) {
    if (ok()) m.emit(canon::SpindleControl{direction, rpm});
}

void KlartextInterpreter::CycleFunctions::orientSpindle(double angleDeg) {
    if (ok()) m.emit(canon::SpindleOrient{angleDeg});
}

void KlartextInterpreter::CycleFunctions::miscFunction(int number) {
    if (!ok()) return;
    MWords words;
    words.list[0].number = number;
    words.count = 1;
    m.applyMFunctions(words, true);
    m.applyMFunctions(words, false);
}

double KlartextInterpreter::cycleFeed(const cycles::Feed& feed) {
    canon::FeedMode mode = feed.kind == cycles::Feed::Kind::PerRevolution
                               ? canon::FeedMode::PerRevolution
                               : canon::FeedMode::PerMinute;
    if (mode != m_feedMode) {
        m_feedMode = mode;
        emit(canon::SetFeedMode{mode});
    }
    if (feed.isRapid()) {
        // The stream has no rapid arcs: they run at the machine's rapid speed.
        const double perS = m_settings.machine ? m_settings.machine->rapidVelocityMmPerS : 250.0;
        return perS * 60.0;
    }
    return feed.value;
}

Vec3 KlartextInterpreter::toLocal(const Pose& pose) const {
    const PlaneAxes a = planeAxes(workingPlane());
    return {pose[a.first], pose[a.second], pose[a.normal]};
}

Pose KlartextInterpreter::fromLocal(const Vec3& local) const {
    const PlaneAxes a = planeAxes(workingPlane());
    Pose p = m_programmed;
    p[a.first] = local.x();
    p[a.second] = local.y();
    p[a.normal] = local.z();
    return p;
}

void KlartextInterpreter::moveProgrammed(const Pose& target, bool rapid, double feed) {
    double moved = 0.0;
    for (size_t i = 0; i < target.values.size(); ++i) {
        moved = std::max(moved, std::fabs(target.values[i] - m_programmed.values[i]));
    }
    if (moved <= 1e-9) return;
    submitMove(ContourElement::line(workingPlane(), m_programmed, target), rapid, feed,
               CommonWords{});
}

cycles::CycleValues KlartextInterpreter::callValues() const {
    cycles::CycleValues values = m_cycle->values;
    for (uint16_t q : m_cycle->predef) {
        if (std::find(m_globalSet.begin(), m_globalSet.end(), q) != m_globalSet.end()) {
            values.setFeed(q, m_globals.feed(q));
        }
    }
    return values;
}

bool KlartextInterpreter::runMachiningCycle(const cycles::CycleValues& values) {
    if (m_comp == CompWord::Left || m_comp == CompWord::Right) {
        fail("cycle-call",
             KERF_TR_NOOP("a cycle cannot be called with radius compensation RL/RR: program R0"));
        return false;
    }
    const cycles::CycleDescriptor& d = *m_cycle->descriptor;
    if (d.number == 12) {
        callProgram(CallPgm{m_cycle->program});
        return m_status != interp::RunStatus::Failed;
    }
    cycles::CycleContext ctx;
    ctx.start = toLocal(m_programmed);
    ctx.tool.number = m_tool.number;
    ctx.tool.radius = m_tool.effectiveRadius();
    ctx.tool.length = m_tool.effectiveLength();
    ctx.tool.radius2 = m_tool.radius2 + m_tool.tableDr2 + m_tool.callDr2;
    ctx.tool.pointAngleDeg = m_tool.pointAngle;
    ctx.tool.plungeAngleDeg = m_tool.plungeAngle;
    ctx.tool.cuttingLength = m_tool.cuttingLength;
    ctx.tool.pitch = m_tool.pitch;
    ctx.tool.cutterCount = m_tool.cutterCount;
    ctx.spindle = m_spindle;
    ctx.spindleRpm = m_spindleSpeed;
    ctx.positiveDepthIsError = m_settings.positiveDepthIsError;
    ctx.slReturnToStart = m_settings.slReturnToStart;
    ctx.clearingCache = &m_clearingCache;
    if (d.number == 225) {  // only engraving reads the clock
        ctx.now = m_settings.engravingTime ? *m_settings.engravingTime : localNow();
        ctx.counter = m_settings.partCounter;
    }
    const PlaneAxes axes = planeAxes(workingPlane());
    ctx.mirroredMain = (m_frame.mirror() & axisBit(axes.first)) != 0;
    ctx.mirroredSecondary = (m_frame.mirror() & axisBit(axes.second)) != 0;

    if (m_cycleMovesInBlock > kCycleMovesPerBlock) {
        fail("cycle-limit", KERF_TR_NOOP("the cycle calls of this block need more than {1} moves"),
             {std::to_string(kCycleMovesPerBlock)});
        return false;
    }
    if (d.group == cycles::CycleGroup::Contours) {
        if (d.number == 25 || d.number == 275 || d.number == 276) {
            if (!captureTrain(d.number, ctx.train)) return false;
            ctx.trainData = m_trainData ? &*m_trainData : nullptr;
        } else if (!captureContours(ctx.contours) || !captureFormula(ctx.formula)) {
            return false;
        }
        ctx.contourData = m_contourData ? &*m_contourData : nullptr;
        ctx.roughingRadius = m_roughingRadius;
        ctx.toolByNumber = [this](int number) -> std::optional<cycles::ToolInfo> {
            const tables::ToolData* data = toolTable() ? toolTable()->byNumber(number) : nullptr;
            auto own = m_programTools.find(number);
            if (own != m_programTools.end()) data = &own->second;
            if (data == nullptr) return std::nullopt;
            cycles::ToolInfo tool;
            tool.number = number;
            tool.radius = data->radius;  // without DR (spec: cycles 21 and 22)
            tool.length = data->length;
            return tool;
        };
    }
    std::unique_ptr<cycles::CycleEmitter> cylinder;
    if (d.group == cycles::CycleGroup::CylinderSurface) {
        cylinder = cylinderOutput(values, ctx);
        if (!cylinder) return false;
    }
    const canon::FeedMode mode = m_feedMode;
    CycleOutput out(*this);
    cycles::CyclePath path(cylinder ? *cylinder : out, ctx.start);
    auto error = d.expand(values, ctx, path);
    if (!error && path.limitReached()) error = cycles::tooManyMoves(d.number);
    m_cycleMovesInBlock += path.moves();
    if (m_feedMode != mode && m_status != interp::RunStatus::Failed) {
        m_feedMode = mode;
        emit(canon::SetFeedMode{mode});
    }
    m_lastTangent.reset();
    if (error) {
        failCycle(*error);
        return false;
    }
    if (d.number == 22) m_roughingRadius = ctx.tool.radius;
    return m_status != interp::RunStatus::Failed;
}

void KlartextInterpreter::callCycleHere(const cycles::CycleValues* overrides) {
    if (!m_cycle) {
        fail("cycle-call", KERF_TR_NOOP("no machining cycle is defined (CYCL DEF)"));
        return;
    }
    runMachiningCycle(overrides ? *overrides : callValues());
}

void KlartextInterpreter::afterPositioning(const MWords& m) {
    if (m_modalCycleCall && m_capturePath == nullptr && !hasM(m, 89) && !hasM(m, 99) &&
        m_status != interp::RunStatus::Failed) {
        callCycleHere();
    }
}

void KlartextInterpreter::executeCycleCall(const CycleCall& call) {
    m_currentM = call.words.m;
    if (call.kind == CycleCall::Kind::Pattern) {
        callCyclePattern(call);
        return;
    }
    if (call.kind == CycleCall::Kind::Position) {
        callCyclePosition(call);
        return;
    }
    if (call.words.feed.kind != FeedWord::Kind::None) {
        bool rapid = false;
        double feed = 0.0;
        if (!resolveFeed(call.words.feed, rapid, feed)) return;
    }
    applyMFunctions(call.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    callCycleHere();
    if (m_status != interp::RunStatus::Failed) applyMFunctions(call.words.m, false);
}

void KlartextInterpreter::callCyclePattern(const CycleCall& call) {
    if (!m_pattern) {
        fail("cycle-call",
             KERF_TR_NOOP("CYCL CALL PAT: no PATTERN DEF or point table (SEL PATTERN) is active"));
        return;
    }
    if (!m_cycle) {
        fail("cycle-call", KERF_TR_NOOP("no machining cycle is defined (CYCL DEF)"));
        return;
    }
    // Between the points the tool moves at rapid, or at the feed the call programs.
    bool rapid = true;
    double feed = m_feed;
    if (call.words.feed.kind == FeedWord::Kind::Max) {
        fail("feed", KERF_TR_NOOP("CYCL CALL PAT cannot use FMAX (without F it moves at rapid)"));
        return;
    }
    if (call.words.feed.kind != FeedWord::Kind::None) {
        if (!resolveFeed(call.words.feed, rapid, feed)) return;
    }
    applyMFunctions(call.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    const Axis toolAxis = planeAxes(workingPlane()).normal;
    const PlaneAxes axes = planeAxes(workingPlane());
    const double heightAtCall = m_programmed[toolAxis];
    if (m_cycle->descriptor->number == 12) {
        // The program has no clearance of its own: the tool travels at the height of the call.
        ProgramAtPoints run;
        run.points = *m_pattern;
        run.rapid = rapid;
        run.feed = feed;
        run.height = heightAtCall;
        run.after = call.words.m;
        startProgramAtPoints(std::move(run));
        return;
    }
    const bool secondClearance =
        std::find(m_globalSet.begin(), m_globalSet.end(), 345) != m_globalSet.end() &&
        m_globals.integer(345) == 1;
    // Each point is a single-block step of its own; the call's M functions run in the last.
    uint32_t step = 0;
    for (const cycles::PatternPoint& point : *m_pattern) {
        m_at.step = ++step;
        cycles::CycleValues values = callValues();
        values.set(203, point.surface ? *point.surface : values.number(203) + point.surfaceOffset);
        const double second = values.number(203) + values.number(204);
        const double height = secondClearance ? second : std::max(heightAtCall, second);
        Pose up = m_programmed;
        up[toolAxis] = height;
        moveProgrammed(up, rapid, feed);
        Pose over = up;
        over[axes.first] = point.position.x();
        over[axes.second] = point.position.y();
        moveProgrammed(over, rapid, feed);
        if (m_status == interp::RunStatus::Failed || !runMachiningCycle(values)) return;
    }
    applyMFunctions(call.words.m, false);
    m_at.step = 0;
}

void KlartextInterpreter::callCyclePosition(const CycleCall& call) {
    const PlaneAxes axes = planeAxes(workingPlane());
    if (!call.coords.has(axes.first) || !call.coords.has(axes.second) ||
        !call.coords.has(axes.normal)) {
        fail("cycle-call", KERF_TR_NOOP("CYCL CALL POS needs all three coordinates"));
        return;
    }
    if (!m_cycle) {
        fail("cycle-call", KERF_TR_NOOP("no machining cycle is defined (CYCL DEF)"));
        return;
    }
    bool rapid = true;
    double feed = m_feed;
    if (call.words.feed.kind != FeedWord::Kind::None) {
        if (!resolveFeed(call.words.feed, rapid, feed)) return;
    }
    applyMFunctions(call.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    const Pose target = targetOf(call.coords);
    // The tool-axis coordinate acts as an additional datum shift of the cycle's surface.
    cycles::CycleValues values = callValues();
    values.set(203, values.number(203) + target[axes.normal]);
    const double clearance = values.number(203) + values.number(200);
    Pose inPlane = m_programmed;
    inPlane[axes.first] = target[axes.first];
    inPlane[axes.second] = target[axes.second];
    if (m_programmed[axes.normal] > values.number(203)) {
        moveProgrammed(inPlane, rapid, feed);
        Pose down = m_programmed;
        down[axes.normal] = clearance;
        moveProgrammed(down, rapid, feed);
    } else {
        Pose up = m_programmed;
        up[axes.normal] = clearance;
        moveProgrammed(up, rapid, feed);
        inPlane[axes.normal] = clearance;
        moveProgrammed(inPlane, rapid, feed);
    }
    if (m_status == interp::RunStatus::Failed || !runMachiningCycle(values)) return;
    applyMFunctions(call.words.m, false);
}

void KlartextInterpreter::runPatternCycle(const cycles::CycleDescriptor& pattern,
                                          const cycles::CycleValues& values) {
    cycles::PatternPlan plan;
    if (auto error = pattern.pattern(values, plan)) {
        failCycle(*error);
        return;
    }
    const std::string number = std::to_string(pattern.number);
    if (!m_cycle) {
        fail("cycle-call", KERF_TR_NOOP("cycle {1} needs a machining cycle defined before it"),
             {number});
        return;
    }
    if (m_cycle->descriptor->number == 12) {
        ProgramAtPoints run;
        run.plan = std::move(plan);
        startProgramAtPoints(std::move(run));
        return;
    }
    if (!m_cycle->descriptor->takesPatternClearances) {
        fail("cycle-call", KERF_TR_NOOP("cycle {1} cannot call cycle {2}"),
             {number, std::to_string(m_cycle->descriptor->number)});
        return;
    }
    // The pattern's clearances and surface replace the machining cycle's, for later calls too.
    StoredCycle& cycle = *m_cycle;
    auto overwrite = [&](uint16_t q, double value) {
        cycle.values.set(q, value);
        cycle.predef.erase(std::remove(cycle.predef.begin(), cycle.predef.end(), q),
                           cycle.predef.end());
    };
    overwrite(200, plan.setUpClearance);
    overwrite(203, plan.surface);
    overwrite(204, plan.secondClearance);
    if (plan.rotationDeg && cycle.descriptor->parameter(224) != nullptr) {
        overwrite(224, *plan.rotationDeg);
    }
    const cycles::CycleValues callWith = callValues();
    const canon::FeedMode mode = m_feedMode;
    // Each point is a single-block step of its own (the TNC stops between the points).
    for (size_t i = 0; i < plan.points.size(); ++i) {
        m_at.step = static_cast<uint32_t>(i + 1);
        approachPatternPoint(plan, i);
        if (m_status == interp::RunStatus::Failed || !runMachiningCycle(callWith)) return;
    }
    m_at.step = 0;
    restoreFeedMode(mode);
}

void KlartextInterpreter::restoreFeedMode(canon::FeedMode mode) {
    if (m_feedMode != mode) {
        m_feedMode = mode;
        emit(canon::SetFeedMode{mode});
    }
}

// Cycles 220/221: the first point from the 2nd set-up clearance, the others at the travel
// height (a line, or an arc on the pitch circle), then down to the set-up clearance.
void KlartextInterpreter::approachPatternPoint(const cycles::PatternPlan& plan, size_t index) {
    const PlaneAxes axes = planeAxes(workingPlane());
    const double travel =
        plan.surface + (plan.travelAtSecondClearance ? plan.secondClearance : plan.setUpClearance);
    const Vec2 p = plan.points[index].position;
    Pose at = m_programmed;
    at[axes.normal] = index == 0 ? plan.surface + plan.secondClearance : travel;
    moveProgrammed(at, true, m_feed);
    at[axes.first] = p.x();
    at[axes.second] = p.y();
    if (index > 0 && plan.arcTraverse) {
        CycleOutput out(*this);
        out.arc(toLocal(at), plan.arcCentre, plan.arcStepRad, cycles::Feed::rapid());
    } else {
        moveProgrammed(at, true, m_feed);
    }
    at[axes.normal] = plan.surface + plan.setUpClearance;
    moveProgrammed(at, true, m_feed);
}

}  // namespace kerf::klartext
