// Headless rendering on OSMesa at small sizes: shadows land where geometry puts them.
#include "render_test_util.h"

#include "app/headless_frame.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"

#include <gtest/gtest.h>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::io;
using namespace geometry::analysis;

namespace {

app::RenderOptions smallOptions(const std::string& scene) {
    app::RenderOptions o;
    o.scene = scene;
    o.size = {320, 240};
    o.settings.resolution = 1024;
    o.backend = "osmesa";
    return o;
}

} // namespace

// The shadow of a pole on the plane lies along base → base + h·(l_x, l_z)/(−l_y): pixels on that
// line are dark, pixels 0.6 m to either side are lit.
TEST(HeadlessRender, PoleShadowLiesWhereGeometryPutsIt) {
    const app::HeadlessFrame f = app::renderHeadless(smallOptions("plane"));
    EXPECT_EQ(renderer::takeGlErrors(), "");
    const geometry::analysis::Image eye = f.renderer->readEye();
    ASSERT_EQ(eye.width, 320);
    const glm::vec3 l = f.plan.l;
    const Pole& pole = planeScenePoles()[0];
    const glm::vec3 tip = pole.base + glm::vec3(l.x, 0.f, l.z) * (pole.height / -l.y);
    const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 1, 0), tip - pole.base));
    int dark = 0, lit = 0, samples = 0;
    for (float t = 0.25f; t <= 0.9f; t += 0.05f) {
        const glm::vec3 onLine = pole.base + t * (tip - pole.base);
        const auto p = testutil::project(f.plan, onLine, eye.width, eye.height);
        const auto a = testutil::project(f.plan, onLine + 0.6f * side, eye.width, eye.height);
        const auto b = testutil::project(f.plan, onLine - 0.6f * side, eye.width, eye.height);
        ASSERT_TRUE(p && a && b);
        ++samples;
        const float shadowL = testutil::luminance(eye, *p);
        const float litA = testutil::luminance(eye, *a), litB = testutil::luminance(eye, *b);
        dark += shadowL < 0.6f * std::min(litA, litB);
        lit += std::abs(litA - litB) < 0.05f;
    }
    EXPECT_GE(dark, samples - 1) << "pixels on the predicted shadow line should be dark";
    EXPECT_EQ(lit, samples) << "ground beside the shadow should be lit alike on both sides";
}

// Moving the light moves the shadow: the same line is lit when the light comes from the other side.
TEST(HeadlessRender, PoleShadowFollowsTheLight) {
    app::RenderOptions o = smallOptions("plane");
    const Scene scene = makePlaneScene();
    o.light = glm::vec3(-scene.lights[0].direction.x, scene.lights[0].direction.y, -scene.lights[0].direction.z);
    const app::HeadlessFrame f = app::renderHeadless(o);
    const geometry::analysis::Image eye = f.renderer->readEye();
    const glm::vec3 l0 = scene.lights[0].l();
    const Pole& pole = planeScenePoles()[0];
    const glm::vec3 oldTip = pole.base + glm::vec3(l0.x, 0.f, l0.z) * (pole.height / -l0.y);
    const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 1, 0), oldTip - pole.base));
    int stillDark = 0;
    for (float t = 0.25f; t <= 0.9f; t += 0.05f) {
        const glm::vec3 onLine = pole.base + t * (oldTip - pole.base);
        const auto p = testutil::project(f.plan, onLine, eye.width, eye.height);
        const auto a = testutil::project(f.plan, onLine + 0.6f * side, eye.width, eye.height);
        ASSERT_TRUE(p && a);
        stillDark += testutil::luminance(eye, *p) < 0.8f * testutil::luminance(eye, *a);
    }
    EXPECT_EQ(stillDark, 0);
}

// The platform has both lit and shadowed receiver pixels: compare with the same frame drawn with
// no caster (an empty plan split means "nothing casts").
TEST(HeadlessRender, PlatformHasLitAndShadowedReceivers) {
    app::RenderOptions o = smallOptions("platform");
    o.settings.resolution = 512;
    const app::HeadlessFrame f = app::renderHeadless(o, 0);
    EXPECT_EQ(renderer::takeGlErrors(), "");
    const geometry::analysis::Image shadowed = f.renderer->readEye();
    ShadowPlan noCasters = f.plan;
    for (auto& s : noCasters.splits) {
        SplitPlan empty;
        empty.near = s.near;
        empty.far = s.far;
        empty.resolution = s.resolution;
        s = empty;
    }
    f.renderer->render(noCasters, o.size, 64);
    const geometry::analysis::Image unshadowed = f.renderer->readEye();
    EXPECT_EQ(renderer::takeGlErrors(), "");
    int inShadow = 0, litReceivers = 0;
    for (int y = 0; y < shadowed.height; ++y)
        for (int x = 0; x < shadowed.width; ++x) {
            const float a = testutil::luminance(shadowed, {x, y}), b = testutil::luminance(unshadowed, {x, y});
            if (a < b - 0.08f) ++inShadow;
            else if (std::abs(a - b) < 0.01f && b > 0.35f) ++litReceivers;
        }
    const int total = shadowed.width * shadowed.height;
    EXPECT_GT(inShadow, total / 50) << "shadowed pixels";
    EXPECT_GT(litReceivers, total / 50) << "lit pixels";
}

TEST(HeadlessRender, LightViewShowsDepthAndEmptyTexels) {
    const app::HeadlessFrame f = app::renderHeadless(smallOptions("plane"), 0);
    const geometry::analysis::Image light = f.renderer->readLight();
    ASSERT_EQ(light.width, 1024);
    // The ground fills most of the focused map: many grey levels, not one flat colour.
    int levels[256] = {};
    for (int y = 0; y < light.height; y += 4)
        for (int x = 0; x < light.width; x += 4) levels[light.at(x, y)[0]]++;
    int distinct = 0;
    for (int n : levels) distinct += n > 0;
    EXPECT_GT(distinct, 40);
}

TEST(HeadlessRender, EglContextWhereAnEglDeviceExists) {
    std::unique_ptr<renderer::GlContext> ctx;
    try {
        ctx = renderer::createEglContext();
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no usable EGL device here: " << e.what();
    }
    EXPECT_FALSE(ctx->rendererString().empty());
    ctx.reset();
    app::RenderOptions o = smallOptions("plane");
    o.backend = "egl";
    const app::HeadlessFrame f = app::renderHeadless(o, 0);
    EXPECT_EQ(renderer::takeGlErrors(), "");
    const geometry::analysis::Image eye = f.renderer->readEye();
    // Not a blank image: ground, sky and poles give different colours.
    const float sky = testutil::luminance(eye, {160, 2}), ground = testutil::luminance(eye, {160, 230});
    EXPECT_GT(std::abs(sky - ground), 0.05f);
}
