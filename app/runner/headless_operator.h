#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/interp/fagor/user_screen.h"
#include "core/program/dialect.h"

namespace kerf::app {

// The operator of a FAGOR user screen in `kerf run --user-screen MODE`: answers each WKEY with
// the next --operator-input as a key name (F1-F7, $FC00, one character) and each IB with a format
// with the next one as a number. When none is left the run ends with a note (docs/headless.md).
class HeadlessOperator {
public:
    explicit HeadlessOperator(const RunOptions& options);

    bool active() const { return m_screen != nullptr; }
    fagor::UserScreen* screen() const { return m_screen.get(); }
    bool waiting() const {
        return m_screen && m_screen->waiting() != fagor::UserScreen::Waiting::Nothing;
    }
    // Gives the screen the next input; false (with a diagnostic) when the run must end.
    bool answer(DiagnosticList& problems);
    // The customisation program did not end within --max-blocks: normal for a screen loop.
    void noteBlockLimit(DiagnosticList& problems, uint64_t blocks) const;
    void print(std::ostream& out) const;
    void addToReport(nlohmann::json& report) const;
    // A user screen runs FAGOR programs only: an error for another dialect.
    std::optional<Diagnostic> dialectProblem(program::Dialect dialect) const;

private:
    std::string m_program;
    std::unique_ptr<fagor::UserScreen> m_screen;
    std::vector<std::string> m_inputs;
    size_t m_next = 0;
};

// An --operator-input item "IBn=value" (n 0-25): the value of IBn for the whole run, read by any
// FAGOR program; nullopt for the user screen's answers (a key or a number).
std::optional<std::pair<int, double>> inputAssignment(const std::string& item);

// The mode named on the command line; nullopt if none.
std::optional<fagor::UserMode> userModeFromName(const std::string& name);

}  // namespace kerf::app
