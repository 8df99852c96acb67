#pragma once

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/cycles/lathe/lathe_path.h"
#include "core/cycles/lathe/section_turning.h"
#include "core/interp/fagor/block_parser.h"
#include "core/interp/fagor/contour_shaper.h"
#include "core/interp/fagor/fagor_program.h"
#include "core/interp/fagor/fagor_settings.h"
#include "core/interp/fagor/modal_state.h"
#include "core/interp/fagor/nose_compensation.h"
#include "core/interp/fagor/output_stage.h"
#include "core/interp/fagor/parameters.h"
#include "core/interp/fagor/statement_runner.h"
#include "core/interp/fagor/tables/tool_offset_table.h"
#include "core/interp/fagor/tables/tool_table.h"
#include "core/interp/fagor/tables/zero_offset_table.h"
#include "core/interp/fagor/work_zones.h"
#include "core/interp/interpreter.h"
#include "core/program/line_reader.h"
#include "core/program/nc_root.h"
#include "core/program/source_registry.h"

namespace kerf::fagor {

// The FAGOR 8035 T lathe front end: ISO blocks and the high-level language of spec parts 1 and
// 2, emitting the canonical stream (tool tip, workpiece coordinates of the zero offset active at
// the start, mm, X as a radius; DiameterMode says how X is shown). docs/fagor.md lists every
// interpretation choice.
class FagorInterpreter final : public interp::Interpreter,
                               private StatementContext,
                               private ParameterSource {
public:
    FagorInterpreter(program::SourceRegistry& sources, FagorSettings settings);
    ~FagorInterpreter() override;

    // Inline: the program is checked before load() returns. Background: the check runs in a
    // second thread while execution starts; jumps, calls and the end wait for it, and if it finds
    // errors checkFailed() becomes true and everything emitted must be discarded.
    enum class CheckMode : uint8_t { Inline, Background };

    bool load(const std::filesystem::path& path, CheckMode mode = CheckMode::Inline);
    bool loadText(std::string text, const std::string& path);

    interp::RunStatus run(canon::Sink& sink, uint64_t blockBudget) override;
    void resume(const interp::WorldSnapshot& world) override;
    const DiagnosticList& diagnostics() const override { return m_diagnostics; }
    uint64_t blocksExecuted() const override { return m_blocks; }
    Pose nominalPosition() const override { return m_position; }
    bool checkFailed() const override { return m_checkFailed; }
    interp::ProgramStatus programStatus() const override;  // fagor_status.cpp

    // A general logic input INT1-INT4 became active: its subroutine (INT1SUB ...) runs before
    // the next block.
    void raiseInterrupt(int input);

    const Parameters& parameters() const { return m_parameters; }
    // Machine coordinates of the stream's origin (the zero offset active at the start): motion's
    // work offset.
    Pose streamOrigin() const { return m_startOffset; }

private:
    struct Frame {
        enum class Kind : uint8_t { Call, Repeat, ModalCall, MFunction, Interrupt, Program };
        Kind kind = Kind::Call;
        FagorProgram* program = nullptr;  // where execution returns
        BlockPosition returnTo;
        bool newLocals = false;
        bool modal = false;  // the run of an MCALL subroutine or MEXEC program
        // RPT: the range in `rangeProgram`, the repetitions left.
        FagorProgram* rangeProgram = nullptr;
        BlockPosition rangeStart;
        size_t rangeEnd = 0;
        int remaining = 0;
        int mFunction = -1;
        bool emitMAfter = false;
        SourceLocation callAt{};  // MFunction: the block of the M, for what happens after it
        Pose interruptedAt{};
        size_t callBlock = SIZE_MAX;  // offset of the calling block in `program`
        BlockPosition motionBlock;    // ModalCall: the block to run again (X10 N3)
        int subroutine = -1;          // the subroutine this frame runs, for the status display
    };
    struct ToolState {
        int tool = 0;
        int offset = 0;
        int nextTool = -1;
        int nextOffset = -1;
        ToolOffset data;
        double radius = 0.0;  // HTOR
    };
    struct SpindleState {
        canon::SpindleDirection direction = canon::SpindleDirection::Stopped;
        double rpm = 0.0;      // programmed (G97)
        double surface = 0.0;  // G96 speed, m/min
        bool surfaceSet = false;
        double limit = 0.0;        // G92 S (0: none)
        int gear = 0;              // M41-M44
        double orientation = 0.0;  // M19 S
    };
    struct ThreadState {
        bool previousWasThread = false;
        bool previousWasVariable = false;
        double lead = 0.0;     // last G33/G34 lead (L)
        double endLead = 0.0;  // lead reached at the end of the last G34
    };
    // What the G functions of the ISO block being executed ask for besides modal state.
    struct BlockFunctions {
        int arcForm = 0;                  // 8 (G08) or 9 (G09)
        bool absoluteCentre = false;      // G06
        bool machineCoordinates = false;  // G53
        bool hardStop = false;            // G52
        int probe = 0;                    // G75 or G76
        uint32_t probeColumn = 1;         // of the G75/G76 word
        ContourRequest request;           // G36-G39
    };
    // The program OPEN made, kept in memory: WRITE appends to it, and the file is replaced with
    // it (atomically, after the program's check passed) when it is closed or read back.
    struct OpenProgram {
        std::filesystem::path path;  // empty: none is open
        int number = -1;
        std::string content;
    };

    // Loading and the run loop (fagor_interpreter.cpp).
    bool waitForCheck();
    // Replaces a file of the NC root; a dry run (settings.writeFiles false) admits it and keeps
    // the content in m_unwritten, where the run reads it back.
    MaybeError replaceFile(const std::filesystem::path& file, std::string_view content);
    FagorProgram* loadProgram(const std::filesystem::path& path, std::string* error,
                              bool keepLabels);
    void enterProgram(FagorProgram* program, const BlockPosition& at);
    void readFrom(FagorProgram* program, const BlockPosition& at);
    bool endOfText();
    void finish(int mCode);
    void executeBlock();
    void afterBlock();
    // The block at `blockOffset` of the reading program ended: the end of an RPT range?
    bool repeatEnd(size_t blockOffset);
    void fail(const char* code, const char* messageTemplate, std::vector<std::string> args = {});
    void failAt(size_t offset, const Problem& problem);
    void warn(const char* code, const char* messageTemplate, std::vector<std::string> args = {});
    bool pathOk(const std::optional<interp::PathError>& error);
    // Reports a refusal of the output stage (an unsafe number, a zone) the block did not see.
    void outputValuesOk();
    void emit(canon::CommandBody body);
    void resetModal();
    void reportRemovedLoops();

    // Program flow (fagor_flow.cpp).
    bool jump(int64_t label, Problem& problem) override;
    bool repeat(int64_t start, int64_t end, std::optional<int> program, int count,
                Problem& problem) override;
    bool call(CallKind kind, int number, const LocalAssignments& locals, Problem& problem) override;
    bool enterSubroutineDefinition(int number, Problem& problem) override;
    bool returnFromSubroutine(Problem& problem) override;
    bool modalCallOff(Problem& problem) override;
    bool executeProgram(bool modal, int program, Problem& problem) override;
    bool reposition(const std::array<Axis, kAxisCount>& axes, int count, Problem& problem) override;
    bool callSubroutine(Frame frame, int number, const LocalAssignments* locals, Problem& problem);
    const SubroutineEntry* findSubroutine(int number, FagorProgram*& owner, Problem& problem);
    FagorProgram* programByNumber(int number, bool keepLabels, Problem& problem);
    // The program with this number, loaded and checked (its errors not looked at yet).
    FagorProgram* programFileByNumber(int number, bool keepLabels, Problem& problem);
    // Follows the EXEC/MEXEC of constant program numbers, transitively: a missing program or one
    // that fails its check is an error at the call, as the run would stop there.
    void checkCalledPrograms(const FagorProgram& program, DiagnosticList& out);
    void runModalAfterMotion(int repetition);
    int repetitionOfBlock();
    void startPendingInterrupt();
    bool insideModal() const;
    BlockPosition nextBlock() const;

    // ISO blocks (fagor_iso.cpp).
    void executeIso(const IsoBlock& iso, int repetition);
    bool applyModalFunctions(const IsoBlock& iso);
    bool executeAloneFunction(const IsoBlock& iso, int g);
    bool setPlane(int g, const IsoBlock& iso);
    bool setMirror(const IsoBlock& iso);
    bool setScaling(const IsoBlock& iso);
    bool setZeroOffset(int g, const IsoBlock& iso);
    bool setPolarOrigin(const IsoBlock& iso);
    // G93's origin: I/J, or `current` (in the plane frame) without them.
    Vec2 polarOriginOf(const IsoBlock& iso, const Vec2& current) const;
    bool defineWorkZone(int g, const IsoBlock& iso);
    bool setThreadRetraction(const IsoBlock& iso);
    bool setLookAhead(const IsoBlock& iso);
    bool homing(const IsoBlock& iso);
    bool dwellOrStop(const IsoBlock& iso);
    void setDiameter(bool diameter);
    void applyZeroOffset();
    void preparationStop();
    bool preparationStopFree();  // preparationStop(); false if it failed

    // Motion (fagor_motion.cpp).
    bool hasMotion(const IsoBlock& iso) const;
    bool executeMotion(const IsoBlock& iso);
    double length(double programmed) const;  // units
    double xValue(double programmed) const;  // units and diameter
    double axisValue(Axis axis, double programmed) const;
    Pose programmedPosition() const;  // in the program's frame: part zero, no mirror or scale
    Pose fromStream(const Pose& stream) const;  // the inverse of toStream
    Pose toStream(const Pose& programmed) const;
    Vec2 toStreamVector(const Vec2& frameVector) const;
    bool transformFlipsSense() const;
    bool targetOf(const IsoBlock& iso, Pose& target, bool& polar);
    bool arcElement(const IsoBlock& iso, int form, const Pose& start, const Pose& target,
                    bool polar, ContourElement& out);
    // `own`: a cycle move's own feed (0: the active one) and thread data.
    struct OwnMoveData {
        double feed = 0.0;
        ThreadData thread;
    };
    bool submit(const ContourElement& programmed, MoveKind kind, const IsoBlock& iso,
                const OwnMoveData* own = nullptr);
    bool feedFor(MoveKind kind, const ContourElement& element, const IsoBlock& iso, double& feed);
    bool threadData(const IsoBlock& iso, const ContourElement& element, ThreadData& out);
    bool machineCoordinateMove(const IsoBlock& iso);
    // G53: the stream position of the block's machine coordinates (the others as in `from`).
    Pose machineTarget(const IsoBlock& iso, const Pose& from) const;
    bool hardStopMove(const IsoBlock& iso);

    // Canned cycles G81-G89 (fagor_cycles.cpp).
    bool executeCycle(const IsoBlock& iso);
    bool runCycleSteps(const std::vector<cycles::lathe::LatheStep>& steps, const IsoBlock& iso);
    // G84/G85: false with an error when the arc is hollow and tighter than the nose
    // (fagor_tool_reach.cpp).
    bool arcFitsTheNose(const Vec2& call, const Vec2& start,
                        const cycles::lathe::ProfileElement& arc);
    // The raw-stock profile of G66/G68/G69 as the blank for the graphics (canon StockRevolved).
    void emitRawStockBlank(const cycles::lathe::RawStock& raw, const Vec2& call, const Vec2& start,
                           bool stepsAlongX);
    // G68/G69: the profile from label S to label E (fagor_profile.cpp).
    struct RawProfile {
        Vec2 start{0.0, 0.0};
        std::vector<cycles::lathe::ProfileElement> elements;  // empty: no raw-stock profile
    };
    bool readProfile(const CycleWords& w, const Vec2& start,
                     std::vector<cycles::lathe::ProfileElement>& finished, RawProfile& raw);
    // The tool/profile analysis (fagor_tool_reach.cpp): warns about valleys the tool cannot reach
    // and replaces `profile` by the closest one it reaches.
    void checkToolReach(int g, const Vec2& call, const Vec2& start,
                        std::vector<cycles::lathe::ProfileElement>& profile);
    struct ProfileCorner {
        size_t element = 0;  // the corner at the end of this element
        bool round = true;   // G36, else G39
        double size = 0.0;
        uint32_t line = 0;
        uint32_t column = 0;
    };
    bool shapeProfileCorners(const Vec2& start, const std::vector<ProfileCorner>& corners,
                             std::vector<cycles::lathe::ProfileElement>& out, bool here);

    // Probing G75/G76 (fagor_probing.cpp).
    bool probeMove(const IsoBlock& iso);
    void probeResult(const interp::WorldSnapshot& world);
    void ensureStreamFeedMode(canon::FeedMode mode);

    // F, S, T, D, M (fagor_machine.cpp).
    bool setFeed(const IsoBlock& iso);
    bool setSpindleSpeed(const IsoBlock& iso);
    // The block has a spindle M function (M3, M4, M5, M19) that acts before its motion.
    bool spindleMBeforeMotion(const IsoBlock& iso) const;
    bool selectTool(const IsoBlock& iso);
    bool mFunctions(const IsoBlock& iso, bool beforeMotion, bool& calledSubroutine);
    bool mFunction(int number, const MWord& word, bool& calledSubroutine);
    void emitSpindle();
    double maxSpindleRpm() const;
    void loadToolOffset();
    void applyTool();  // radius (HTOR) and tip direction to the compensation
    void emitToolData(bool change);
    // TOFFM06: M06 puts the preselected tool in the spindle (after the changer's subroutine).
    void changeToPreselectedTool();

    // Variables and parameters (fagor_variables.cpp).
    bool parameter(int number, double& out, Problem& problem) override;
    bool readParameter(int number, double& out, Problem& problem) override;
    bool writeParameter(int number, double value, Problem& problem) override;
    bool readVariable(const VariableRef& ref, double& out, Problem& problem) override;
    bool writeVariable(const VariableRef& ref, double value, Problem& problem) override;
    bool readToolVariable(const VariableRef& ref, double& out, Problem& problem);
    bool writeToolVariable(const VariableRef& ref, double value, Problem& problem);
    bool readZeroOffsetVariable(const VariableRef& ref, double& out, Problem& problem);
    bool readFeedVariable(const VariableRef& ref, double& out);
    bool readPositionVariable(const VariableRef& ref, double& out, Problem& problem);
    bool readSpindleVariable(const VariableRef& ref, double& out);
    bool readOtherVariable(const VariableRef& ref, double& out, Problem& problem);
    bool writeOtherVariable(const VariableRef& ref, double value, Problem& problem);
    double displayed(Axis axis, double radiusMm) const;  // units and diameter for reading
    double units(double mm) const { return m_modal.inch ? mm / 25.4 : mm; }
    // kPrepStop / kMachineData of the variables a high-level statement names.
    uint8_t statementFlags(std::string_view statement) const;
    bool gActive(int number) const;
    double tipLength(Axis axis) const;

    // Statements with output (fagor_statements.cpp).
    bool raiseError(std::optional<int> number, std::string_view text, Problem& problem) override;
    bool showMessage(std::string_view text, Problem& problem) override;
    bool graphicZone(double zMin, double zMax, double inner, double outer,
                     Problem& problem) override;
    bool changeLocks(LockChange change, Problem& problem) override;
    bool openProgram(int program, char mode, std::string_view comment, Problem& problem) override;
    bool writeBlock(std::string_view text, Problem& problem) override;
    void commitOpenProgram();
    void closeOpenProgram();
    std::string substituteParameters(std::string_view text, bool marked);
    bool gpos(const VariableRef& ref, double& out, Problem& problem);

    // Screen customisation instructions of the user channel (fagor_screen.cpp).
    bool screen(const ScreenStatement& statement, Problem& problem) override;
    // The block waits for the operator's key or input: it runs again after resume().
    void waitForOperator();

    program::SourceRegistry& m_sources;
    FagorSettings m_settings;
    program::NcRoot m_root;
    BlockParser m_parser;
    StatementRunner m_runner;
    OutputStage m_output;
    NoseCompensation m_compensation;
    ContourShaper m_shaper;

    AxisMask m_machineAxes = 0;  // the enabled axes of the machine
    std::vector<std::unique_ptr<FagorProgram>> m_programs;
    std::thread m_checkThread;
    FagorProgram* m_checking = nullptr;
    bool m_checkFailed = false;
    bool m_scannedRoot = false;
    size_t m_diagnosticsAtLoad = 0;

    FagorProgram* m_program = nullptr;  // the program being read
    std::optional<program::LineReader> m_reader;
    program::LogicalLine m_line;
    ParsedBlock m_block;
    size_t m_blockOffset = 0;
    size_t m_releasedBefore = 0;
    SourceLocation m_at;
    bool m_firstLine = true;
    std::vector<Frame> m_frames;
    bool m_jumped = false;  // the block moved the read position (no RPT end check)

    DiagnosticList m_diagnostics;
    interp::RunStatus m_status = interp::RunStatus::Failed;
    uint64_t m_blocks = 0;
    bool m_started = false;
    bool m_endEmitted = false;
    bool m_resumeBlock = false;      // re-run the block after a sync
    bool m_syncedThisBlock = false;  // machine data is fresh for the block being re-run
    Pose m_world{};                  // the position the last sync reported
    // The G75/G76 block waiting for the machine's probe result.
    struct PendingProbe {
        int g = 75;
        SourceLocation at;
    };
    std::optional<PendingProbe> m_pendingProbe;
    std::optional<interp::ProgramStatus::Probe> m_lastProbe;  // for the status display
    int m_lastCycle = -1;  // the canned cycle executed last (G66-G89), for the status display
    int m_pendingInterrupt = 0;

    // Modal and machine state.
    ModalState m_modal;
    BlockFunctions m_functions;
    Pose m_position{};     // programmed end point of the last move (stream coordinates)
    Pose m_startOffset{};  // zero offset + PLC offset at the start (machine = stream + this)
    Pose m_offset{};       // the same now
    ZeroOffsetSelection m_selection;
    Vec2 m_polarOrigin{0.0, 0.0};  // in the program frame (abscissa, ordinate), part coordinates
    std::optional<Vec2> m_lastTangent;  // end tangent of the last element (program frame)
    double m_feed = 0.0;                // programmed F as written (active units)
    bool m_feedSet = false;
    canon::FeedMode m_streamFeedMode = canon::FeedMode::PerMinute;
    bool m_streamDiameter = true;
    ToolState m_tool;
    SpindleState m_spindle;
    ThreadState m_thread;
    WorkZones m_zones;
    Parameters m_parameters;
    canon::ControlLocks m_locks;
    int m_modalSubroutine = -1;  // MCALL
    // X10 N3 under MCALL: the repetitions left when that block runs again.
    FagorProgram* m_repeatProgram = nullptr;
    size_t m_repeatOffset = SIZE_MAX;
    int m_repeatCount = 0;
    LocalAssignments m_modalLocals;
    int m_modalProgram = -1;  // MEXEC
    OpenProgram m_open;
    // A dry run's writes (kerf check): read back by EXEC/CALL instead of the file left as it was.
    std::map<std::filesystem::path, std::string> m_unwritten;
    std::array<double, 4> m_analogOut{};
    double m_programFeedOverride = 0.0;
    double m_programSpindleOverride = 0.0;
    double m_timer = 0.0;
    double m_partCounter = 0.0;
    int m_keySource = 0;
    int m_key = 0;                 // KEY: the last key the user channel read
    bool m_askedOperator = false;  // the block being run again waited for a key or a number
    int m_probeInput = 1;
    int m_probeMode = 0;
    std::array<double, kAxisCount> m_secondUpperLimit{};
    std::array<double, kAxisCount> m_secondLowerLimit{};
    std::array<bool, 45> m_mActive{};  // MSn: which of M00-M44 is in effect
    std::chrono::steady_clock::time_point m_startTime = std::chrono::steady_clock::now();
    int64_t m_lastLabel = -1;  // BLKN
    Pose m_lastDelta{};        // displacement of the last feed move (FREAL of an axis)

    std::optional<ToolOffsetTable> m_toolOffsets;
    std::optional<ZeroOffsetTable> m_zeroOffsets;
    std::optional<ToolTable> m_toolTable;
    bool m_warnedNoOffsets = false;
};

}  // namespace kerf::fagor
