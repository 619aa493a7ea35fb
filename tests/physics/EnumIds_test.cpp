// Physics/EnumIds.h: one id table gives an enum's id, its value back from the id, and the list for messages.
#include "Physics/EnumIds.h"

#include <gtest/gtest.h>

#include <string>

namespace {

enum class Colour { Red, Green, Blue };
constexpr EnumId<Colour> kColours[] = {{Colour::Red, "red"}, {Colour::Green, "green"}};

TEST(EnumIds, EveryIdParsesBackToItsValue) {
    for (const EnumId<Colour>& e : kColours) {
        Colour parsed = Colour::Blue;
        ASSERT_TRUE(ParseId(kColours, e.id, &parsed)) << e.id;
        EXPECT_EQ(parsed, e.value);
        EXPECT_STREQ(IdOf(kColours, e.value), e.id);
    }
}

TEST(EnumIds, AnUnknownIdLeavesTheValueUntouchedAndAValueWithoutAnIdSaysSo) {
    Colour parsed = Colour::Blue;
    EXPECT_FALSE(ParseId(kColours, "Red", &parsed)) << "ids are matched exactly";
    EXPECT_FALSE(ParseId(kColours, "", &parsed));
    EXPECT_EQ(parsed, Colour::Blue);
    EXPECT_TRUE(ParseId(kColours, "green", static_cast<Colour*>(nullptr))) << "a check without an output";
    EXPECT_STREQ(IdOf(kColours, Colour::Blue), "unknown");
}

TEST(EnumIds, TheIdsAreListedInTableOrder) { EXPECT_EQ(JoinIds(kColours), "red, green"); }

}  // namespace
