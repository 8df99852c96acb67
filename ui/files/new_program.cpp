#include "ui/files/new_program.h"

#include <cmath>
#include <cstdio>

namespace kerf::ui {

namespace {

bool isLathe(const machine::MachineConfig& machine) {
    return machine.kind == machine::MachineKind::Lathe;
}

// A signed value as Klartext writes it: "+100", "-40", "+12.5".
std::string signedValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.4f", value == 0.0 ? 0.0 : value);
    std::string out = text;
    while (out.back() == '0')
        out.pop_back();
    if (out.back() == '.') out.pop_back();
    return out;
}

std::string programStem(const std::string& fileName) {
    return std::filesystem::path(fileName).stem().string();
}

bool isIsoName(const std::string& fileName) {
    const std::string extension = std::filesystem::path(fileName).extension().string();
    return extension == ".I" || extension == ".i";
}

// The blank's corners in the ISO blocks G30 (with the tool axis' plane) and G31.
std::string isoProgramText(const machine::MachineConfig& machine, const NewProgramSpec& spec,
                           const std::string& name) {
    const std::string unit = spec.inch ? " G70 *\n" : " G71 *\n";
    const std::string plane =
        machine.toolAxis == 'X' ? "G19" : (machine.toolAxis == 'Y' ? "G18" : "G17");
    const auto& lo = spec.blankMin;
    const auto& hi = spec.blankMax;
    return "%" + name + unit +  //
           "N10 G30 " + plane + " X" + signedValue(lo[0]) + " Y" + signedValue(lo[1]) + " Z" +
           signedValue(lo[2]) + " *\n" +  //
           "N20 G31 G90 X" + signedValue(hi[0]) + " Y" + signedValue(hi[1]) + " Z" +
           signedValue(hi[2]) + " *\n" +  //
           "N99999999 %" + name + unit;
}

}  // namespace

std::string newProgramFileName(const machine::MachineConfig& machine, const std::string& given) {
    // A FAGOR programmer writes the name as the header has it, "%PART": the % is no part of it.
    const std::string name = isLathe(machine) && given.starts_with('%') ? given.substr(1) : given;
    if (std::filesystem::path(name).has_extension()) return name;
    return name + (isLathe(machine) ? ".PIM" : ".H");
}

std::string newProgramText(const machine::MachineConfig& machine, const NewProgramSpec& spec) {
    const std::string name = programStem(newProgramFileName(machine, spec.name));
    if (isLathe(machine)) {
        return "%" + name + ",MX,\n" + (spec.inch ? "N10 G70\n" : "N10 G71\n") + "N20 M30\n";
    }
    if (isIsoName(spec.name)) return isoProgramText(machine, spec, name);
    const std::string unit = spec.inch ? "INCH" : "MM";
    const std::string axis(1, machine.toolAxis);
    const auto& lo = spec.blankMin;
    const auto& hi = spec.blankMax;
    return "0 BEGIN PGM " + name + " " + unit + "\n" +  //
           "1 BLK FORM 0.1 " + axis + " X" + signedValue(lo[0]) + " Y" + signedValue(lo[1]) + " Z" +
           signedValue(lo[2]) + "\n" +  //
           "2 BLK FORM 0.2 X" + signedValue(hi[0]) + " Y" + signedValue(hi[1]) + " Z" +
           signedValue(hi[2]) + "\n" +  //
           "3 END PGM " + name + " " + unit + "\n";
}

}  // namespace kerf::ui
