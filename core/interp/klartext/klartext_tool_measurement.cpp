// The TT cycles 30-33 / 480-483 (spec 7): tool measurement on the machine file's simulated tool
// touch probe, with the real tool differing from its table entry by [[simulation.tool_error]];
// the measured values go into the tool table and take effect at once.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/parameter_check.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/workpiece/simulated_tool_probe.h"
#include "core/workpiece/tool_probe_surface.h"

namespace kerf::klartext {

// The machine of a TT cycle: moves go into the canonical stream; touches are decided on the
// simulated TT with the real tool in plain runs, and come from the machine's latch when the
// settings say so. Positions are the spindle's gauge point in machine coordinates; the
// interpreter positions the tool tip with the tool's current length.
class KlartextInterpreter::ToolProbeAdapter final : public cycles::probing::ToolProbingMachine {
public:
    ToolProbeAdapter(KlartextInterpreter& interpreter, const workpiece::SimulatedToolProbe& tt,
                     workpiece::RealTool tool)
        : m_k(interpreter),
          m_tt(tt),
          m_tool(tool),
          m_direction(interpreter.m_spindle),
          m_rpm(interpreter.m_spindleSpeed) {}

    Vec3 gauge() const override { return gaugeOf(m_k.m_frame.toWorkpiece(m_k.m_programmed)); }
    void moveTo(const Vec3& gauge) override { move(program(gauge)); }
    void spindle(canon::SpindleDirection direction, double rpm) override {
        if (direction == m_direction && rpm == m_rpm) return;
        m_direction = direction;
        m_rpm = rpm;
        if (!m_k.touchPassQuiet()) m_k.emit(canon::SpindleControl{direction, rpm});
    }
    void orientSpindle(double angleDeg) override {
        if (!m_k.touchPassQuiet()) m_k.emit(canon::SpindleOrient{angleDeg});
    }

    std::optional<Vec3> touch(const Vec3& direction, double maxPath, double feed) override {
        const Vec3 start = gauge();
        if (m_k.m_touchReplay) return latched(start, direction, maxPath, feed);
        auto hit = m_tt.touch(start, direction, maxPath, m_tool);
        const Vec3 end = hit ? *hit : Vec3(start + maxPath * direction);
        interp::ProgramStatus::Probe status;
        status.triggered = hit.has_value();
        status.position = m_k.m_frame.toWorkpiece(program(end));
        m_k.m_lastProbe = status;
        m_k.moveProgrammed(program(end), false, feed);
        m_k.moveProgrammed(program(start), true, 0.0);
        return hit;
    }
    bool deflected() const override { return m_tt.touches(gauge(), m_tool); }

    // Puts the spindle back as the program had it.
    void restoreSpindle() { spindle(m_k.m_spindle, m_k.m_spindleSpeed); }

private:
    // A touch whose trigger the machine latches (as the workpiece probe's, klartext_probing.cpp).
    std::optional<Vec3> latched(const Vec3& start, const Vec3& direction, double maxPath,
                                double feed) {
        const Vec3 farEnd = start + maxPath * direction;
        const LatchedTouch* latch =
            m_k.nextLatchedTouch(program(farEnd), feed, [this] { return surface(); });
        if (latch == nullptr) return std::nullopt;
        const Vec3 end = latch->triggered ? gaugeOf(latch->tip) : farEnd;
        m_k.followLatchedTouch(program(end));
        move(program(start));
        if (!latch->triggered) return std::nullopt;
        return end;
    }
    // The TT as the drives see it: the real tool on the stylus, its gauge point the tool tip
    // (stream coordinates) shifted by the preset and the tool's current length.
    std::shared_ptr<const canon::ProbeSurface> surface() const {
        const Eigen::Affine3d map{Eigen::Translation3d(tipToGauge())};
        return std::make_shared<workpiece::ToolProbeSurface>(m_tt, map, m_tool);
    }
    // A rapid positioning move; a quiet pass only follows it.
    void move(const Pose& target) {
        if (m_k.touchPassQuiet()) {
            m_k.m_programmed = target;
            return;
        }
        m_k.moveProgrammed(target, true, 0.0);
    }
    // Tool tip (the stream's coordinates) -> gauge point: the preset and the tool's length.
    Vec3 tipToGauge() const {
        return m_k.m_settings.presetInMachine.xyz() + Vec3(0.0, 0.0, m_k.m_tool.effectiveLength());
    }
    Vec3 gaugeOf(const Pose& tip) const { return tip.xyz() + tipToGauge(); }
    Pose program(const Vec3& gauge) const {
        Pose workpiece = m_k.m_frame.toWorkpiece(m_k.m_programmed);
        workpiece.setXyz(gauge - tipToGauge());
        return m_k.m_frame.toProgram(workpiece);
    }

