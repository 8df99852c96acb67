#pragma once

#include <cstdint>
#include <string_view>

#include "core/geometry/axes.h"

namespace kerf::fagor {

// The internal variables of spec part 2 §5, grouped as the manual groups them.
enum class VarFamily : uint8_t {
    Tool,
    ZeroOffset,
    MachineParameter,
    WorkZone,
    Feed,
    Position,
    Handwheel,
    Measurement,
    Spindle,
    Plc,
    Parameters,
    OperatingMode,
    Other,
};

// How the name is completed: nothing (TOOL), an axis letter (POSX), a number (TOX3), an axis and a
// number (ORGX 55), or GPOS's axis, block and program (GPOSX N99 P100).
enum class VarShape : uint8_t { Simple, Axis, Table, AxisTable, Gpos };

enum VarFlag : uint8_t {
    kRead = 1u << 0,         // readable from a part program
    kWrite = 1u << 1,        // writable from a part program
    kPrepStop = 1u << 2,     // reading it stops block preparation (spec part 2 §5.1)
    kMachineData = 1u << 3,  // its value comes from the running machine: the interpreter syncs
};

enum class VarId : uint8_t {
    // Tools
    Tool,
    Tod,
    NxTool,
    NxTod,
    Tmzp,
    Tlfd,
    Tlff,
    Tlfn,
    Tlfr,
    Tmzt,
    Htor,
    Tox,
    Toz,
    Tof,
    Tor,
    Toi,
    Tok,
    NoseA,
    NoseW,
    CutA,
    // Zero offsets
    Org,
    PorgF,
    PorgS,
    OrgTable,
    PlcOf,
    AdiOf,
    // Machine parameters
    Mpg,
    MpAxis,
    Mps,
    Mplc,
    // Work zones: zone n = (id - ZoneStatus1) / 3 ...
    Zone1,
    Zone1Lo,
    Zone1Up,
    Zone2,
    Zone2Lo,
    Zone2Up,
    Zone3,
    Zone3Lo,
    Zone3Up,
    Zone4,
    Zone4Lo,
    Zone4Up,
    Zone5,
    Zone5Lo,
    Zone5Up,
    // Feeds
    FReal,
    FRealAxis,
    FTeoAxis,
    Feed,
    DncF,
    PlcF,
    PrgF,
    FPrev,
    DncFpr,
    PlcFpr,
    PrgFpr,
    PrgFin,
    Fro,
    PrgFro,
    DncFro,
    PlcFro,
    CncFro,
    PlcCfr,
    // Positions
    PPos,
    Pos,
    TPos,
    APos,
    ATPos,
    Flwe,
    Dply,
    GPos,
    Dist,
    LimPl,
    LimMi,
    // Handwheels
    HanPf,
    HanPs,
    HanPt,
    HanPfo,
    HanDse,
    HanFct,
    HbeVar,
    MasLan,
    MasCfi,
    MasCse,
    // Measurement
    AsinAxis,
    BsinAxis,
    AsinS,
    BsinS,
    // Spindle
    SReal,
    FTeoS,
    Speed,
    DncS,
    PlcS,
    PrgS,
    Css,
    DncCss,
    PlcCss,
    PrgCss,
    Sso,
    PrgSso,
    DncSso,
    PlcSso,
    CncSso,
    SLimit,
    DncSsl,
    PlcSl,
    PrgSl,
    MdiSl,
    PosS,
    RPosS,
    TPosS,
    RTPosS,
    PrgSp,
    FlweS,
    // PLC
    PlcMsg,
    PlcI,
    PlcO,
    PlcM,
    PlcR,
    PlcT,
    PlcC,
    PlcMm,
    // Parameters
    CallP,
    Gup,
    Lup,
    // Operating mode
    OpMode,
    // Other
    NbTool,
    PrgN,
    BlkN,
    Gs,
    Ggsa,
    Ggsb,
    Ggsc,
    Ggsd,
    Ms,
    Gms,
    Plane,
    LongAx,
    Mirror,
    Scale,
    ScaleAxis,
    OrgRot,
    PrbSt,
    Clock,
    Time,
    Date,
    Timer,
    CyTime,
    PartC,
    First,
    Key,
    KeySrc,
    Ib,
    AnaI,
    AnaO,
    CncErr,
    PlcErr,
    DncErr,
    DncSta,
    TimeG,
    SelPro,
    Diam,
    PrbMod,
    Rip,
};

struct VariableInfo {
    std::string_view name;  // as programmed, without the axis letter or number
    VarId id;
    VarShape shape;
    VarFamily family;
    uint8_t flags;
};

// A variable as a block names it.
struct VariableRef {
    const VariableInfo* info = nullptr;
    Axis axis = Axis::X;
    int index = 0;    // table element, zone, machine parameter, GPOS block label
    int program = 0;  // GPOS program number
};

// The variable named exactly `name` with this shape (aliases of appendix C included).
const VariableInfo* findVariable(std::string_view name, VarShape shape);

}  // namespace kerf::fagor
