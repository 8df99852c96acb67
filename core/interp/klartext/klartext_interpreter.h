#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/cycle_values.h"
#include "core/cycles/pattern/pattern_plan.h"
#include "core/cycles/probing/probing_cycle.h"
#include "core/cycles/probing/probing_log_html.h"
#include "core/cycles/probing/single_touch.h"
#include "core/cycles/probing/tool_measurement.h"
#include "core/cycles/transform/coordinate_frame.h"
#include "core/geometry/fk/fk_solver.h"
#include "core/geometry/offset_contour.h"
#include "core/interp/interpreter.h"
#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/block_reader.h"
#include "core/interp/klartext/fk_trace.h"
#include "core/interp/klartext/program_file.h"
#include "core/interp/klartext/q_parameters.h"
#include "core/interp/path/path_builder.h"
#include "core/interp/path/value_guard.h"
#include "core/machine/machine_config.h"
#include "core/machine/table_kinematics.h"
#include "core/program/nc_root.h"
#include "core/program/source_registry.h"
#include "core/tables/datum_table.h"
#include "core/tables/free_table.h"
#include "core/tables/preset_table.h"
#include "core/tables/probe_table.h"
#include "core/tables/tool_table.h"
#include "core/workpiece/cut_recorder.h"
#include "core/workpiece/simulated_tool_probe.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::cycles {
struct LegacyCycle;
}

namespace kerf::klartext {

struct KlartextSettings {
    const machine::MachineConfig* machine = nullptr;  // required
    // Tool data for TOOL CALL. Without a table every tool is accepted with zero geometry and a
    // warning, so that programs can be checked without the machine's tool table.
    const tables::ToolTable* tools = nullptr;
    // Where the TT cycles write `tools` back (inside the NC root); empty: TOOL.T of the NC root.
    std::filesystem::path toolTableFile;
    std::filesystem::path ncRoot;                   // CALL PGM, FN 16 and FN 26 stay inside it
    std::vector<std::filesystem::path> runOutputs;  // files the run writes: never read
    std::filesystem::path remanentFile;             // QR parameters; empty: not kept between runs
    bool writeFiles = true;  // false: files the program writes are admitted, not written
    Pose presetInMachine{};  // the active preset (workpiece datum), machine coords
    // The active preset's basic rotation (its SPC column: a probed misalignment), degrees about
    // the tool axis: the program starts in the working plane turned by it.
    double basicRotationDeg = 0.0;
    Pose startPosition{};  // tool tip at the start, workpiece coordinates
    // False: startPosition is a stand-in (a headless run that starts "at the origin"); the
    // simulated part then takes no cut and sees no collision on the way from it.
    bool startPositionKnown = true;
    bool blockSkip = false;  // skip blocks marked with '/'
    // Cycle 247 reads presets from this table (PRESET.PR in the NC root when not given).
    const tables::PresetTable* presets = nullptr;
    // Machine parameter displayDepthErr: a positive cycle depth is an error.
    bool positiveDepthIsError = true;
    // Machine parameter posAfterContPocket: true (PosBeforeMachining) ends the SL cycles back at
    // the position before the cycle; false (ToolAxClearanceHeight) at Q7, the tool axis only.
    bool slReturnToStart = false;
    // Cycle 225: the date and time %time engraves (a fixed one for tests; unset: the local
    // time of the computer) and the MOD counter %count engraves (0 in test run).
    std::optional<cycles::DateTime> engravingTime;
    unsigned long long partCounter = 0;
    int maxLabelNesting = 19;
    int maxProgramNesting = 19;
    // The DIN/ISO syntax (core/interp/tnciso): called programs named `.I` are read with it, and
    // the main program too when `mainProgramIso` is set. Unset: conversational only.
    SyntaxMaker isoSyntax;
    bool mainProgramIso = false;
    // An MDI block run as a program of its own: it starts with the spindle speed S the machine
    // was left with, and its end leaves the spindle and coolant as they are (a TNC's MDI keeps
    // them between blocks; a program's END PGM switches them off).
    bool mdi = false;
    double startSpindleRpm = 0.0;
    canon::SpindleDirection startSpindle = canon::SpindleDirection::Stopped;  // as it turns
    // The touch-probe cycles' touches come from the machine's latch (a probe move and a sync
    // point per touch: `kerf run --motion`, the panel's simulated machine); false: the
    // interpreter decides them on the simulated part (plain `kerf run`, the test run).
    bool touchesFromMachine = false;
};

// The TNC 320 engine: runs conversational ("Klartext") programs, and DIN/ISO programs through the
// syntax of core/interp/tnciso, with the same Q parameters, cycles, transformations and tables.
class KlartextInterpreter final : public interp::Interpreter {
public:
    KlartextInterpreter(program::SourceRegistry& sources, KlartextSettings settings);
    ~KlartextInterpreter() override;

    // Inline: the program is checked before load() returns. Background: the check runs in a
    // second thread while execution starts; jumps and the program end wait for it, and if it
    // finds errors checkFailed() becomes true and the run stops.
    enum class CheckMode : uint8_t { Inline, Background };

    // Loads and checks the main program. False if it cannot run (diagnostics() says why).
    bool load(const std::filesystem::path& path, CheckMode mode = CheckMode::Inline);
    bool loadText(std::string text, const std::string& path);

