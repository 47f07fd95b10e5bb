// casters.lod = auto on OSMesa (docs/design.md §3.8): passes draw simplified levels where the
// map cannot tell them from the original, a 2.4 cm bar keeps its shadow, and on the piperack the
// shadow passes draw about half the triangles while the truth comparison barely moves.
#include "geometry/analysis/ground_truth.h"
#include "geometry/io/preset.h"
#include "geometry/lod/caster_lod.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/shadow/caster_detail.h"
#include "renderer/context.h"
#include "renderer/measure.h"
#include "renderer/plan_frame.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numeric>
#include <string>

using namespace geometry::scene;
using namespace geometry::shadow;

namespace {

/// A 2 km ground and a bar 2.4 cm across, 10 m long, 3 m above it: a 16-sided tube in 40 rings,
/// which a decimator would happily thin to a line; seen from 2 m above its shadow.
Scene barScene() {
    Scene scene;
    scene.name = "bar";
    MeshBuilder ground("ground", glm::vec3(0.7f));
    ground.addGroundGrid({0, 0, 0}, 2000.f, 8);
    scene.meshes.push_back(ground.build());
    MeshBuilder bar("bar", glm::vec3(0.8f, 0.3f, 0.2f));
    for (int ring = 0; ring < 40; ++ring)
        bar.addCylinder({0, 3, -5 + 0.25f * ring}, {0, 3, -5 + 0.25f * (ring + 1)}, 0.012f, 16,
                        ring == 0 || ring == 39);
    scene.meshes.push_back(bar.build());
    scene.camera.eye = {-1.f, 2.f, 0.2f};
    scene.camera.target = {0.45f, 0.f, 0.15f};
    scene.camera.near = 0.1f;
    scene.camera.far = 2000.f;
    scene.lights[0].direction = {0.15f, -1.f, 0.05f};
    return scene;
}

uint64_t sum(const std::vector<uint64_t>& v) { return std::accumulate(v.begin(), v.end(), uint64_t(0)); }

/// Shadowed pixels on the ground under the bar (its shadow falls 0.45 m along x, 0.15 m along z).
size_t barShadow(const std::vector<float>& mask, const std::vector<glm::vec4>& positions) {
    size_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        const glm::vec3 p(positions[i]);
        if (std::abs(p.y) < 0.01f && std::abs(p.x - 0.45f) < 1.5f && std::abs(p.z - 0.15f) < 6.f) n += mask[i] < 0.5f;
    }
    return n;
}

} // namespace

TEST(CasterLod, AThinBarKeepsItsShadow) {
    auto context = renderer::createOSMesaContext();
    const Scene scene = barScene();
    renderer::Renderer r(scene);
    r.setCasterLod(geometry::lod::buildCasterLod(scene)); // without its thin-part rule: 517 → 417 pixels
    // One hard-test map fitted to the visible ground, with texels about as wide as the bar, and
    // caster levels allowed 4 texels of error: the bar's levels would be allowed if it had any.
    ShadowSettings settings;
    settings.resolution = 256;
    settings.filter.type = FilterType::None;
    settings.focus = FocusMode::Samples;
    const Viewport vp{320, 240};
    const ShadowPlan off = renderer::planFrame(r, settings, scene.bounds(), scene.camera, scene.lights[0], vp);
    r.render(off, vp, 16);
    const size_t shadowOff = barShadow(r.readShadowMask(), r.readPositions());
    geometry::scene::Aabb under;
    under.add({0.45f, 0.f, 0.15f});
    const float texel = finestTexelOver(off, 0, under);
    EXPECT_GT(texel, 0.006f);
    EXPECT_LT(texel, 0.05f);
    settings.casters.lod = CasterLod::Auto;
    settings.casters.lodTexels = 4.f;
    const ShadowPlan on = renderer::planFrame(r, settings, scene.bounds(), scene.camera, scene.lights[0], vp);
    r.render(on, vp, 16);
    ASSERT_GT(shadowOff, 50u);
    EXPECT_EQ(barShadow(r.readShadowMask(), r.readPositions()), shadowOff);
    EXPECT_EQ(sum(r.stats().splitTriangles), sum(r.stats().splitTrianglesFull));
    EXPECT_TRUE(r.stats().warnings.empty());
}

// Without levels given, auto draws every triangle and says so.
TEST(CasterLod, WithoutLevelsEveryTriangleIsDrawnWithAWarning) {
    auto context = renderer::createOSMesaContext();
    const Scene scene = barScene();
    renderer::Renderer r(scene);
    ShadowSettings settings;
    settings.resolution = 256;
    settings.casters.lod = CasterLod::Auto;
    const Viewport vp{64, 48};
    r.render(planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp), vp, 16);
    EXPECT_EQ(sum(r.stats().splitTriangles), sum(r.stats().splitTrianglesFull));
    ASSERT_EQ(r.stats().warnings.size(), 1u);
    EXPECT_NE(r.stats().warnings[0].find("casters.lod"), std::string::npos);
}

// The piperack (curved CAD surfaces; 250k triangles, more coarsely tessellated than the 4M of
// docs/performance.md), walk view, pssm3 at 1024²: LOD auto draws at most 70 % of the shadow triangles, and
// misclassified pixels change by at most 0.1 percentage point.
TEST(CasterLod, PiperackHalvesShadowTrianglesAtTheSameAccuracy) {
    auto context = renderer::createOSMesaContext();
    const Scene scene = makePiperackScene();
    renderer::Renderer r(scene);
    r.setCasterLod(geometry::lod::buildCasterLod(scene));
    const geometry::analysis::GroundTruth truth(scene);
    ShadowSettings settings =
        geometry::io::loadPreset(std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/pssm3.json");
    settings.resolution = 1024;
    const Viewport vp{320, 180};
    const auto run = [&] {
        const auto m = renderer::measure(r, settings, scene.bounds(), scene.camera, scene.lights[0], vp,
                                         {.warmup = 0, .frames = 1, .timed = false}, &truth);
        const auto& t = *m.inspection.truth;
        return std::pair{t.falseLit + t.falseShadow, sum(r.stats().splitTriangles)};
    };
    const auto [missOff, trianglesOff] = run();
    settings.casters.lod = CasterLod::Auto;
    const auto [missOn, trianglesOn] = run();
    EXPECT_LT(double(trianglesOn), 0.7 * double(trianglesOff));
    EXPECT_NEAR(missOn, missOff, 0.001) << missOff << " → " << missOn;
}
