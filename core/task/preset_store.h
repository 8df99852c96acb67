#pragma once

#include <array>
#include <filesystem>
#include <optional>

#include "core/base/expected.h"
#include "core/geometry/axes.h"
#include "core/program/nc_root.h"

namespace kerf::task {

// The machine's active preset kept where an operator edits it: row 0 of PRESET.PR in the NC
// root, machine coordinates, as a TNC keeps the preset set in Manual operation in its row 0.
// The file goes through the NC root's file-access layer (docs/files.md).
// Task thread (file I/O; never from the servo cycle).
class PresetStore {
public:
    explicit PresetStore(const std::filesystem::path& ncRoot)
        : m_root(ncRoot), m_file(m_root.path() / "PRESET.PR") {}

    // The values row 0 sets; an axis without a value (or no table, or a table that cannot be
    // read) has none.
    std::array<std::optional<double>, kAxisCount> read() const;
    // Row 0's basic rotation (SPC, degrees) that programs start with; 0 without one.
    double basicRotationDeg() const;
    // Writes the origin of the given axes into row 0 atomically (a column the table lacks is
    // added), creating the table with the standard columns if it is missing.
    MaybeError write(const Pose& origin, AxisMask axes) const;
    // Writes the basic rotation into row 0 (SPC, where the probing cycles keep it; ROT in an
    // older table without SPC; a table with neither gets an SPC column), in degrees.
    MaybeError writeBasicRotation(double degrees) const;

    const std::filesystem::path& file() const { return m_file; }

private:
    program::NcRoot m_root;
    std::filesystem::path m_file;
};

}  // namespace kerf::task
