// The first frame of each demo against the book's reference frames (795x593 captures with the panels):
// layout only, region by region: panel edges, the background and the ground colour. Not a pixel match.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "Platform/PngCodec.h"
#include "tests/app/SandboxRun.h"

namespace fs = std::filesystem;

namespace {

constexpr int kRefWidth = 795, kRefHeight = 593;
const int kBackground[3] = {128, 153, 178};  // clear colour (0.5, 0.6, 0.7), docs/book-reference.md §1.3

struct Rect {
    int x0, y0, x1, y1;  // inclusive-exclusive
};

struct Reference {
    const char* id;
    const char* file;
    Rect sky;     ///< a patch of background in the reference (no objects)
    Rect ground;  ///< a patch of the ground plane
};

// Patches picked by eye on the reference frames; the ground is static, so frame 0 shows it the same.
const Reference kReferences[] = {
    {"ch14", "book-ch14-early.png", {560, 115, 620, 145}, {300, 520, 500, 580}},
    {"ch15", "book-ch15-early.png", {650, 200, 720, 240}, {300, 520, 500, 580}},
    {"ch16", "book-ch16-early.png", {650, 140, 720, 180}, {300, 520, 500, 580}},
};

std::string ReferenceDir() {
    // The captures of the book's demo are not part of the repository; they are looked for beside it.
    return (fs::path(PSB_SOURCE_DIR).parent_path() / "shared" / "reference").string();
}

bool IsBackground(const Image& img, int x, int y) {
    const std::uint8_t* p = img.Pixel(x, y);
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - kBackground[c]) > 24) return false;
    return true;
}

// First x in [from, to) (stepping either way) whose pixel on row y is not background; -1 if none.
int FirstNonBackground(const Image& img, int y, int from, int to) {
    const int step = from < to ? 1 : -1;
    for (int x = from; x != to; x += step)
        if (!IsBackground(img, x, y)) return x;
    return -1;
}

// First y going down column x from `from` that is background; -1 if none.
int FirstBackgroundBelow(const Image& img, int x, int from) {
    for (int y = from; y < img.height; ++y)
        if (IsBackground(img, x, y)) return y;
    return -1;
}

void MeanColour(const Image& img, const Rect& r, double out[3]) {
    out[0] = out[1] = out[2] = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
            for (int c = 0; c < 3; ++c) out[c] += img.Pixel(x, y)[c];
    const double n = double(r.x1 - r.x0) * (r.y1 - r.y0);
    for (int c = 0; c < 3; ++c) out[c] /= n;
}

struct PanelEdges {
    int mainLeft, mainRight, mainBottom;  // "Physics Demo" at (10,10), 370 wide (docs/book-reference.md §1.7)
    int demoLeft, demoRight, demoBottom;  // the demo's panel at (400,10), 370 wide
};

// Measured on the title-bar row (y = 17) and down columns inside each panel, from the background side.
PanelEdges MeasurePanels(const Image& img) {
    PanelEdges e;
    e.mainLeft = FirstNonBackground(img, 17, 0, 60);
    e.mainRight = FirstNonBackground(img, 17, 395, 300);
    e.mainBottom = FirstBackgroundBelow(img, 30, 30);
    e.demoLeft = FirstNonBackground(img, 17, 380, 460);
    e.demoRight = FirstNonBackground(img, 17, kRefWidth - 1, 700);
    e.demoBottom = FirstBackgroundBelow(img, 760, 30);
    return e;
}

void ExpectAllEdgesFound(const PanelEdges& e, const std::string& what) {
    for (int edge : {e.mainLeft, e.mainRight, e.mainBottom, e.demoLeft, e.demoRight, e.demoBottom})
        EXPECT_GE(edge, 0) << what << ": a panel edge was not found";
}

