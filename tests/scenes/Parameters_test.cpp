// ParameterSet: inclusive ranges in the stored type, aliases, panel-only entries; and every scene's table, which
// generates both `--set` and the panel: each panel widget is a --set key with the same range, both bounds
// are accepted, and the labels, ranges, widths and line breaks are the book's (docs/book-reference.md §2).
#include "Demos/Scenes/Parameters.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "Demos/Scenes/Ch15Scene.h"
#include "Demos/Scenes/Ch16Scene.h"
#include "Demos/Scenes/CollisionFeatureScene.h"
#include "Demos/Scenes/JointScene.h"
#include "Demos/Scenes/LinearImpulseScene.h"
#include "Demos/Scenes/MomentumScene.h"
#include "Demos/Scenes/RaycastScene.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Demos/Scenes/SpringsScene.h"

namespace {

using Entry = ParameterSet::Entry;
using Type = ParameterSet::Widget::Type;

/// A bound as `--params` prints it (default stream precision): "0.1", "0.0005", "-5".
std::string BoundText(const Entry& e, double bound) {
    std::ostringstream s;
    if (e.kind == ParameterSet::Kind::Int)
        s << static_cast<long>(bound);
    else
        s << bound;
    return s.str();
}

/// One expected panel widget: the book's label, range (sliders), item width and whether it continues a line.
struct BookWidget {
    const char* label;
    Type type;
    double min, max;
    float itemWidth;
    bool sameLine;
};

/// Checks the table's panel widgets, in order, against `expected`.
void ExpectPanel(const ParameterSet& set, const std::vector<BookWidget>& expected) {
    std::vector<const Entry*> widgets;
    for (const Entry& e : set.Entries())
        if (e.widget.type != Type::None && e.widget.type != Type::Text) widgets.push_back(&e);
    ASSERT_EQ(widgets.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const Entry& e = *widgets[i];
        const BookWidget& b = expected[i];
        SCOPED_TRACE(b.label);
        EXPECT_EQ(e.widget.label, b.label);
        EXPECT_EQ(e.widget.type, b.type);
        EXPECT_EQ(e.widget.itemWidth, b.itemWidth);
        EXPECT_EQ(e.widget.sameLine, b.sameLine);
        if (b.type == Type::Slider || b.type == Type::InputInt) {
            EXPECT_EQ(static_cast<float>(e.min), static_cast<float>(b.min));
            EXPECT_EQ(static_cast<float>(e.max), static_cast<float>(b.max));
        }
    }
}

/// Every value widget is a --set key of a matching kind; --set accepts both bounds as printed, inclusive,
/// and refuses values just outside; every button runs something.
void ExpectWidgetsAreKeys(ParameterSet& set) {
    // Set may run onChange (a scene rebuild); it never changes the table itself.
    for (const Entry& e : set.Entries()) {
        const Type type = e.widget.type;
        if (type == Type::None || type == Type::Text) continue;
        SCOPED_TRACE(e.widget.label.empty() ? e.key : e.widget.label);
        if (type == Type::Button) {
            EXPECT_TRUE(static_cast<bool>(e.onChange));
            continue;
        }
        ASSERT_FALSE(e.key.empty());
        EXPECT_EQ(set.Find(e.key), &e);
        switch (type) {
            case Type::Slider:
                EXPECT_TRUE(e.kind == ParameterSet::Kind::Int || e.kind == ParameterSet::Kind::Float);
                break;
            case Type::InputInt:
                EXPECT_EQ(e.kind, ParameterSet::Kind::Int);
                break;
            case Type::Checkbox:
                EXPECT_EQ(e.kind, ParameterSet::Kind::Bool);
                break;
            case Type::RadioButtons:
                EXPECT_EQ(e.kind, ParameterSet::Kind::Choice);
                EXPECT_EQ(e.widget.choiceLabels.size(), e.choices.size());
                break;
            default:
                break;
        }
        if (e.kind != ParameterSet::Kind::Int && e.kind != ParameterSet::Kind::Float) continue;
        const std::string key = e.key;
        const double lo = e.min, hi = e.max;
        const bool isInt = e.kind == ParameterSet::Kind::Int;
        const double step = isInt ? 1.0 : (hi - lo) * 1e-3;
        std::string error;
        EXPECT_TRUE(set.Set(key, BoundText(e, lo), &error)) << error;
        EXPECT_EQ(set.Get(key), BoundText(e, lo));
        EXPECT_TRUE(set.Set(key, BoundText(e, hi), &error)) << error;
        EXPECT_EQ(set.Get(key), BoundText(e, hi));
        EXPECT_FALSE(set.Set(key, BoundText(e, lo - step), &error)) << key;
        EXPECT_FALSE(set.Set(key, BoundText(e, hi + step), &error)) << key;
    }
}

}  // namespace