    KlartextInterpreter& m_k;
    const workpiece::SimulatedToolProbe& m_tt;
    workpiece::RealTool m_tool;
    // The spindle as the stream last set it: the program's, then the cycle's.
    canon::SpindleDirection m_direction;
    double m_rpm;
};

namespace {
// The simulated machine's real tools, kept from run to run: "T length radius" lines, mm, each
// followed by the machine file's error it was made with.
constexpr const char* kRealToolsFile = "SIMTOOLS.TXT";
}  // namespace

// The real tool: as recorded in SIMTOOLS.TXT, else as the table held it when the run started plus
// the machine file's error.
workpiece::RealTool KlartextInterpreter::realTool(const tables::ToolData& row) const {
    const tables::ToolData* original =
        m_settings.tools != nullptr ? m_settings.tools->byNumber(row.number) : nullptr;
    const tables::ToolData& start = original != nullptr ? *original : row;
    workpiece::RealTool real{start.length + start.deltaLength, start.radius + start.deltaRadius};
    const machine::ToolErrorConfig* error =
        m_settings.machine != nullptr ? m_settings.machine->toolError(row.number) : nullptr;
    if (error == nullptr) return real;
    real.centreOffset = Vec2(error->centreOffsetMm[0], error->centreOffsetMm[1]);
    if (const workpiece::RealTool* recorded = recordedRealTool(row.number)) {
        real.length = recorded->length;
        real.radius = recorded->radius;
    } else {
        real.length += error->lengthMm;
        real.radius += error->radiusMm;
    }
    return real;
}

// The recorded real tool, unless the machine file's error changed since (another real tool).
const workpiece::RealTool* KlartextInterpreter::recordedRealTool(int tool) const {
    if (!m_recordedRealTools) {
        m_recordedRealTools.emplace();
        if (auto bytes = m_root.read(m_root.path() / kRealToolsFile)) {
            std::istringstream in{std::string(*bytes)};
            int number = 0;
            RecordedRealTool record;
            while (in >> number >> record.real.length >> record.real.radius >> record.errorLength >>
                   record.errorRadius) {
                if (std::isfinite(record.real.length) && std::isfinite(record.real.radius))
                    (*m_recordedRealTools)[number] = record;
            }
        }
    }
    auto found = m_recordedRealTools->find(tool);
    const machine::ToolErrorConfig* error =
        m_settings.machine != nullptr ? m_settings.machine->toolError(tool) : nullptr;
    if (found == m_recordedRealTools->end() || error == nullptr ||
        found->second.errorLength != error->lengthMm ||
        found->second.errorRadius != error->radiusMm) {
        return nullptr;
    }
    return &found->second.real;
}

// A real tool does not change when a measurement corrects its table row: before the first
// correction of a tool with a [[simulation.tool_error]], its real size is written down, and later
// runs take it from there instead of adding the error to the corrected row again.
bool KlartextInterpreter::recordRealTool(int cycle, int tool) {
    const tables::ToolData* row = toolTable() != nullptr ? toolTable()->byNumber(tool) : nullptr;
    if (row == nullptr || m_settings.machine == nullptr ||
        m_settings.machine->toolError(tool) == nullptr || recordedRealTool(tool) != nullptr) {
        return true;
    }
    const machine::ToolErrorConfig& toolError = *m_settings.machine->toolError(tool);
    (*m_recordedRealTools)[tool] = {realTool(*row), toolError.lengthMm, toolError.radiusMm};
    std::string text;
    for (const auto& [number, record] : *m_recordedRealTools) {
        text += std::to_string(number) + " " + formatFixed(record.real.length, 6) + " " +
                formatFixed(record.real.radius, 6) + " " + formatFixed(record.errorLength, 6) +
                " " + formatFixed(record.errorRadius, 6) + "\n";
    }
    if (auto error = replaceFile(m_root.path() / kRealToolsFile, text)) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the simulated tools: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    return true;
}

namespace {

// The number after the last ':' of an old-format sub-block ("31.1 CHECK: 1 Q5") and, when
// `status` is given, an optional Q parameter after it.
bool oldBlockValue(std::string_view rest, double& value, uint16_t* status) {
    const size_t colon = rest.rfind(':');
    if (colon == std::string_view::npos) return false;
    const std::string text(rest.substr(colon + 1));
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || !std::isfinite(value)) return false;
    std::string_view tail(end);
    while (!tail.empty() && tail.front() == ' ')
        tail.remove_prefix(1);
    if (tail.empty()) return true;
    if (status == nullptr || (tail.front() != 'Q' && tail.front() != 'q')) return false;
    char* qEnd = nullptr;
    const std::string digits(tail.substr(1));
    const long q = std::strtol(digits.c_str(), &qEnd, 10);
    if (qEnd == digits.c_str() || q < 0 || q > 1999) return false;
    for (const char* c = qEnd; *c != '\0'; ++c) {
        if (*c != ' ') return false;
    }
    *status = static_cast<uint16_t>(q);
    return true;
}

}  // namespace

