#include "core/canon/trace_format.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

#include "core/base/fixed_format.h"
#include "core/geometry/arc_math.h"

namespace kerf::canon {

namespace {

constexpr int kLengthDecimals = 4;
constexpr int kFeedDecimals = 3;

// A line gathered on the stack and handed to the string in one append (one per line unless a
// quoted text is long): std::string's per-character checks cost more than the formatting.
class LineWriter {
public:
    explicit LineWriter(std::string& out) : m_out(out) {}
    ~LineWriter() { spill(); }
    LineWriter(const LineWriter&) = delete;
    LineWriter& operator=(const LineWriter&) = delete;

    LineWriter& operator+=(char c) {
        room(1);
        *m_end++ = c;
        return *this;
    }
    LineWriter& operator+=(std::string_view text) {
        if (text.size() > kSize / 2) {
            spill();
            m_out.append(text);
            return *this;
        }
        room(text.size());
        std::memcpy(m_end, text.data(), text.size());
        m_end += text.size();
        return *this;
    }
    void fixed(double value, int decimals) {
        room(kMaxFixedChars);
        m_end = writeFixed(m_end, value, decimals);
    }
    void integer(int64_t value) {
        room(kMaxIntegerChars);
        m_end = std::to_chars(m_end, m_end + kMaxIntegerChars, value).ptr;
    }

private:
    static constexpr size_t kSize = 1024;
    static constexpr size_t kMaxIntegerChars = 20;
    void room(size_t chars) {
        if (static_cast<size_t>(m_buffer + kSize - m_end) < chars) spill();
    }
    void spill() {
        m_out.append(m_buffer, m_end);
        m_end = m_buffer;
    }
    std::string& m_out;
    char m_buffer[kSize];
    char* m_end = m_buffer;
};

void appendPose(LineWriter& out, const Pose& pose, AxisMask axes) {
    for (int i = 0; i < kAxisCount; ++i) {
        auto axis = static_cast<Axis>(i);
        if ((axes & axisBit(axis)) == 0) continue;
        out += ' ';
        out += axisLetter(axis);
        out.fixed(pose[axis], kLengthDecimals);
    }
}

void appendWord(LineWriter& out, std::string_view word, double value, int decimals) {
    out += ' ';
    out += word;
    out.fixed(value, decimals);
}

void appendQuoted(LineWriter& out, const std::string& text) {
    out += '"';
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            out += c;
        }
    }
    out += '"';
}

const char* spindleName(SpindleDirection direction) {
    switch (direction) {
        case SpindleDirection::Clockwise:
            return "CW";
        case SpindleDirection::CounterClockwise:
            return "CCW";
        case SpindleDirection::Stopped:
            break;
    }
    return "STOP";
}

const char* messageKindName(MessageKind kind) {
    switch (kind) {
        case MessageKind::Print:
            return "PRINT";
        case MessageKind::Error:
            return "ERROR";
        case MessageKind::Info:
            break;
    }
    return "INFO";
}

const char* syncName(SyncReason reason) {
    switch (reason) {
        case SyncReason::ProbeResult:
            return "PROBE";
        case SyncReason::Inputs:
            return "INPUTS";
        case SyncReason::Operator:
            return "OPERATOR";
        case SyncReason::ReadPosition:
            break;
    }
    return "POSITION";
}

void appendGeometry(LineWriter& out, const ToolGeometry& g, Axis toolAxis) {
    appendWord(out, "L=", g.lengthMm, kLengthDecimals);
    appendWord(out, "R=", g.radiusMm, kLengthDecimals);
    const bool lathe = g.locationCode >= 0;
    if (!lathe) appendWord(out, "R2=", g.radius2Mm, kLengthDecimals);  // a mill cutter's only
    out += " AXIS ";
    out += axisLetter(toolAxis);
    if (lathe) {
        out += " D";
        out.integer(g.offsetNumber);
        appendWord(out, "TIPX=", g.tipXMm, kLengthDecimals);
        appendWord(out, "TIPZ=", g.tipZMm, kLengthDecimals);
        out += " LOC ";
        out.integer(g.locationCode);
        if (g.cuttingWidthMm > 0.0) appendWord(out, "W=", g.cuttingWidthMm, kLengthDecimals);
        if (g.noseAngleDeg > 0.0) appendWord(out, "NOSEA=", g.noseAngleDeg, kLengthDecimals);
    }
}