// The documented minimums were refused: "0.1" parses to a double below the bound 0.1f (0.10000000149).
TEST(ParameterSet, FloatRangeIsInclusiveAtTheDocumentedBounds) {
    float distance = 0.5f, projection = 0.45f, dt = 0.03f;
    ParameterSet set;
    set.AddFloat("distance", &distance, 0.1f, 1.0f, "");
    set.AddFloat("projection", &projection, 0.2f, 0.8f, "");
    set.AddFloat("dt", &dt, kMinSceneDt, kMaxSceneDt, "");
    std::string error;
    EXPECT_TRUE(set.Set("distance", "0.1", &error)) << error;
    EXPECT_EQ(distance, 0.1f);
    EXPECT_TRUE(set.Set("distance", "1", &error)) << error;
    EXPECT_TRUE(set.Set("projection", "0.2", &error)) << error;
    EXPECT_EQ(projection, 0.2f);
    EXPECT_TRUE(set.Set("projection", "0.8", &error)) << error;
    EXPECT_TRUE(set.Set("dt", "0.0005", &error)) << error;
    EXPECT_EQ(dt, 0.0005f);
    EXPECT_TRUE(set.Set("dt", "0.1", &error)) << error;
    EXPECT_FALSE(set.Set("distance", "0.0999", &error));
    EXPECT_NE(error.find("expected number 0.1..1"), std::string::npos) << error;
    EXPECT_FALSE(set.Set("projection", "0.8001", &error));
    EXPECT_FALSE(set.Set("dt", "0.0004", &error));
    EXPECT_EQ(dt, 0.1f);  // a refused value changes nothing
}

// A step entry (docs/app.md, "Steps") takes a decimal or a fraction; one that is not a whole number of microseconds
// is kept with a note (the host runs it rounded), and a positive one that rounds to 0 is refused, not made the
// host's step (0). Other float entries take no fraction.
TEST(ParameterSet, StepEntriesTakeFractionsAndNoteRounding) {
    float dt = 0.03f, other = 0.5f;
    ParameterSet set;
    set.AddFloat("dt", &dt, 0.0f, 0.1f, "").Step();
    set.AddFloat("other", &other, 0.0f, 1.0f, "");
    std::string error, note;
    EXPECT_TRUE(set.Set("dt", "0.01", &error, &note)) << error;
    EXPECT_EQ(dt, 0.01f);
    EXPECT_TRUE(note.empty()) << note;
    EXPECT_TRUE(set.Set("dt", "1/50", &error, &note)) << error;
    EXPECT_EQ(dt, 0.02f);
    EXPECT_TRUE(note.empty()) << note;
    EXPECT_TRUE(set.Set("dt", "0.0166666667", &error, &note)) << error;
    EXPECT_EQ(note,
              "--set dt=0.0166666667: 0.0166666667 s rounded to 0.016667 s (a step is a whole number of "
              "microseconds; docs/app.md, \"Steps\")");
    note.clear();
    EXPECT_TRUE(set.Set("dt", "1/60", &error, &note)) << error;
    EXPECT_NE(note.find("1/60 s rounded to 0.016667 s"), std::string::npos) << note;
    EXPECT_TRUE(set.Set("dt", "0", &error, &note)) << error;
    EXPECT_EQ(dt, 0.0f);
    EXPECT_FALSE(set.Set("dt", "1e-9", &error, &note));
    EXPECT_NE(error.find("bad value '1e-9' for 'dt'"), std::string::npos) << error;
    EXPECT_EQ(dt, 0.0f);
    EXPECT_FALSE(set.Set("dt", "1e-400", &error, &note));  // below a double: not 0, the host's step
    EXPECT_FALSE(set.Set("other", "1/2", &error));
}

TEST(ParameterSet, IntRangeIsInclusive) {
    int count = 10;
    ParameterSet set;
    set.AddInt("count", &count, 5, 30, "");
    std::string error;
    EXPECT_TRUE(set.Set("count", "5", &error)) << error;
    EXPECT_TRUE(set.Set("count", "30", &error)) << error;
    EXPECT_EQ(count, 30);
    EXPECT_FALSE(set.Set("count", "4", &error));
    EXPECT_FALSE(set.Set("count", "31", &error));
}