// Old format: 30.0 / 30.1 HEIGHT; 31.0 ... 33.0 / .1 CHECK: mode [Qn] / .2 HEIGHT / .3 PROBING
// THE TEETH. The cycle runs with its last sub-block.
void KlartextInterpreter::executeOldToolProbeBlock(const CycleDefinition& def) {
    const auto* cycle = cycles::probing::findOldToolProbeCycle(def.number);
    const std::string owner = "TCH PROBE " + std::to_string(def.number);
    if (def.subNumber == 0) {
        m_oldToolProbe = OldToolProbe{def.number, {}, 0};
        return;
    }
    if (m_oldToolProbe.number != def.number) {
        fail("cycle-syntax", KERF_TR_NOOP("TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it"),
             {std::to_string(def.number), std::to_string(def.subNumber)});
        return;
    }
    const bool calibrate = def.number == 30;
    const int last = calibrate ? 1 : 3;
    double value = 0.0;
    const bool check = !calibrate && def.subNumber == 1;
    uint16_t status = 0;
    if (def.subNumber > last || !oldBlockValue(def.rest, value, check ? &status : nullptr)) {
        fail("cycle-syntax", KERF_TR_NOOP("{1}.{2}: a number after ':' expected"),
             {owner, std::to_string(def.subNumber)});
        return;
    }
    // The sub-blocks hold Q260 (HEIGHT), Q340 (CHECK) and Q341 (PROBING THE TEETH).
    const uint16_t q = calibrate || def.subNumber == 2 ? 260 : (def.subNumber == 1 ? 340 : 341);
    for (const cycles::ParameterDescriptor& d : cycle->parameters) {
        if (d.q != q) continue;
        if (auto outside = cycles::parameterValueError(owner, d, value)) {
            failCycle(*outside);
            return;
        }
    }
    m_oldToolProbe.values.set(q, q == 260 ? value * lengthScale() : value);
    if (check) m_oldToolProbe.statusParameter = status;
    if (def.subNumber < last) return;
    const cycles::CycleValues values = m_oldToolProbe.values;
    const uint16_t statusParameter = m_oldToolProbe.statusParameter;
    m_oldToolProbe = OldToolProbe{};
    if (!calibrate && (!values.has(340) || !values.has(260) || !values.has(341))) {
        fail("cycle-syntax", KERF_TR_NOOP("{1}: sub-blocks .1, .2 and .3 are needed"), {owner});
        return;
    }
    executeToolMeasurement(*cycle, values, true, statusParameter);
}

