// The contact-solver parameters shared by the rigid-volume scenes: the choice list follows the enum, and the panel
// row names a non-book solver only.
#include "Demos/Scenes/ContactSolverParameters.h"

#include <gtest/gtest.h>

#include <iterator>
#include <string>
#include <vector>

TEST(ContactSolverParameters, ChoicesFollowTheEnumOrder) {
    const std::vector<std::string> choices = ContactSolverChoices();
    ASSERT_EQ(choices.size(), std::size(kAllContactSolvers));
    EXPECT_EQ(choices, (std::vector<std::string>{"book", "accumulated", "soft"}));
    for (ContactSolver solver : kAllContactSolvers) {
        const int index = ContactSolverIndex(solver);
        EXPECT_EQ(index, static_cast<int>(solver));  // Ch15Params::solver = 1 is the accumulated solver
        EXPECT_EQ(ContactSolverAt(index), solver);
        EXPECT_EQ(choices[static_cast<std::size_t>(index)], ToString(solver));
    }
    EXPECT_EQ(ContactSolverAt(-1), ContactSolver::Book);
    EXPECT_EQ(ContactSolverAt(99), ContactSolver::Book);
}

TEST(ContactSolverParameters, KeysAreBoundToTheSettingsWithTheirRanges) {
    ContactSolverChoice choice;
    const SoftSolverSettings& soft = choice.soft;
    int changes = 0;
    ParameterSet set;
    AddContactSolverParameters(&set, &choice, "help", [&changes] { ++changes; });
    std::string error;
    ASSERT_TRUE(set.Set("solver", "soft", &error)) << error;
    EXPECT_EQ(ContactSolverAt(choice.solver), ContactSolver::Soft);
    ASSERT_TRUE(set.Set("soft-substeps", "64", &error)) << error;
    ASSERT_TRUE(set.Set("soft-contact-hertz", "0.1", &error)) << error;  // the bounds are inclusive
    EXPECT_EQ(soft.substeps, 64);
    EXPECT_EQ(soft.contactHertz, 0.1f);
    EXPECT_EQ(changes, 3);
    EXPECT_FALSE(set.Set("soft-substeps", "65", &error));
    EXPECT_FALSE(set.Set("soft-contact-hertz", "0", &error));
    EXPECT_FALSE(set.Set("soft-contact-damping-ratio", "-1", &error));
    EXPECT_FALSE(set.Set("soft-max-pushout-speed", "nan", &error));
    EXPECT_EQ(changes, 3);
    ASSERT_TRUE(set.Set("sleep", "1", &error)) << error;
    EXPECT_TRUE(choice.sleep);
    EXPECT_EQ(changes, 4);
    for (const char* key : {"solver", "soft-substeps", "soft-iterations", "soft-relax-iterations", "soft-contact-hertz",
                            "soft-contact-damping-ratio", "soft-max-pushout-speed", "sleep"}) {
        const ParameterSet::Entry* e = set.Find(key);
        ASSERT_NE(e, nullptr) << key;
        EXPECT_EQ(e->widget.type, ParameterSet::Widget::Type::None) << key << ": not a book widget";
    }
}

TEST(ContactSolverParameters, PanelRowNamesANonBookSolver) {
    SoftSolverSettings soft;
    EXPECT_EQ(ContactSolverRow(ContactSolver::Book, soft), "");
    EXPECT_EQ(ContactSolverRow(ContactSolver::Accumulated, soft), "Contact solver: accumulated");
    soft.substeps = 8;
    soft.contactHertz = 45.0f;
    EXPECT_EQ(ContactSolverRow(ContactSolver::Soft, soft), "Contact solver: soft, 8 substeps, 45 Hz");
}
