// TCH PROBE cycles (spec tnc-probing-cycles.md): the probe's data, the touches on the simulated
// workpiece, and the results written where the TNC writes them (Q parameters, the active preset,
// the preset table, the measuring log).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <numbers>

#include "core/base/translate.h"
#include "core/cycles/probing/probing_14xx.h"
#include "core/cycles/probing/probing_cycle.h"
#include "core/cycles/probing/probing_log_html.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/tables/probe_table.h"
#include "core/workpiece/ball_probe_surface.h"
#include "core/workpiece/blank_solids.h"
#include "core/workpiece/simulated_part.h"

namespace kerf::klartext {

namespace {

// Something under that name, a dangling link too: a table that may be missing is read whenever
// this is true, so a link out of the NC root, a FIFO or a folder in its place is an error
// rather than "no table, use the defaults".
bool isThere(const std::filesystem::path& file) {
    std::error_code ignored;
    return std::filesystem::exists(std::filesystem::symlink_status(file, ignored));
}

// A datum cycle writes only the axes it measured into a preset row that already exists (the
// seed's example 14.15: 417 writes Z, then 416 X and Y, of the same row). `offset` is relative
// to the active preset `presetInMachine`; the other columns get the row's own values.
void keepUnmeasuredColumns(const tables::PresetTable& table, const std::string& rotaryLetters,
                           const Pose& presetInMachine, int row, const std::array<bool, 3>& written,
                           Pose& offset) {
    const tables::PresetData* existing = table.byNumber(row);
    if (existing == nullptr) return;
    std::vector<Axis> axes{Axis::X, Axis::Y, Axis::Z};
    for (char letter : rotaryLetters)
        axes.push_back(*axisFromLetter(letter));
    for (Axis axis : axes) {
        const auto i = static_cast<size_t>(axis);
        if (i < 3 && written[i]) continue;
        if (const std::optional<double> value = existing->axis(axisLetter(axis)))
            offset[axis] = *value - presetInMachine[axis];
    }
}

// Result parameters that are not lengths: angles and status flags keep their value in INCH
// programs.
bool isLengthResult(uint16_t q) {
    static constexpr uint16_t kOthers[] = {150, 158, 159, 170, 171, 172, 180,
                                           181, 182, 183, 964, 965, 994, 995};
    return std::find(std::begin(kOthers), std::end(kOthers), q) == std::end(kOthers);
}

std::string upperName(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = upper(c);
    return out;
}

}  // namespace

// The machine of a probing cycle in plain runs: moves go into the canonical stream, touches
// are decided on the simulated workpiece (the program's blank placed with the machine file's
// setup error). Positions are ball centres in the cycle's local frame.
class KlartextInterpreter::ProbeAdapter final : public cycles::probing::ProbingMachine {
public:
    // `real`: the stylus as it really is ([[simulation.tool_error]] of the probe), what the
    // calibration cycles find; the control computes with the table's values (R, L, CAL_OF).
    ProbeAdapter(KlartextInterpreter& interpreter, const cycles::probing::ProbeData& probe,
                 const workpiece::SimulatedWorkpiece& part, workpiece::RealTool real)
        : m_k(interpreter),
          m_probe(probe),
          m_part(part),
          m_realRadius(real.radius),
          m_realCentreOffset(real.centreOffset),
          m_realHeight(real.radius - probe.ballRadius -
                       (real.length - interpreter.m_tool.effectiveLength())),
          m_orientationDeg(probe.calibrationAngleDeg) {
        // The tool probing is a touch probe: its moves remove no material.
        m_k.m_cuts.activeToolIsProbe();
        if (m_k.m_cuts.takeOverflowNotice()) {
            m_k.warn("probe",
                     KERF_TR_NOOP("the simulated part holds the cuts of the first {1} tool "
                                  "moves only: later moves removed no material"),
                     {std::to_string(workpiece::RemovedMaterial::kMaxSweeps)});
        }
    }

    // The control's ball centre: the spindle position, its CAL_OF turned with the spindle and
    // r_b above the tip.
    Vec3 ballCentre() const override { return m_k.toLocal(m_k.m_programmed) + controlOffset(); }

    void moveTo(const Vec3& ballCentre) override {
        const bool rapid = m_probe.positioningFeed <= 0.0;
        move(ballCentre, rapid, m_probe.positioningFeed);
    }