    interp::RunStatus run(canon::Sink& sink, uint64_t blockBudget) override;
    void resume(const interp::WorldSnapshot& world) override;
    const DiagnosticList& diagnostics() const override { return m_diagnostics; }
    uint64_t blocksExecuted() const override { return m_blocks; }
    // Workpiece coordinates of the start preset (the frame of the canonical stream).
    Pose nominalPosition() const override { return m_frame.toWorkpiece(m_programmed); }
    bool checkFailed() const override { return m_checkFailed; }
    interp::ProgramStatus programStatus() const override;  // klartext_status.cpp
    // The material the program's tools removed from its blank so far, in stream coordinates
    // (the part its probing cycles touch); it keeps growing while the program runs.
    std::shared_ptr<const workpiece::RemovedMaterial> removedMaterial() const {
        return m_cuts.removed();
    }

    const QParameters& parameters() const { return m_q; }
    // Records what the FK solver does into `trace` (nullptr: nothing), for the programming
    // graphics; the trace must outlive the run.
    void traceFk(FkTrace* trace) { m_fkTrace = trace; }

private:
    class Environment;
    // What every cycle output does besides moving: dwell, spindle, M functions
    // (klartext_cycle_calls.cpp); CycleOutput and CylinderOutput add the moves.
    class CycleFunctions : public cycles::CycleEmitter {
    public:
        explicit CycleFunctions(KlartextInterpreter& owner) : m(owner) {}
        void dwell(double seconds) override;
        void spindle(canon::SpindleDirection direction, double rpm) override;
        void orientSpindle(double angleDeg) override;
        void miscFunction(int number) override;

    protected:
        bool ok() const { return m.m_status != interp::RunStatus::Failed; }
        KlartextInterpreter& m;
    };
    class CycleOutput;
    class ProbeAdapter;
    class ToolProbeAdapter;

    struct Level {  // one program in the CALL PGM chain
        ProgramFile* program = nullptr;
        size_t returnOffset = 0;
        uint32_t returnLine = 0;
        bool inch = false;
    };
    struct LabelFrame {  // an active CALL LBL
        size_t level = 0;
        size_t callOffset = 0;
        LabelPosition target;
        size_t returnOffset = 0;
        uint32_t returnLine = 0;
        int remaining = 0;
    };
    struct ToolState {
        int number = -1;
        std::string name;
        double length = 0.0, radius = 0.0, radius2 = 0.0;
        double tableDl = 0.0, tableDr = 0.0, tableDr2 = 0.0;
        double callDl = 0.0, callDr = 0.0, callDr2 = 0.0;
        int cutterCount = 0;
        double pointAngle = 0.0, plungeAngle = 0.0, cuttingLength = 0.0, pitch = 0.0;
        double effectiveRadius() const { return radius + tableDr + callDr; }
        double effectiveLength() const { return length + tableDl + callDl; }
        canon::ToolGeometry geometry() const {
            return {effectiveLength(), effectiveRadius(), radius2 + tableDr2 + callDr2};
        }
    };
    struct Pole {
        Vec2 point{0.0, 0.0};
        Plane plane = Plane::XY;
        bool set = false;
    };
    // What the interpreter reads once the machine has caught up: FN 18 positions (id 240 or
    // 270), or nothing (id 0, FN 20: WAIT FOR SYNC).
    struct PendingSync {
        QRef target;
        int id = 0, nr = 0, idx = 0;
    };

    // Program flow (klartext_interpreter.cpp).
    bool waitForCheck();
    // The main program is the operator's choice; called programs are opened through the NC root.
    enum class Origin : uint8_t { Main, Called };
    ProgramFile* loadProgram(const std::filesystem::path& path, std::string* error, Origin origin,
                             bool check = true);
    // Whether the program at `path` is read as DIN/ISO; makes its reader and parser current.
    bool isIsoProgram(const std::filesystem::path& path, Origin origin) const;
    void selectProgram(const ProgramFile& program);
    // The parser for a program read on the side (contour programs): the conversational one, or
    // a new one of the program's own syntax held in `own`.
    BlockSyntax& parserFor(const ProgramFile& program, std::unique_ptr<BlockSyntax>& own);
    void startLevel(ProgramFile* program, size_t returnOffset, uint32_t returnLine);
    bool endOfProgram(bool explicitEnd);
    void finish(bool emitEnd, int mCode);
    void execute(const Statement& statement);
    void jumpTo(const LabelPosition& position);
    const LabelPosition* resolveLabel(const LabelTarget& target);
    void callLabel(const CallLabel& call);
    void returnFromLabel();
    void gotoLabel(const LabelTarget& target);
    void callProgram(const CallPgm& call);
    // The file a `CALL PGM name` from `callerFolder` opens, or why it cannot be called.
    Expected<std::filesystem::path> calledProgramPath(const std::string& name,
                                                      const std::filesystem::path& callerFolder,
                                                      bool isoCaller) const;
    // Loads and checks every program `program` calls by name (CALL PGM, cycle 12, contours), and
    // theirs, once each, and reads the tables they select: a missing or faulty program or table
    // fails the check of the main program, before anything runs.
    void checkCalledPrograms(const ProgramFile& program, DiagnosticList& out);