struct BodyPrinter {
    LineWriter& out;
    AxisMask axes;

    void operator()(const RapidMove& m) {
        out += "RAPID";
        appendPose(out, m.target, axes);
    }
    void operator()(const LinearMove& m) {
        out += "LINE";
        appendPose(out, m.target, axes);
        appendWord(out, "F", m.feed, kFeedDecimals);
    }
    void operator()(const ArcMove& m) {
        out += "ARC";
        appendPose(out, m.target, axes);
        PlaneAxes plane = planeAxes(m.plane);
        out += " CENTER ";
        out += axisLetter(plane.first);
        out.fixed(m.center[axisIndex(plane.first)], kLengthDecimals);
        out += ' ';
        out += axisLetter(plane.second);
        out.fixed(m.center[axisIndex(plane.second)], kLengthDecimals);
        out += " PLANE ";
        out += planeName(m.plane);
        appendWord(out, "SWEEP ", radToDeg(m.sweepRad), kLengthDecimals);
        appendWord(out, "F", m.feed, kFeedDecimals);
    }
    void operator()(const SpindleSyncedMove& m) {
        out += "SYNCMOVE";
        appendPose(out, m.target, axes);
        appendWord(out, "LEAD ", m.leadMmPerRev, kLengthDecimals);
        appendWord(out, "ANGLE ", m.startAngleDeg, kLengthDecimals);
        if (m.leadChangeMmPerRev != 0.0) {
            appendWord(out, "LEADCHANGE ", m.leadChangeMmPerRev, kLengthDecimals);
        }
    }
    void operator()(const ThreadRetraction& m) {
        out += "THREADRETRACT";
        if (m.axes == 0) {
            out += " OFF";
        } else {
            appendPose(out, m.distance, m.axes);
        }
    }
    void operator()(const ControlLocks& m) {
        out += "LOCKS";
        if (!m.joinBlocks && !m.stopDisabled && !m.feedHoldDisabled) out += " NONE";
        if (m.joinBlocks) out += " JOIN-BLOCKS";
        if (m.stopDisabled) out += " STOP-DISABLED";
        if (m.feedHoldDisabled) out += " FEEDHOLD-DISABLED";
    }
    void operator()(const DiameterMode& m) {
        out += m.xInDiameter ? "XMODE DIAMETER" : "XMODE RADIUS";
    }
    void operator()(const Dwell& m) {
        out += "DWELL";
        appendWord(out, "", m.seconds, kFeedDecimals);
    }
    void operator()(const SpindleControl& m) {
        out += "SPINDLE ";
        out += spindleName(m.direction);
        appendWord(out, "S", m.speedRpm, kFeedDecimals);
        if (m.surfaceSpeedMPerMin > 0.0) {
            appendWord(out, "CSS ", m.surfaceSpeedMPerMin, kFeedDecimals);
            appendWord(out, "MAX ", m.maxRpm, kFeedDecimals);
        }
    }
    void operator()(const SpindleOrient& m) {
        out += "ORIENT";
        appendWord(out, "", m.angleDeg, kLengthDecimals);
    }
    void operator()(const CoolantControl& m) {
        out += "COOLANT ";
        if (m.flood && m.mist) {
            out += "FLOOD+MIST";
        } else if (m.flood) {
            out += "FLOOD";
        } else if (m.mist) {
            out += "MIST";
        } else {
            out += "OFF";
        }
    }
    void operator()(const ToolChange& m) {
        out += "TOOL T";
        out.integer(m.number);
        if (!m.name.empty()) {
            out += ' ';
            appendQuoted(out, m.name);
        }
        appendGeometry(out, m.geometry, m.toolAxis);
    }
    void operator()(const ToolUpdate& m) {
        out += "TOOLDATA";
        appendGeometry(out, m.geometry, m.toolAxis);
    }
    void operator()(const SetFeedMode& m) {
        out += m.mode == FeedMode::PerRevolution ? "FEEDMODE PER-REV" : "FEEDMODE PER-MIN";
    }
    void operator()(const ProbeMove& m) {
        out += "PROBE";
        appendPose(out, m.target, axes);
        appendWord(out, "F", m.feed, kFeedDecimals);
        if (m.untilRelease) out += " UNTIL-RELEASE";
    }
    void operator()(const SyncPoint& m) {
        out += "SYNC ";
        out += syncName(m.reason);
    }
    void operator()(const Message& m) {
        out += "MSG ";
        out += messageKindName(m.kind);
        out += ' ';
        appendQuoted(out, m.text);
    }
    void operator()(const ProgramStop& m) {
        switch (m.kind) {
            case StopKind::Program:
                out += "STOP";
                break;
            case StopKind::Optional:
                out += "OPTIONAL-STOP";
                break;
            case StopKind::End:
                out += "END";
                break;
        }
        if (m.mCode >= 0) {
            out += " M";
            out.integer(m.mCode);
        }
    }
    void operator()(const MachineFunction& m) {
        out += "MFUNC M";
        out.integer(m.number);
    }
    void operator()(const StockDefinition& m) {
        if (const auto* box = std::get_if<StockBox>(&m.shape)) {
            out += "STOCK BOX";
            Pose lo, hi;
            lo.setXyz(box->min);
            hi.setXyz(box->max);
            appendPose(out, lo, kXyzMask);
            appendPose(out, hi, kXyzMask);
        } else if (const auto* revolved = std::get_if<StockRevolved>(&m.shape)) {
            // The side as the axis letter with its sign, then the outline's points.
            const Vec3& side = revolved->materialSide;
            out += "STOCK REVOLVED SIDE ";
            out += side.x() + side.z() < 0.0 ? '-' : '+';
            out += std::fabs(side.x()) > std::fabs(side.z()) ? 'X' : 'Z';
            for (const Vec3& p : revolved->outline) {
                appendWord(out, "X", p.x(), kLengthDecimals);
                appendWord(out, "Z", p.z(), kLengthDecimals);
            }
        } else {
            const auto& cylinder = std::get<StockCylinder>(m.shape);
            out += "STOCK CYLINDER ";
            out += axisLetter(cylinder.axis);
            appendWord(out, "R", cylinder.radiusMm, kLengthDecimals);
            appendWord(out, "RI", cylinder.innerRadiusMm, kLengthDecimals);
            appendWord(out, "L", cylinder.lengthMm, kLengthDecimals);
            appendWord(out, "DIST", cylinder.distanceMm, kLengthDecimals);
        }
    }
    void operator()(const PathTolerance& m) {
        out += "TOLERANCE";
        appendWord(out, "", m.toleranceMm, kLengthDecimals);
    }
};

}  // namespace

void appendCommand(std::string& text, const Command& command, const TraceFormat& format) {
    LineWriter out(text);
    const SourceLocation& at = command.location;
    if (at.fileId != 0 && format.fileName) {
        out += format.fileName(at.fileId);
        out += ':';
    }
    out.integer(at.line);
    out += ':';
    out.integer(at.column);
    out += ' ';
    if (at.blockNumber >= 0) {
        out += 'N';
        out.integer(at.blockNumber);
        out += ' ';
    }
    std::visit(BodyPrinter{out, format.axes}, command.body);
}

}  // namespace kerf::canon