std::optional<cycles::probing::ToolProbeData> KlartextInterpreter::toolProbeData(int cycle) {
    const machine::MachineConfig* machine = m_settings.machine;
    if (machine == nullptr || !machine->toolProbe.enabled) {
        fail("PRB-023",
             KERF_TR_NOOP("touch probe cycle {1}: the machine has no tool touch probe "
                          "([simulation.tool_probe] enabled = true)"),
             {std::to_string(cycle)});
        return std::nullopt;
    }
    if (m_ttCalibration) return m_ttCalibration;
    const machine::ToolProbeConfig& c = machine->toolProbe;
    cycles::probing::ToolProbeData tt;
    tt.top = Vec3(c.centreXMm, c.centreYMm, c.centreZMm);
    tt.diameter = c.diameterMm;
    tt.cube = c.shape == machine::ToolProbeShape::Cube;
    tt.offsetToolAxis = c.offsetToolAxisMm;
    tt.safetyDistance = c.safetyDistanceMm;
    tt.maxPeripheralSpeed = c.maxPeripheralSpeedMPerMin;
    tt.measureTolerance = c.measureToleranceMm;
    tt.probingFeed = c.probingFeedMmPerMin;
    tt.maxRpm = machine->spindle.maxRpm;
    readToolProbeCalibration(tt);
    return tt;
}

namespace {
constexpr const char* kCalibrationFile = "TTCALIB.TXT";
}

// The last calibration (30/480/484) stays with the machine's NC root, so later runs start from
// it: "TOP_X/TOP_Y/TOP_Z/DIAMETER value" lines, machine coordinates in mm.
void KlartextInterpreter::writeToolProbeCalibration(int cycle,
                                                    const cycles::probing::ToolProbeData& tt) {
    if (!waitForCheck()) return;
    std::string text;
    auto line = [&text](const char* key, double value) {
        text += std::string(key) + " " + formatFixed(value, 6) + "\n";
    };
    line("TOP_X", tt.top.x());
    line("TOP_Y", tt.top.y());
    line("TOP_Z", tt.top.z());
    line("DIAMETER", tt.diameter);
    if (auto error = replaceFile(m_root.path() / kCalibrationFile, text)) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the TT calibration: {2}"),
             {std::to_string(cycle), error->format()});
    }
}

void KlartextInterpreter::readToolProbeCalibration(cycles::probing::ToolProbeData& tt) {
    auto bytes = m_root.read(m_root.path() / kCalibrationFile);
    if (!bytes) return;
    std::istringstream in{std::string(*bytes)};
    std::string key;
    double value = 0.0;
    while (in >> key >> value) {
        if (!std::isfinite(value)) continue;
        if (key == "TOP_X") tt.top.x() = value;
        if (key == "TOP_Y") tt.top.y() = value;
        if (key == "TOP_Z") tt.top.z() = value;
        if (key == "DIAMETER" && value > 0.0) tt.diameter = value;
    }
}

