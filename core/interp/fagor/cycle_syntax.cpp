#include "core/interp/fagor/cycle_syntax.h"

#include <iterator>

namespace kerf::fagor {

namespace {

// Shorthands for the manual's formats.
constexpr CycleParameter signedReq(char l, bool nonZero = false) {
    return {l, 5, 5, true, true, nonZero};
}
constexpr CycleParameter signedOpt(char l) {
    return {l, 5, 5, true, false, false};
}
constexpr CycleParameter unsignedReq(char l, bool nonZero = false) {
    return {l, 5, 5, false, true, nonZero};
}
constexpr CycleParameter unsignedOpt(char l, bool nonZero = false) {
    return {l, 5, 5, false, false, nonZero};
}
constexpr CycleParameter whole(char l, uint8_t digits, bool required, uint32_t max = 0) {
    return {l, digits, 0, false, required, false, max};
}

// G66 X Z I C [A] [L] [M] [H] S E [Q]
constexpr CycleParameter kG66[] = {
    signedReq('X'),          signedReq('Z'),      unsignedReq('I'),     unsignedReq('C', true),
    whole('A', 1, false, 1), signedOpt('L'),      signedOpt('M'),       unsignedOpt('H'),
    whole('S', 4, true),     whole('E', 4, true), whole('Q', 6, false),
};
// G68/G69 X Z C [D] [L] [M] [K] [F] [H] S E [Q]
constexpr CycleParameter kStockRemoval[] = {
    signedReq('X'),   signedReq('Z'),      unsignedReq('C', true), unsignedOpt('D'),
    signedOpt('L'),   signedOpt('M'),      unsignedOpt('K'),       unsignedOpt('F'),
    unsignedOpt('H'), whole('S', 4, true), whole('E', 4, true),    whole('Q', 6, false),
};
// G81/G82 X Z Q R C [D] [L] [M] [F] [H]
constexpr CycleParameter kStraight[] = {
    signedReq('X'),   signedReq('Z'),   signedReq('Q'),   signedReq('R'),   unsignedReq('C', true),
    unsignedOpt('D'), unsignedOpt('L'), unsignedOpt('M'), unsignedOpt('F'), unsignedOpt('H'),
};
// G84/G85 X Z Q R C [D] [L] [M] [F] [H] I K
constexpr CycleParameter kCurved[] = {
    signedReq('X'),         signedReq('Z'),   signedReq('Q'),   signedReq('R'),
    unsignedReq('C', true), unsignedOpt('D'), unsignedOpt('L'), unsignedOpt('M'),
    unsignedOpt('F'),       unsignedOpt('H'), signedReq('I'),   signedReq('K'),
};
// G83 X Z I B [D] [K] [H] [C] [L] [R]
constexpr CycleParameter kG83[] = {
    signedReq('X'),   signedReq('Z'),       signedReq('I', true), unsignedReq('B'),
    unsignedOpt('D'), whole('K', 5, false), unsignedOpt('H'),     unsignedOpt('C'),
    unsignedOpt('L'), unsignedOpt('R'),
};
// G86/G87 X Z Q R [K] I B [E] [D] [L] C [J] [A] [W] [V] [M]
constexpr CycleParameter kThreading[] = {
    signedReq('X'), signedReq('Z'),       signedReq('Q'),       signedReq('R'),
    signedOpt('K'), signedReq('I', true), signedReq('B', true), signedOpt('E'),
    signedOpt('D'), signedOpt('L'),       signedReq('C', true), signedOpt('J'),
    signedOpt('A'), signedOpt('W'),       signedOpt('V'),       signedOpt('M'),
};
// G88/G89 X Z Q R [C] [D] [K]
constexpr CycleParameter kGrooving[] = {
    signedReq('X'),         signedReq('Z'),   signedReq('Q'),       signedReq('R'),
    unsignedOpt('C', true), unsignedOpt('D'), whole('K', 5, false),
};

constexpr CycleSyntax kCycles[] = {
    {66, kG66},       {68, kStockRemoval}, {69, kStockRemoval}, {81, kStraight},
    {82, kStraight},  {83, kG83},          {84, kCurved},       {85, kCurved},
    {86, kThreading}, {87, kThreading},    {88, kGrooving},     {89, kGrooving},
};

}  // namespace

const CycleSyntax* cycleSyntax(int number) {
    for (const CycleSyntax& c : kCycles) {
        if (c.g == number) return &c;
    }
    return nullptr;
}

}  // namespace kerf::fagor
