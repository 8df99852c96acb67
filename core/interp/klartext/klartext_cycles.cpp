// CYCL DEF (parameter capture, PREDEF, FAUTO/FMAX/FU/FZ), GLOBAL DEF, PATTERN DEF, SEL TABLE and
// SEL PATTERN. Old-style sub-blocks are dispatched to klartext_transform.cpp.
#include <algorithm>
#include <array>

#include "core/base/translate.h"
#include "core/cycles/cycle_registry.h"
#include "core/cycles/global_def.h"
#include "core/cycles/legacy/legacy_cycles.h"
#include "core/cycles/parameter_check.h"
#include "core/cycles/probing/probing_14xx.h"
#include "core/geometry/plane.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/tables/point_table.h"

namespace kerf::klartext {

namespace {

std::string trimmedUpper(std::string_view text) {
    size_t a = 0, b = text.size();
    while (a < b && (text[a] == ' ' || text[a] == '\t'))
        ++a;
    while (b > a && (text[b - 1] == ' ' || text[b - 1] == '\t'))
        --b;
    std::string out(text.substr(a, b - a));
    for (char& c : out)
        c = upper(c);
    return out;
}

bool scalesWithUnit(cycles::Unit unit) {
    return unit == cycles::Unit::Millimetre || unit == cycles::Unit::FeedPerMinute;
}

// The number after FU / FZ in a cycle parameter ("FU0.15").
std::optional<double> numberAfter(const std::string& raw, size_t at) {
    Cursor c(raw, at);
    auto v = c.signedNumber();
    if (!v || !c.atEnd()) return std::nullopt;
    return v;
}

}  // namespace

// A text parameter: "text" in quotes, or the string parameter QSn (cycle 225 QS500=QS10).
std::optional<std::string> KlartextInterpreter::cycleText(std::string_view raw) const {
    size_t a = 0, b = raw.size();
    while (a < b && (raw[a] == ' ' || raw[a] == '\t'))
        ++a;
    while (b > a && (raw[b - 1] == ' ' || raw[b - 1] == '\t'))
        --b;
    const std::string_view text = raw.substr(a, b - a);
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
        return std::string(text.substr(1, text.size() - 2));
    }
    if (text.size() > 2 && upper(text[0]) == 'Q' && upper(text[1]) == 'S') {
        unsigned index = 0;
        for (char c : text.substr(2)) {
            if (!isDigit(c) || index >= static_cast<unsigned>(kQCount)) return std::nullopt;
            index = index * 10 + static_cast<unsigned>(c - '0');
        }
        if (index < static_cast<unsigned>(kQCount)) {
            return m_q.getString(static_cast<uint16_t>(index));
        }
    }
    return std::nullopt;
}

void KlartextInterpreter::failCycle(const cycles::CycleError& error) {
    fail(error.code.c_str(), error.messageTemplate.c_str(), error.args);
}

