#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "core/interp/interpreter.h"

namespace kerf::app {

struct Session;
class CanMachine;

// Checks --drives, --can-trace and --inject-fault before anything runs; the usage error if not.
std::optional<std::string> checkDriveOptions(const RunOptions& options);

// `kerf run --drives can-sim`: the canonical stream the run consumes also goes through the whole
// drive chain (planner, servo cycle, CANopen master, simulated CiA 402 drives on the virtual bus)
// in simulated time, behind the same check as --motion (SoftLimitGate): a program that would
// leave the work area is refused before anything moves. The report's final_position then comes
// from the drives' feedback; a drive fault ends the run with the drive set's diagnostic, naming
// node and cause, and the report says where every drive came to rest.
class DriveOutput {
public:
    DriveOutput(const RunOptions& options, const Session& session);
    ~DriveOutput();
    DriveOutput(const DriveOutput&) = delete;
    DriveOutput& operator=(const DriveOutput&) = delete;

    bool active() const { return m_active; }
    // Commands are checked and held, and go to the drives at a sync point or the end.
    canon::Sink& sink();
    // Boots the drives where the program starts; a refused bus or a failed boot is appended to
    // `problems` and stops the run before its first block.
    void setStart(const Pose& start, DiagnosticList& problems);
    // The interpreter's slice: small with drives, so a fault after a release of held commands
    // stops it within a few blocks.
    uint64_t blocksPerSlice(uint64_t withoutDrives) const;
    // The drives stopped (fault, lost node, failed boot) or the check refused a block:
    // interpret no further.
    bool stopped() const;
    // Runs the machine until everything queued is executed: the world at a sync point.
    interp::WorldSnapshot drain();
    // After the run: executes the rest when the program ran (nothing when it was rejected),
    // closes the trace and appends the drive diagnostics to `problems`.
    void finish(bool programRan, DiagnosticList& problems);
    // Replaces final_position with the drives' feedback and adds "drives" to the report.
    void addToReport(nlohmann::json& report, bool xInDiameter) const;

private:
    struct Result;
    struct Checked;
    std::string fileOf(uint32_t fileId) const;
    const RunOptions& m_options;
    const Session& m_session;
    bool m_active = false;
    bool m_bootFailed = false;
    std::unique_ptr<Checked> m_checked;
    std::unique_ptr<CanMachine> m_machine;
    std::unique_ptr<Result> m_result;
};

}  // namespace kerf::app
