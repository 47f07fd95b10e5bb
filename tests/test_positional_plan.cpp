// Spot and point light plans (geometry/shadow/positional_plan.h, docs/design.md §3.10): every
// receiver the camera sees within the light's reach, and every caster between it and the light,
// lands in the map the eye pass reads for it; never NaN, wherever the light is.
#include "geometry/shadow/overlays.h"
#include "geometry/shadow/positional_plan.h"
#include "geometry/shadow/shadow_plan.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>
#include <utility>

#include "random_util.h"

using namespace geometry::scene;
using namespace geometry::shadow;
using testutil::randomUnit;
using testutil::uniform;

namespace {

bool finiteMatrix(const glm::mat4& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m[i][j])) return false;
    return true;
}

/// p in map `viewProj`: in front of the light and inside its unit cube (a small tolerance); its
/// window depth in `depth`.
bool insideMap(const glm::mat4& viewProj, const glm::vec3& p, float* depth = nullptr) {
    const glm::vec4 c = viewProj * glm::vec4(p, 1.f);
    if (!(c.w > 0.f)) return false;
    const glm::vec3 w = glm::vec3(c) / c.w * 0.5f + 0.5f;
    if (depth) *depth = w.z;
    const float tol = 1e-4f;
    return w.x >= -tol && w.x <= 1.f + tol && w.y >= -tol && w.y <= 1.f + tol && w.z >= -tol && w.z <= 1.f + tol;
}

bool inCone(const Light& light, const glm::vec3& p) {
    const float c = glm::dot(glm::normalize(p - light.position), light.l());
    return c > std::cos(glm::radians(std::min(0.5f * light.coneDeg, 80.f))) + 1e-3f;
}

bool seenByCamera(const Camera& cam, float aspect, const glm::vec3& p) {
    const glm::vec4 c = cam.projection(aspect) * cam.view() * glm::vec4(p, 1.f);
    return c.w > 0.f && std::abs(c.x) < c.w && std::abs(c.y) < c.w && std::abs(c.z) < c.w;
}

/// A 10 × 2 × 10 scene seen from 12 m away.
std::pair<Aabb, Camera> smallScene() {
    Aabb S;
    S.add({-5, 0, -5});
    S.add({5, 2, 5});
    Camera cam;
    cam.eye = {0, 3, 12};
    cam.target = {0, 0, 0};
    return {S, cam};
}

} // namespace

TEST(PositionalPlan, CubeFaceIsTheMajorAxis) {
    EXPECT_EQ(cubeFace({2, 1, -1}), 0);
    EXPECT_EQ(cubeFace({-2, 1, -1}), 1);
    EXPECT_EQ(cubeFace({0.1f, 3, -1}), 2);
    EXPECT_EQ(cubeFace({0.1f, -3, -1}), 3);
    EXPECT_EQ(cubeFace({0.1f, 0.3f, 1}), 4);
    EXPECT_EQ(cubeFace({0.1f, 0.3f, -1}), 5);
    EXPECT_EQ(cubeFace({0, 0, 0}), 0);
    EXPECT_EQ(cubeFace({std::nanf(""), 0, 0}), 0);
    // 6 texels of reach on a 2048 map: the 90° partition spans the middle 2036 texels.
    EXPECT_DOUBLE_EQ(cubeFaceTanHalf(2048, 6.0), 2048.0 / 2036.0);
}