    // Motion and machine functions (klartext_motion.cpp).
    void executeLinear(const LinearBlock& block);
    void executeLineNormal(const LineNormalBlock& block);  // klartext_line_normal.cpp
    // LN: false (failed) for an oversize M107 does not permit or a corner radius R2 + DR2
    // outside 0 ... R + DR.
    bool cutterFitsLineNormal();
    // A direction on the part (workpiece coordinates) in the program's coordinates at `at`.
    Vec3 programDirectionOf(const Vec3& onPart, const Pose& at) const;
    void executeCircle(const Coordinates& coords, Direction direction, const CommonWords& words,
                       std::optional<double> radius);
    void executeTangentCircle(const Coordinates& coords, const PolarWords* polar,
                              const CommonWords& words);
    void executeCircleCenter(const CircleCenter& block);
    void executeLinePolar(const LinePolarBlock& block);
    void executeCirclePolar(const CirclePolarBlock& block);
    void executeApproach(const ApproachBlock& block);
    void executeCorner(bool chamfer, double size, const FeedWord& feed);
    bool resolveFeed(const FeedWord& word, bool& rapid, double& feed);
    void executeToolCall(const ToolCall& call);
    void executeToolDef(const ToolDef& def);
    void executeBlkForm(const BlkForm& blk);
    void executeMOnly(const CommonWords& words);
    void applyMFunctions(const MWords& m, bool atStart);
    // M94: every rotary axis, or only those in `only` (M94 C).
    void reduceRotaryDisplay(AxisMask only);
    bool hasM(const MWords& m, int number) const;
    void submitMove(const ContourElement& element, bool rapid, double feed,
                    const CommonWords& words);
    void emit(canon::CommandBody body);
    Pose targetOf(const Coordinates& coords) const;
    // Sets the working-plane coordinates of `target` from polar words about the pole CC.
    void applyPolar(const PolarWords& polar, Pose& target) const;
    Plane workingPlane() const;
    double lengthScale() const { return m_inch ? 25.4 : 1.0; }
    bool checkPathError(const std::optional<interp::PathError>& error);
    // False (and the run failed) when the output refused a command with an unsafe number.
    bool outputValuesOk();

