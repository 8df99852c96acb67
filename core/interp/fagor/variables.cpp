#include "core/interp/fagor/variables.h"

#include <unordered_map>

namespace kerf::fagor {

namespace {

constexpr uint8_t R = kRead;
constexpr uint8_t RW = kRead | kWrite;
constexpr uint8_t P = kPrepStop;
constexpr uint8_t MD = kMachineData | kPrepStop;
constexpr uint8_t NONE = 0;  // not accessible from a part program (PLC or DNC only)

using S = VarShape;
using F = VarFamily;
using I = VarId;

// Access from the CNC column of appendix C (spec part 2 §5).
constexpr VariableInfo kVariables[] = {
    {"TOOL", I::Tool, S::Simple, F::Tool, R},
    {"TOD", I::Tod, S::Simple, F::Tool, R},
    {"NXTOOL", I::NxTool, S::Simple, F::Tool, R},
    {"NXTOD", I::NxTod, S::Simple, F::Tool, R},
    {"TMZP", I::Tmzp, S::Table, F::Tool, R},
    {"TLFD", I::Tlfd, S::Table, F::Tool, RW},
    {"TLFF", I::Tlff, S::Table, F::Tool, RW},
    {"TLFN", I::Tlfn, S::Table, F::Tool, RW},
    {"TLFR", I::Tlfr, S::Table, F::Tool, RW},
    {"TMZT", I::Tmzt, S::Table, F::Tool, RW},
    {"HTOR", I::Htor, S::Simple, F::Tool, RW},
    {"TOX", I::Tox, S::Table, F::Tool, RW},
    {"TOZ", I::Toz, S::Table, F::Tool, RW},
    {"TOF", I::Tof, S::Table, F::Tool, RW},
    {"TOR", I::Tor, S::Table, F::Tool, RW},
    {"TOI", I::Toi, S::Table, F::Tool, RW},
    {"TOK", I::Tok, S::Table, F::Tool, RW},
    {"NOSEA", I::NoseA, S::Table, F::Tool, RW},
    {"NOSEW", I::NoseW, S::Table, F::Tool, RW},
    {"CUTA", I::CutA, S::Table, F::Tool, RW},

    {"ORG", I::Org, S::Axis, F::ZeroOffset, R},
    {"PORGF", I::PorgF, S::Simple, F::ZeroOffset, R},
    {"PORGS", I::PorgS, S::Simple, F::ZeroOffset, R},
    {"ORG", I::OrgTable, S::AxisTable, F::ZeroOffset, RW},
    {"PLCOF", I::PlcOf, S::Axis, F::ZeroOffset, RW | P},
    {"ADIOF", I::AdiOf, S::Axis, F::ZeroOffset, R},

    {"MPG", I::Mpg, S::Table, F::MachineParameter, R},
    {"MP", I::MpAxis, S::AxisTable, F::MachineParameter, R},
    {"MPS", I::Mps, S::Table, F::MachineParameter, R},
    {"MPLC", I::Mplc, S::Table, F::MachineParameter, R},

    {"FZONE", I::Zone1, S::Simple, F::WorkZone, R},
    {"FZLO", I::Zone1Lo, S::Axis, F::WorkZone, R},
    {"FZUP", I::Zone1Up, S::Axis, F::WorkZone, R},
    {"SZONE", I::Zone2, S::Simple, F::WorkZone, R},
    {"SZLO", I::Zone2Lo, S::Axis, F::WorkZone, R},
    {"SZUP", I::Zone2Up, S::Axis, F::WorkZone, R},
    {"TZONE", I::Zone3, S::Simple, F::WorkZone, R},
    {"TZLO", I::Zone3Lo, S::Axis, F::WorkZone, R},
    {"TZUP", I::Zone3Up, S::Axis, F::WorkZone, R},
    {"FOZONE", I::Zone4, S::Simple, F::WorkZone, R},
    {"FOZLO", I::Zone4Lo, S::Axis, F::WorkZone, R},
    {"FOZUP", I::Zone4Up, S::Axis, F::WorkZone, R},
    {"FIZONE", I::Zone5, S::Simple, F::WorkZone, R},
    {"FIZLO", I::Zone5Lo, S::Axis, F::WorkZone, R},
    {"FIZUP", I::Zone5Up, S::Axis, F::WorkZone, R},

    {"FREAL", I::FReal, S::Simple, F::Feed, R},
    {"FREAL", I::FRealAxis, S::Axis, F::Feed, R},
    {"FTEO", I::FTeoAxis, S::Axis, F::Feed, R},
    {"FEED", I::Feed, S::Simple, F::Feed, R},
    {"DNCF", I::DncF, S::Simple, F::Feed, R},
    {"PLCF", I::PlcF, S::Simple, F::Feed, R},
    {"PRGF", I::PrgF, S::Simple, F::Feed, R},
    {"FPREV", I::FPrev, S::Simple, F::Feed, R},
    {"DNCFPR", I::DncFpr, S::Simple, F::Feed, R},
    {"PLCFPR", I::PlcFpr, S::Simple, F::Feed, R},
    {"PRGFPR", I::PrgFpr, S::Simple, F::Feed, R},
    {"PRGFIN", I::PrgFin, S::Simple, F::Feed, R},
    {"FRO", I::Fro, S::Simple, F::Feed, R},
    {"PRGFRO", I::PrgFro, S::Simple, F::Feed, RW},
    {"DNCFRO", I::DncFro, S::Simple, F::Feed, R},
    {"PLCFRO", I::PlcFro, S::Simple, F::Feed, R},
    {"CNCFRO", I::CncFro, S::Simple, F::Feed, R},
    {"PLCCFR", I::PlcCfr, S::Simple, F::Feed, R},

    {"PPOS", I::PPos, S::Axis, F::Position, R},
    {"POS", I::Pos, S::Axis, F::Position, R | MD},
    {"TPOS", I::TPos, S::Axis, F::Position, R | MD},
    {"APOS", I::APos, S::Axis, F::Position, R | MD},
    {"ATPOS", I::ATPos, S::Axis, F::Position, R | MD},
    {"FLWE", I::Flwe, S::Axis, F::Position, R | P},
    {"DPLY", I::Dply, S::Axis, F::Position, R},
    {"GPOS", I::GPos, S::Gpos, F::Position, R},
    {"DIST", I::Dist, S::Axis, F::Position, RW | P},
    {"LIMPL", I::LimPl, S::Axis, F::Position, RW},
    {"LIMMI", I::LimMi, S::Axis, F::Position, RW},

    {"HANPF", I::HanPf, S::Simple, F::Handwheel, R},
    {"HANPS", I::HanPs, S::Simple, F::Handwheel, R},
    {"HANPT", I::HanPt, S::Simple, F::Handwheel, R},
    {"HANPFO", I::HanPfo, S::Simple, F::Handwheel, R},
    {"HANDSE", I::HanDse, S::Simple, F::Handwheel, R},
    {"HANFCT", I::HanFct, S::Simple, F::Handwheel, R},
    {"HBEVAR", I::HbeVar, S::Simple, F::Handwheel, R},
    {"MASLAN", I::MasLan, S::Simple, F::Handwheel, RW},
    {"MASCFI", I::MasCfi, S::Simple, F::Handwheel, RW},
    {"MASCSE", I::MasCse, S::Simple, F::Handwheel, RW},

    {"ASIN", I::AsinAxis, S::Axis, F::Measurement, R},
    {"BSIN", I::BsinAxis, S::Axis, F::Measurement, R},
    {"ASINS", I::AsinS, S::Simple, F::Measurement, R},
    {"BSINS", I::BsinS, S::Simple, F::Measurement, R},

    {"SREAL", I::SReal, S::Simple, F::Spindle, R | P},
    {"FTEOS", I::FTeoS, S::Simple, F::Spindle, R},
    {"SPEED", I::Speed, S::Simple, F::Spindle, R},
    {"DNCS", I::DncS, S::Simple, F::Spindle, R},
    {"PLCS", I::PlcS, S::Simple, F::Spindle, R},
    {"PRGS", I::PrgS, S::Simple, F::Spindle, R},
    {"CSS", I::Css, S::Simple, F::Spindle, R},
    {"DNCCSS", I::DncCss, S::Simple, F::Spindle, R},
    {"PLCCSS", I::PlcCss, S::Simple, F::Spindle, R},
    {"PRGCSS", I::PrgCss, S::Simple, F::Spindle, R},
    {"SSO", I::Sso, S::Simple, F::Spindle, R},
    {"PRGSSO", I::PrgSso, S::Simple, F::Spindle, RW},
    {"DNCSSO", I::DncSso, S::Simple, F::Spindle, R},
    {"DNCSO", I::DncSso, S::Simple, F::Spindle, R},
    {"PLCSSO", I::PlcSso, S::Simple, F::Spindle, R},
    {"CNCSSO", I::CncSso, S::Simple, F::Spindle, R},
    {"CNCSO", I::CncSso, S::Simple, F::Spindle, R},
    {"SLIMIT", I::SLimit, S::Simple, F::Spindle, R},
    {"DNCSSL", I::DncSsl, S::Simple, F::Spindle, R},
    {"DNCSL", I::DncSsl, S::Simple, F::Spindle, R},
    {"PLCSL", I::PlcSl, S::Simple, F::Spindle, R},
    {"PRGSL", I::PrgSl, S::Simple, F::Spindle, R},
    {"MDISL", I::MdiSl, S::Simple, F::Spindle, R},
    {"POSS", I::PosS, S::Simple, F::Spindle, R | P},
    {"RPOSS", I::RPosS, S::Simple, F::Spindle, R | P},
    {"TPOSS", I::TPosS, S::Simple, F::Spindle, R | P},
    {"RTPOSS", I::RTPosS, S::Simple, F::Spindle, R | P},
    {"PRGSP", I::PrgSp, S::Simple, F::Spindle, R},
    {"FLWES", I::FlweS, S::Simple, F::Spindle, R | P},

    {"PLCMSG", I::PlcMsg, S::Simple, F::Plc, R | P},
    {"PLCMMSG", I::PlcMsg, S::Simple, F::Plc, R | P},
    {"PLCI", I::PlcI, S::Table, F::Plc, RW | P},
    {"PLCO", I::PlcO, S::Table, F::Plc, RW | P},
    {"PLCM", I::PlcM, S::Table, F::Plc, RW | P},
    {"PLCR", I::PlcR, S::Table, F::Plc, RW | P},
    {"PLCT", I::PlcT, S::Table, F::Plc, RW | P},
    {"PLCC", I::PlcC, S::Table, F::Plc, RW | P},
    {"PLCMM", I::PlcMm, S::Table, F::Plc, RW | P},

    {"CALLP", I::CallP, S::Simple, F::Parameters, R},
    {"GUP", I::Gup, S::Table, F::Parameters, NONE},
    {"LUP", I::Lup, S::Table, F::Parameters, NONE},

    {"OPMODE", I::OpMode, S::Simple, F::OperatingMode, R},

    {"NBTOOL", I::NbTool, S::Simple, F::Other, R},
    {"PRGN", I::PrgN, S::Simple, F::Other, R},
    {"BLKN", I::BlkN, S::Simple, F::Other, R},
    {"GS", I::Gs, S::Table, F::Other, R},
    {"GGSA", I::Ggsa, S::Simple, F::Other, NONE},
    {"GGSB", I::Ggsb, S::Simple, F::Other, NONE},
    {"GGSC", I::Ggsc, S::Simple, F::Other, NONE},
    {"GGSD", I::Ggsd, S::Simple, F::Other, NONE},
    {"MS", I::Ms, S::Table, F::Other, R},
    {"GMS", I::Gms, S::Simple, F::Other, NONE},
    {"PLANE", I::Plane, S::Simple, F::Other, R},
    {"LONGAX", I::LongAx, S::Simple, F::Other, R},
    {"MIRROR", I::Mirror, S::Simple, F::Other, R},
    {"SCALE", I::Scale, S::Simple, F::Other, R},
    {"SCALE", I::ScaleAxis, S::Axis, F::Other, R},
    {"ORGROT", I::OrgRot, S::Simple, F::Other, R},
    {"PRBST", I::PrbSt, S::Simple, F::Other, R | P},
    {"CLOCK", I::Clock, S::Simple, F::Other, R | P},
    {"TIME", I::Time, S::Simple, F::Other, R | P},
    {"DATE", I::Date, S::Simple, F::Other, R | P},
    {"TIMER", I::Timer, S::Simple, F::Other, RW | P},
    {"CYTIME", I::CyTime, S::Simple, F::Other, R | P},
    {"PARTC", I::PartC, S::Simple, F::Other, RW | P},
    {"FIRST", I::First, S::Simple, F::Other, R},
    {"KEY", I::Key, S::Simple, F::Other, RW | P},
    {"KEYSRC", I::KeySrc, S::Simple, F::Other, RW},
    {"IB", I::Ib, S::Table, F::Other, R},
    {"ANAI", I::AnaI, S::Table, F::Other, R | P},
    {"ANAO", I::AnaO, S::Table, F::Other, RW | P},
    {"CNCERR", I::CncErr, S::Simple, F::Other, NONE},
    {"PLCERR", I::PlcErr, S::Simple, F::Other, NONE},
    {"DNCERR", I::DncErr, S::Simple, F::Other, NONE},
    {"DNCSTA", I::DncSta, S::Simple, F::Other, NONE},
    {"TIMEG", I::TimeG, S::Simple, F::Other, R},
    {"SELPRO", I::SelPro, S::Simple, F::Other, RW | P},
    {"DIAM", I::Diam, S::Simple, F::Other, RW},
    {"PRBMOD", I::PrbMod, S::Simple, F::Other, RW},
    {"RIP", I::Rip, S::Simple, F::Other, R},
};

}  // namespace

const VariableInfo* findVariable(std::string_view name, VarShape shape) {
    // Asked for every word of every expression, mostly for names that are none (P1, a label):
    // a hash lookup instead of comparing with every entry made an endless GOTO loop take a
    // minute to reach the default block guard.
    static const std::unordered_multimap<std::string_view, const VariableInfo*> byName = [] {
        std::unordered_multimap<std::string_view, const VariableInfo*> index;
        for (const VariableInfo& v : kVariables)
            index.emplace(v.name, &v);
        return index;
    }();
    auto [first, last] = byName.equal_range(name);
    for (; first != last; ++first) {
        if (first->second->shape == shape) return first->second;
    }
    return nullptr;
}

}  // namespace kerf::fagor