TEST(ParameterSet, ADeprecatedKeySetsTheSameValueAndItsNoteNamesTheNewKey) {
    float bound = 0.0f;
    ParameterSet set;
    set.AddFloat("error-budget", &bound, 0.0f, 1.0f, "").DeprecatedAlias("tolerance");
    std::string error, note;
    ASSERT_TRUE(set.Set("tolerance", "0.25", &error, &note)) << error;
    EXPECT_EQ(bound, 0.25f);
    EXPECT_NE(note.find("'tolerance' is deprecated; use 'error-budget'"), std::string::npos) << note;
    note.clear();
    ASSERT_TRUE(set.Set("error-budget", "0.5", &error, &note)) << error;
    EXPECT_EQ(bound, 0.5f);
    EXPECT_EQ(note, "");
    EXPECT_FALSE(set.Set("tolerance", "2", &error, &note));  // the old key keeps the new key's range
    EXPECT_NE(error.find("'tolerance'"), std::string::npos) << error;
    EXPECT_EQ(set.Describe().find("tolerance"), std::string::npos) << set.Describe();  // not listed as a key
}

TEST(ParameterSet, AliasesSetTheSameValueAndAreListed) {
    float value = 0.0f;
    ParameterSet set;
    set.AddFloat("spring-damping", &value, 0.0f, 1.0f, "damping").Alias("damping").Alias("d");
    std::string error;
    ASSERT_TRUE(set.Set("damping", "0.25", &error)) << error;
    EXPECT_EQ(value, 0.25f);
    ASSERT_TRUE(set.Set("d", "0.5", &error)) << error;
    EXPECT_EQ(value, 0.5f);
    EXPECT_EQ(set.Find("damping"), set.Find("spring-damping"));
    EXPECT_EQ(set.Keys(), "spring-damping");
    EXPECT_NE(set.Describe().find("spring-damping = 0.5"), std::string::npos) << set.Describe();
    EXPECT_NE(set.Describe().find("(also: damping, d)"), std::string::npos) << set.Describe();
    int count = 50, iterations = 8;
    set.AddInt("count", &count, 2, 100, "").OnPanel(ParameterSet::Widget::Slider("##count").Caption("Particle count"));
    set.AddInt("iterations", &iterations, 1, 20, "").Alias("it").OnPanel(ParameterSet::Widget::Slider("Iteration"));
    EXPECT_NE(set.Describe().find("(panel \"Particle count\")"), std::string::npos) << set.Describe();
    EXPECT_NE(set.Describe().find("(also: it; panel \"Iteration\")"), std::string::npos) << set.Describe();
}

TEST(ParameterSet, PanelOnlyEntriesAreNotKeys) {
    int clicks = 0;
    ParameterSet set;
    set.AddAction(
        "reset", [&] { ++clicks; }, "reset");
    set.AddPanelButton(ParameterSet::Widget::Button("Show Help").SameLine(), [&] { clicks += 10; });
    set.AddPanelText([] { return std::string("row"); });
    EXPECT_EQ(set.Entries().size(), 3u);
    EXPECT_EQ(set.Keys(), "reset");
    EXPECT_EQ(set.Find(""), nullptr);
    std::string error;
    EXPECT_FALSE(set.Set("", "1", &error));
    EXPECT_FALSE(set.Set("Show Help", "1", &error));
    EXPECT_EQ(clicks, 0);
    EXPECT_EQ(set.Describe().find("Show Help"), std::string::npos);
    EXPECT_EQ(set.Entries()[1].widget.label, "Show Help");
    EXPECT_TRUE(set.Entries()[1].widget.sameLine);
    EXPECT_EQ(set.Entries()[2].text(), "row");
}

TEST(ParameterTables, Ch15IsTheBooksPanel) {
    Ch15Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"Porjection", Type::Slider, 0.2, 0.8, 55.0f, false},
                      {"Slop", Type::Slider, 0.01, 0.1, 55.0f, true},
                      {"Iteration", Type::Slider, 1, 20, 55.0f, true},
                      {"Reset", Type::Button, 0, 0, 0.0f, false},
                      {"Debug Render", Type::Checkbox, 0, 0, 0.0f, true},
                      {"Linear Projection", Type::Checkbox, 0, 0, 0.0f, true}});
    ExpectWidgetsAreKeys(set);
    // The book's word survives as an alias of the honest key.
    std::string error;
    ASSERT_TRUE(set.Set("projection", "0.3", &error)) << error;
    EXPECT_EQ(scene.Params().projectionFraction, 0.3f);
}

