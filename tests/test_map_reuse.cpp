// Shadow-map reuse (ViewOptions::reuseShadowMaps): a plan whose shadowMapKey() is unchanged keeps
// the maps, and the frame is the same, pixel for pixel, as one drawn from scratch; a plan that
// changes what the maps hold redraws them; switching between two view sizes keeps both sizes' images.
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

namespace {

using namespace geometry::shadow;
using namespace geometry::scene;

class MapReuse : public ::testing::Test {
protected:
    void SetUp() override { context_ = renderer::createOSMesaContext(); }
    ShadowPlan plan(const ShadowSettings& s, Viewport vp = {320, 240}) const {
        return planShadows(s, scene_.bounds(), scene_.camera, scene_.light, vp);
    }
    static renderer::ViewOptions views(bool reuse) {
        renderer::ViewOptions v;
        v.lightViewSize = 64;
        v.reuseShadowMaps = reuse;
        return v;
    }
    std::unique_ptr<renderer::GlContext> context_;
    Scene scene_ = makePlatformScene();
};

TEST_F(MapReuse, EyeSideChangesKeepTheMapsAndTheSamePixels) {
    ShadowSettings s;
    s.resolution = 512;
    s.filter.type = FilterType::Pcf;
    s.filter.kernel = 3;
    ShadowSettings eyeSide = s;
    eyeSide.filter.kernel = 7;
    eyeSide.bias.constant *= 2.f; // a receiver offset: the eye pass applies it
    ASSERT_EQ(renderer::shadowMapKey(plan(s)), renderer::shadowMapKey(plan(eyeSide)));

    renderer::Renderer reusing(scene_);
    reusing.render(plan(s), {320, 240}, views(true));
    EXPECT_FALSE(reusing.stats().shadowMapsReused);
    const uint64_t triangles = reusing.stats().shadowTriangles;
    reusing.render(plan(eyeSide), {320, 240}, views(true));
    EXPECT_TRUE(reusing.stats().shadowMapsReused);
    EXPECT_EQ(reusing.stats().shadowPasses, 1u);
    EXPECT_EQ(reusing.stats().eyePasses, 2u);
    EXPECT_EQ(reusing.stats().shadowTriangles, triangles) << "the counts describe the maps in use";

    renderer::Renderer fresh(scene_);
    fresh.render(plan(eyeSide), {320, 240}, views(false));
    EXPECT_EQ(reusing.readEye().rgba, fresh.readEye().rgba);
    EXPECT_EQ(reusing.readShadowMask(), fresh.readShadowMask());
}

TEST_F(MapReuse, MapSideChangesRedrawAndMeasurementsNeverReuse) {
    ShadowSettings s;
    s.resolution = 512;
    renderer::Renderer r(scene_);
    r.render(plan(s), {320, 240}, views(true));
    ShadowSettings warped = s;
    warped.warp.method = WarpMethod::Lispsm;
    EXPECT_NE(renderer::shadowMapKey(plan(s)), renderer::shadowMapKey(plan(warped)));
    r.render(plan(warped), {320, 240}, views(true));
    EXPECT_FALSE(r.stats().shadowMapsReused);
    EXPECT_EQ(r.stats().shadowPasses, 2u);
    ShadowSettings vsm = warped;
    vsm.filter.type = FilterType::Vsm; // the moments pass is part of the maps
    r.render(plan(vsm), {320, 240}, views(true));
    EXPECT_FALSE(r.stats().shadowMapsReused);
    r.render(plan(vsm), {320, 240}, views(false)); // same plan, but reuse off: drawn again
    EXPECT_FALSE(r.stats().shadowMapsReused);
    EXPECT_EQ(r.stats().shadowPasses, 4u);
}

TEST_F(MapReuse, TwoViewSizesAlternateWithoutChangingEitherImage) {
    ShadowSettings s;
    s.resolution = 512;
    renderer::Renderer r(scene_);
    r.render(plan(s, {320, 240}), {320, 240}, views(true));
    const auto full = r.readEye();
    const GLuint fullTexture = r.eyeTexture();
    r.render(plan(s, {160, 120}), {160, 120}, views(true));
    EXPECT_EQ(r.readEye().width, 160);
    EXPECT_NE(r.eyeTexture(), fullTexture);
    r.render(plan(s, {320, 240}), {320, 240}, views(true));
    EXPECT_EQ(r.eyeTexture(), fullTexture) << "the full-size image keeps its texture";
    EXPECT_EQ(r.readEye().rgba, full.rgba);
}

} // namespace
