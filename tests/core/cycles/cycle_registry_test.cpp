// The catalogue: every cycle of the issue is present once, with parameters the HMI can use.
#include "core/cycles/cycle_registry.h"

#include <set>

#include <gtest/gtest.h>

namespace kerf::cycles {
namespace {

TEST(CycleRegistry, ListsEveryImplementedCycleOnce) {
    std::set<int> numbers;
    for (const CycleDescriptor* c : allCycles())
        EXPECT_TRUE(numbers.insert(c->number).second);
    for (int n : {7,   8,   9,   10,  11,  12,  13,  14,  18,  19,  20,  21,  22,  23,
                  24,  26,  32,  200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 220,
                  221, 225, 232, 240, 241, 247, 251, 252, 253, 254, 256, 257, 258, 262,
                  263, 264, 265, 267, 25,  270, 275, 233, 276, 27,  28,  29,  39}) {
        EXPECT_NE(findCycle(n), nullptr) << n;
    }
}

TEST(CycleRegistry, DescriptorsAreComplete) {
    for (const CycleDescriptor* c : allCycles()) {
        EXPECT_NE(c->name, nullptr);
        EXPECT_FALSE(c->parameters.empty()) << c->number;
        const bool callActive = c->activation == Activation::Call;
        // Machining cycles expand; pattern cycles list points; the rest the interpreter runs.
        if (callActive && c->number != 12) {
            EXPECT_NE(c->expand, nullptr) << c->number;
        }
        std::set<uint16_t> qs;
        for (const ParameterDescriptor& p : c->parameters) {
            EXPECT_NE(p.description, nullptr) << c->number;
            EXPECT_LE(p.min, p.max) << c->number << " Q" << p.q;
            EXPECT_TRUE(p.q != 0 || p.word != nullptr) << c->number;
            if (p.q != 0) {
                EXPECT_TRUE(qs.insert(p.q).second) << c->number << " Q" << p.q;
            }
        }
    }
    EXPECT_EQ(findCycle(220)->activation, Activation::Def);
    EXPECT_EQ(findCycle(200)->activation, Activation::Call);
}

TEST(CycleRegistry, RangeErrorsNameCycleParameterAndMeaning) {
    const CycleDescriptor& c = *findCycle(202);
    auto error = checkParameter(c, *c.parameter(214), 5.0);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->args[0], "202");
    EXPECT_EQ(error->args[1], "Q214");
    EXPECT_NE(error->args[2].find("Disengaging"), std::string::npos);
    EXPECT_FALSE(checkParameter(c, *c.parameter(214), 4.0));
    EXPECT_TRUE(checkParameter(c, *c.parameter(214), 2.5));  // whole numbers only
}

TEST(GlobalDef, GroupsHoldTheirParameters) {
    ASSERT_NE(findGlobalDefGroup(125), nullptr);
    EXPECT_EQ(findGlobalDefGroup(125)->parameters[0].q, 345);
    for (int n : {100, 105, 110, 111, 120})
        EXPECT_NE(findGlobalDefGroup(n), nullptr) << n;
    EXPECT_EQ(findGlobalDefGroup(130), nullptr);
}

}  // namespace
}  // namespace kerf::cycles
