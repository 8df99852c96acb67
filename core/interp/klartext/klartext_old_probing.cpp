// The old touch-probe cycles written in sub-blocks, one touch each (spec 4 and 5):
//   0.0 REF. PLANE Q5 X-   0.1 X+5 Y+0 Z-5
//   1.0 POLAR DATUM PLANE   1.1 X ANGLE: +30   1.2 X+5 Y+0 Z-5
//   3.0 MEASURING   3.1 Q1   3.2 X ANGLE: +15   3.3 DIST +10 F100 MB1 REFERENCE SYSTEM: 0
//   3.4 ERRORMODE1 (optional)
//   4.0 MEASURING IN 3-D   4.1 Q1   4.2 IX-0.5 IY-1 IZ-1   4.3 ABST+45 F100 MB50 REFERENCE SYSTEM:0
// The texts are the control's language: only the numbers, axis letters, Q, F and MB count.
#include <cmath>
#include <cstdlib>

#include "core/base/translate.h"
#include "core/cycles/parameter_check.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

using namespace cycles::probing::single_touch_words;

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

// The blank-separated words of a sub-block's text.
std::vector<std::string_view> wordsOf(std::string_view text) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && isBlank(text[i]))
            ++i;
        const size_t start = i;
        while (i < text.size() && !isBlank(text[i]))
            ++i;
        if (i > start) out.push_back(text.substr(start, i - start));
    }
    return out;
}

// A number at the start of `text` ("+10", "-0.5"), with the characters it used.
std::optional<double> leadingNumber(std::string_view text, size_t& used) {
    const std::string copy(text);
    char* end = nullptr;
    const double value = std::strtod(copy.c_str(), &end);
    used = static_cast<size_t>(end - copy.c_str());
    if (used == 0 || !std::isfinite(value)) return std::nullopt;
    return value;
}

// "Q5" as a whole word: the result parameter.
std::optional<double> resultParameter(std::string_view text) {
    for (std::string_view w : wordsOf(text)) {
        if (w.size() < 2 || upper(w[0]) != 'Q' || !isDigit(w[1])) continue;
        size_t used = 0;
        auto n = leadingNumber(w.substr(1), used);
        if (n && used == w.size() - 1) return n;
    }
    return std::nullopt;
}

// "X" at the start of the text (1.1, 3.2): 0, 1 or 2.
std::optional<int> leadingAxis(std::string_view text) {
    auto words = wordsOf(text);
    if (words.empty() || words.front().size() != 1) return std::nullopt;
    const char c = upper(words.front()[0]);
    if (c < 'X' || c > 'Z') return std::nullopt;
    return c - 'X';
}

std::optional<double> numberAfterLastColon(std::string_view text) {
    const size_t colon = text.rfind(':');
    if (colon == std::string_view::npos) return std::nullopt;
    std::string_view rest = text.substr(colon + 1);
    while (!rest.empty() && isBlank(rest.front()))
        rest.remove_prefix(1);
    size_t used = 0;
    auto value = leadingNumber(rest, used);
    for (size_t i = used; value && i < rest.size(); ++i) {
        if (!isBlank(rest[i])) return std::nullopt;
    }
    return value;
}

// "DIST +10 F100 MB1 REFERENCE SYSTEM: 0": the path is the number after the first word, F and
// MB carry theirs, the reference system follows the last ':' (none: 0).
struct MeasuringWords {
    std::optional<double> path, feed, retract;
    double referenceSystem = 0.0;
};

bool measuringWords(std::string_view text, MeasuringWords& out) {
    const size_t colon = text.rfind(':');
    if (colon != std::string_view::npos) {
        auto system = numberAfterLastColon(text);
        if (!system) return false;
        out.referenceSystem = *system;
        text = text.substr(0, colon);
    }
    size_t i = 0;
    bool first = true;
    while (i < text.size()) {
        while (i < text.size() && isBlank(text[i]))
            ++i;
        const size_t start = i;
        while (i < text.size() && !isBlank(text[i]) && text[i] != '+' && text[i] != '-' &&
               !isDigit(text[i]) && text[i] != '.')
            ++i;
        const std::string key = [&] {
            std::string k;
            for (char c : text.substr(start, i - start))
                k += upper(c);
            return k;
        }();
        while (i < text.size() && isBlank(text[i]))
            ++i;
        size_t used = 0;
        auto value = leadingNumber(text.substr(i), used);
        if (!value) {
            if (key.empty()) return i >= text.size();
            continue;  // a word of the reference system's name
        }
        i += used;
        if (key == "F") {
            out.feed = value;
        } else if (key == "MB") {
            out.retract = value;
        } else if (first && !key.empty()) {
            out.path = value;
        } else {
            return false;
        }
        first = false;
    }
    return true;
}

}  // namespace