Image RenderFirstFrame(const std::string& id) {
    const std::string out = ScratchDir("layout_" + id);
    const SandboxResult r =
        RunSandboxExe({"--demo", id, "--frames", "1", "--size", "795x593", "--out", out, "--quiet"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Image img;
    std::string error;
    EXPECT_TRUE(ReadPngFile(out + "/frame_00000.png", &img, &error)) << error;
    fs::remove_all(out);
    return img;
}

bool Registered(const std::string& id) {
    for (const std::string& d : ListDemoIds())
        if (d == id) return true;
    return false;
}

}  // namespace

class FirstFrameLayout : public ::testing::TestWithParam<Reference> {};

TEST_P(FirstFrameLayout, MatchesTheBookReference) {
    const Reference& ref = GetParam();
    const std::string path = ReferenceDir() + "/" + ref.file;
    if (!fs::exists(path)) GTEST_SKIP() << "reference frame " << path << " not found (../shared/reference)";
    ASSERT_TRUE(Registered(ref.id)) << "demo " << ref.id << " is not registered";
    Image book;
    std::string error;
    ASSERT_TRUE(ReadPngFile(path, &book, &error)) << error;
    ASSERT_EQ(book.width, kRefWidth);
    ASSERT_EQ(book.height, kRefHeight);
    const Image ours = RenderFirstFrame(ref.id);
    ASSERT_EQ(ours.width, kRefWidth);
    ASSERT_EQ(ours.height, kRefHeight);

    // Background: the patch is the clear colour in both.
    double bookSky[3], ourSky[3];
    MeanColour(book, ref.sky, bookSky);
    MeanColour(ours, ref.sky, ourSky);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(bookSky[c], kBackground[c], 3.0) << "reference sky channel " << c;
        EXPECT_NEAR(ourSky[c], kBackground[c], 1.0) << "our sky channel " << c;
    }
    // Ground: same lit colour (docs/book-reference.md §1.5: saturated top faces), within GIF quantisation.
    double bookGround[3], ourGround[3];
    MeanColour(book, ref.ground, bookGround);
    MeanColour(ours, ref.ground, ourGround);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ourGround[c], bookGround[c], 12.0) << "ground channel " << c;

    // Panels: edges within a few pixels of the reference. Every edge is found on the reference (-1 = not
    // found), so two missing edges cannot compare equal.
    const PanelEdges b = MeasurePanels(book), o = MeasurePanels(ours);
    ExpectAllEdgesFound(b, "reference");
    EXPECT_NEAR(o.mainLeft, b.mainLeft, 3);
    EXPECT_NEAR(o.mainRight, b.mainRight, 3);
    EXPECT_NEAR(o.mainBottom, b.mainBottom, 4);
    EXPECT_NEAR(o.demoLeft, b.demoLeft, 3);
    EXPECT_NEAR(o.demoRight, b.demoRight, 3);
    EXPECT_NEAR(o.demoBottom, b.demoBottom, 4);
}

INSTANTIATE_TEST_SUITE_P(Book, FirstFrameLayout, ::testing::ValuesIn(kReferences),
                         [](const ::testing::TestParamInfo<Reference>& info) { return std::string(info.param.id); });

// Demos without a reference frame of their own still put the "Physics Demo" panel where the book does.
TEST(FirstFrameLayout, EveryDemoPlacesTheMainPanelAsTheBook) {
    const std::string path = ReferenceDir() + "/book-ch14-early.png";
    if (!fs::exists(path)) GTEST_SKIP() << "reference frame " << path << " not found (../shared/reference)";
    Image book;
    std::string error;
    ASSERT_TRUE(ReadPngFile(path, &book, &error)) << error;
    const PanelEdges b = MeasurePanels(book);
    ASSERT_GE(b.mainLeft, 0);
    ASSERT_GE(b.mainRight, 0);
    const std::vector<std::string> ids = ListDemoIds();
    ASSERT_FALSE(ids.empty());
    for (const std::string& id : ids) {
        const Image ours = RenderFirstFrame(id);
        ASSERT_EQ(ours.width, kRefWidth) << id;
        ASSERT_EQ(ours.height, kRefHeight) << id;
        const PanelEdges o = MeasurePanels(ours);
        EXPECT_NEAR(o.mainLeft, b.mainLeft, 3) << id;
        EXPECT_NEAR(o.mainRight, b.mainRight, 3) << id;
    }
}