bool KlartextInterpreter::resolveParameters(
    const std::string& owner, std::span<const cycles::ParameterDescriptor> descriptors,
    const std::vector<CycleParameter>& written, cycles::CycleValues& values,
    std::vector<uint16_t>* predef, int probeCycle) {
    for (const CycleParameter& p : written) {
        const bool known = std::any_of(descriptors.begin(), descriptors.end(),
                                       [&](const auto& d) { return d.q == p.q; });
        if (!known) {
            warn("cycle-parameter", KERF_TR_NOOP("{1} has no parameter Q{2}: it is ignored"),
                 {owner, std::to_string(p.q)});
        }
    }
    const double scale = lengthScale();
    for (const cycles::ParameterDescriptor& d : descriptors) {
        auto it = std::find_if(written.rbegin(), written.rend(),
                               [&](const CycleParameter& p) { return p.q == d.q; });
        const std::string name = cycles::parameterName(d);
        const std::string meaning = d.description;
        if (it == written.rend()) {
            if (auto missing = cycles::missingParameterError(owner, d)) {
                failCycle(*missing);
                return false;
            }
            values.set(d.q, d.defaultValue * (scalesWithUnit(d.unit) ? scale : 1.0));
            continue;
        }
        if (it->unknown) {
            // "?": a 14xx cycle's nominal position not known (semi-automatic mode).
            if (!cycles::probing::takesActualPosition(probeCycle, d.q)) {
                failCycle(cycles::probing::unknownPositionError(owner, d));
                return false;
            }
            values.set(d.q, 0.0);
            cycles::probing::setUnknownPosition(values, d.q);
            continue;
        }
        if (d.toolName && !it->value) {
            // Q330="MILL_D10": a tool name instead of a number.
            if (auto text = cycleText(it->raw)) {
                values.setText(d.q, std::move(*text));
                continue;
            }
        }
        if (it->isString || d.unit == cycles::Unit::Text) {
            auto text = cycleText(it->raw);
            if (!text) {
                fail("cycle-parameter",
                     KERF_TR_NOOP("{1}: parameter {2} ({3}) needs a text in quotes or a QS "
                                  "parameter"),
                     {owner, name, meaning});
                return false;
            }
            values.setText(d.q, std::move(*text));
            continue;
        }
        const std::string raw = trimmedUpper(it->raw);
        auto refuse = [&](const std::string& keyword) {
            fail("cycle-parameter", KERF_TR_NOOP("{1}: parameter {2} ({3}) does not accept {4}"),
                 {owner, name, meaning, keyword});
            return false;
        };
        if (raw == "PREDEF") {
            if (!d.predef || predef == nullptr) return refuse("PREDEF");
            predef->push_back(d.q);
            values.set(d.q, d.defaultValue * (scalesWithUnit(d.unit) ? scale : 1.0));
            continue;
        }
        if (raw == "FMAX") {
            if ((d.keywords & cycles::kFeedMax) == 0) return refuse("FMAX");
            values.setFeed(d.q, cycles::Feed::rapid());
            continue;
        }
        if (raw == "FAUTO") {
            if ((d.keywords & cycles::kFeedAuto) == 0) return refuse("FAUTO");
            if (m_toolCallFeed <= 0.0) {
                fail("feed", KERF_TR_NOOP("FAUTO: the TOOL CALL block gave no feed rate F"));
                return false;
            }
            values.setFeed(d.q, cycles::Feed::perMinute(m_toolCallFeed));
            continue;
        }
        if (raw.rfind("FU", 0) == 0 || raw.rfind("FZ", 0) == 0) {
            const bool tooth = raw[1] == 'Z';
            if ((d.keywords & (tooth ? cycles::kFeedPerTooth : cycles::kFeedPerRev)) == 0) {
                return refuse(raw.substr(0, 2));
            }
            auto v = numberAfter(raw, 2);
            if (!v || *v < 0.0) {
                fail("cycle-parameter", KERF_TR_NOOP("{1}: {2} needs a feed value after {3}"),
                     {owner, name, raw.substr(0, 2)});
                return false;
            }
            if (tooth && m_tool.cutterCount <= 0) {
                fail("feed", KERF_TR_NOOP("FZ needs the number of teeth (CUT) of the tool"));
                return false;
            }
            const double perRev = *v * scale * (tooth ? m_tool.cutterCount : 1);
            values.setFeed(d.q, cycles::Feed::perRevolution(perRev));
            continue;
        }
        if (!it->value) {
            fail("cycle-parameter", KERF_TR_NOOP("{1}: parameter {2} ({3}) = '{4}' is not a value"),
                 {owner, name, meaning, it->raw});
            return false;
        }
        const double value = *it->value;
        if (auto outside = cycles::parameterValueError(owner, d, value)) {
            failCycle(*outside);
            return false;
        }
        values.set(d.q, value * (scalesWithUnit(d.unit) ? scale : 1.0));
        if (!it->actual) continue;
        // "nominal@actual": only a 14xx cycle's nominal positions (TCH PROBE `probeCycle`).
        if (!cycles::probing::takesActualPosition(probeCycle, d.q)) {
            failCycle(cycles::probing::actualPositionError(owner, d));
            return false;
        }
        if (auto outside = cycles::parameterValueError(owner, d, *it->actual)) {
            failCycle(*outside);
            return false;
        }
        cycles::probing::setActualPosition(values, d.q,
                                           *it->actual * (scalesWithUnit(d.unit) ? scale : 1.0));
    }
    return true;
}