    // Cycle definitions, GLOBAL DEF, PATTERN DEF, point and datum tables (klartext_cycles.cpp).
    struct StoredCycle {  // the last defined machining cycle
        const cycles::CycleDescriptor* descriptor = nullptr;
        cycles::CycleValues values;
        std::vector<uint16_t> predef;  // parameters written PREDEF: GLOBAL DEF value at the call
        std::string program;           // cycle 12
    };
    void executeCycleDefinition(const CycleDefinition& def);
    void executeOldCycle(const CycleDefinition& def);
    void executeGlobalDef(const GlobalDefinition& def);
    void executePatternDef(const PatternDefinition& def);
    void executeSelectTable(const SelectTable& select);
    void executeSelectPattern(const SelectPattern& select);
    void callSelectedProgram();  // CALL SELECTED PGM: the program of the last SEL PGM
    bool resolveParameters(const std::string& owner,
                           std::span<const cycles::ParameterDescriptor> descriptors,
                           const std::vector<CycleParameter>& written, cycles::CycleValues& values,
                           std::vector<uint16_t>* predef, int probeCycle = 0);
    void failCycle(const cycles::CycleError& error);
    std::optional<std::string> cycleText(std::string_view raw) const;
    // The table file `SEL TABLE`/`SEL PATTERN name` from `folder` opens (the extension may be
    // left out), or why it cannot be opened.
    Expected<std::filesystem::path> selectedTablePath(const std::string& name,
                                                      const std::filesystem::path& folder,
                                                      const char* extension) const;
    std::optional<std::filesystem::path> tablePath(const std::string& name, const char* extension);
    // Why the table `table` selects cannot be read (nothing when it can), for the check.
    MaybeError checkSelectedTable(const TableReference& table,
                                  const std::filesystem::path& folder) const;
    // Old-style sub-blocks (klartext_transform.cpp).
    void datumShift(const CycleDefinition& def);
    void mirrorImage(const CycleDefinition& def);
    void rotation(const CycleDefinition& def);
    void scaling(const CycleDefinition& def);
    void axisScaling(const CycleDefinition& def);
    void presetting(const cycles::CycleValues& values);
    void workingPlane(const CycleDefinition& def);
    void dwellTime(const CycleDefinition& def);
    void programCall(const CycleDefinition& def);
    void spindleOrientation(const CycleDefinition& def);
    void threadCutting(const CycleDefinition& def);
    // Machining cycles of older TNCs (1, 2, 4, 5, 17): sub-block words to the stored cycle.
    void legacyCycle(const CycleDefinition& def, const cycles::LegacyCycle& legacy);
    void tolerance(const CycleDefinition& def);
    // FK free contour programming (klartext_fk.cpp): blocks go to the solver, resolved elements
    // are emitted as lines and arcs with the words and location of their own block.
    struct FkBlockState {
        SourceLocation at;
        CommonWords words;
        std::vector<std::pair<Statement, SourceLocation>> after;  // RND/CHF after the element
    };
    struct FkState {
        fk::FkSolver solver;
        bool active = false;      // an FK sequence is open
        Plane plane = Plane::XY;  // the working plane it runs in
        std::map<size_t, FkBlockState> blocks;
        size_t nextTag = 0;
        std::optional<FkPole> pole;  // FPOL (in mm) stays until the next FPOL
        bool tentative = false;      // tracing: solution 1 was taken for a missing FSELECT
    };
    void executeFk(const FkBlock& block);
    void executeFkSelect(const FkSelect& select);
    void executeFkPole(const FkPole& pole);
    // True when `statement` was taken by the open FK sequence (RND/CHF between FK elements).
    // Other blocks end the sequence first.
    bool routeThroughFk(const Statement& statement);
    void finishFk();
    // Tracing for the programming graphics: an FSELECT is missing; report it and go on with
    // solution 1, so the elements after it can be drawn.
    void chooseTentatively();
    void applyFkStep(const fk::FkStep& step);
    void emitFkElement(const fk::FkResolved& resolved);
    void traceAmbiguity();
    // Every file the program writes (FN 16, tables, TOOL.T) goes through here: with
    // writeFiles false it is admitted but not written.
    MaybeError replaceFile(const std::filesystem::path& file, std::string_view content)
        const;  // the solver offers alternatives: m_fkTrace records them
    // Cycle 14 and the contour subprograms of the SL cycles (klartext_contours.cpp).
    void contourLabels(const CycleDefinition& def);
    bool captureContours(std::vector<cycles::SubContour>& out);
    bool captureContour(const LabelPosition& position, int label, cycles::SubContour& out);
    // Cycles 25, 275 and 276: the first label's contour as a path, open or closed.
    bool captureTrain(int cycle, cycles::ContourTrain& out);
    struct ChainRules {
        bool approach = false;  // APPR/DEP allowed (275)
        bool toolAxis = false;  // tool-axis coordinates allowed (276)
        // A contour-description program of the contour formula: the whole program, its first
        // move L or LP, tool-axis coordinates and radius compensation of no account.
        bool formula = false;
    };
    struct CapturedChain {
        std::vector<PlanarSegment> segments;
        std::vector<std::pair<double, double>> heights;  // tool axis at each segment's ends
        CompWord side = CompWord::Off;                   // of the first move
        bool approach = false;                           // the first move is an APPR block
    };
    bool captureChain(const ProgramFile& program, const LabelPosition& position, ChainRules rules,
                      CapturedChain& out);
    // A contour named `name` ("LBL 5", a program) that exists (`noContour` otherwise) and lies
    // within reach; closeContour() closes it and refuses one without area or crossing itself.
    bool checkContourReach(const std::vector<PlanarSegment>& segments, const std::string& name,
                           const char* noContour);
    bool closeContour(std::vector<PlanarSegment> segments, const std::string& name,
                      ClosedContour& out);
    // The contour formula (klartext_contour_formula.cpp): SEL CONTOUR and CONTOUR DEF select
    // the SL contour instead of cycle 14, whichever was programmed last.
    void executeSelectContour(const SelectContour& select);
    void executeDeclareContour(const DeclareContour& declare);
    void executeContourFormula(const ContourFormula& formula);
    void executeContourDefinition(const ContourDefinition& definition);
    bool captureLabelContour(const LabelTarget& label, cycles::FormulaContour& out);
    bool captureFormula(std::optional<cycles::ContourFormula>& out);
    bool runDefinitionProgram(cycles::ContourFormula& out);
    const ProgramFile* loadContourProgram(const std::string& name,
                                          const std::filesystem::path& folder, bool isoCaller);
    bool captureProgramContour(const std::string& name, const std::filesystem::path& folder,
                               bool isoCaller, cycles::FormulaContour& out);
    struct FormulaBuild;
    // Where moves go: the canonical stream, or a contour subprogram being read.
    interp::PathBuilder& activePath() { return m_capturePath ? *m_capturePath : m_path; }
    const interp::PathBuilder& activePath() const {
        return m_capturePath ? *m_capturePath : m_path;
    }
    std::optional<double> lastValue(const CycleDefinition& def, const char* what);
    // Coordinate transformations of path functions and cycles alike: the element in the
    // coordinates the path works in (the stream's, or the tilted plane's for TCPM and for a
    // swivel head turned out of the machine's planes).
    std::optional<ContourElement> toPathSpace(const ContourElement& element);
    bool pathInTiltedPlane() const {
        return activePath().space() == &m_tiltedPlaneSpace || activePath().space() == &m_tcpmSpace;
    }
    // A program point in those coordinates, and back.
    Pose pathOfProgram(const Pose& program) const;
    // Arcs in `plane` turn the other way in the path's coordinates (radius compensation changes
    // side).
    bool pathFlipsOrientation(Plane plane) const;
    // Arcs in `plane` stay arcs of that plane in the path's coordinates.
    bool pathKeepsArcs(Plane plane) const;
    Pose programOfPath(const Pose& path) const;
    // After TCPM or the tilted plane's frame changed: the path works in the space they need
    // (klartext_tcpm.cpp). Flushes the path.
    void updatePathSpace();
    // Touch-probe cycles (klartext_probing.cpp).
    void executeProbeCycle(const CycleDefinition& def);
    std::optional<cycles::probing::ProbeData> activeProbe(int cycle);
    workpiece::SimulatedWorkpiece simulatedPart() const;
    // The tool table names the tool a touch probe (a TP_NO): it removes no material.
    bool isTouchProbe(int toolNumber) const;
    bool writeProtocol(int cycle, const char* name, const std::vector<std::string>& lines);
    bool applyDatum(int cycle, const cycles::probing::ProbingResults& results);
    // PRESET.PR of the NC root, or the default table when there is none; nullopt after a failure.
    std::optional<tables::PresetTable> presetTableToEdit(const std::filesystem::path& file);
    bool writePreset(int cycle, int row, const Pose& offset);
    // 460/462/463: the calibrated CAL_OF1/CAL_OF2 into the probe's row of tchprobe.tp.
    bool writeProbeCentreOffset(int cycle, int probe, const Vec2& offset);
    // 460-463: adds the calibration to TCHPRAUTO.html (the run's calibrations so far).
    bool logCalibration(int cycle, const char* name, const tables::ToolData& before,
                        const cycles::probing::ProbeData& probe,
                        const cycles::probing::ProbeCalibration& calibration);
    bool applyBasicRotation(int cycle, const cycles::probing::ProbingResults& results);
    // klartext_probe_writes.cpp: 403/405's table turn, SPC of a preset row, the datum table.
    std::string tableAxisLetters() const;
    void activatePreset(const Pose& offset);
    bool applyRotaryCompensation(int cycle, const cycles::probing::ProbingResults& results);
    bool writePresetRotation(int cycle, int row, double degrees);
    bool writeDatumRow(int cycle, int row, const std::vector<std::pair<char, double>>& axes);
    // The old single-touch cycles 0, 1, 3, 4 (klartext_old_probing.cpp): sub-blocks collected
    // in m_oldProbe, run with the last one (cycle 3 with 3.4 or before the next other block).
    void executeOldProbeBlock(const CycleDefinition& def);
    bool continuesOldProbe(const Statement& statement) const;
    void runOldProbe();
    // One touch of those cycles on the simulated part (klartext_probing.cpp); `feed`: their own
    // probing feed (3, 4). Gives the probe's data with the result.
    std::optional<cycles::probing::SingleTouchResult> probeOnce(
        int cycle, const cycles::probing::SingleTouch& touch, std::optional<double> feed,
        cycles::probing::ProbeData& probe);
    // The probe as it really is ([[simulation.tool_error]]).
    workpiece::RealTool realProbe() const;
    // A 4xx cycle's touches and results, after its checks (klartext_probing.cpp).
    void probeAndApply(const cycles::probing::ProbingCycleDescriptor& cycle,
                       const cycles::CycleValues& values, const cycles::probing::ProbeData& probe);
    // A block's probing, from its first move, with touches from the machine's latch when the
    // settings say so (klartext_probing_latch.cpp).
    void runTouching(std::function<void()> block);
    void passTouching();
    void resumeTouch(const interp::WorldSnapshot& world);
    // The current pass handed a touch to the machine: the rest of it moves nothing and its
    // results do not count.
    bool touchHandedToMachine() const { return m_touchReplay && m_touchReplay->waiting; }
    // The TT cycles 30-33 / 480-483 (klartext_tool_measurement.cpp).
    void executeOldToolProbeBlock(const CycleDefinition& def);
    void executeToolMeasurement(const cycles::probing::ProbingCycleDescriptor& cycle,
                                const cycles::CycleValues& values, bool oldFormat,
                                uint16_t statusParameter);
    // A TT cycle's touches and results, after its checks; `status`: the status parameter (0:
    // none).
    void measureToolAndApply(const cycles::probing::ProbingCycleDescriptor& cycle,
                             const cycles::CycleValues& values, uint16_t status,
                             const cycles::probing::ToolProbeData& tt,
                             const cycles::probing::MeasuredToolData& tool,
                             const workpiece::RealTool& real, double clearanceZ);
    std::optional<cycles::probing::ToolProbeData> toolProbeData(int cycle);
    workpiece::RealTool realTool(const tables::ToolData& row) const;
    const workpiece::RealTool* recordedRealTool(int tool) const;
    bool recordRealTool(int cycle, int tool);
    void writeToolProbeCalibration(int cycle, const cycles::probing::ToolProbeData& tt);
    void readToolProbeCalibration(cycles::probing::ToolProbeData& tt);
    struct ToolTableEdit {  // what a probing cycle writes into a tool's row
        std::optional<double> length, radius, deltaLength, deltaRadius;
        bool lock = false;  // TL = L
    };
    // `index`: the row of an indexed tool (T 5.2); the tool in the spindle has index 0.
    bool writeToolTable(int cycle, int tool, int index, const ToolTableEdit& edit);
    // Q330: a tool number (5.2: tool 5, index 2) or a name in quotes.
    bool applyToolMonitoring(int cycle, const cycles::CycleValues& values,
                             const cycles::probing::ToolCorrection& correction);
    // The tool data TOOL CALL reads: the table as the TT cycles left it.
    const tables::ToolTable* toolTable() const {
        return m_toolTable ? &*m_toolTable : m_settings.tools;
    }
    // Cycle calls (klartext_cycle_calls.cpp).
    void executeCycleCall(const CycleCall& call);
    void callCycleHere(const cycles::CycleValues* overrides = nullptr);
    void callCyclePattern(const CycleCall& call);
    void callCyclePosition(const CycleCall& call);
    void runPatternCycle(const cycles::CycleDescriptor& pattern, const cycles::CycleValues& values);
    bool runMachiningCycle(const cycles::CycleValues& values);
    // The feed of a cycle's move (switching the feed mode when it changes).
    double cycleFeed(const cycles::Feed& feed);
    // The cylinder-surface cycles 27, 28, 29, 39 on the rotary table (klartext_cylinder.cpp):
    // checks the machine, reads the contour in mm into ctx.train, sets ctx.start on the
    // development and returns where the cycle's moves go; nothing (and the run failed) when the
    // cycle cannot run here.
    class CylinderOutput;
    std::unique_ptr<cycles::CycleEmitter> cylinderOutput(const cycles::CycleValues& values,
                                                         cycles::CycleContext& ctx);
    cycles::CycleValues callValues() const;
    void moveProgrammed(const Pose& target, bool rapid, double feed);
    void afterPositioning(const MWords& m);
    void approachPatternPoint(const cycles::PatternPlan& plan, size_t index);
    void restoreFeedMode(canon::FeedMode mode);
    // Cycle 12 at the points of CYCL CALL PAT or of cycle 220/221 (klartext_program_points.cpp):
    // the program runs once per point, with the point as an additional datum shift; when it
    // returns, the next point follows.
    struct ProgramAtPoints {
        size_t callerLevel = 0;  // m_levels.size() of the calling program
        SourceLocation at;       // the calling block: the moves between the points carry it
        std::string program;
        std::vector<cycles::PatternPoint> points;  // CYCL CALL PAT
        std::optional<cycles::PatternPlan> plan;   // cycle 220/221: its points and heights
        bool rapid = true;                         // CYCL CALL PAT: traverse and height
        double feed = 0.0;
        double height = 0.0;
        MWords after;  // M functions of CYCL CALL PAT that act after the last point
        Pose outerShift{};
        size_t next = 0;
    };
    void startProgramAtPoints(ProgramAtPoints run);
    void callProgramAtNextPoint();
    void returnFromPointProgram();
    void setPointShift(const Pose& shift);
    Vec3 toLocal(const Pose& pose) const;
    Pose fromLocal(const Vec3& local) const;

