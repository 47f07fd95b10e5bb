// Shadow-map reuse (ViewOptions::reuseShadowMaps): a plan whose shadowMapKey() is unchanged keeps
// the maps, and the frame is the same, pixel for pixel, as one drawn from scratch; a plan that
// changes what the maps hold redraws them; switching between two view sizes keeps both sizes' images.
// Every declared setting is on the side its row says: a change to a map-side setting changes the
// key, and a change to an eye-side one keeps it and gives, on reused maps, the picture drawn anew.
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace geometry::shadow;
using namespace geometry::scene;

class MapReuse : public ::testing::Test {
protected:
    void SetUp() override { context_ = renderer::createOSMesaContext(); }
    ShadowPlan plan(const ShadowSettings& s, Viewport vp = {320, 240}) const {
        return planShadows(s, scene_.bounds(), scene_.camera, scene_.lights[0], vp);
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

/// A setting changed from one value to another, under settings where it applies.
struct SettingChange {
    const SettingInfo* info;
    ShadowSettings from, to;
    [[nodiscard]] std::string what() const {
        return std::string(info->key) + ": " + info->format(from) + " → " + info->format(to);
    }
};

/// The first of a fixed list of settings under which `info` applies (each enum's values, several
/// splits of each scheme, the eye blur on, caster levels on).
ShadowSettings baseWhereApplies(const SettingInfo& info) {
    ShadowSettings d;
    d.resolution = 128;
    std::vector<ShadowSettings> bases{d};
    const auto add = [&](auto change) {
        ShadowSettings s = d;
        change(s);
        bases.push_back(s);
    };
    for (size_t i = 0; i < kEnumCount<BiasType>; ++i) add([&](ShadowSettings& s) { s.bias.type = BiasType(i); });
    for (size_t i = 0; i < kEnumCount<FilterType>; ++i) add([&](ShadowSettings& s) { s.filter.type = FilterType(i); });
    for (size_t i = 0; i < kEnumCount<WarpMethod>; ++i) add([&](ShadowSettings& s) { s.warp.method = WarpMethod(i); });
    for (size_t i = 0; i < kEnumCount<SplitScheme>; ++i)
        add([&](ShadowSettings& s) { s.splits.count = 3, s.splits.scheme = SplitScheme(i); });
    add([](ShadowSettings& s) { s.filter.eyeBlurIterations = 1; });
    add([](ShadowSettings& s) { s.casters.lod = CasterLod::Auto; });
    add([](ShadowSettings& s) { s.technique = Technique::Virtual; });
    for (const ShadowSettings& s : bases)
        if (info.appliesTo(s)) return s;
    ADD_FAILURE() << info.key << " applies under none of the test's settings";
    return d;
}

/// Every other choice; the flag flipped; or one other number in range.
std::vector<SettingChange> changesOf(const SettingInfo& info) {
    const ShadowSettings from = baseWhereApplies(info);
    const double v = info.get(from);
    std::vector<double> others;
    switch (info.kind) {
    case SettingInfo::Kind::Choice:
        for (size_t i = 0; i < info.choices.size(); ++i)
            if (double(i) != v) others.push_back(double(i));
        break;
    case SettingInfo::Kind::Bool: others.push_back(v != 0.0 ? 0.0 : 1.0); break;
    case SettingInfo::Kind::Int: {
        const double step = info.odd ? 2.0 : 1.0;
        others.push_back(v + step <= info.max ? v + step : v - step);
        break;
    }
    case SettingInfo::Kind::Float:
        for (const double c : {v * 1.5, v + 0.25 * (info.max - info.min), 0.5 * (info.min + info.max)})
            if (c != v && c >= info.min && c <= info.max) {
                others.push_back(c);
                break;
            }
        break;
    }
    std::vector<SettingChange> out;
    for (const double o : others) {
        SettingChange c{&info, from, from};
        info.set(c.to, o);
        out.push_back(c);
    }
    return out;
}

std::vector<SettingChange> everyDeclaredChange() {
    std::vector<SettingChange> out;
    for (const SettingInfo& info : settingsDeclaration())
        for (SettingChange& c : changesOf(info)) out.push_back(std::move(c));
    return out;
}

ShadowPlan planePlan(const Scene& scene, const ShadowSettings& s) {
    return planShadows(s, scene.bounds(), scene.camera, scene.lights[0], Viewport{96, 64});
}

TEST(MapKey, EveryMapSideSettingChangesTheKeyAndNoEyeSideOneDoes) {
    const Scene scene = makePlaneScene();
    int mapSide = 0, eyeSide = 0;
    for (const SettingChange& c : everyDeclaredChange()) {
        const bool draws = c.info->drawsMaps(c.from) || c.info->drawsMaps(c.to);
        const bool keyChanged =
            renderer::shadowMapKey(planePlan(scene, c.from)) != renderer::shadowMapKey(planePlan(scene, c.to));
        // The key is derived from the rows: a map-side row outside it is a defect in the derivation,
        // and an eye-side row that moves the plan's matrices or depth ranges is a wrong declaration.
        EXPECT_EQ(keyChanged, draws) << c.what() << (draws ? " is map-side" : " is eye-side");
        (draws ? mapSide : eyeSide)++;
    }
    EXPECT_GT(mapSide, 30);
    EXPECT_GE(eyeSide, 15);
}

TEST_F(MapReuse, EveryEyeSideChangeOnReusedMapsGivesTheFreshPicture) {
    const Scene scene = makePlaneScene();
    renderer::Renderer reusing(scene), fresh(scene);
    renderer::ViewOptions v = views(true);
    v.lightViewSize = 16;
    v.unwarped = false;
    v.overlays = false;
    int checked = 0;
    for (const SettingChange& c : everyDeclaredChange()) {
        const ShadowPlan from = planePlan(scene, c.from), to = planePlan(scene, c.to);
        if (renderer::shadowMapKey(from) != renderer::shadowMapKey(to)) continue;
        reusing.render(from, {96, 64}, v);
        reusing.render(to, {96, 64}, v);
        ASSERT_TRUE(reusing.stats().shadowMapsReused) << c.what();
        renderer::ViewOptions anew = v;
        anew.reuseShadowMaps = false;
        fresh.render(to, {96, 64}, anew);
        EXPECT_EQ(reusing.readShadowMask(), fresh.readShadowMask()) << c.what() << ": the maps depend on it";
        ++checked;
    }
    EXPECT_GE(checked, 15);
}

// The renderer fills one key in place every frame: written over the key of another plan (four
// splits, caster levels on, a warp), it equals the key made fresh, field for field.
TEST_F(MapReuse, AKeyWrittenInPlaceEqualsAFreshOne) {
    ShadowSettings busy;
    busy.splits.count = 4;
    busy.casters.lod = CasterLod::Auto;
    busy.warp.method = WarpMethod::Lispsm;
    const ShadowPlan stale = plan(busy), simple = plan(ShadowSettings{});
    renderer::ShadowMapKey key = renderer::shadowMapKey(stale);
    ASSERT_NE(key, renderer::shadowMapKey(simple));
    ASSERT_NE(key.lodEye, glm::vec3(0.f));
    renderer::shadowMapKey(simple, key);
    EXPECT_EQ(key, renderer::shadowMapKey(simple));
    EXPECT_EQ(key.splits.size(), simple.splits.size());
    EXPECT_EQ(key.lodEye, glm::vec3(0.f)) << "no caster levels: the eye is not part of the key";
    renderer::shadowMapKey(stale, key);
    EXPECT_EQ(key, renderer::shadowMapKey(stale));
}

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