void KlartextInterpreter::executeCycleDefinition(const CycleDefinition& def) {
    if (def.probe) {
        executeProbeCycle(def);
        return;
    }
    m_lastCycleDefined = def.number;
    if (def.subNumber >= 0) {
        executeOldCycle(def);
        return;
    }
    if (def.number == 14) {  // the single-block form "CYCL DEF 14 CONTOUR LABEL 1/2"
        contourLabels(def);
        return;
    }
    const cycles::CycleDescriptor* d = cycles::findCycle(def.number);
    if (d == nullptr || d->oldStyle) {
        fail("not-supported", KERF_TR_NOOP("cycle {1} is not supported yet"),
             {std::to_string(def.number)});
        return;
    }
    const std::string owner = "cycle " + std::to_string(def.number);
    StoredCycle stored;
    stored.descriptor = d;
    if (!resolveParameters(owner, d->parameters, def.parameters, stored.values, &stored.predef)) {
        return;
    }
    if (d->activation == cycles::Activation::Call) {
        m_cycle = std::move(stored);
        m_modalCycleCall = false;  // a new machining cycle cancels M89
        return;
    }
    for (uint16_t q : stored.predef) {
        if (std::find(m_globalSet.begin(), m_globalSet.end(), q) != m_globalSet.end()) {
            stored.values.setFeed(q, m_globals.feed(q));
        }
    }
    if (d->pattern != nullptr) {
        runPatternCycle(*d, stored.values);
    } else if (def.number == 20) {
        m_contourData = std::move(stored.values);
    } else if (def.number == 270) {
        m_trainData = std::move(stored.values);
    } else if (def.number == 247) {
        const Pose at = m_frame.toWorkpiece(m_programmed);
        presetting(stored.values);
        m_programmed = m_frame.toProgram(at);
    }
}

void KlartextInterpreter::executeOldCycle(const CycleDefinition& def) {
    using Handler = void (KlartextInterpreter::*)(const CycleDefinition&);
    struct Entry {
        int number;
        Handler handler;
    };
    static constexpr std::array<Entry, 12> kHandlers = {{
        {7, &KlartextInterpreter::datumShift},
        {8, &KlartextInterpreter::mirrorImage},
        {9, &KlartextInterpreter::dwellTime},
        {10, &KlartextInterpreter::rotation},
        {11, &KlartextInterpreter::scaling},
        {12, &KlartextInterpreter::programCall},
        {13, &KlartextInterpreter::spindleOrientation},
        {14, &KlartextInterpreter::contourLabels},
        {18, &KlartextInterpreter::threadCutting},
        {19, &KlartextInterpreter::workingPlane},
        {26, &KlartextInterpreter::axisScaling},
        {32, &KlartextInterpreter::tolerance},
    }};
    auto it = std::find_if(kHandlers.begin(), kHandlers.end(),
                           [&](const Entry& e) { return e.number == def.number; });
    const cycles::LegacyCycle* legacy = cycles::findLegacyCycle(def.number);
    if (it == kHandlers.end() && legacy == nullptr) {
        // Cycles in the old block format that Kerf does not run: the header stops.
        if (def.subNumber == 0) {
            fail("not-supported", KERF_TR_NOOP("cycle {1} is not supported yet"),
                 {std::to_string(def.number)});
        }
        return;
    }
    if (def.subNumber == 0) {
        m_oldCycle = def.number;
    } else if (m_oldCycle != def.number) {
        fail("cycle-syntax", KERF_TR_NOOP("CYCL DEF {1}.{2} without CYCL DEF {1}.0 before it"),
             {std::to_string(def.number), std::to_string(def.subNumber)});
        return;
    }
    if (legacy != nullptr) return legacyCycle(def, *legacy);
    // Cycle 19 with F moves the rotary axes and keeps the position it reached itself.
    if (def.number == 19) return workingPlane(def);
    // A transformation changes coordinates, not where the tool is: keep its position.
    const Pose at = m_frame.toWorkpiece(m_programmed);
    (this->*(it->handler))(def);
    m_programmed = m_frame.toProgram(at);
}

