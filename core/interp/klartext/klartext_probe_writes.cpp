// Where the probing cycles' rotations and datums go besides the active frame (spec 1.12): the
// rotary table turned by 403/405 and its display zeroed, a basic rotation in a preset row (the
// SPC column), and datums written to the datum table selected with SEL TABLE (Q303 = 0).
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

std::string KlartextInterpreter::tableAxisLetters() const {
    if (!m_kinematics || !m_kinematics->hasTable()) return {};
    // The secondary table rides on the primary one: it is the nearer to the workpiece. A swivel
    // head's axis turns no table.
    std::string letters(1, m_kinematics->innerTable());
    if (m_kinematics->twoAxes() && !m_kinematics->hasHead()) letters += m_kinematics->primary();
    return letters;
}

// A new preset offset (from the start preset) becomes active; the basic rotation stays.
void KlartextInterpreter::activatePreset(const Pose& offset) {
    const Pose at = m_frame.toWorkpiece(m_programmed);
    const double rotation = m_frame.rotationDeg();
    m_frame.setPreset(offset);
    if (rotation != 0.0) m_frame.setRotation(rotation, false, workingPlane());
    m_programmed = m_frame.toProgram(at);
    updatePathSpace();
}

bool KlartextInterpreter::applyRotaryCompensation(int cycle,
                                                  const cycles::probing::ProbingResults& results) {
    const cycles::probing::RotaryCompensation& rotary = *results.rotary;
    const Axis axis = *axisFromLetter(rotary.axis);
    Pose target = m_programmed;
    target[axis] += rotary.turnDeg;
    if (!rotaryWithinLimits(target)) return false;
    moveProgrammed(target, true, 0.0);
    if (!checkPathError(m_path.flush())) return false;
    if (rotary.datumRow) {
        // 405 with Q337 > 0: the turn is added to the axis's shift in that datum row.
        const double before =
            m_datumTable && m_datumTable->byNumber(*rotary.datumRow)
                ? m_datumTable->byNumber(*rotary.datumRow)->axis(rotary.axis).value_or(0.0)
                : 0.0;
        return writeDatumRow(cycle, *rotary.datumRow, {{rotary.axis, before + rotary.turnDeg}});
    }
    if (!rotary.zeroDisplay) return true;
    // The axis shows 0 where it stands now: through the datum table (Q303 = 0) or the preset.
    const double shown = m_programmed[axis];
    if (results.transfer == 0) {
        return writeDatumRow(cycle, std::max(results.tableRow, 0), {{rotary.axis, shown}});
    }
    Pose offset = m_frame.preset();
    offset[axis] += shown;
    const int row = std::max(results.tableRow, 0);
    if (!writePreset(cycle, row, offset)) return false;
    if (row == 0) activatePreset(offset);
    return true;
}

bool KlartextInterpreter::writePresetRotation(int cycle, int row, double degrees) {
    if (!waitForCheck()) return false;
    const std::filesystem::path file = m_root.path() / "PRESET.PR";
    std::optional<tables::PresetTable> table = presetTableToEdit(file);
    if (!table) return false;
    if (table->byNumber(row) == nullptr) (void)table->addPreset(row);
    if (auto error = table->setBasicRotation(row, degrees)) {
        failCycle({error->code, error->messageTemplate, error->args});
        return false;
    }
    if (auto error = replaceFile(file, table->serialize())) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the preset table: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    m_presetFile = std::move(*table);
    return true;
}

bool KlartextInterpreter::writeDatumRow(int cycle, int row,
                                        const std::vector<std::pair<char, double>>& axes) {
    if (!m_datumTable || !m_datumTablePath) {
        fail("PRB-004",
             KERF_TR_NOOP("touch probe cycle {1}: Q303 = 0 writes the active datum table: select "
                          "one with SEL TABLE first"),
             {std::to_string(cycle)});
        return false;
    }
    if (!waitForCheck()) return false;
    tables::DatumTable table = *m_datumTable;
    if (table.byNumber(row) == nullptr) {
        if (auto error = table.addDatum(row)) {
            failCycle({error->code, error->messageTemplate, error->args});
            return false;
        }
    }
    for (const auto& [letter, value] : axes) {
        if (auto error = table.setAxis(row, letter, value)) {
            failCycle({error->code, error->messageTemplate, error->args});
            return false;
        }
    }
    if (auto error = replaceFile(*m_datumTablePath, table.serialize())) {
        fail("io", KERF_TR_NOOP("touch probe cycle {1}: cannot write the datum table: {2}"),
             {std::to_string(cycle), error->format()});
        return false;
    }
    m_datumTable = std::move(table);
    return true;
}

}  // namespace kerf::klartext
