#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/expected.h"
#include "core/tables/probe_type.h"
#include "core/tables/table_unit.h"
#include "core/tables/table_validation.h"
#include "core/tables/tnc_table.h"

namespace kerf::tables {

// One workpiece touch probe of the touch-probe table (tchprobe.tp); the tool table links a tool
// to it through column TP_NO. Lengths in the table's unit, feeds in mm/min (inch/min).
struct ProbeData {
    int number = 0;                          // NO
    std::string type;                        // TYPE: probe model, e.g. "TS460"
    const ProbeType* model = nullptr;        // what TYPE names (an empty cell: TS460)
    double centreOffsetMain = 0.0;           // CAL_OF1: probe axis to spindle axis, main axis
    double centreOffsetSecondary = 0.0;      // CAL_OF2: the same along the secondary axis
    double calibrationAngle = 0.0;           // CAL_ANG: spindle angle for calibrating and probing
    double probingFeed = 0.0;                // F
    double rapidFeed = 0.0;                  // FMAX: pre-positioning between touch points
    double maxProbingPath = 0.0;             // DIST: error when not deflected within it
    double setUpClearance = 0.0;             // SET_UP
    bool prepositionAtMachineRapid = false;  // F_PREPOS: FMAX_MACHINE (else FMAX_PROBE)
    bool track = false;                      // TRACK: ON orients the probe before each touch
    std::string serial;                      // SERIAL: filled by EnDat probes
    size_t row = 0;                          // row in table()
};

// Typed view of the touch-probe table (.TP), keyed by NO (spec tnc-probing-cycles.md 1.3).
// Feeds, path and clearance must not be negative, F and DIST must be positive, F_PREPOS is
// FMAX_PROBE or FMAX_MACHINE, TRACK is ON or OFF (ON only for a probe that can be oriented to
// any angle), TYPE names a model of probeTypes(); empty cells take the defaults of a new row.
class ProbeTable {
public:
    static Expected<ProbeTable> fromTable(TncTable table);
    static Expected<ProbeTable> parse(std::string_view bytes, std::string fileName = {});
    static Expected<ProbeTable> load(const std::filesystem::path& path);
    MaybeError save(const std::filesystem::path& path) const;
    std::string serialize() const { return m_table.serialize(); }

    // "BEGIN <name>.TP MM", every column of the spec, probe 1 with the defaults of a new row.
    static std::string createDefault(std::string_view name = "TCHPROBE",
                                     TableUnit unit = TableUnit::Millimetre);

    const TncTable& table() const { return m_table; }
    const std::vector<ProbeData>& probes() const { return m_probes; }
    const ProbeData* byNumber(int number) const;

    // Writes what calibration found (spec 6): CAL_OF1 and CAL_OF2 of probe `number`. A table
    // without those columns gets them at the end. The table is unchanged if it fails.
    MaybeError setCentreOffset(int number, double main, double secondary);

private:
    explicit ProbeTable(TncTable table) : m_table(std::move(table)) {}

    TncTable m_table;
    std::vector<ProbeData> m_probes;
};

}  // namespace kerf::tables