bool KlartextInterpreter::continuesOldProbe(const Statement& statement) const {
    if (std::holds_alternative<Empty>(statement)) return true;
    const auto* def = std::get_if<CycleDefinition>(&statement);
    return def != nullptr && def->probe && def->number == m_oldProbe.number &&
           def->subNumber == m_oldProbe.lastSub + 1;
}

void KlartextInterpreter::executeOldProbeBlock(const CycleDefinition& def) {
    const std::string owner = "TCH PROBE " + std::to_string(def.number);
    const std::string sub = std::to_string(def.subNumber);
    if (def.subNumber == 0) {
        m_oldProbe = OldProbe{};
        m_oldProbe.number = def.number;
        m_oldProbe.lastSub = 0;
    } else if (m_oldProbe.number != def.number || m_oldProbe.lastSub != def.subNumber - 1) {
        fail("cycle-syntax", KERF_TR_NOOP("TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it"),
             {std::to_string(def.number), sub});
        return;
    }
    OldProbe& p = m_oldProbe;
    p.lastSub = def.subNumber;
    auto check = [&](const cycles::ParameterDescriptor& d, std::optional<double> value) {
        if (!value) {
            failCycle(*cycles::missingParameterError(owner + "." + sub, d));
            return false;
        }
        if (auto outside = cycles::parameterValueError(owner + "." + sub, d, *value)) {
            failCycle(*outside);
            return false;
        }
        return true;
    };
    auto axisExpected = [&] {
        fail("cycle-syntax", KERF_TR_NOOP("{1}.{2}: the probing axis X, Y or Z expected"),
             {owner, sub});
    };
    // Positions and IX IY IZ of 0.1, 1.2 and 4.2.
    auto positions = [&](bool incremental) {
        for (const cycles::CycleWord& w : def.words) {
            const auto axis = w.key.size() == 1 ? w.key[0] - 'X' : -1;
            if (axis < 0 || axis > 2 || !w.value || w.incremental != incremental) {
                fail("cycle-syntax", KERF_TR_NOOP("unexpected '{1}'"),
                     {(w.incremental ? "I" : "") + w.key});
                return false;
            }
            if (incremental) {
                p.vector[axis] = *w.value;
            } else {
                p.touch.prePosition[static_cast<size_t>(axis)] = *w.value * lengthScale();
            }
        }
        return true;
    };
    const int n = def.number;
    const int s = def.subNumber;
    if (n == 0 && s == 0) {
        // "REF. PLANE Q5 X-": the result parameter and the probing axis with its direction.
        const auto words = wordsOf(def.rest);
        const std::string_view last = words.empty() ? std::string_view() : words.back();
        const char letter = last.size() == 2 ? upper(last[0]) : '\0';
        if (letter < 'X' || letter > 'Z' || (last[1] != '+' && last[1] != '-')) {
            axisExpected();
            return;
        }
        p.axis = letter - 'X';
        p.sign = last[1] == '-' ? -1.0 : 1.0;
        const auto q = resultParameter(def.rest);
        if (!check(kResult, q)) return;
        p.result = static_cast<uint16_t>(*q);
    } else if ((n == 3 || n == 4) && s == 1) {
        const auto q = resultParameter(def.rest);
        if (!check(kResult, q)) return;
        if (!check(kResult, *q + 3)) return;  // four parameters from Qn
        p.result = static_cast<uint16_t>(*q);
    } else if ((n == 1 && s == 1) || (n == 3 && s == 2)) {
        const auto axis = leadingAxis(def.rest);
        if (!axis) {
            axisExpected();
            return;
        }
        const auto angle = numberAfterLastColon(def.rest);
        if (!check(kAngle, angle)) return;
        p.axis = *axis;
        p.angleDeg = *angle;
    } else if ((n == 0 && s == 1) || (n == 1 && s == 2)) {
        if (!positions(false)) return;
    } else if (n == 4 && s == 2) {
        if (!positions(true)) return;
        if (p.vector.norm() < 1e-9) {
            fail("cycle-syntax", KERF_TR_NOOP("{1}.{2}: the probing direction IX, IY, IZ is zero"),
                 {owner, sub});
            return;
        }
    } else if ((n == 3 || n == 4) && s == 3) {
        MeasuringWords m;
        if (!measuringWords(def.rest, m)) {
            fail("cycle-syntax", KERF_TR_NOOP("unexpected '{1}'"), {def.rest});
            return;
        }
        if (!check(kPath, m.path) || !check(kFeed, m.feed) || !check(kRetract, m.retract) ||
            !check(kReferenceSystem, m.referenceSystem)) {
            return;
        }
        p.touch.maxPath = std::abs(*m.path) * lengthScale();
        p.sign = *m.path < 0.0 ? -1.0 : 1.0;
        p.feed = *m.feed * lengthScale();
        p.touch.retract = *m.retract * lengthScale();
        p.machineSystem = m.referenceSystem == 1.0;
    } else if (n == 3 && s == 4) {
        // "ERRORMODE1": the number at the end.
        const std::string_view text = def.rest;
        size_t at = text.size();
        while (at > 0 && (isDigit(text[at - 1]) || isBlank(text[at - 1])))
            --at;
        size_t used = 0;
        const auto mode = leadingNumber(text.substr(at), used);
        if (!check(kErrorMode, mode)) return;
        p.touch.deflectedIsError = *mode == 0.0;
    } else if (s > 0) {
        fail("cycle-syntax", KERF_TR_NOOP("unexpected '{1}'"),
             {owner + "." + sub + " " + def.rest});
        return;
    }
    const int last = n == 0 ? 1 : n == 1 ? 2 : 3;
    if (n == 3 && s == 3) {
        p.pending = true;  // a 3.4 may follow
        return;
    }
    if (s == last || (n == 3 && s == 4)) runOldProbe();
}