    // The tilted working plane and the rotary axes (klartext_plane.cpp).
    struct TiltState {
        bool active = false;
        Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // tilted axes, untilted coords
    };
    struct TiltRequest {
        Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
        machine::RotaryAngles angles;
        bool reset = false;
        PlaneBlock::Positioning positioning = PlaneBlock::Positioning::Stay;
        double distance = 0.0;  // MOVE: the point this far along the tool stays put
        bool rapid = true;
        double feed = 0.0;
        std::optional<double> retract;  // MB
        bool retractMax = false;        // MB MAX
    };
    void executePlane(const PlaneBlock& block);
    std::optional<Eigen::Matrix3d> planeRotation(const PlaneBlock& block);
    machine::RotaryAngles currentTableAngles() const;
    std::optional<machine::RotaryAngles> solvePlane(const Eigen::Matrix3d& rotation,
                                                    PlaneBlock::Sequence sequence,
                                                    bool tableRotation, std::string_view feature);
    void applyTilt(const TiltRequest& request);
    // The frame's turn and offset of the linear axes for the plane's solved angles and the tool
    // now in the spindle (a swivel head turns the tip by its length).
    void setTableFrame();
    Vec3 tiltPreset() const;
    // A line in stream coordinates (the machine's linear axes), past the transformations.
    void emitStreamMove(const Pose& from, const Pose& to, bool rapid, double feed);
    // Where a rotary axis word takes the axis (program coordinates): endless axes count from
    // the angle shown modulo 360, or take the short way with M126.
    double rotaryTarget(Axis axis, double current, double programmed, bool incremental) const;
    // False (and the run failed) when a rotary axis would leave its soft limits.
    bool rotaryWithinLimits(const Pose& programTarget);
    // The same for a stream pose (the machine's axes less the preset): the error, or none.
    std::optional<interp::PathError> rotaryLimitError(const Pose& stream,
                                                      const SourceLocation& location) const;