void KlartextInterpreter::legacyCycle(const CycleDefinition& def,
                                      const cycles::LegacyCycle& legacy) {
    const cycles::CycleDescriptor& d = *legacy.descriptor;
    const std::string number = std::to_string(def.number);
    if (def.subNumber == 0) {
        StoredCycle stored;
        stored.descriptor = &d;
        for (size_t i = 0; i < d.parameters.size(); ++i) {
            if (d.parameters[i].optional)
                stored.values.set(static_cast<uint16_t>(i + 1), d.parameters[i].defaultValue);
        }
        m_cycle = std::move(stored);
        m_modalCycleCall = false;
        return;
    }
    if (def.subNumber > legacy.subBlocks) {
        fail("cycle-syntax", KERF_TR_NOOP("cycle {1} has no sub-block {1}.{2}"),
             {number, std::to_string(def.subNumber)});
        return;
    }
    // The keywords before the values depend on the control's language (ABST, SET UP, DIST):
    // F is the feed, DR the direction, the first other word with a value the value.
    const cycles::CycleWord* value = nullptr;
    const cycles::CycleWord* feed = nullptr;
    const cycles::CycleWord* direction = nullptr;
    for (const cycles::CycleWord& w : def.words) {
        if (w.key == "F") {
            feed = &w;
        } else if (w.key == "DR") {
            direction = &w;
        } else if (value == nullptr && w.value) {
            value = &w;
        }
    }
    for (const cycles::LegacyWordSlot& slot : legacy.slots) {
        if (slot.subBlock != def.subNumber) continue;
        const cycles::ParameterDescriptor& p = d.parameters[slot.id - 1u];
        if (slot.kind == cycles::LegacyWordKind::Axis) {
            const char secondary = axisLetter(planeAxes(workingPlane()).second);
            const bool onSecondary =
                value != nullptr && value->key.size() == 1 && value->key.front() == secondary;
            if (m_cycle && m_cycle->descriptor == &d)
                m_cycle->values.set(slot.id, onSecondary ? 1.0 : 0.0);
            continue;
        }
        const cycles::CycleWord* w = slot.kind == cycles::LegacyWordKind::Value  ? value
                                     : slot.kind == cycles::LegacyWordKind::Feed ? feed
                                                                                 : direction;
        if (w == nullptr || !w->value) {
            if (p.optional) continue;
            fail("cycle-syntax", KERF_TR_NOOP("cycle {1}: {2} expected in {1}.{3}"),
                 {number, p.word, std::to_string(def.subNumber)});
            return;
        }
        if (auto e = cycles::checkParameter(d, p, *w->value)) {
            failCycle(*e);
            return;
        }
        if (!m_cycle || m_cycle->descriptor != &d) continue;
        if (slot.kind == cycles::LegacyWordKind::Feed) {
            m_cycle->values.setFeed(slot.id, cycles::Feed::perMinute(*w->value * lengthScale()));
        } else {
            const bool length = p.unit == cycles::Unit::Millimetre;
            m_cycle->values.set(slot.id, *w->value * (length ? lengthScale() : 1.0));
        }
    }
}

void KlartextInterpreter::executeGlobalDef(const GlobalDefinition& def) {
    const cycles::GlobalDefGroup* group = cycles::findGlobalDefGroup(def.group);
    if (group == nullptr) {
        fail("cycle-syntax", KERF_TR_NOOP("GLOBAL DEF {1} does not exist"),
             {std::to_string(def.group)});
        return;
    }
    // Only the parameters written in the block are set; the others keep their values.
    std::vector<cycles::ParameterDescriptor> written;
    for (const cycles::ParameterDescriptor& d : group->parameters) {
        const bool present = std::any_of(def.parameters.begin(), def.parameters.end(),
                                         [&](const CycleParameter& p) { return p.q == d.q; });
        if (present) written.push_back(d);
    }
    cycles::CycleValues values;
    if (!resolveParameters("GLOBAL DEF " + std::to_string(def.group), written, def.parameters,
                           values, nullptr)) {
        return;
    }
    for (const cycles::ParameterDescriptor& d : written) {
        m_globals.setFeed(d.q, values.feed(d.q));
        if (std::find(m_globalSet.begin(), m_globalSet.end(), d.q) == m_globalSet.end()) {
            m_globalSet.push_back(d.q);
        }
    }
}

void KlartextInterpreter::executePatternDef(const PatternDefinition& def) {
    std::vector<cycles::PatternElement> elements = def.elements;
    const double scale = lengthScale();
    for (cycles::PatternElement& e : elements) {
        for (auto* w : {&e.x, &e.y, &e.z, &e.d, &e.dx, &e.dy})
            w->value *= scale;
    }
    std::vector<cycles::PatternPoint> points;
    if (auto error = cycles::patternPoints(elements, points)) {
        failCycle(*error);
        return;
    }
    m_pattern = std::move(points);
}