    std::optional<Vec3> touch(const Vec3& direction, double maxPath) override {
        return probe(direction, maxPath, true);
    }
    std::optional<Vec3> touchAndStay(const Vec3& direction, double maxPath) override {
        return probe(direction, maxPath, false);
    }

    bool deflected() const override {
        return m_part.touches(toPart(ballCentre() + realError()), m_realRadius);
    }

    void orient(double angleDeg) override {
        if (!quiet()) m_k.emit(canon::SpindleOrient{angleDeg});
        m_orientationDeg = angleDeg;
    }

    Vec2 centreOffsetApplied() const override { return controlOffset().head<2>(); }

    // The program stops with the prompt. With touches from the machine the stop is a sync
    // point too, and the pass continues from where the machine says the probe stands after NC
    // start; without a machine nobody moves it ([choice], docs/probing.md).
    void waitForOperator(const cycles::probing::OperatorPrompt& prompt) override {
        if (!m_k.m_touchReplay) {
            stopForOperator(prompt);
            return;
        }
        KlartextInterpreter::TouchReplay& replay = *m_k.m_touchReplay;
        if (replay.waiting) return;
        const size_t event = replay.next++;
        if (event == replay.latched.size()) {
            if (!m_k.checkPathError(m_k.m_path.flush())) return;
            stopForOperator(prompt);
            m_k.emit(canon::SyncPoint{canon::SyncReason::Operator});
            replay.waiting = replay.placing = true;
            return;
        }
        if (replay.quiet()) {
            m_k.m_programmed = m_k.m_frame.toProgram(replay.latched[event].tip);
        } else {
            // The last stop: the moves after it start where the operator left the probe.
            m_k.m_programmed = m_k.programOfPath(m_k.m_path.toolPosition());
        }
    }

private:
    void stopForOperator(const cycles::probing::OperatorPrompt& prompt) {
        m_k.emit(canon::Message{canon::MessageKind::Info,
                                substituteArgs(prompt.messageTemplate, prompt.args)});
        m_k.emit(canon::ProgramStop{canon::StopKind::Program, -1});
    }
    std::optional<Vec3> probe(const Vec3& direction, double maxPath, bool backToStart) {
        if (m_probe.track && direction.head<2>().norm() > 1e-9) {
            // Angle tracking: the stylus faces the probing direction in the plane.
            double angle = std::atan2(direction.y(), direction.x()) * 180.0 / std::numbers::pi;
            if (angle <= -180.0) angle += 360.0;  // -0 in y: (-180, 180]
            orient(angle);
        }
        const Vec3 start = ballCentre();
        if (m_k.m_touchReplay) return latched(start, direction, maxPath, backToStart);
        const Vec3 real = start + realError();
        auto hit = m_part.touch(toPart(real), toPart(real + direction) - toPart(real), maxPath,
                                m_realRadius);
        const Vec3 end =
            hit ? Vec3(fromPart(*hit) - realError()) : Vec3(start + maxPath * direction);
        interp::ProgramStatus::Probe status;
        status.triggered = hit.has_value();
        status.position = m_k.m_frame.toWorkpiece(m_k.fromLocal(spindleOf(end)));
        m_k.m_lastProbe = status;
        m_k.moveProgrammed(m_k.fromLocal(spindleOf(end)), false, m_probe.probingFeed);
        if (backToStart) m_k.moveProgrammed(m_k.fromLocal(spindleOf(start)), true, 0.0);
        if (!hit) return std::nullopt;
        return end;
    }
    // A touch whose trigger the machine latches. A pass of the block reaches its touches in
    // order: one latched before gives its trigger, the first one not latched yet becomes a
    // probe move to the end of DIST and a sync point, and the pass ends there.
    std::optional<Vec3> latched(const Vec3& start, const Vec3& direction, double maxPath,
                                bool backToStart) {
        const Vec3 farEnd = start + maxPath * direction;
        const LatchedTouch* latch = m_k.nextLatchedTouch(
            m_k.fromLocal(spindleOf(farEnd)), m_probe.probingFeed, [this] { return surface(); });
        if (latch == nullptr) return std::nullopt;
        const Vec3 end = latch->triggered ? ballOf(latch->tip) : farEnd;
        m_k.followLatchedTouch(m_k.fromLocal(spindleOf(end)));
        if (backToStart) move(start, true, 0.0);
        if (!latch->triggered) return std::nullopt;
        return end;
    }
    // The part as the drives see it: a tool tip in the stream's coordinates -> the real ball
    // centre in the part's, affine while the tables and the spindle stand still.
    std::shared_ptr<const canon::ProbeSurface> surface() const {
        auto realBall = [this](const Vec3& tip) {
            Pose pose = m_k.m_frame.toWorkpiece(m_k.m_programmed);
            pose.setXyz(tip);
            return toPart(m_k.toLocal(m_k.m_frame.toProgram(pose)) + controlOffset() + realError());
        };
        const Vec3 at = m_k.m_frame.toWorkpiece(m_k.m_programmed).xyz();
        Eigen::Affine3d map = Eigen::Affine3d::Identity();
        for (int i = 0; i < 3; ++i)
            map.linear().col(i) = realBall(at + Vec3::Unit(i)) - realBall(at);
        map.translation() = realBall(at) - map.linear() * at;
        return std::make_shared<workpiece::BallProbeSurface>(m_part, map, m_realRadius);
    }
    // The control's ball centre for a latched tool tip (stream coordinates).
    Vec3 ballOf(const Pose& tip) const {
        return m_k.toLocal(m_k.m_frame.toProgram(tip)) + controlOffset();
    }
    bool quiet() const { return m_k.touchPassQuiet(); }
    // A positioning move of the ball centre; a quiet pass only follows it.
    void move(const Vec3& ballCentre, bool rapid, double feed) {
        const Pose target = m_k.fromLocal(spindleOf(ballCentre));
        if (quiet()) {
            m_k.m_programmed = target;
            return;
        }
        m_k.moveProgrammed(target, rapid, feed);
    }
    static Vec2 turned(const Vec2& v, double degrees) {
        const double a = degrees * std::numbers::pi / 180.0;
        return {std::cos(a) * v.x() - std::sin(a) * v.y(),
                std::sin(a) * v.x() + std::cos(a) * v.y()};
    }
    // Tool tip -> the control's ball centre: CAL_OF (measured at CAL_ANG) turned by the
    // orientation since, and r_b up.
    Vec3 controlOffset() const {
        const Vec2 plane =
            turned(m_probe.centreOffset, m_orientationDeg - m_probe.calibrationAngleDeg);
        return {plane.x(), plane.y(), m_probe.ballRadius};
    }
    Vec3 spindleOf(const Vec3& ball) const { return ball - controlOffset(); }
    // The control's ball centre -> the real one: the stylus's true offset (at spindle angle 0,
    // turned with the spindle) less what CAL_OF corrects, and the true length and radius.
    Vec3 realError() const {
        const Vec2 plane = turned(m_realCentreOffset, m_orientationDeg) - controlOffset().head<2>();
        return {plane.x(), plane.y(), m_realHeight};
    }
    // Local program coordinates <-> the workpiece frame of the start preset, where the part is
    // when the rotary tables stand at 0; the tables carry it round as they stand now.
    Vec3 toPart(const Vec3& local) const {
        const Vec3 stream = m_k.m_frame.toWorkpiece(m_k.fromLocal(local)).xyz();
        if (!m_k.m_kinematics) return stream;
        return m_k.m_kinematics->tipOf(stream, m_k.currentTableAngles(),
                                       m_k.m_settings.presetInMachine.xyz(),
                                       m_k.m_tool.effectiveLength());
    }
    Vec3 fromPart(const Vec3& part) const {
        Pose p = m_k.m_frame.toWorkpiece(m_k.m_programmed);
        if (m_k.m_kinematics) {
            p.setXyz(m_k.m_kinematics->axesOf(part, m_k.currentTableAngles(),
                                              m_k.m_settings.presetInMachine.xyz(),
                                              m_k.m_tool.effectiveLength()));
        } else {
            p.setXyz(part);
        }
        return m_k.toLocal(m_k.m_frame.toProgram(p));
    }