    // TCPM (klartext_tcpm.cpp): tool-tip positions on the part while the tables turn.
    void switchTcpm(const TcpmBlock& mode);
    machine::RotaryAngles tableAnglesOf(const Pose& pose) const;
    Pose axesOfTip(const Pose& tip) const;  // workpiece tip -> stream (linear axes)
    Pose tipOf(const Pose& axes) const;     // and back
    // The target of a motion block: targetOf(), and with AXIS SPAT the rotary axes that turn the
    // tool to the spatial angles A, B, C written. Nothing (and the run failed) when they cannot.
    std::optional<Pose> moveTarget(const Coordinates& coords);
    // Both solutions of the rotary axes for the tool along `direction` (workpiece), the one
    // nearer to `near` (stream pose: its rotary axes), as stream angles a turn nearer to it.
    std::optional<machine::RotaryAngles> anglesNear(const Vec3& direction, const Pose& near) const;
    // Sets the rotary axes of `target` (program coordinates) to turn the tool along `direction`
    // (workpiece coordinates), the solution nearer to where the axes stand; false when none.
    bool turnToolTo(const Vec3& direction, Pose& target) const;
    // The spaces the path may work in (core/interp/path/path_space.h). TCPM works in the
    // tilted plane's coordinates (the frame up to the datum shift): the rest of the frame, taken
    // when the space was chosen and without the tables' turn, brings the tip onto the part, and
    // the kinematics at the pose's rotary angles bring the axes to it.
    class TcpmSpace final : public interp::PathSpace {
    public:
        explicit TcpmSpace(const KlartextInterpreter& owner) : m(owner) {}
        Pose toMachine(const Pose& tilted) const override {
            return m.axesOfTip(frame.tiltedPlaneToWorkpiece(tilted));
        }
        Pose toPath(const Pose& axes) const override {
            return frame.workpieceToTiltedPlane(m.tipOf(axes));
        }
        Pose along(const ContourElement& element, double t) const override;
        double deviation(const Pose& passed, const Pose& meant) const override;
        bool feedAlongElement() const override { return !feedContour; }
        // The rotary axes turn through the element (PATHCTRL VECTOR, AXIS SPAT): each piece
        // keeps their soft limits, not just the block's end.
        std::optional<interp::PathError> refusePiece(
            const Pose& axes, const SourceLocation& location) const override {
            return m.rotaryLimitError(axes, location);
        }
        cycles::CoordinateFrame frame;
        bool feedContour = false;  // F CONT
        bool vectorPath = false;   // PATHCTRL VECTOR
        double reachMm = 1.0;      // VECTOR: the tool's point this far up is kept on its plane

    private:
        Vec3 directionAt(const Pose& tilted) const;  // the tool's, in workpiece coordinates
        const KlartextInterpreter& m;
    };
    // The outer half of the frame as it was when the space was chosen (tilt, preset, tables).
    class TiltedPlaneSpace final : public interp::PathSpace {
    public:
        Pose toMachine(const Pose& tilted) const override {
            return frame.tiltedPlaneToWorkpiece(tilted);
        }
        Pose toPath(const Pose& axes) const override { return frame.workpieceToTiltedPlane(axes); }
        cycles::CoordinateFrame frame;
    };

    // Q parameter functions and FN blocks (klartext_functions.cpp).
    void executeSysRead(const SysRead& read);
    void waitForSync();
    std::optional<double> sysReadValue(const SysRead& read, bool& needsSync);
    void executeCircleData(const CircleData& data);
    void executePrint(const PrintBlock& print);
    void executeTableOpen(const TableOpen& open);
    void executeTableAccess(const TableAccess& access);
    void executeError(const ErrorBlock& block);

