// Old-style cycles: the coordinate transformations 7, 8, 10, 11, 26 (and 247, 19) acting on
// everything that follows, and 9, 12, 13, 18, 32. Each sub-block acts when it is read.
#include <cmath>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/base/saturating.h"
#include "core/base/translate.h"
#include "core/cycles/cycle_registry.h"
#include "core/cycles/transform/transformation_cycles.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

// Linear values of the words in mm (INCH programs); angles and factors stay.
cycles::CycleWords inMm(cycles::CycleWords words, double scale, bool factors) {
    for (cycles::CycleWord& w : words) {
        if (!w.value) continue;
        bool incremental = false;
        auto axis = cycles::wordAxis(w, incremental);
        const bool centre = w.key.size() == 3 && w.key.compare(0, 2, "CC") == 0;
        if ((axis && cycles::isLinearAxis(*axis) && !factors) || centre) *w.value *= scale;
    }
    return words;
}

}  // namespace

std::optional<ContourElement> KlartextInterpreter::toPathSpace(const ContourElement& e) {
    // With TCPM and in a swivel head's oblique plane the path works in the tilted plane's
    // coordinates: only the inner half of the frame applies.
    const bool tiltedPlane = pathInTiltedPlane();
    if (!tiltedPlane && m_frame.identity()) return e;
    auto map = [&](const Pose& p) {
        return tiltedPlane ? m_frame.toTiltedPlane(p) : m_frame.toWorkpiece(p);
    };
    if (e.kind == ContourElement::Kind::Line)
        return ContourElement::line(e.plane, map(e.start), map(e.end));
    if (!pathKeepsArcs(e.plane)) {
        fail("transformation",
             KERF_TR_NOOP("an arc in the {1} plane cannot be rotated out of its plane or scaled "
                          "with different factors"),
             {planeName(e.plane)});
        return std::nullopt;
    }
    Pose centre = e.start;
    e.setInPlane(centre, e.center);
    const Pose c = map(centre);
    const double sweep = pathFlipsOrientation(e.plane) ? -e.sweep : e.sweep;
    return ContourElement::arc(e.plane, map(e.start), map(e.end), e.inPlane(c), sweep);
}

void KlartextInterpreter::datumShift(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    if (!def.words.empty() && def.words.front().key == "#") {
        // 7.1 #5: datum 5 of the selected datum table, absolute values from the preset.
        const double number = def.words.front().value.value_or(-1.0);
        if (!m_datumTable) {
            fail("datum-table", KERF_TR_NOOP("cycle 7: no datum table selected (SEL TABLE)"));
            return;
        }
        const tables::DatumData* row = number >= 0.0 && number <= 9999.0
                                           ? m_datumTable->byNumber(saturatingInt(number))
                                           : nullptr;
        if (row == nullptr) {
            fail("datum-table", KERF_TR_NOOP("cycle 7: datum {1} is not in the datum table"),
                 {formatFixed(number, 0)});
            return;
        }
        for (int i = 0; i < kAxisCount; ++i) {
            const auto axis = static_cast<Axis>(i);
            const double value = row->axis(axisLetter(axis)).value_or(0.0);
            m_frame.setShift(axis, cycles::isLinearAxis(axis) ? value * lengthScale() : value,
                             false);
        }
        return;
    }
    if (auto e = cycles::applyDatumShift(m_frame, inMm(def.words, lengthScale(), false))) {
        failCycle(*e);
    }
}

void KlartextInterpreter::mirrorImage(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    bool ignored = false;
    if (auto e = cycles::applyMirror(m_frame, def.words, m_toolAxis, ignored)) {
        failCycle(*e);
        return;
    }
    if (ignored) {
        warn("transformation",
             KERF_TR_NOOP("cycle 8: the tool axis {1} cannot be mirrored; it is left out"),
             {std::string(1, axisLetter(m_toolAxis))});
    }
}

void KlartextInterpreter::rotation(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    // The basic rotation belongs to the preset: ROT turns on top of it.
    const Plane plane = workingPlane();
    m_frame.setRotation(m_frame.rotationDeg() - m_basicRotationDeg, false, plane);
    auto error = cycles::applyRotation(m_frame, def.words, plane);
    m_frame.setRotation(m_frame.rotationDeg() + m_basicRotationDeg, false, plane);
    if (error) {
        failCycle(*error);
        return;
    }
    // Cycle 10 cancels radius compensation (spec §9).
    m_comp = CompWord::Off;
}

void KlartextInterpreter::scaling(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    if (auto e = cycles::applyScaling(m_frame, def.words)) failCycle(*e);
}

void KlartextInterpreter::axisScaling(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    if (auto e = cycles::applyAxisScaling(m_frame, inMm(def.words, lengthScale(), true))) {
        failCycle(*e);
    }
}