void KlartextInterpreter::runOldProbe() {
    const OldProbe p = m_oldProbe;
    m_oldProbe = OldProbe{};
    runTouching([this, p] { probeOld(p); });
}

void KlartextInterpreter::probeOld(const OldProbe& collected) {
    OldProbe p = collected;
    const int n = p.number;
    cycles::probing::SingleTouch& touch = p.touch;
    if (n == 0) {
        touch.direction = Vec3::Zero();
        touch.direction[p.axis] = p.sign;
    } else if (n == 1 || n == 3) {
        touch.direction = cycles::probing::polarDirection(p.axis, p.angleDeg);
    } else {
        touch.direction = p.vector.normalized();
    }
    const bool ownMeasuring = n == 3 || n == 4;
    if (ownMeasuring) touch.direction *= p.sign;  // a negative path probes the other way
    touch.missIsError = !ownMeasuring;
    if (n == 4) touch.deflectedIsError = false;
    // REFERENCE SYSTEM 1: the direction is given in machine axes, the result too.
    auto programOf = [&](const Vec3& workpiece) {
        Pose pose = m_frame.toWorkpiece(m_programmed);
        pose.setXyz(workpiece);
        return toLocal(m_frame.toProgram(pose));
    };
    if (ownMeasuring && p.machineSystem) {
        touch.direction = (programOf(touch.direction) - programOf(Vec3::Zero())).normalized();
    }
    cycles::probing::ProbeData probe;
    auto result =
        probeOnce(n, touch, ownMeasuring ? std::optional<double>(p.feed) : std::nullopt, probe);
    if (!result) return;
    const double scale = lengthScale();
    // 4 reports the ball centre with the calibrated centre offset, 0, 1 and 3 without it
    // (spec 1.5).
    const Vec3& touched = n == 4 ? result->ball : result->uncorrectedBall;
    if (ownMeasuring) {
        // Qn..Qn+2 the ball centre, Qn+3 the status (0 valid, -1 none).
        Vec3 ball = touched;
        if (p.machineSystem) {
            ball = m_frame.toWorkpiece(fromLocal(ball)).xyz() + m_settings.presetInMachine.xyz();
        }
        for (uint16_t i = 0; i < 3; ++i) {
            m_q.set({QKind::Q, static_cast<uint16_t>(*p.result + i)},
                    result->valid ? ball[i] / scale : 0.0);
        }
        m_q.set({QKind::Q, static_cast<uint16_t>(*p.result + 3)}, result->valid ? 0.0 : -1.0);
        return;
    }
    // 0 and 1: Q115-Q119 the trigger position without the stylus's length and radius (the
    // spindle's gauge point), the 4th and 5th axis where they stand; 0 also the touched surface
    // coordinate in its parameter.
    const Vec3 gauge = touched + Vec3(0.0, 0.0, probe.length - probe.ballRadius);
    for (uint16_t i = 0; i < 3; ++i)
        m_q.set({QKind::Q, static_cast<uint16_t>(115 + i)}, gauge[i] / scale);
    uint16_t extra = 118;
    if (m_settings.machine != nullptr) {
        for (const machine::AxisConfig& axis : m_settings.machine->axes) {
            const auto a = axisFromLetter(axis.letter);
            if (!a || *a == Axis::X || *a == Axis::Y || *a == Axis::Z || extra > 119) continue;
            const bool rotary = *a == Axis::A || *a == Axis::B || *a == Axis::C;
            m_q.set({QKind::Q, extra++}, m_programmed[*a] / (rotary ? 1.0 : scale));
        }
    }
    for (; extra <= 119; ++extra)
        m_q.set({QKind::Q, extra}, 0.0);
    if (n == 0) {
        const double surface = touched[p.axis] + p.sign * probe.ballRadius;
        m_q.set({QKind::Q, *p.result}, surface / scale);
    }
}

}  // namespace kerf::klartext
