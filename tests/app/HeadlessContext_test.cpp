// The headless back ends (Platform/HeadlessContext.h): each one built in makes a current GL 2.1 context with
// 24 depth and 8 stencil bits, draws where glReadPixels reads, and both draw the same lit, depth-tested scene
// to the same pixels on llvmpipe (the goldens rely on that).
#include "Platform/HeadlessContext.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

constexpr int kW = 64, kH = 48;

/// Two overlapping lit triangles at different depths and a stencil-masked quad; returns RGBA pixels.
std::vector<std::uint8_t> DrawScene() {
    glViewport(0, 0, kW, kH);
    glClearColor(0.5f, 0.6f, 0.7f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    const float light[4] = {0.5f, 1.0f, -1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    // The near (z 0) green triangle first, then the far (z 0.5) red one: only the depth test keeps the green.
    glBegin(GL_TRIANGLES);
    glNormal3f(0.3f, 0.8f, 0.5f);
    glColor3f(0.1f, 1.0f, 0.1f);
    glVertex3f(-0.9f, 0.9f, 0.0f), glVertex3f(0.9f, 0.9f, 0.0f), glVertex3f(0.0f, -0.9f, 0.0f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glColor3f(1.0f, 0.1f, 0.1f);
    glVertex3f(-0.9f, -0.9f, 0.5f), glVertex3f(0.9f, -0.9f, 0.5f), glVertex3f(0.0f, 0.9f, 0.5f);
    glEnd();
    glDisable(GL_LIGHTING);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glRectf(-0.5f, -0.5f, 0.0f, 0.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glColor3f(0.0f, 0.0f, 1.0f);
    glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    glDisable(GL_STENCIL_TEST);
    std::vector<std::uint8_t> pixels(std::size_t(kW) * kH * 4);
    glFinish();
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

std::vector<std::uint8_t> Render(HeadlessBackend backend, HeadlessInfo* info) {
    std::string error;
    std::unique_ptr<HeadlessContext> context = CreateHeadlessContext(kW, kH, backend, info, &error);
    EXPECT_TRUE(context) << ToString(backend) << ": " << error;
    if (!context) return {};
    return DrawScene();
}

std::uint8_t At(const std::vector<std::uint8_t>& p, int x, int y, int c) {
    return p[(std::size_t(y) * kW + x) * 4 + c];
}

class HeadlessBackendTest : public ::testing::TestWithParam<HeadlessBackend> {
protected:
    void SetUp() override {
        PinSoftwareRasterizer();
        if (!HeadlessBackendBuilt(GetParam())) GTEST_SKIP() << ToString(GetParam()) << " is not built in";
    }
};

TEST_P(HeadlessBackendTest, DrawsDepthTestedLitAndStencilledPixels) {
    HeadlessInfo info;
    const std::vector<std::uint8_t> p = Render(GetParam(), &info);
    ASSERT_EQ(p.size(), std::size_t(kW) * kH * 4);
    EXPECT_EQ(info.backend, ToString(GetParam()));
    EXPECT_GE(info.depthBits, 24);
    EXPECT_GE(info.stencilBits, 8);
    // Corner: the clear colour (0.5, 0.6, 0.7).
    EXPECT_NEAR(At(p, kW - 1, kH - 1, 0), 128, 1);
    EXPECT_NEAR(At(p, kW - 1, kH - 1, 2), 179, 1);
    // Centre-top: the green triangle is nearer (z 0 < 0.5) and keeps the red one, drawn after it, out.
    EXPECT_GT(At(p, kW / 2, kH * 3 / 4, 1), At(p, kW / 2, kH * 3 / 4, 0));
    // Lit, not flat: the default ambient 0.2 plus the diffuse term N.L = 0.107 (N = (0.3, 0.8, 0.5),
    // L = (0.5, 1, -1.5) normalised) of the green 1.0 gives about 0.31 (79 of 255), not the unlit 255.
    EXPECT_NEAR(At(p, kW / 2, kH * 3 / 4, 1), 79, 12);
    // Inside the stencilled square only: blue.
    EXPECT_EQ(At(p, kW * 3 / 8, kH * 3 / 8, 2), 255);
    EXPECT_EQ(At(p, kW * 3 / 8, kH * 3 / 8, 0), 0);
    EXPECT_NE(At(p, kW * 7 / 8, kH / 8, 2), 255);
}

INSTANTIATE_TEST_SUITE_P(Backends, HeadlessBackendTest,
                         ::testing::Values(HeadlessBackend::OSMesa, HeadlessBackend::Egl),
                         [](const ::testing::TestParamInfo<HeadlessBackend>& i) { return ToString(i.param); });

TEST(HeadlessBackends, OSMesaAndEglDrawTheSamePixelsOnLlvmpipe) {
    PinSoftwareRasterizer();
    if (!HeadlessBackendBuilt(HeadlessBackend::OSMesa) || !HeadlessBackendBuilt(HeadlessBackend::Egl))
        GTEST_SKIP() << "needs both back ends built in";
    HeadlessInfo a, b;
    const std::vector<std::uint8_t> osmesa = Render(HeadlessBackend::OSMesa, &a);
    const std::vector<std::uint8_t> egl = Render(HeadlessBackend::Egl, &b);
    if (b.renderer.find("llvmpipe") == std::string::npos) GTEST_SKIP() << "EGL renderer is " << b.renderer;
    EXPECT_EQ(a.renderer, b.renderer);
    EXPECT_TRUE(osmesa == egl);
}

TEST(HeadlessBackends, NamesParseAndUnknownNamesAreRefused) {
    HeadlessBackend b = HeadlessBackend::Auto;
    EXPECT_TRUE(ParseHeadlessBackend("egl", &b));
    EXPECT_EQ(b, HeadlessBackend::Egl);
    EXPECT_TRUE(ParseHeadlessBackend("osmesa", &b));
    EXPECT_EQ(b, HeadlessBackend::OSMesa);
    EXPECT_TRUE(ParseHeadlessBackend("auto", &b));
    EXPECT_EQ(b, HeadlessBackend::Auto);
    EXPECT_FALSE(ParseHeadlessBackend("vulkan", &b));
    EXPECT_FALSE(ParseHeadlessBackend("", &b));
    EXPECT_TRUE(HeadlessBackendBuilt(HeadlessBackend::Auto));
}

}  // namespace
