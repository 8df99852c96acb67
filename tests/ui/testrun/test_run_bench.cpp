// Manual benchmark: how long the test run takes to interpret a long Klartext program (a zigzag
// of N linear blocks) and how much of that the status snapshots cost. Figures in
// docs/benchmarks.md. Usage: test_run_bench [BLOCKS] [--no-clock] (without the machining clock:
// the interpretation alone).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/machine/machine_loader.h"
#include "motion/sim/simulated_clock.h"
#include "ui/testrun/test_run_program.h"

int main(int argc, char** argv) {
    const long blocks = argc > 1 ? std::atol(argv[1]) : 100000;
    kerf::ui::TestRunInput input;
    input.machine = *kerf::machine::loadMachine("mill");
    input.path = "ZIGZAG.H";
    const bool clock = !(argc > 2 && std::string(argv[2]) == "--no-clock");
    if (clock) input.clock = kerf::motion::makeSimulatedClock;  // as in the HMI
    std::string& text = input.text;
    text =
        "0 BEGIN PGM ZIGZAG MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-10\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
        "3 TOOL CALL 0 Z S1000 DR+3\n4 L X+0 Y+0 Z-1 R0 F1000\n";
    for (long i = 0; i < blocks; ++i) {
        text += std::to_string(i + 5) + " L X+" + std::to_string((i % 2) * 100) + " Y+" +
                std::to_string(static_cast<double>(i) * 100.0 / static_cast<double>(blocks)) + "\n";
    }
    text += std::to_string(blocks + 5) + " END PGM ZIGZAG MM\n";
    const auto start = std::chrono::steady_clock::now();
    const kerf::ui::TestRunProgram program = kerf::ui::interpretForTestRun(input);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "%ld blocks: %.2f s, %zu commands, %zu status snapshots, machining time %.0f s, %s\n",
        blocks, seconds, program.commands.size(), program.statuses.size(), program.machiningTimeS(),
        program.ran ? "ran" : "failed");
    return program.ran ? 0 : 1;
}