TEST(ParameterTables, Ch16IsTheBooksPanel) {
    Ch16Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"Count", Type::Slider, 5, 30, 50.0f, false},
                      {"Distance", Type::Slider, 0.1, 1.0, 50.0f, true},
                      {"Spring k", Type::Slider, -5.0, 0.0, 50.0f, true},
                      {"Reset", Type::Button, 0, 0, 0.0f, false}});
    ExpectWidgetsAreKeys(set);
    std::string error;
    ASSERT_TRUE(set.Set("damping", "0.2", &error)) << error;  // the old key, now an alias
    EXPECT_EQ(scene.Params().springDamping, 0.2f);
    ASSERT_TRUE(set.Set("dt", "0.0005", &error)) << error;  // the documented minimum
    EXPECT_EQ(scene.Params().dt, 0.0005f);
}

TEST(ParameterTables, SpringsIsTheBooksPanel) {
    SpringsScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"k", Type::Slider, -5.0, 0.0, 100.0f, false},
                      {"b", Type::Slider, 0.0, 1.0, 100.0f, true},
                      {"l", Type::Slider, 0.0, 5.0, 100.0f, true},
                      {"Reset", Type::Button, 0, 0, 0.0f, false}});
    ExpectWidgetsAreKeys(set);
    std::string error;
    ASSERT_TRUE(set.Set("b", "0.25", &error)) << error;
    EXPECT_EQ(scene.Params().springDamping, 0.25f);
    ASSERT_TRUE(set.Set("l", "2", &error)) << error;
    EXPECT_EQ(scene.Params().restLength, 2.0f);
}

TEST(ParameterTables, JointIsTheBooksPanel) {
    JointScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"##count", Type::Slider, 2, 100, 100.0f, false}, {"Reset", Type::Button, 0, 0, 0.0f, true}});
    EXPECT_EQ(set.Find("particles")->widget.caption, "Particle count");
    ExpectWidgetsAreKeys(set);
    std::string error;
    ASSERT_TRUE(set.Set("count", "20", &error)) << error;
    EXPECT_EQ(scene.Params().particleCount, 20);
}

TEST(ParameterTables, LinearImpulseIsTheBooksPanel) {
    LinearImpulseScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"Step", Type::Button, 0, 0, 0.0f, false},
                      {"Frames", Type::InputInt, 1, 1000, 100.0f, true},
                      {"Reset", Type::Button, 0, 0, 0.0f, true},
                      {"Pause", Type::Checkbox, 0, 0, 0.0f, true},
                      {"Spheres", Type::Checkbox, 0, 0, 0.0f, false},
                      {"Drop", Type::Checkbox, 0, 0, 0.0f, true}});
    // Only Spheres and Drop take effect at once on the panel (they reset the scene, as the book).
    for (const Entry& e : set.Entries())
        EXPECT_EQ(e.widget.appliesAtOnce, e.key == "spheres" || e.key == "drop") << e.key;
    ExpectWidgetsAreKeys(set);
}

TEST(ParameterTables, MomentumIsTheBooksPanel) {
    MomentumScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    ExpectPanel(set, {{"Reset", Type::Button, 0, 0, 0.0f, false}});
    ExpectWidgetsAreKeys(set);
}

TEST(ParameterTables, CollisionFeatureRadioButtonsAreTheBooks) {
    CollisionFeatureParams params;
    ParameterSet set;
    AddCollisionFeatureParameters(&set, &params);
    const Entry* gizmo = set.Find("gizmo");
    const Entry* space = set.Find("space");
    ASSERT_NE(gizmo, nullptr);
    ASSERT_NE(space, nullptr);
    EXPECT_EQ(gizmo->widget.choiceLabels, (std::vector<std::string>{"Translate", "Rotate", "Scale"}));
    EXPECT_EQ(space->widget.choiceLabels, (std::vector<std::string>{"Local", "World"}));
    EXPECT_EQ(set.Find("script")->widget.type, Type::None);  // --set only: the book has no such widget
    ExpectWidgetsAreKeys(set);
    std::string error;
    ASSERT_TRUE(set.Set("gizmo", "scale", &error)) << error;
    EXPECT_EQ(params.gizmo, 2);
}

TEST(ParameterTables, RaycastPanel) {
    RaycastParams params;
    ParameterSet set;
    AddRaycastParameters(&set, &params);
    ExpectPanel(
        set, {{"Scripted pick", Type::Checkbox, 0, 0, 0.0f, false}, {"Speed", Type::Slider, 0.0, 8.0, 100.0f, true}});
    EXPECT_EQ(set.Find("speed")->widget.format, "%.2f");
    ExpectWidgetsAreKeys(set);
}