    void fail(const char* code, const char* messageTemplate, std::vector<std::string> args = {});
    // LP/CP: fails when a working-plane axis stands beside PR/PA.
    bool polarWithoutPlaneAxes(const Coordinates& coords);
    void warn(const char* code, const char* messageTemplate, std::vector<std::string> args = {});
    // Rapids the cut recorder found taking material of the blank, as warnings at their blocks.
    void reportCollisions();
    Diagnostic diagnosticAt(Severity severity, const char* code, const char* messageTemplate,
                            std::vector<std::string> args) const;

    program::SourceRegistry& m_sources;
    KlartextSettings m_settings;
    AxisMask m_machineAxes = kAllAxesMask;  // the machine's enabled axes; all without a machine
    program::NcRoot m_root;
    std::unique_ptr<FormulaEnvironment> m_environment;  // an Environment
    BlockParser m_parser;
    std::unique_ptr<BlockSyntax> m_isoParser;  // made when the first ISO program runs
    BlockSyntax* m_activeParser = &m_parser;   // the syntax of the program running
    interp::ValueGuard m_out;                  // every command leaves through it
    workpiece::CutRecorder m_cuts;             // then this: the material the tools removed
    interp::PathBuilder m_path;
    QParameters m_q;

    std::vector<std::unique_ptr<ProgramFile>> m_programs;
    std::thread m_checkThread;
    ProgramFile* m_checking = nullptr;  // program the background check works on
    bool m_checkFailed = false;
    size_t m_diagnosticsAtLoad = 0;
    std::vector<Level> m_levels;
    std::vector<LabelFrame> m_frames;
    std::optional<BlockReader> m_reader;
    program::LogicalLine m_line;
    ParsedBlock m_block;
    size_t m_blockOffset = 0;
    size_t m_releasedBefore = 0;
    SourceLocation m_at;

    DiagnosticList m_diagnostics;
    interp::RunStatus m_status = interp::RunStatus::Failed;
    uint64_t m_blocks = 0;
    bool m_started = false;
    bool m_endEmitted = false;
    std::optional<PendingSync> m_pendingSync;

    // Modal state.
    Pose m_programmed{};  // last programmed contour point, workpiece coordinates
    bool m_inch = false;
    double m_feed = 0.0;
    bool m_feedSet = false;
    canon::FeedMode m_feedMode = canon::FeedMode::PerMinute;
    double m_toolCallFeed = 0.0;
    CompWord m_comp = CompWord::Off;
    Axis m_toolAxis = Axis::Z;
    Pole m_pole;
    Direction m_direction = Direction::None;
    std::optional<Vec2> m_lastTangent;  // end tangent of the last contour element (CT)
    Plane m_lastTangentPlane = Plane::XY;
    canon::SpindleDirection m_spindle = canon::SpindleDirection::Stopped;
    canon::SpindleDirection m_lastSpindleDirection = canon::SpindleDirection::Stopped;
    double m_spindleSpeed = 0.0;
    bool m_coolant = false;
    ToolState m_tool;
    int m_preparedTool = -1;
    std::map<int, tables::ToolData> m_programTools;  // TOOL DEF n L.. R.. in old programs
    std::optional<Vec3> m_blankMin;
    // What the simulated touch probe touches: the blank (a tube's bore as a cavity); none before
    // a BLK FORM (the machine's [simulation.blank] then).
    std::optional<std::vector<workpiece::Solid>> m_blank;
    MWords m_currentM;  // M functions of the block being executed (M91/M92 change coordinates)
    std::optional<tables::FreeTable> m_openTable;
    bool m_warnedNoToolTable = false;