// Random spot and point lights (in S, in V, behind the camera, far off) and random cameras: each
// visible receiver within the light's range (and cone) lies in the map the eye pass picks for it,
// and a caster half-way to the light lies in the same map, nearer the light.
TEST(PositionalPlan, ReceiversAndCastersLandInTheirMap) {
    std::mt19937 rng(2029);
    Aabb S;
    S.add({-30, 0, -40});
    S.add({30, 20, 40});
    const Viewport viewport{320, 200};
    int checked = 0, spotChecked = 0, pointChecked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Camera cam;
        cam.eye = {uniform(rng, -40, 40), uniform(rng, 1, 30), uniform(rng, -50, 50)};
        cam.target = cam.eye + randomUnit(rng);
        cam.fovYDeg = uniform(rng, 30, 80);
        cam.near = uniform(rng, 0.1f, 1.f);
        cam.far = uniform(rng, 50.f, 200.f);
        Light light;
        light.type = trial % 2 ? LightType::Spot : LightType::Point;
        switch (trial % 5) {
        case 0: light.position = cam.eye; break;                                       // at the camera
        case 1: light.position = cam.eye + cam.viewDir() * uniform(rng, 2, 20); break; // in V
        case 2: light.position = cam.eye - cam.viewDir() * uniform(rng, 2, 20); break; // behind the camera
        case 3: light.position = {uniform(rng, -30, 30), uniform(rng, 0, 20), uniform(rng, -40, 40)}; break;
        default: light.position = glm::vec3(0, 150, 0) + randomUnit(rng) * 20.f; break; // far off
        }
        light.direction = trial % 3 ? randomUnit(rng) : (glm::vec3(0, 5, 0) - light.position);
        light.coneDeg = uniform(rng, 10, 170);
        light.range = uniform(rng, 30, 300);
        ShadowSettings settings;
        settings.warp.method = WarpMethod::Uniform;
        settings.splits.count = 1;
        const ShadowPlan plan = planShadows(settings, S, cam, light, viewport);
        ASSERT_EQ(plan.splits.size(), light.type == LightType::Point ? 6u : 1u);
        for (const auto& split : plan.splits) {
            ASSERT_TRUE(finiteMatrix(split.lightViewProj)) << "trial " << trial;
            for (const auto& p : split.body) ASSERT_TRUE(std::isfinite(p.x + p.y + p.z));
        }
        ASSERT_TRUE(std::isfinite(plan.gammaDeg));
        for (int k = 0; k < 150; ++k) {
            const glm::vec3 p{uniform(rng, S.lo.x, S.hi.x), uniform(rng, S.lo.y, S.hi.y), uniform(rng, S.lo.z, S.hi.z)};
            const float distance = glm::length(p - light.position);
            if (!seenByCamera(cam, viewport.aspect(), p) || distance > 0.98f * light.range ||
                distance < 0.05f * light.range)
                continue;
            if (light.type == LightType::Spot && !inCone(light, p)) continue;
            const int face = light.type == LightType::Point ? cubeFace(p - light.position) : 0;
            const SplitPlan& split = plan.splits[size_t(face)];
            ASSERT_FALSE(split.empty()) << "trial " << trial;
            float receiverDepth = 0.f, casterDepth = 0.f;
            EXPECT_TRUE(insideMap(split.lightViewProj, p, &receiverDepth)) << "trial " << trial << " face " << face;
            const glm::vec3 q = 0.5f * (p + light.position);
            if (S.contains(q) && glm::length(q - light.position) > 0.01f * light.range) {
                EXPECT_TRUE(insideMap(split.lightViewProj, q, &casterDepth)) << "trial " << trial;
                EXPECT_LT(casterDepth, receiverDepth);
            }
            ++checked;
            ++(light.type == LightType::Point ? pointChecked : spotChecked);
        }
    }
    EXPECT_GT(spotChecked, 200);
    EXPECT_GT(pointChecked, 1000);
    EXPECT_GT(checked, 1200);
}

// A spot light's map is fitted to what it lights of V ∩ S: a narrow view of a wide cone's edge gets a
// map much narrower than the cone.
TEST(PositionalPlan, SpotMapIsFittedToTheFocusBody) {
    Aabb S;
    S.add({-50, 0, -50});
    S.add({50, 1, 50});
    Camera cam;
    cam.eye = {20, 5, 20};
    cam.target = {25, 0, 25};
    cam.fovYDeg = 20.f;
    cam.far = 30.f;
    Light light;
    light.type = LightType::Spot;
    light.position = {0, 30, 0};
    light.direction = {0, -1, 0};
    light.coneDeg = 120.f;
    light.range = 200.f;
    ShadowSettings settings;
    settings.warp.method = WarpMethod::Lispsm;
    const ShadowPlan plan = planShadows(settings, S, cam, light, Viewport{320, 200});
    ASSERT_EQ(plan.splits.size(), 1u);
    const SplitPlan& split = plan.splits[0];
    ASSERT_FALSE(split.empty());
    // The map's angular width: from its near-plane extent.
    const float tanWidth = 2.f / split.lightProj[0][0];
    EXPECT_LT(tanWidth, 0.25f * 2.f * std::tan(glm::radians(60.f)));
    // The light is positional: it looks from its position, and the plan says which settings it ignores.
    EXPECT_EQ(split.warpCentre, light.position);
    EXPECT_FALSE(split.warped());
    bool warned = false;
    for (const auto& w : plan.warnings) warned |= w.find("warp.method") != std::string::npos;
    EXPECT_TRUE(warned) << "lispsm does not apply to a spot light";
}