    KlartextInterpreter& m_k;
    const cycles::probing::ProbeData& m_probe;
    const workpiece::SimulatedWorkpiece& m_part;
    double m_realRadius;
    Vec2 m_realCentreOffset;  // at spindle angle 0
    double m_realHeight;      // real ball centre above the control's
    double m_orientationDeg;  // the spindle's orientation in the plane
};

std::optional<cycles::probing::ProbeData> KlartextInterpreter::activeProbe(int cycle) {
    if (m_tool.number < 0) {
        fail("PRB-012",
             KERF_TR_NOOP("touch probe cycle {1}: call the touch probe with TOOL CALL "
                          "first (it defines the probe axis)"),
             {std::to_string(cycle)});
        return std::nullopt;
    }
    // The probe table row the tool links with TP_NO (row 1 without the column), read from the
    // NC root; without a table the defaults of a new row.
    int row = 1;
    if (const tables::ToolTable* tools = toolTable()) {
        const tables::ToolData* data = tools->byNumber(m_tool.number);
        auto column = tools->table().findColumn("TP_NO");
        // The table's check made a TP_NO that is not empty a whole number 0-99999.
        if (data != nullptr && column) {
            if (auto number = tools->table().number(data->row, *column))
                row = static_cast<int>(*number);
        }
    }
    if (!m_probeTable) {
        // No table: the defaults of a new row; a table that cannot be read is an error.
        const std::filesystem::path file = m_root.path() / "tchprobe.tp";
        auto bytes = isThere(file) ? m_root.read(file) : tables::ProbeTable::createDefault();
        auto table = bytes ? tables::ProbeTable::parse(*bytes, file.string()) : bytes.error();
        if (!table) {
            fail(table.error().code.c_str(), table.error().messageTemplate.c_str(),
                 table.error().args);
            return std::nullopt;
        }
        m_probeTable = std::move(*table);
    }
    const tables::ProbeData* data = m_probeTable->byNumber(row);
    if (data == nullptr) {
        fail("PRB-012", KERF_TR_NOOP("touch probe cycle {1}: probe {2} is not in tchprobe.tp"),
             {std::to_string(cycle), std::to_string(row)});
        return std::nullopt;
    }
    cycles::probing::ProbeData probe;
    probe.number = row;
    probe.ballRadius = m_tool.effectiveRadius();
    probe.probingFeed = data->probingFeed;
    probe.positioningFeed = data->prepositionAtMachineRapid ? 0.0 : data->rapidFeed;
    probe.maxPath = data->maxProbingPath;
    probe.setUp = data->setUpClearance;
    probe.tableAxes = tableAxisLetters();
    probe.length = m_tool.effectiveLength();
    probe.track = data->track;
    // A probe whose TYPE cannot carry a centre offset is taken as running true.
    if (data->model->supportsCentreOffset)
        probe.centreOffset = Vec2(data->centreOffsetMain, data->centreOffsetSecondary);
    probe.calibrationAngleDeg = data->calibrationAngle;
    probe.reversible = tables::canReverse(*data->model);
    if (m_fastProbing) {
        const cycles::Feed& feed = m_fastProbing->positioning;
        const bool rapid = m_fastProbing->machineRapid || feed.kind == cycles::Feed::Kind::Rapid;
        probe.positioningFeed = rapid ? 0.0 : feed.value;
        probe.track = m_fastProbing->tracking;
        if (probe.track && data->model->orientation != tables::ProbeOrientation::Any) {
            fail("PRB-024",
                 KERF_TR_NOOP("touch probe cycle {1}: the probe {2} cannot be turned to each "
                              "probing direction (angle tracking of cycle 441, Q399 = 1)"),
                 {std::to_string(cycle), std::string(data->model->name)});
            return std::nullopt;
        }
    }
    return probe;
}

workpiece::SimulatedWorkpiece KlartextInterpreter::simulatedPart() const {
    workpiece::SimulatedWorkpiece part;
    if (m_blank) {
        part = workpiece::simulatedPart(m_settings.machine, *m_blank, Vec3::Zero());
    } else {
        // A program that only probes (a setup program): the machine's simulated blank, clamped
        // at the machine file's preset, so it stays put when probing moves the preset.
        static const machine::MachineConfig kDefaults;
        const machine::MachineConfig& machine =
            m_settings.machine ? *m_settings.machine : kDefaults;
        part = workpiece::simulatedPart(
            m_settings.machine, workpiece::blankSolids(workpiece::simulationBlank(machine)),
            workpiece::machineFilePresetIn(machine, m_settings.presetInMachine));
    }
    // What the program's tools cut so far (the path was flushed before the cycle).
    part.setRemoved(m_cuts.removed());
    return part;
}

bool KlartextInterpreter::isTouchProbe(int toolNumber) const {
    const tables::ToolTable* tools = toolTable();
    if (tools == nullptr) return false;
    const tables::ToolData* data = tools->byNumber(toolNumber);
    auto column = tools->table().findColumn("TP_NO");
    return data != nullptr && column && tools->table().number(data->row, *column).has_value();
}

void KlartextInterpreter::executeProbeCycle(const CycleDefinition& def) {
    if (def.subNumber >= 0 && cycles::probing::findOldToolProbeCycle(def.number) != nullptr) {
        executeOldToolProbeBlock(def);
        return;
    }
    if (def.subNumber >= 0 && cycles::probing::isSingleTouchCycle(def.number)) {
        executeOldProbeBlock(def);
        return;
    }
    const auto* cycle = cycles::probing::findProbingCycle(def.number);
    if (cycle == nullptr || def.subNumber >= 0) {
        fail("not-supported", KERF_TR_NOOP("touch probe cycle {1} is not supported yet"),
             {std::to_string(def.number)});
        return;
    }
    const std::string owner = "touch probe cycle " + std::to_string(def.number);
    cycles::CycleValues values;
    std::vector<uint16_t> predef;
    if (!resolveParameters(owner, cycle->parameters, def.parameters, values, &predef, def.number)) {
        return;
    }
    for (uint16_t q : predef) {
        if (std::find(m_globalSet.begin(), m_globalSet.end(), q) == m_globalSet.end()) {
            fail("PRB-013", KERF_TR_NOOP("{1}: Q{2} is PREDEF but GLOBAL DEF 120 gives no value"),
                 {owner, std::to_string(q)});
            return;
        }
        values.set(q, m_globals.number(q));
    }
    if (def.number == cycles::probing::kExtrusionCycle) {
        // It probes nothing: the next 14xx cycle repeats its touch points (Q1145 = 0: none).
        m_extrusion = values;
        if (!cycles::probing::extrusionOf(values)) m_extrusion.reset();
        return;
    }
    if (def.number >= 1400 && m_extrusion) {
        cycles::probing::addExtrusion(*m_extrusion, values);
        if (!cycles::probing::extrusionStays(*m_extrusion)) m_extrusion.reset();
    }
    if (cycle->toolMeasurement != cycles::probing::ToolMeasurementKind::None) {
        if (def.number == 484) {
            // Q536 = 0: the operator jogs the pin over the TT, NC start goes on from there.
            if (values.integer(536) == 0) emit(canon::ProgramStop{canon::StopKind::Program, -1});
            values.set(260, toLocal(m_programmed).z());
        }
        executeToolMeasurement(*cycle, values, false, 0);
        return;
    }
    if ((def.number <= 402 || def.number == 404) && m_basicRotationDeg != 0.0) {
        // Cycles 400-402 cancel the basic rotation before they probe (spec 2), 404 before it
        // sets a new one.
        const Pose at = m_frame.toWorkpiece(m_programmed);
        m_frame.setRotation(m_frame.rotationDeg() - m_basicRotationDeg, false, workingPlane());
        m_programmed = m_frame.toProgram(at);
        m_basicRotationDeg = 0.0;
    }
    // A basic rotation is allowed; cycle 10 only in the datum cycles.
    const bool datumCycle = def.number >= 408 && def.number <= 419;
    const bool rotated = m_frame.rotationDeg() != m_basicRotationDeg;
    if (m_frame.mirror() != 0 || m_frame.scale() != 1.0 || !m_frame.pointShift().xyz().isZero() ||
        !m_frame.shift().xyz().isZero() || (rotated && !datumCycle)) {
        fail("PRB-005",
             KERF_TR_NOOP("{1}: probing is not possible while a coordinate "
                          "transformation is active (cycles 7, 8, 10, 11, 26)"),
             {owner});
        return;
    }
    if (m_toolAxis != Axis::Z) {
        fail("not-supported", KERF_TR_NOOP("{1}: probing runs with tool axis Z only so far"),
             {owner});
        return;
    }
    auto probe = activeProbe(def.number);
    if (!probe) return;
    if (!checkPathError(m_path.flush())) return;
    for (uint16_t q : cycle->results)
        m_q.set(QRef{QKind::Q, q}, 0.0);
    runTouching([this, cycle, values, probe = *probe] { probeAndApply(*cycle, values, probe); });
}

void KlartextInterpreter::probeAndApply(const cycles::probing::ProbingCycleDescriptor& cycle,
                                        const cycles::CycleValues& values,
                                        const cycles::probing::ProbeData& probe) {
    const workpiece::SimulatedWorkpiece part = simulatedPart();
    ProbeAdapter machine(*this, probe, part, realProbe());
    cycles::probing::ProbingResults results;
    const auto error = cycle.run(values, probe, machine, results);
    if (touchHandedToMachine()) return;
    if (error) {
        failCycle(*error);
        return;
    }
    for (const auto& [q, value] : results.parameters)
        m_q.set(QRef{QKind::Q, q}, isLengthResult(q) ? value / lengthScale() : value);
    if (results.protocol && !writeProtocol(cycle.number, cycle.name, *results.protocol)) return;
    const bool monitored = values.number(330) != 0.0 || !values.text(330).empty();
    if (results.toolCorrection && monitored &&
        !applyToolMonitoring(cycle.number, values, *results.toolCorrection)) {
        return;
    }
    if (results.datum && !applyDatum(cycle.number, results)) return;
    if (results.basicRotationDeg && !applyBasicRotation(cycle.number, results)) return;
    if (results.rotary && !applyRotaryCompensation(cycle.number, results)) return;
    if (results.calibration) {
        // The probe's row: the calibrated L and R replace the table's, with no deltas.
        if (toolTable() == nullptr || toolTable()->byNumber(m_tool.number) == nullptr) {
            fail("PRB-015",
                 KERF_TR_NOOP("touch probe cycle {1}: calibration writes the probe's row of the "
                              "tool table TOOL.T: call the probe from it"),
                 {std::to_string(cycle.number)});
            return;
        }
        ToolTableEdit edit;
        edit.length = results.calibration->length;
        edit.radius = results.calibration->radius;
        const tables::ToolData row = *toolTable()->byNumber(m_tool.number);
        if (edit.length && row.deltaLength != 0.0) edit.deltaLength = 0.0;
        if (edit.radius && row.deltaRadius != 0.0) edit.deltaRadius = 0.0;
        if (!writeToolTable(cycle.number, m_tool.number, 0, edit)) return;
        if (results.calibration->centreOffset &&
            !writeProbeCentreOffset(cycle.number, probe.number,
                                    *results.calibration->centreOffset)) {
            return;
        }
        if (!logCalibration(cycle.number, cycle.name, row, probe, *results.calibration)) return;
    }
    if (results.toleranceStop) {
        failCycle(*results.toleranceStop);
        return;
    }
    if (results.fastProbing) m_fastProbing = results.fastProbing;
    // 441 Q400 = 0: a log asked for on screen does not interrupt the program.
    const bool interrupt = !m_fastProbing || m_fastProbing->interrupt;
    if (results.protocolStop && interrupt) emit(canon::ProgramStop{canon::StopKind::Program, -1});
}

workpiece::RealTool KlartextInterpreter::realProbe() const {
    if (const tables::ToolTable* tools = toolTable()) {
        if (const tables::ToolData* row = tools->byNumber(m_tool.number)) return realTool(*row);
    }
    return {m_tool.effectiveLength(), m_tool.effectiveRadius()};
}

std::optional<cycles::probing::SingleTouchResult> KlartextInterpreter::probeOnce(
    int cycle, const cycles::probing::SingleTouch& touch, std::optional<double> feed,
    cycles::probing::ProbeData& probe) {
    const std::string owner = "touch probe cycle " + std::to_string(cycle);
    if (m_frame.mirror() != 0 || m_frame.scale() != 1.0) {
        fail("PRB-005",
             KERF_TR_NOOP("{1}: probing is not possible while a coordinate "
                          "transformation is active (cycles 7, 8, 10, 11, 26)"),
             {owner});
        return std::nullopt;
    }
    if (m_toolAxis != Axis::Z) {
        fail("not-supported", KERF_TR_NOOP("{1}: probing runs with tool axis Z only so far"),
             {owner});
        return std::nullopt;
    }
    auto active = activeProbe(cycle);
    if (!active) return std::nullopt;
    probe = *active;
    if (feed) probe.probingFeed = *feed;
    if (!checkPathError(m_path.flush())) return std::nullopt;
    const workpiece::SimulatedWorkpiece part = simulatedPart();
    ProbeAdapter machine(*this, probe, part, realProbe());
    cycles::probing::SingleTouchResult result;
    const auto error = cycles::probing::runSingleTouch(cycle, touch, probe, machine, result);
    if (touchHandedToMachine()) return std::nullopt;
    if (error) {
        failCycle(*error);
        return std::nullopt;
    }
    return result;
}

bool KlartextInterpreter::writeProtocol(int cycle, const char* name,
                                        const std::vector<std::string>& lines) {
    if (!waitForCheck()) return false;
    const ProgramFile& program = *m_levels.back().program;
    std::string text =
        "Measuring log for probing cycle " + std::to_string(cycle) + " " + upperName(name) + "\n";
    text += "Measuring program: " + m_sources.displayName(program.fileId) + "\n";
    for (const std::string& line : lines)
        text += line + "\n";
    text += "End of measuring log\n";
    const std::filesystem::path file = m_root.path() / ("TCHPR" + std::to_string(cycle) + ".TXT");
    if (auto error = replaceFile(file, text)) {
        fail("io", KERF_TR_NOOP("cannot write the measuring log {1}: {2}"),
             {file.filename().string(), error->format()});
        return false;
    }
    return true;
}

// Spec 1.12.1: Q305 = 0 sets the active preset (and row 0 of the preset table), Q305 > 0 with
// Q303 = 1 writes that preset row without activating it.
bool KlartextInterpreter::applyDatum(int cycle, const cycles::probing::ProbingResults& results) {
    if (results.tableRow != 0 && results.transfer == 0) {
        // The datum table row gets the shift that gives the feature its nominal values in the
        // active system (no datum shift is active while probing: PRB-005).
        const PlaneAxes a = planeAxes(workingPlane());
        const Axis programAxes[] = {a.first, a.second, a.normal};
        std::vector<std::pair<char, double>> shift;
        for (size_t i = 0; i < 3; ++i) {
            if (!results.datum->measured[i]) continue;
            shift.emplace_back(axisLetter(programAxes[i]),
                               *results.datum->measured[i] - results.datum->nominal[i]);
        }
        return writeDatumRow(cycle, results.tableRow, shift);
    }
    // The measured feature moves to its nominal values along the axes of the active (possibly
    // turned) frame: the preset moves by that difference, seen in workpiece coordinates.
    Vec3 delta(0.0, 0.0, 0.0);
    for (int i = 0; i < 3; ++i) {
        const auto axis = static_cast<size_t>(i);
        if (results.datum->measured[axis]) {
            delta[i] = *results.datum->measured[axis] - results.datum->nominal[axis];
        }
    }
    const Vec3 origin = toLocal(m_programmed);
    const Vec3 moved = (m_frame.toWorkpiece(fromLocal(origin + delta)).xyz() -
                        m_frame.toWorkpiece(fromLocal(origin)).xyz());
    Pose offset = m_frame.preset();
    offset.setXyz(offset.xyz() + moved);
    const int row = results.tableRow;
    if (row > 0) {
        // Columns the measurement moves: the measured axes, and any the frame's turn involves.
        const PlaneAxes a = planeAxes(workingPlane());
        const Axis programAxes[] = {a.first, a.second, a.normal};
        std::array<bool, 3> written{};
        for (size_t i = 0; i < 3; ++i) {
            const auto xyz = static_cast<size_t>(programAxes[i]);
            if (xyz < 3 && results.datum->measured[i]) written[xyz] = true;
            if (moved[static_cast<int>(i)] != 0.0) written[i] = true;
        }
        const std::optional<tables::PresetTable> table =
            presetTableToEdit(m_root.path() / "PRESET.PR");
        if (!table) return false;
        keepUnmeasuredColumns(*table, tableAxisLetters(), m_settings.presetInMachine, row, written,
                              offset);
    }
    if (!writePreset(cycle, row, offset)) return false;
    if (row == 0) {
        const Pose at = m_frame.toWorkpiece(m_programmed);
        const double rotation = m_frame.rotationDeg();
        m_frame.setPreset(offset);
        // The basic rotation belongs to the preset: it stays.
        if (rotation != 0.0) m_frame.setRotation(rotation, false, workingPlane());
        m_programmed = m_frame.toProgram(at);
        updatePathSpace();
    }
    return true;
}

bool KlartextInterpreter::logCalibration(int cycle, const char* name,
                                         const tables::ToolData& before,
                                         const cycles::probing::ProbeData& probe,
                                         const cycles::probing::ProbeCalibration& calibration) {
    cycles::probing::CalibrationLogEntry entry{
        cycle, upperName(name), m_tool.number, probe.number, {}};
    if (calibration.radius)
        entry.values.push_back({"R", before.radius + before.deltaRadius, *calibration.radius});
    if (calibration.length)
        entry.values.push_back({"L", before.length + before.deltaLength, *calibration.length});
    if (calibration.centreOffset) {
        entry.values.push_back({"CAL_OF1", probe.centreOffset.x(), calibration.centreOffset->x()});
        entry.values.push_back({"CAL_OF2", probe.centreOffset.y(), calibration.centreOffset->y()});
    }
    m_calibrationLog.push_back(std::move(entry));
    // All calibrations of the run in one file, in the main program's folder (spec 1.15).
    const ProgramFile& program = *m_levels.front().program;
    const std::filesystem::path file = program.folder / "TCHPRAUTO.html";
    const std::string text = cycles::probing::calibrationLogHtml(
        m_sources.displayName(program.fileId), m_calibrationLog);
    if (auto error = replaceFile(file, text)) {
        fail("io", KERF_TR_NOOP("cannot write the calibration log {1}: {2}"),
             {file.filename().string(), error->format()});
        return false;
    }
    return true;
}

bool KlartextInterpreter::writeProbeCentreOffset(int cycle, int probe, const Vec2& offset) {
    if (!waitForCheck()) return false;
    tables::ProbeTable table = *m_probeTable;
    if (auto error = table.setCentreOffset(probe, offset.x(), offset.y())) {
        failCycle({error->code, error->messageTemplate, error->args});
        return false;
    }
    if (auto error = replaceFile(m_root.path() / "tchprobe.tp", table.serialize())) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the touch-probe table: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    m_probeTable = std::move(table);
    return true;
}

std::optional<tables::PresetTable> KlartextInterpreter::presetTableToEdit(
    const std::filesystem::path& file) {
    auto bytes = isThere(file) ? m_root.read(file) : tables::PresetTable::createDefault();
    auto table = bytes ? tables::PresetTable::parse(*bytes, file.string()) : bytes.error();
    if (!table) {
        failCycle({table.error().code, table.error().messageTemplate, table.error().args});
        return std::nullopt;
    }
    return std::move(*table);
}

bool KlartextInterpreter::writePreset(int cycle, int row, const Pose& offset) {
    if (!waitForCheck()) return false;
    const std::filesystem::path file = m_root.path() / "PRESET.PR";
    std::optional<tables::PresetTable> table = presetTableToEdit(file);
    if (!table) return false;
    if (table->byNumber(row) == nullptr) (void)table->addPreset(row);
    std::vector<Axis> axes{Axis::X, Axis::Y, Axis::Z};
    for (char letter : tableAxisLetters())
        axes.push_back(*axisFromLetter(letter));
    for (Axis axis : axes) {
        const double ref = m_settings.presetInMachine[axis] + offset[axis];
        if (auto error = table->setAxis(row, axisLetter(axis), ref)) {
            failCycle({error->code, error->messageTemplate, error->args});
            return false;
        }
    }
    if (auto error = replaceFile(file, table->serialize())) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the preset table: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    m_presetFile = std::move(*table);
    return true;
}

// The basic rotation of 400-404 and 414: with Q305 = 0 it becomes active (a rotation of the
// working plane about the datum) and is the active preset's, row 0's SPC; Q305 > 0 stores it.
bool KlartextInterpreter::applyBasicRotation(int cycle,
                                             const cycles::probing::ProbingResults& results) {
    // Q305 > 0: stored in the row's SPC column, not activated.
    if (results.tableRow > 0) {
        return writePresetRotation(cycle, results.tableRow, *results.basicRotationDeg);
    }
    // Q305 = 0: measured in the active (possibly turned) system, it adds to the active basic
    // rotation, which is the active preset's: row 0's SPC, like the datum.
    const double total = m_basicRotationDeg + *results.basicRotationDeg;
    if (!writePresetRotation(cycle, 0, total)) return false;
    const Pose at = m_frame.toWorkpiece(m_programmed);
    m_frame.setRotation(m_frame.rotationDeg() + *results.basicRotationDeg, false, workingPlane());
    m_programmed = m_frame.toProgram(at);
    m_basicRotationDeg = total;
    return true;
}

}  // namespace kerf::klartext