    // Cycles.
    std::optional<StoredCycle> m_cycle;  // last defined machining cycle
    int m_lastCycleDefined = -1;         // any cycle, for the status display
    int m_oldCycle = -1;                 // old-style cycle whose sub-blocks are being read
    bool m_modalCycleCall = false;       // M89
    cycles::CycleValues m_globals;       // GLOBAL DEF values
    std::vector<uint16_t> m_globalSet;
    std::optional<std::vector<cycles::PatternPoint>> m_pattern;  // PATTERN DEF or point table
    std::optional<tables::DatumTable> m_datumTable;
    std::optional<std::filesystem::path> m_datumTablePath;  // SEL TABLE: probing writes it back
    std::string m_selectedProgram;                          // SEL PGM, for CALL SELECTED PGM
    std::optional<tables::PresetTable> m_presetFile;
    std::optional<double> m_orientAngle;           // cycle 13
    std::optional<tables::ToolTable> m_toolTable;  // TOOL.T once a TT cycle has written it
    std::optional<cycles::probing::ToolProbeData> m_ttCalibration;  // cycle 30/480 of this run
    // SIMTOOLS.TXT of the NC root, read when first needed.
    struct RecordedRealTool {
        workpiece::RealTool real;
        double errorLength = 0.0, errorRadius = 0.0;  // the machine file's when it was recorded
    };
    mutable std::optional<std::map<int, RecordedRealTool>> m_recordedRealTools;
    // An old-format TT cycle (TCH PROBE 31.0 ...) collecting its sub-blocks.
    struct OldToolProbe {
        int number = -1;
        cycles::CycleValues values;
        uint16_t statusParameter = 0;  // 0: none
    };
    OldToolProbe m_oldToolProbe;
    // An old single-touch cycle (TCH PROBE 0.0 ... 4.3) collecting its sub-blocks.
    struct OldProbe {
        int number = -1;
        int lastSub = -1;
        std::optional<uint16_t> result;  // 0 and 3, 4: the (first) result parameter
        int axis = 2;                    // 0, 1, 3: the probing axis (0 X, 1 Y, 2 Z)
        double sign = -1.0;              // 0: its direction
        double angleDeg = 0.0;           // 1, 3
        Vec3 vector{0.0, 0.0, 0.0};      // 4: IX IY IZ
        cycles::probing::SingleTouch touch;
        double feed = 0.0;           // 3, 4: mm/min
        bool machineSystem = false;  // 3, 4: REFERENCE SYSTEM 1
        bool pending = false;        // 3: complete after 3.3, waits for an optional 3.4
    };
    OldProbe m_oldProbe;
    void probeOld(const OldProbe& p);  // the collected cycle's touch and results
    // A probing block whose touches the machine latches: after each latched touch the block runs
    // again from its start, moving nothing up to the last latched touch (docs/probing.md, "How
    // a cycle runs").
    // A touch, or where the operator positioned the probe at a stop of the semi-automatic mode.
    struct LatchedTouch {
        bool triggered = false;
        Pose tip;  // the tool tip at the trigger (or where it stood), stream coordinates
    };
    struct TouchReplay {
        std::function<void()> block;  // the block's probing, from its first move
        Pose start;                   // m_programmed when it began
        std::vector<LatchedTouch> latched;
        size_t next = 0;       // touches the current pass has reached
        bool waiting = false;  // the current pass handed touch `latched.size()` to the machine
        bool placing = false;  // ... or stopped for the operator to position the probe there
        // Before the last latched touch's trigger, or after a touch was handed over: the pass
        // only follows the cycle's positions.
        bool quiet() const { return waiting || next < latched.size(); }
    };
    std::optional<TouchReplay> m_touchReplay;
    // The next touch of a pass under the latch (both probes' adapters): the one latched before,
    // or null when this pass hands it to the machine now (a probe move to `farEnd` at `feed`
    // carrying `surface()`, then a sync point) or handed one over already.
    const LatchedTouch* nextLatchedTouch(
        const Pose& farEnd, double feed,
        const std::function<std::shared_ptr<const canon::ProbeSurface>()>& surface);
    // After a latched touch: the pass goes on from `end`, the trigger as the cycle computes it,
    // or, after the last latched touch, from where the machine stopped.
    void followLatchedTouch(const Pose& end);
    // The pass only follows the cycle's positions and emits nothing.
    bool touchPassQuiet() const { return m_touchReplay && m_touchReplay->quiet(); }
    std::optional<tables::ProbeTable> m_probeTable;  // tchprobe.tp, read at the first probing
    std::optional<interp::ProgramStatus::Probe> m_lastProbe;  // last touch, for the status
    double m_basicRotationDeg = 0.0;  // the preset's, or set by 400-404 (kept in m_frame)
    std::optional<cycles::CycleValues> m_extrusion;  // 1493's, for the next 14xx cycle(s)
    std::optional<cycles::probing::FastProbing> m_fastProbing;           // cycle 441, until the end
    std::vector<cycles::probing::CalibrationLogEntry> m_calibrationLog;  // TCHPRAUTO.html
    cycles::CoordinateFrame m_frame;
    // Rotary tables of the machine, the tilted plane, the tables' turn in m_frame, and M126.
    std::optional<machine::TableKinematics> m_kinematics;
    TiltState m_tilt;
    Eigen::Matrix3d m_tableTurn = Eigen::Matrix3d::Identity();
    Vec3 m_tableOffset = Vec3::Zero();
    machine::RotaryAngles m_tiltAngles;  // the active plane's solved angles
    bool m_shortestRotary = false;
    bool m_permitOversize = false;                // M107 (until M108): LN takes DR, DR2 > 0
    bool m_tcpm = false;                          // M128 / FUNCTION TCPM
    bool m_tcpmSpatial = false;                   // AXIS SPAT
    std::array<double, 3> m_spatialDeg{0, 0, 0};  // its tool angles A, B, C (modal)
    TcpmSpace m_tcpmSpace{*this};
    TiltedPlaneSpace m_tiltedPlaneSpace;
    // Moves the cycles of the current block emitted: a pattern of many points stays bounded.
    size_t m_cycleMovesInBlock = 0;
    std::vector<ProgramAtPoints> m_pointRuns;  // cycle 12 at pattern points, innermost last
    // SL cycles: the labels of cycle 14, the values of cycle 20, the radius of the tool of the
    // last cycle 22 (cycle 24's condition), and the path of a contour subprogram being read.
    std::vector<int> m_contourLabels;
    std::optional<cycles::CycleValues> m_contourData;
    std::optional<cycles::CycleValues> m_trainData;  // cycle 270
    cycles::contour::ClearingCache m_clearingCache;  // SL cycles 21-23 plan a region once
    double m_roughingRadius = 0.0;
    interp::PathBuilder* m_capturePath = nullptr;
    enum class ContourSource : uint8_t { Labels, Formula, Simple };
    ContourSource m_contourSource = ContourSource::Labels;
    std::string m_contourProgram;            // SEL CONTOUR: the definition program, as programmed
    std::filesystem::path m_contourFolder;   // and the folder of the program that selected it
    bool m_contourIsoCaller = false;         // which is a DIN/ISO program (.I names first)
    ContourDefinition m_simpleContours;      // CONTOUR DEF
    FormulaBuild* m_formulaBuild = nullptr;  // a definition program being read
    // Transformations programmed in the contour subprograms of the cycle being called.
    cycles::CoordinateFrame m_subcontourFrame;
    FkState m_fk;
    FkTrace* m_fkTrace = nullptr;
};

}  // namespace kerf::klartext