Expected<std::filesystem::path> KlartextInterpreter::selectedTablePath(
    const std::string& name, const std::filesystem::path& folder, const char* extension) const {
    auto path = m_root.resolve(name, folder);
    if (!path) return path.error();
    std::filesystem::path target = *path;
    std::error_code ignored;
    if (!std::filesystem::exists(target, ignored)) {
        for (std::string ext : {std::string(extension), trimmedUpper(extension)}) {
            std::filesystem::path withExt = target;
            withExt += ext;
            if (std::filesystem::exists(withExt, ignored)) {
                target = withExt;
                break;
            }
        }
    }
    // The name actually opened is checked, after the extension was added.
    if (MaybeError refused = m_root.admit(target)) {
        refused->args = {name};
        return *refused;
    }
    return target;
}

std::optional<std::filesystem::path> KlartextInterpreter::tablePath(const std::string& name,
                                                                    const char* extension) {
    auto path = selectedTablePath(name, m_levels.back().program->folder, extension);
    if (!path) {
        fail("path", path.error().messageTemplate.c_str(), path.error().args);
        return std::nullopt;
    }
    return *path;
}

MaybeError KlartextInterpreter::checkSelectedTable(const TableReference& table,
                                                   const std::filesystem::path& folder) const {
    const bool points = table.kind == TableReference::Kind::Point;
    auto path = selectedTablePath(table.name, folder, points ? ".pnt" : ".d");
    if (!path) return path.error();
    std::string reason;
    if (auto bytes = m_root.read(*path); !bytes) {
        reason = bytes.error().message();
    } else if (points) {
        if (auto parsed = tables::PointTable::parse(*bytes, path->string()); !parsed)
            reason = parsed.error().message();
    } else if (auto parsed = tables::DatumTable::parse(*bytes, path->string()); !parsed) {
        reason = parsed.error().message();
    }
    if (reason.empty()) return std::nullopt;
    return Diagnostic::make(Severity::Error, "io", "", 0, 0,
                            points ? KERF_TR_NOOP("cannot read the point table {1}: {2}")
                                   : KERF_TR_NOOP("cannot read the datum table {1}: {2}"),
                            table.name, reason);
}

void KlartextInterpreter::executeSelectTable(const SelectTable& select) {
    auto path = tablePath(select.path, ".d");
    if (!path) return;
    auto bytes = m_root.read(*path);
    if (!bytes) {
        fail("io", KERF_TR_NOOP("cannot read the datum table {1}: {2}"),
             {select.path, bytes.error().message()});
        return;
    }
    auto table = tables::DatumTable::parse(*bytes, path->string());
    if (!table) {
        fail("io", KERF_TR_NOOP("cannot read the datum table {1}: {2}"),
             {select.path, table.error().message()});
        return;
    }
    m_datumTable = std::move(*table);
    m_datumTablePath = *path;
}

void KlartextInterpreter::executeSelectPattern(const SelectPattern& select) {
    auto path = tablePath(select.path, ".pnt");
    if (!path) return;
    auto bytes = m_root.read(*path);
    if (!bytes) {
        fail("io", KERF_TR_NOOP("cannot read the point table {1}: {2}"),
             {select.path, bytes.error().message()});
        return;
    }
    auto table = tables::PointTable::parse(*bytes, path->string());
    if (!table) {
        fail("io", KERF_TR_NOOP("cannot read the point table {1}: {2}"),
             {select.path, table.error().message()});
        return;
    }
    // Plane coordinates are the hole centres, the tool-axis value shifts the surface; a column
    // that is off keeps the position where the tool is now. Faded rows are skipped.
    const PlaneAxes axes = planeAxes(workingPlane());
    const double scale = lengthScale();
    std::vector<cycles::PatternPoint> points;
    for (const tables::PointData& p : table->points()) {
        if (p.fade) continue;
        cycles::PatternPoint point;
        point.position = {
            p.axis(axisLetter(axes.first)).value_or(m_programmed[axes.first] / scale) * scale,
            p.axis(axisLetter(axes.second)).value_or(m_programmed[axes.second] / scale) * scale};
        point.surfaceOffset = p.axis(axisLetter(axes.normal)).value_or(0.0) * scale;
        points.push_back(point);
    }
    m_pattern = std::move(points);
}

}  // namespace kerf::klartext
