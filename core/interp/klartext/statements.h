#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/cycles/cycle_word.h"
#include "core/cycles/pattern/pattern_definition.h"
#include "core/geometry/axes.h"
#include "core/geometry/fk/fk_element.h"
#include "core/interp/klartext/q_parameters.h"

// One conversational block after parsing. Values are already evaluated (Q parameters read when the
// block is parsed for execution; 0 when it is parsed only to check syntax).
namespace kerf::klartext {

struct AxisWord {
    bool present = false;
    bool incremental = false;
    double value = 0.0;
};

struct Coordinates {
    std::array<AxisWord, kAxisCount> axes{};
    AxisMask present = 0;
    bool has(Axis a) const { return (present & axisBit(a)) != 0; }
    const AxisWord& operator[](Axis a) const { return axes[static_cast<size_t>(a)]; }
};

struct PolarWords {
    std::optional<double> radius;  // PR
    bool radiusIncremental = false;
    std::optional<double> angle;  // PA
    bool angleIncremental = false;
};

enum class CompWord : uint8_t { None, Off, Left, Right };  // (absent), R0, RL, RR

struct FeedWord {
    enum class Kind : uint8_t { None, Value, Max, Auto, PerRevolution, PerTooth };
    Kind kind = Kind::None;
    double value = 0.0;
};

struct MWord {
    int number = 0;
    std::optional<double> parameter;  // M140 MB value, M120 LA block count
    bool maxParameter = false;        // M140 MB MAX
    AxisMask axes = 0;                // M94 C: the rotary axes it reduces (0: all)
};

struct MWords {
    std::array<MWord, 6> list{};
    uint8_t count = 0;
};

enum class Direction : uint8_t { None, Ccw, Cw };  // DR+ / DR-

struct CommonWords {
    CompWord comp = CompWord::None;
    FeedWord feed;
    MWords m;
};

struct Empty {};  // blank line, ';' comment or '*' structure block

struct BeginPgm {
    std::string name;
    bool inch = false;
};
struct EndPgm {
    std::string name;
    bool inch = false;
};

struct BlkForm {
    enum class Kind : uint8_t { MinPoint, MaxPoint, Cylinder };
    Kind kind = Kind::MinPoint;
    Axis toolAxis = Axis::Z;
    Coordinates point;
    double radius = 0.0, innerRadius = 0.0, length = 0.0, distance = 0.0;
};

struct ToolCall {
    std::optional<int> number;
    std::optional<std::string> name;
    std::optional<Axis> axis;
    std::optional<double> speed;
    std::optional<double> feed;
    std::optional<double> dl, dr, dr2;
};

struct ToolDef {
    std::optional<int> number;
    std::optional<std::string> name;
    std::optional<double> length, radius;  // old programs define the tool in the program
};

struct LinearBlock {  // L
    Coordinates coords;
    CommonWords words;
};
// LN (klartext_line_normal.cpp): a straight line with 3D tool compensation. NX NY NZ: the
// surface normal at the programmed point; TX TY TZ (optional, with TCPM): the tool's direction.
struct LineNormalBlock {
    Coordinates coords;
    CommonWords words;
    Vec3 normal{0.0, 0.0, 1.0};
    std::optional<Vec3> tool;
};
struct CircleCenter {  // CC
    Coordinates coords;
};
struct CircleBlock {  // C
    Coordinates coords;
    Direction direction = Direction::None;
    CommonWords words;
};
struct CircleRadiusBlock {  // CR
    Coordinates coords;
    double radius = 0.0;
    Direction direction = Direction::None;
    CommonWords words;
};
struct CircleTangentBlock {  // CT
    Coordinates coords;
    CommonWords words;
};
struct RoundBlock {  // RND
    double radius = 0.0;
    FeedWord feed;
};
struct ChamferBlock {  // CHF
    double length = 0.0;
    FeedWord feed;
};
struct LinePolarBlock {  // LP
    PolarWords polar;
    Coordinates coords;  // tool-axis coordinate
    CommonWords words;
};
struct CirclePolarBlock {  // CP
    PolarWords polar;
    Coordinates coords;  // helix: tool-axis coordinate
    Direction direction = Direction::None;
    CommonWords words;
};
struct CircleTangentPolarBlock {  // CTP
    PolarWords polar;
    Coordinates coords;
    CommonWords words;
};

enum class ApproachKind : uint8_t { LT, LN, CT, LCT };

struct ApproachBlock {  // APPR / DEP
    bool depart = false;
    ApproachKind kind = ApproachKind::LT;
    bool polar = false;
    Coordinates coords;
    PolarWords polarWords;
    std::optional<double> length;  // LEN
    std::optional<double> angle;   // CCA
    std::optional<double> radius;  // R
    CommonWords words;
};

struct LabelTarget {
    std::optional<int> number;
    std::optional<std::string> name;
    std::optional<uint16_t> stringParameter;  // CALL LBL QS5: the name is QS5's value
};

struct Label {
    LabelTarget target;
};
struct CallLabel {
    LabelTarget target;
    int repeat = 0;  // REP
};
struct CallPgm {
    std::string path;
};
struct SelectProgram {  // SEL PGM "name" / SEL PGM QSn, called later by CALL SELECTED PGM
    std::string path;
    bool fromParameter = false;  // QSn: the name is known only when the block runs
};
struct CallSelectedProgram {};
struct StopBlock {
    MWords m;
};
struct MFunctionBlock {  // "M3 M8" or "L M6"-style blocks without motion
    CommonWords words;
};

struct QAssign {
    QRef target;
    double value = 0.0;
};
struct QStringAssign {
    uint16_t index = 0;
    std::string value;
};

enum class Comparison : uint8_t { Equal, NotEqual, Greater, Less };

struct ConditionalJump {  // FN 9..12
    Comparison comparison = Comparison::Equal;
    double left = 0.0;
    double right = 0.0;
    LabelTarget target;
};
struct ErrorBlock {  // FN 14
    int number = 0;
};
struct PrintBlock {  // FN 15 (values) / FN 16 (format file to output file)
    bool formatted = false;
    std::vector<double> values;
    std::string text;
    std::string maskFile;
    std::string outputFile;
};
struct SysRead {  // FN 18
    QRef target;
    int id = 0;
    int nr = 0;
    int idx = 0;
    bool hasIdx = false;
};
struct CircleData {  // FN 23 / FN 24
    int points = 3;
    QRef target;
    QRef source;
};
struct TableOpen {  // FN 26
    std::string path;
};
struct TableAccess {  // FN 27 / FN 28
    bool write = false;
    int row = 0;
    std::string columns;  // as written: "X,Y,Z"
    size_t columnCount = 0;
    QRef parameter;  // first parameter written or read
};

// FK free contour programming: FL, FLT, FC, FCT (solved by core/geometry/fk), FPOL, FSELECT.
// Coordinates are kept by axis (X, Y, Z): the interpreter puts the working plane's two into the
// element (first and second axis of the plane), so FK works in every plane.
struct FkBlock {
    fk::FkElement element;  // the data other than coordinates
    std::array<std::optional<fk::FkValue>, 3> end, centre, pointAtDistance;  // X Y, CCX, PDX ...
    std::array<std::array<std::optional<double>, 3>, 3> pointsOn{};          // P1X ... P3Z
    CommonWords words;
};
struct FkPole {
    std::array<std::optional<double>, 3> coords;  // X, Y, Z: two of them
};
struct FkSelect {
    int choice = 1;
};

// PLANE: the tilted working plane (block_parser_plane.cpp, klartext_plane.cpp).
struct PlaneBlock {
    enum class Kind : uint8_t { Spatial, Projected, Euler, Vector, Points, Relative, Axial, Reset };
    enum class Positioning : uint8_t { Stay, Turn, Move };
    enum class Sequence : uint8_t { Shortest, Positive, Negative };  // (none), SEQ+, SEQ-
    Kind kind = Kind::Reset;
    // The numbers in the order written: SPA SPB SPC, PROPR PROMIN ROT, EULPR EULNU EULROT,
    // BX BY BZ NX NY NZ, P1X ... P3Z; RELATIV: the angle and `relativeAxis` (0 SPA, 1 SPB, 2 SPC);
    // AXIAL: A B C with `axialPresent`.
    std::array<double, 9> values{};
    int relativeAxis = 0;
    std::array<bool, 3> axialPresent{};
    Positioning positioning = Positioning::Stay;
    double distance = 0.0;          // MOVE DIST: tool tip to the point kept during tilting
    FeedWord feed;                  // F or FMAX of the rotary positioning
    std::optional<double> retract;  // MB: retract along the tool axis before tilting
    bool retractMax = false;        // MB MAX
    Sequence sequence = Sequence::Shortest;
    bool tableRotation = false;  // TABLE ROT (else COORD ROT)
};

// FUNCTION TCPM ... / FUNCTION RESET TCPM (block_parser_plane.cpp): programmed positions are
// tool-tip positions on the part while the rotary axes move (as M128 / M129). The options:
// F CONT (F is the axes' contouring feed, not the tip's), AXIS SPAT (A, B, C in the blocks are
// spatial angles of the tool in the working plane, not axis positions), PATHCTRL VECTOR (the
// tool's direction turns in the plane of its start and end directions).
struct TcpmBlock {
    bool on = false;
    bool feedContour = false;
    bool spatialAngles = false;
    bool vectorPath = false;
};

// FN 20: WAIT FOR SYNC: the interpreter waits for the machine before it reads on.
struct WaitForSync {};

// Blocks that parse and are kept but that this release does not execute yet (fixed cycles,
// patterns, probing, FK, PLANE ...). `feature` names them in the diagnostic.
struct Deferred {
    std::string feature;
    std::string text;
};

// CYCL DEF, kept with its parameters for the cycle framework.
struct CycleParameter {
    uint16_t q = 0;
    bool isString = false;
    std::string raw;  // value text as written ("+5", "PREDEF", "FAUTO", "Q1")
    std::optional<double> value;
    std::optional<double> actual;  // "nominal@actual" (14xx nominal positions): the actual
    size_t actualOffset = 0;       // where its '@' (or its '?') is in the block text
    bool unknown = false;          // "?" (14xx nominal positions): semi-automatic mode
    std::string comment;
    size_t offset = 0;     // where "Qnnn=" starts in the block text
    bool literal = false;  // `value` uses no Q parameter: known before the run
};
struct CycleDefinition {
    int number = 0;
    int subNumber = -1;        // old-style "7.1" blocks; -1 for parameter-list cycles
    std::string name;          // language-dependent text after the number
    std::string rest;          // old style: the text after "n.m "
    cycles::CycleWords words;  // old style: `rest` as evaluated words (not for 12.1 PGM ...)
    std::vector<CycleParameter> parameters;
    bool probe = false;  // TCH PROBE n: a touch-probe cycle (numbered apart from CYCL DEF)
};
// GLOBAL DEF nnn with its parameter lines.
struct GlobalDefinition {
    int group = 0;
    std::vector<CycleParameter> parameters;
};
struct PatternDefinition {
    std::vector<cycles::PatternElement> elements;
};
struct SelectTable {  // SEL TABLE "datum table"
    std::string path;
};
struct SelectPattern {  // SEL PATTERN "point table"
    std::string path;
};
// Contour formula (spec §8): SEL CONTOUR "definition program", DECLARE CONTOUR QC1 = "program"
// DEPTH5, QC10 = (QC1 | QC2) \ QC3, and the simple CONTOUR DEF P1 = "..." I2 = LBL 2 DEPTH5.
struct SelectContour {
    std::string path;
};
struct DeclareContour {
    int descriptor = 0;
    std::string path;
    double depth = 0.0;  // 0: cycle 20's depth
    bool hasDepth = false;
};
struct ContourFormulaStep {  // postfix: descriptors and the operators & | ^ \ (left to right)
    enum class Kind : uint8_t { Descriptor, Union, Intersection, Difference, SymmetricDifference };
    Kind kind = Kind::Descriptor;
    int descriptor = 0;
    size_t offset = 0;  // in the block text, for errors
};
struct ContourFormula {
    int target = 0;
    std::vector<ContourFormulaStep> steps;
};
struct ContourDefinition {
    struct Item {
        bool island = false;
        int number = 0;
        std::string path;                  // P1 = "program"
        std::optional<LabelTarget> label;  // P1 = LBL 1 / LBL "name": a label of this program
        size_t offset = 0;                 // of the label in the block text, for errors
        double depth = 0.0;
    };
    std::vector<Item> items;
};
struct CycleCall {
    enum class Kind : uint8_t { Plain, Pattern, Position };
    Kind kind = Kind::Plain;
    Coordinates coords;
    CommonWords words;
};

using Statement =
    std::variant<Empty, BeginPgm, EndPgm, BlkForm, ToolCall, ToolDef, LinearBlock, LineNormalBlock,
                 CircleCenter, CircleBlock, CircleRadiusBlock, CircleTangentBlock, RoundBlock,
                 ChamferBlock, LinePolarBlock, CirclePolarBlock, CircleTangentPolarBlock,
                 ApproachBlock, Label, CallLabel, CallPgm, SelectProgram, CallSelectedProgram,
                 StopBlock, MFunctionBlock, QAssign, QStringAssign, ConditionalJump, ErrorBlock,
                 PrintBlock, SysRead, CircleData, TableOpen, TableAccess, CycleDefinition,
                 GlobalDefinition, PatternDefinition, SelectTable, SelectPattern, SelectContour,
                 DeclareContour, ContourFormula, ContourDefinition, CycleCall, FkBlock, FkPole,
                 FkSelect, PlaneBlock, TcpmBlock, WaitForSync, Deferred>;

struct ParsedBlock {
    Statement statement;
    // Statements that follow in the same block: one DIN/ISO block can be several conversational
    // ones ("G54 X+10" is CYCL DEF 7.0 and 7.1). Always empty for conversational text.
    std::vector<Statement> more;
    int64_t blockNumber = -1;
    bool hidden = false;  // '/' block skip
};

}  // namespace kerf::klartext