void KlartextInterpreter::executeToolMeasurement(
    const cycles::probing::ProbingCycleDescriptor& cycle, const cycles::CycleValues& values,
    bool oldFormat, uint16_t statusParameter) {
    const std::string number = std::to_string(cycle.number);
    if (m_frame.mirror() != 0 || m_frame.scale() != 1.0) {
        fail("PRB-005",
             KERF_TR_NOOP("touch probe cycle {1}: tool measurement is not possible while "
                          "mirroring or scaling is active (cycles 8, 11, 26)"),
             {number});
        return;
    }
    if (m_toolAxis != Axis::Z) {
        fail("not-supported",
             KERF_TR_NOOP("touch probe cycle {1}: probing runs with tool axis Z only so far"),
             {number});
        return;
    }
    const tables::ToolData* row = m_tool.number >= 0 && toolTable() != nullptr
                                      ? toolTable()->byNumber(m_tool.number)
                                      : nullptr;
    if (row == nullptr) {
        fail("PRB-012",
             KERF_TR_NOOP("touch probe cycle {1}: call the tool to be measured from the tool "
                          "table TOOL.T with TOOL CALL first"),
             {number});
        return;
    }
    auto tt = toolProbeData(cycle.number);
    if (!tt) return;
    if (!checkPathError(m_path.flush())) return;
    // 481-483 give the status in Q199, 31-33 in the parameter of their CHECK block (or none).
    const uint16_t status = oldFormat ? statusParameter : 199;
    for (uint16_t q : cycle.results) {
        if (q != 199) m_q.set(QRef{QKind::Q, q}, 0.0);
    }
    if (status != 0) m_q.set(QRef{QKind::Q, status}, 0.0);

    const tables::ToolTable& table = *toolTable();
    cycles::probing::MeasuredToolData tool;
    tool.length = row->length;
    tool.radius = row->radius;
    tool.deltaLength = row->deltaLength;
    tool.deltaRadius = row->deltaRadius;
    tool.cutterCount = row->cutterCount;
    tool.lengthWear = table.numberCell(row->number, "LTOL").value_or(0.0);
    tool.radiusWear = table.numberCell(row->number, "RTOL").value_or(0.0);
    tool.lengthBreak = table.numberCell(row->number, "LBREAK").value_or(0.0);
    tool.radiusBreak = table.numberCell(row->number, "RBREAK").value_or(0.0);
    tool.radiusOffset = table.numberCell(row->number, "R-OFFS");
    tool.lengthOffset = table.numberCell(row->number, "L-OFFS").value_or(0.0);
    tool.cuttingDirection = table.numberCell(row->number, "DIRECT").value_or(-1.0);

    const workpiece::RealTool real = realTool(*row);
    // Q260 is a tool-tip height of the active datum.
    Pose clearance = m_programmed;
    clearance[Axis::Z] = values.number(260);
    const double clearanceZ =
        m_frame.toWorkpiece(clearance)[Axis::Z] + m_settings.presetInMachine[Axis::Z];
    runTouching([this, &cycle, values, status, tt = *tt, tool, real, clearanceZ] {
        measureToolAndApply(cycle, values, status, tt, tool, real, clearanceZ);
    });
}

void KlartextInterpreter::measureToolAndApply(const cycles::probing::ProbingCycleDescriptor& cycle,
                                              const cycles::CycleValues& values, uint16_t status,
                                              const cycles::probing::ToolProbeData& tt,
                                              const cycles::probing::MeasuredToolData& tool,
                                              const workpiece::RealTool& real, double clearanceZ) {
    using cycles::probing::ToolMeasurementKind;
    const machine::ToolProbeConfig& c = m_settings.machine->toolProbe;
    const workpiece::SimulatedToolProbe simulated({Vec3(c.centreXMm, c.centreYMm, c.centreZMm),
                                                   c.diameterMm,
                                                   c.shape == machine::ToolProbeShape::Cube});
    ToolProbeAdapter machine(*this, simulated, real);
    // Results only from the pass that completes (a pass that handed a touch to the machine
    // ends with its probe move): TTCALIB.TXT, the Q parameters, TOOL.T and SIMTOOLS.TXT.
    if (cycle.toolMeasurement == ToolMeasurementKind::Calibrate) {
        cycles::probing::ToolProbeData calibrated;
        auto error = cycles::probing::calibrateToolProbe(cycle.number, clearanceZ, tt, tool,
                                                         machine, calibrated);
        machine.restoreSpindle();
        if (touchHandedToMachine()) return;
        if (error) {
            failCycle(*error);
            return;
        }
        m_ttCalibration = calibrated;
        writeToolProbeCalibration(cycle.number, calibrated);
        return;
    }
    cycles::probing::ToolMeasurementRequest request;
    request.length = cycle.toolMeasurement != ToolMeasurementKind::Radius;
    request.radius = cycle.toolMeasurement != ToolMeasurementKind::Length;
    request.mode = values.integer(340);
    request.clearanceZ = clearanceZ;
    request.teeth = values.integer(341) == 1;
    cycles::probing::ToolMeasurementResult result;
    auto error = cycles::probing::measureTool(cycle.number, request, tt, tool, machine, result);
    machine.restoreSpindle();
    if (touchHandedToMachine()) return;
    if (error) {
        failCycle(*error);
        return;
    }
    if (request.length) m_q.set(QRef{QKind::Q, 115}, result.lengthDeviation / lengthScale());
    if (request.radius) m_q.set(QRef{QKind::Q, 116}, result.radiusDeviation / lengthScale());
    if (status != 0) m_q.set(QRef{QKind::Q, status}, result.status);
    if (request.mode != 2) {
        writeToolTable(cycle.number, m_tool.number, 0,
                       {result.newLength, result.newRadius, result.newDeltaLength,
                        result.newDeltaRadius, result.lock});
    }
}