void KlartextInterpreter::presetting(const cycles::CycleValues& values) {
    const int number = values.integer(339);
    Pose offset{};
    double basicRotation = m_settings.basicRotationDeg;
    if (number != 0) {
        const tables::PresetTable* table = m_settings.presets;
        if (table == nullptr && !m_presetFile) {
            const std::filesystem::path file = m_root.path() / "PRESET.PR";
            auto bytes = m_root.read(file);
            auto loaded = bytes ? tables::PresetTable::parse(*bytes, file.string()) : bytes.error();
            if (loaded) m_presetFile = std::move(*loaded);
        }
        if (table == nullptr && m_presetFile) table = &*m_presetFile;
        if (table == nullptr) {
            fail("preset",
                 KERF_TR_NOOP("cycle 247: no preset table (PRESET.PR) to read preset "
                              "{1} from"),
                 {std::to_string(number)});
            return;
        }
        const tables::PresetData* row = table->byNumber(number);
        if (row == nullptr) {
            fail("preset", KERF_TR_NOOP("cycle 247: preset {1} is not in the preset table"),
                 {std::to_string(number)});
            return;
        }
        // The stream stays in the frame of the preset the run started with.
        for (int i = 0; i < kAxisCount; ++i) {
            const auto axis = static_cast<Axis>(i);
            if (auto v = row->axis(axisLetter(axis))) {
                offset[axis] = *v - m_settings.presetInMachine[axis];
            }
        }
        basicRotation = table->basicRotationDeg(number);
    }
    m_frame.setPreset(offset);
    // The preset brings its basic rotation (SPC) along.
    m_basicRotationDeg = basicRotation;
    if (basicRotation != 0.0) m_frame.setRotation(basicRotation, false, workingPlane());
    updatePathSpace();  // the preset moves the tilted plane on the axes
}

std::optional<double> KlartextInterpreter::lastValue(const CycleDefinition& def, const char* what) {
    for (auto it = def.words.rbegin(); it != def.words.rend(); ++it) {
        if (it->value) return it->value;
    }
    fail("cycle-syntax", KERF_TR_NOOP("cycle {1}: {2} expected"),
         {std::to_string(def.number), what});
    return std::nullopt;
}

void KlartextInterpreter::dwellTime(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    auto seconds = lastValue(def, "dwell time");
    if (!seconds) return;
    if (auto e = cycles::checkParameter(*cycles::findCycle(9), cycles::findCycle(9)->parameters[0],
                                        *seconds)) {
        failCycle(*e);
        return;
    }
    if (*seconds > 0.0) emit(canon::Dwell{*seconds});
}

void KlartextInterpreter::programCall(const CycleDefinition& def) {
    if (def.subNumber == 0) {
        StoredCycle stored;
        stored.descriptor = cycles::findCycle(12);
        m_cycle = std::move(stored);
        m_modalCycleCall = false;
        return;
    }
    const std::string path = cycle12Program(def.rest);
    if (path.empty()) {
        fail("cycle-syntax", KERF_TR_NOOP("cycle 12: program name expected"));
        return;
    }
    if (m_cycle && m_cycle->descriptor->number == 12) m_cycle->program = path;
}

void KlartextInterpreter::spindleOrientation(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    auto angle = lastValue(def, "angle");
    if (!angle) return;
    const cycles::CycleDescriptor& d = *cycles::findCycle(13);
    if (auto e = cycles::checkParameter(d, d.parameters[0], *angle)) {
        failCycle(*e);
        return;
    }
    m_orientAngle = *angle;
}

void KlartextInterpreter::threadCutting(const CycleDefinition& def) {
    if (def.subNumber == 0) {
        StoredCycle stored;
        stored.descriptor = cycles::findCycle(18);
        m_cycle = std::move(stored);
        m_modalCycleCall = false;
        return;
    }
    const cycles::CycleDescriptor& d = *cycles::findCycle(18);
    if (def.subNumber > static_cast<int>(d.parameters.size())) {
        fail("cycle-syntax", KERF_TR_NOOP("cycle 18 has no sub-block 18.{1}"),
             {std::to_string(def.subNumber)});
        return;
    }
    auto value = lastValue(def, d.parameters[static_cast<size_t>(def.subNumber - 1)].word);
    if (!value) return;
    if (auto e = cycles::checkParameter(d, d.parameters[static_cast<size_t>(def.subNumber - 1)],
                                        *value)) {
        failCycle(*e);
        return;
    }
    if (m_cycle && m_cycle->descriptor == &d) {
        m_cycle->values.set(static_cast<uint16_t>(def.subNumber), *value * lengthScale());
    }
}

void KlartextInterpreter::tolerance(const CycleDefinition& def) {
    if (def.subNumber == 0) return;
    const cycles::CycleDescriptor& d = *cycles::findCycle(32);
    for (const cycles::CycleWord& w : def.words) {
        const cycles::ParameterDescriptor* p = nullptr;
        for (const cycles::ParameterDescriptor& candidate : d.parameters) {
            if (w.key == candidate.word) p = &candidate;
        }
        if (p == nullptr || !w.value) {
            fail("cycle-syntax", KERF_TR_NOOP("cycle 32: unexpected '{1}'"), {w.key});
            return;
        }
        if (auto e = cycles::checkParameter(d, *p, *w.value)) {
            failCycle(*e);
            return;
        }
        // T goes to the planner; HSC-MODE and TA select machine filters the stream has no
        // command for.
        if (w.key == "T") emit(canon::PathTolerance{*w.value * lengthScale()});
    }
}

}  // namespace kerf::klartext