// Nothing within range: every map is empty (no pass), and nothing is NaN.
TEST(PositionalPlan, LightOutOfRangeHasEmptyMaps) {
    const std::pair<Aabb, Camera> world = smallScene();
    const Aabb& S = world.first;
    const Camera& cam = world.second;
    Light light;
    light.type = LightType::Point;
    light.position = {0, 100, 0};
    light.range = 50.f;
    const ShadowPlan plan = planShadows(ShadowSettings{}, S, cam, light, Viewport{320, 200});
    ASSERT_EQ(plan.splits.size(), 6u);
    for (const auto& split : plan.splits) EXPECT_TRUE(split.empty());
    EXPECT_TRUE(finiteMatrix(plan.unwarpedViewProj));
}

// The light view's overlays show a positional light's volume: a spot's rim and apex lines lie on its
// cone at the range, a point light's eight rays run along the cube's diagonals (where its faces
// meet); a directional light has none.
TEST(PositionalPlan, OverlaysDrawTheConeAndTheFaceBoundaries) {
    const std::pair<Aabb, Camera> world = smallScene();
    const Aabb& S = world.first;
    const Camera& cam = world.second;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1, 8, 0};
    spot.direction = {0, -1, 0.2f};
    spot.coneDeg = 50.f;
    spot.range = 20.f;
    const auto volume = [&](const Light& light) {
        const ShadowPlan plan = planShadows(ShadowSettings{}, S, cam, light, Viewport{320, 200});
        std::vector<OverlaySegment> segments;
        for (const auto& s : warpedViewOverlays(plan, 0))
            if (s.kind == OverlayKind::LightVolume) segments.push_back(s);
        size_t unwarped = 0;
        for (const auto& s : unwarpedViewOverlays(plan)) unwarped += s.kind == OverlayKind::LightVolume;
        EXPECT_EQ(unwarped, segments.size());
        return segments;
    };
    const auto cone = volume(spot);
    ASSERT_EQ(cone.size(), size_t(kConeRimSegments + 4));
    const float cosHalf = std::cos(glm::radians(25.f));
    for (const auto& s : cone) {
        EXPECT_FALSE(s.inMapNdc);
        for (const glm::vec3& p : {s.a, s.b}) {
            const glm::vec3 d = p - spot.position;
            EXPECT_NEAR(glm::dot(glm::normalize(d), spot.l()), cosHalf, 1e-4f);
        }
        EXPECT_NEAR(glm::length(s.b - spot.position), spot.range, 1e-3f);
    }
    Light point = spot;
    point.type = LightType::Point;
    const auto faces = volume(point);
    ASSERT_EQ(faces.size(), 8u);
    for (const auto& s : faces) {
        const glm::vec3 d = glm::abs(s.b - point.position);
        EXPECT_NEAR(d.x, d.y, 1e-3f);
        EXPECT_NEAR(d.y, d.z, 1e-3f);
        EXPECT_NEAR(glm::length(s.b - point.position), point.range, 1e-3f);
    }
    EXPECT_TRUE(volume(Light{glm::vec3(0, -1, 0)}).empty());
}

// A light's own settings override the shared ones in its plan (and so in its passes and shader
// block); another light planned with the same shared settings keeps them.
TEST(PositionalPlan, ALightsOwnSettingsOverrideTheSharedOnes) {
    const std::pair<Aabb, Camera> world = smallScene();
    const Aabb& S = world.first;
    const Camera& cam = world.second;
    ShadowSettings shared;
    shared.resolution = 2048;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 8, 0};
    spot.direction = {0, -1, 0};
    spot.range = 30.f;
    spot.settings = {"shadow_map.resolution=512", "filter.type=pcf"};
    const ShadowPlan own = planShadows(shared, S, cam, spot, Viewport{320, 200});
    EXPECT_EQ(own.settings.resolution, 512);
    EXPECT_EQ(own.settings.filter.type, FilterType::Pcf);
    EXPECT_EQ(own.splits.at(0).resolution, 512);
    const ShadowPlan sun = planShadows(shared, S, cam, Light{glm::vec3(0, -1, 0)}, Viewport{320, 200});
    EXPECT_EQ(sun.settings.resolution, 2048);
    EXPECT_EQ(sun.settings.filter.type, shared.filter.type);
}
