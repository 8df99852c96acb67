#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/headless_run.h"

// Programs for the machining time of the test run and of `kerf run`'s report against the
// simulated program run (`kerf run --motion`): rapids, feeds, arcs and a dwell on the mill; on the
// lathe also mm/rev (G95), constant surface speed (G96, limited by G92) and mm/min (G94).
namespace kerf::test {

// Feeds and the dwell alone take 26.448 s: 7 mm at F200 (2.1 s), 70 mm at F800 (5.25 s), the
// quarter circle R20 at F800 (2.356 s), 50 mm at F1200 (2.5 s), the half circle R20 at F1200
// (3.142 s), the dwell (2.5 s), 50 mm at F600 (5 s), 6 mm at F100 (3.6 s).
inline constexpr const char* kMillTimingProgram =
    "0 BEGIN PGM TIMING MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
    "3 TOOL CALL 1 Z S3000\n"
    "4 L Z+5 R0 FMAX M3\n"
    "5 L X+10 Y+10 R0 FMAX\n"
    "6 L Z-2 R0 F200\n"
    "7 L X+80 F800\n"
    "8 CC X+80 Y+30\n"
    "9 C X+100 Y+30 DR+\n"
    "10 L Y+80 F1200\n"
    "11 CR X+60 Y+80 R+20 DR+\n"
    "12 CYCL DEF 9.0 DWELL TIME\n"
    "13 CYCL DEF 9.1 DWELL 2.5\n"
    "14 L X+10 F600\n"
    "15 L Z+5 FMAX\n"
    "16 L X+50 Y+50 FMAX\n"
    "17 L Z-1 F100\n"
    "18 L Z+50 FMAX M30\n"
    "19 END PGM TIMING MM\n";
inline constexpr double kMillFeedAndDwellS = 26.448;

inline constexpr const char* kLatheTimingProgram =
    "N10 G0 X120 Z5\n"
    "N20 T1 D1\n"
    "N25 M41\n"
    "N30 G96 S180 M3\n"
    "N35 G92 S3000\n"
    "N40 G95 G1 X80 Z2 F0.25\n"
    "N50 G1 Z-40 F0.2\n"
    "N60 G2 X100 Z-50 R10\n"
    "N70 G1 X110 F0.3\n"
    "N80 G4 K150\n"
    "N90 G0 X120 Z5\n"
    "N100 G97 S1200 M4\n"
    "N110 G94 G1 X60 Z0 F400\n"
    "N120 G3 X70 Z-5 R5\n"
    "N130 G1 Z-30 F600\n"
    "N140 G4 K50\n"
    "N150 G0 X150 Z50\n"
    "N160 M30\n";

// Writes the program to `path` and runs it like `kerf run PATH --motion --report R.json
// --machine MACHINE`: the report.
inline nlohmann::json runReport(const std::filesystem::path& path, const std::string& text,
                                const std::string& machine, bool motion) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    app::RunOptions options;
    options.program = path;
    options.machine = machine;
    options.motion = motion;
    options.reportFile = path.parent_path() / "report.json";
    options.stateDir = path.parent_path() / "state";
    std::ostringstream diagnostics;
    app::runProgramCommand(options, diagnostics);
    std::ifstream in(*options.reportFile);
    return nlohmann::json::parse(in);
}

// The simulated program run's time: `kerf run --motion`'s motion.duration_s.
inline double simulatedProgramRunS(const std::filesystem::path& path, const std::string& text,
                                   const std::string& machine) {
    return runReport(path, text, machine, true)["motion"]["duration_s"].get<double>();
}

}  // namespace kerf::test
