#include "core/interp/fagor/g_functions.h"

#include <array>
#include <cstddef>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

constexpr uint16_t kM = kModal;

constexpr GFunction kFunctions[] = {
    {0, GGroup::Motion, kM, KERF_TR_NOOP("rapid positioning")},
    {1, GGroup::Motion, kM, KERF_TR_NOOP("linear interpolation")},
    {2, GGroup::Motion, kM, KERF_TR_NOOP("circular interpolation clockwise")},
    {3, GGroup::Motion, kM, KERF_TR_NOOP("circular interpolation counter-clockwise")},
    {4, GGroup::None, 0, KERF_TR_NOOP("dwell / stop block preparation")},
    {5, GGroup::Corner, kM, KERF_TR_NOOP("round corner")},
    {6, GGroup::None, 0, KERF_TR_NOOP("arc centre in absolute coordinates")},
    {7, GGroup::Corner, kM, KERF_TR_NOOP("sharp corner")},
    {8, GGroup::ArcForm, 0, KERF_TR_NOOP("arc tangent to the previous path")},
    {9, GGroup::ArcForm, 0, KERF_TR_NOOP("arc through three points")},
    {10, GGroup::Mirror, kM, KERF_TR_NOOP("mirror image off")},
    {11, GGroup::Mirror, kM | kCombinable, KERF_TR_NOOP("mirror image in X")},
    {12, GGroup::Mirror, kM | kCombinable, KERF_TR_NOOP("mirror image in Y")},
    {13, GGroup::Mirror, kM | kCombinable, KERF_TR_NOOP("mirror image in Z")},
    {14, GGroup::Mirror, kM | kAlone, KERF_TR_NOOP("mirror image in the programmed axes")},
    {16, GGroup::Plane, kM | kAlone, KERF_TR_NOOP("main plane by two axes")},
    {17, GGroup::Plane, kM, KERF_TR_NOOP("main plane XY")},
    {18, GGroup::Plane, kM, KERF_TR_NOOP("main plane ZX")},
    {19, GGroup::Plane, kM, KERF_TR_NOOP("main plane YZ")},
    {20, GGroup::WorkZone, 0, KERF_TR_NOOP("work zone lower limits")},
    {21, GGroup::WorkZone, 0, KERF_TR_NOOP("work zone upper limits")},
    {22, GGroup::WorkZone, 0, KERF_TR_NOOP("work zone enable/disable")},
    {32, GGroup::FeedMode, kM, KERF_TR_NOOP("feed as inverse of time")},
    {33, GGroup::Motion, kM, KERF_TR_NOOP("electronic threading")},
    {34, GGroup::Motion, kM, KERF_TR_NOOP("variable-pitch threading")},
    {36, GGroup::CornerShape, 0, KERF_TR_NOOP("corner rounding")},
    {37, GGroup::None, 0, KERF_TR_NOOP("tangential entry")},
    {38, GGroup::CornerShape, 0, KERF_TR_NOOP("tangential exit")},
    {39, GGroup::CornerShape, 0, KERF_TR_NOOP("chamfer")},
    {40, GGroup::Compensation, kM, KERF_TR_NOOP("radius compensation off")},
    {41, GGroup::Compensation, kM, KERF_TR_NOOP("radius compensation left")},
    {42, GGroup::Compensation, kM, KERF_TR_NOOP("radius compensation right")},
    {46, GGroup::None, kNotSupported, KERF_TR_NOOP("inclined-axis transformation")},
    {50, GGroup::Corner, kM, KERF_TR_NOOP("controlled round corner")},
    {51, GGroup::Corner, kM | kAlone, KERF_TR_NOOP("look-ahead")},
    {52, GGroup::None, 0, KERF_TR_NOOP("move to hard stop")},
    {53, GGroup::ZeroOffset, 0, KERF_TR_NOOP("coordinates from machine zero")},
    {54, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("absolute zero offset 1")},
    {55, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("absolute zero offset 2")},
    {56, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("absolute zero offset 3")},
    {57, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("absolute zero offset 4")},
    {58, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("additive zero offset 1")},
    {59, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("additive zero offset 2")},
    {66, GGroup::None, 0, KERF_TR_NOOP("pattern repeat cycle")},
    {68, GGroup::None, 0, KERF_TR_NOOP("stock removal cycle along X")},
    {69, GGroup::None, 0, KERF_TR_NOOP("stock removal cycle along Z")},
    {70, GGroup::Units, kM, KERF_TR_NOOP("programming in inches")},
    {71, GGroup::Units, kM, KERF_TR_NOOP("programming in millimetres")},
    {72, GGroup::None, kM | kAlone, KERF_TR_NOOP("scaling factor")},
    {74, GGroup::None, kNoOtherG, KERF_TR_NOOP("machine reference search")},
    {75, GGroup::None, 0, KERF_TR_NOOP("probing move until touching")},
    {76, GGroup::None, 0, KERF_TR_NOOP("probing move until no longer touching")},
    {81, GGroup::None, 0, KERF_TR_NOOP("turning cycle, straight sections")},
    {82, GGroup::None, 0, KERF_TR_NOOP("facing cycle, straight sections")},
    {83, GGroup::None, 0, KERF_TR_NOOP("drilling cycle")},
    {84, GGroup::None, 0, KERF_TR_NOOP("turning cycle, curved sections")},
    {85, GGroup::None, 0, KERF_TR_NOOP("facing cycle, curved sections")},
    {86, GGroup::None, 0, KERF_TR_NOOP("longitudinal threading cycle")},
    {87, GGroup::None, 0, KERF_TR_NOOP("face threading cycle")},
    {88, GGroup::None, 0, KERF_TR_NOOP("grooving cycle along X")},
    {89, GGroup::None, 0, KERF_TR_NOOP("grooving cycle along Z")},
    {90, GGroup::Distance, kM, KERF_TR_NOOP("absolute programming")},
    {91, GGroup::Distance, kM, KERF_TR_NOOP("incremental programming")},
    {92, GGroup::ZeroOffset, kAlone, KERF_TR_NOOP("coordinate preset / spindle speed limit")},
    {93, GGroup::None, kAlone, KERF_TR_NOOP("polar origin preset")},
    {94, GGroup::FeedMode, kM, KERF_TR_NOOP("feed per minute")},
    {95, GGroup::FeedMode, kM, KERF_TR_NOOP("feed per revolution")},
    {96, GGroup::SpindleMode, kM, KERF_TR_NOOP("constant surface speed")},
    {97, GGroup::SpindleMode, kM, KERF_TR_NOOP("spindle speed in rpm")},
    {151, GGroup::XFormat, kM, KERF_TR_NOOP("X in diameter")},
    {152, GGroup::XFormat, kM, KERF_TR_NOOP("X in radius")},
    {159, GGroup::ZeroOffset, kM | kAlone, KERF_TR_NOOP("absolute zero offset N1-N20")},
    {233, GGroup::None, kM | kAlone, KERF_TR_NOOP("axis retraction when threading stops")},
};

constexpr int kMaxNumber = 319;

constexpr std::array<int16_t, kMaxNumber + 1> buildIndex() {
    std::array<int16_t, kMaxNumber + 1> index{};
    for (auto& i : index)
        i = -1;
    for (size_t i = 0; i < std::size(kFunctions); ++i) {
        index[kFunctions[i].number] = static_cast<int16_t>(i);
    }
    return index;
}

constexpr auto kIndex = buildIndex();

}  // namespace

const GFunction* gFunction(int number) {
    if (number < 0 || number > kMaxNumber) return nullptr;
    const int16_t i = kIndex[static_cast<size_t>(number)];
    return i < 0 ? nullptr : &kFunctions[i];
}

}  // namespace kerf::fagor