// Measured values into TOOL.T (atomically, after the program check); a change of the tool in
// the spindle takes effect at once (spec 7.1: "take effect automatically at the end of the
// probing cycle").
bool KlartextInterpreter::writeToolTable(int cycle, int tool, int index,
                                         const ToolTableEdit& edit) {
    if (!waitForCheck()) return false;
    if (!recordRealTool(cycle, tool)) return false;
    tables::ToolTable table = *toolTable();
    auto set = [&](const char* column, const std::optional<double>& value) -> bool {
        if (!value) return true;
        if (auto error = table.setNumber(tool, column, *value, index)) {
            failCycle({error->code, error->messageTemplate, error->args});
            return false;
        }
        return true;
    };
    if (!set("L", edit.length) || !set("R", edit.radius) || !set("DL", edit.deltaLength) ||
        !set("DR", edit.deltaRadius)) {
        return false;
    }
    if (edit.lock) {
        if (auto error = table.setText(tool, "TL", "L", index)) {
            failCycle({error->code, error->messageTemplate, error->args});
            return false;
        }
    }
    const std::filesystem::path file =
        m_settings.toolTableFile.empty() ? m_root.path() / "TOOL.T" : m_settings.toolTableFile;
    if (auto error = replaceFile(file, table.serialize())) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the tool table: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    m_toolTable = std::move(table);
    if (tool != m_tool.number || index != 0) return true;
    const tables::ToolData* row = m_toolTable->byNumber(tool);
    m_tool.length = row->length;
    m_tool.radius = row->radius;
    m_tool.tableDl = row->deltaLength;
    m_tool.tableDr = row->deltaRadius;
    emit(canon::ToolUpdate{m_tool.geometry(), m_toolAxis});
    m_path.setToolRadius(m_tool.effectiveRadius());
    m_q.set({QKind::Q, 108}, m_tool.effectiveRadius() / lengthScale());
    m_q.set({QKind::Q, 114}, m_tool.effectiveLength() / lengthScale());
    return true;
}

// Q330 (spec 1.14): the monitored tool's DR (DL for 427 in the tool axis) gets the deviation
// added, even within tolerance; beyond its RBREAK the tool is locked and the program stops.
bool KlartextInterpreter::applyToolMonitoring(int cycle, const cycles::CycleValues& values,
                                              const cycles::probing::ToolCorrection& correction) {
    const std::string& name = values.text(330);
    const double number = values.number(330);
    const int whole = static_cast<int>(number);
    const int index = static_cast<int>(std::lround((number - whole) * 10.0));
    const tables::ToolTable* table = toolTable();
    const tables::ToolData* row = table == nullptr ? nullptr
                                  : name.empty()   ? table->byNumber(whole, index)
                                                   : table->byName(name);
    const std::string shown = !name.empty() ? name
                              : index == 0  ? std::to_string(whole)
                                            : std::to_string(whole) + "." + std::to_string(index);
    if (row == nullptr) {
        fail("PRB-012",
             KERF_TR_NOOP("touch probe cycle {1}: the tool to monitor (Q330 = {2}) is not in "
                          "the tool table"),
             {std::to_string(cycle), shown});
        return false;
    }
    ToolTableEdit edit;
    if (!correction.breakageOnly) {
        (correction.length ? edit.deltaLength : edit.deltaRadius) =
            (correction.length ? row->deltaLength : row->deltaRadius) + correction.delta;
    }
    const double breakage = table->numberCell(row->number, "RBREAK", row->index).value_or(0.0);
    edit.lock = breakage > 0.0 && std::abs(correction.delta) > breakage;
    if ((edit.deltaLength || edit.deltaRadius || edit.lock) &&
        !writeToolTable(cycle, row->number, row->index, edit)) {
        return false;
    }
    if (edit.lock) {
        fail("PRB-007",
             KERF_TR_NOOP("touch probe cycle {1}: tool {2} is broken (deviation {3} mm beyond "
                          "RBREAK); it is locked"),
             {std::to_string(cycle), shown, std::to_string(correction.delta)});
        return false;
    }
    return true;
}

}  // namespace kerf::klartext
