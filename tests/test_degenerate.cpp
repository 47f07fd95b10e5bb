// Degenerate configurations (issue 9): light exactly parallel and anti-parallel to the view, light
// and camera straight down, camera inside geometry, n = 0.001 with f = 1e5, empty scene, one
// triangle, zero-size viewport, eight splits over a tiny depth range. Each is planned for every
// warp method and rendered headless (OSMesa, 160×120) against ray-traced truth: no NaN anywhere
// in the plan, no GL error, and the fallback each case documents (docs/stability.md).
#include "render_test_util.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/mesh_builder.h"
#include "renderer/context.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

constexpr Viewport kSize{160, 120};
constexpr WarpMethod kMethods[] = {WarpMethod::Uniform, WarpMethod::Psm,   WarpMethod::Lispsm,
                                   WarpMethod::Glispsm, WarpMethod::Gmnpr, WarpMethod::Manual};

renderer::GlContext& context() {
    static const std::unique_ptr<renderer::GlContext> c = renderer::createOSMesaContext();
    c->makeCurrent();
    return *c;
}

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

/// Every number in the plan is finite, except n' = +∞, which must then mean "not warped".
void expectFinitePlan(const ShadowPlan& p, const std::string& what) {
    SCOPED_TRACE(what);
    EXPECT_TRUE(finite(p.l) && finite(p.v));
    EXPECT_TRUE(std::isfinite(p.gammaDeg) && std::isfinite(p.lightViewAngleDeg));
    EXPECT_TRUE(finite(p.eyeView) && finite(p.eyeProj) && finite(p.unwarpedViewProj));
    for (const auto& c : p.viewFrustum) EXPECT_TRUE(finite(c));
    EXPECT_TRUE(finite(p.eye));
    ASSERT_FALSE(p.splits.empty());
    for (size_t i = 0; i < p.splits.size(); ++i) {
        const SplitPlan& s = p.splits[i];
        SCOPED_TRACE("split " + std::to_string(i));
        EXPECT_TRUE(std::isfinite(s.near) && std::isfinite(s.far) && s.near <= s.far);
        EXPECT_TRUE(finite(s.lightView) && finite(s.lightProj) && finite(s.lightViewProj));
        EXPECT_FALSE(std::isnan(s.nPrime));
        EXPECT_GT(s.nPrime, 0.0);
        EXPECT_EQ(std::isinf(s.nPrime), !s.warped());
        EXPECT_TRUE(std::isfinite(s.lambda));
        EXPECT_TRUE(finite(s.warpDir) && finite(s.warpCentre) && std::isfinite(s.warpDepth));
        for (const auto& b : s.body) EXPECT_TRUE(finite(b));
        for (const auto& c : s.frustum) EXPECT_TRUE(finite(c));
        for (const auto& c : s.mapVolume) EXPECT_TRUE(finite(c));
        EXPECT_TRUE(finite(s.bodyDepthRange) && finite(s.linearDepthRange) && std::isfinite(s.depthPerUnit));
        EXPECT_GT(s.resolution, 0);
    }
}

struct Frame {
    ShadowPlan plan;
    geometry::analysis::Inspection in;
    geometry::analysis::Image eye;
    size_t at(glm::ivec2 p) const { return size_t(p.y) * size_t(in.width) + size_t(p.x); }
    size_t centre() const { return at({in.width / 2, in.height / 2}); }
    bool lit(size_t i) const { return in.shadow[i] >= 0.5f; }
    bool truthShadowed(size_t i) const { return (*in.occluded)[i] != 0; }
};

/// Plans and renders `scene` with every warp method (the settings' other values kept), checks
/// the plan and GL errors for each, and returns the last method's frame (the one asked for).
Frame renderAll(const Scene& scene, ShadowSettings settings, WarpMethod keep = WarpMethod::Glispsm,
                Viewport vp = kSize) {
    context();
    renderer::Renderer r(scene);
    const GroundTruth truth(scene);
    Frame kept;
    for (const WarpMethod m : kMethods) {
        settings.warp.method = m;
        const std::string what(warpMethodName(m));
        Frame f;
        f.plan = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp);
        expectFinitePlan(f.plan, what);
        r.render(f.plan, vp, 64);
        f.in = renderer::inspect(r, f.plan, &truth);
        f.eye = r.readEye();
        EXPECT_EQ(renderer::takeGlErrors(), "") << what;
        EXPECT_EQ(f.in.aliasing.skipped, 0u) << what << ": receivers with a non-finite m";
        EXPECT_EQ(f.in.truth->skipped, 0u) << what << ": receivers with a non-finite shadow factor";
        if (m == keep) kept = std::move(f);
    }
    return kept;
}

ShadowSettings small(int resolution = 512) {
    ShadowSettings s;
    s.resolution = resolution;
    return s;
}

double misclassified(const Frame& f) { return f.in.truth->falseLit + f.in.truth->falseShadow; }

} // namespace

// l = v: the light shines from behind the eye along the view (γ = 0). Every warp falls back to
// uniform (V_P is undefined), and the image centre, whose ray to the light runs back along the
// eye ray, is lit.
TEST(Degenerate, LightExactlyParallelToTheView) {
    Scene scene = makePlaneScene();
    scene.lights[0].direction = scene.camera.viewDir();
    for (const WarpMethod m : kMethods) {
        ShadowSettings s = small();
        s.warp.method = m;
        s.splits.count = 3;
        const ShadowPlan p = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], kSize);
        EXPECT_EQ(p.gammaDeg, 0.f);
        EXPECT_EQ(p.lightViewAngleDeg, 0.f);
        for (const auto& split : p.splits) EXPECT_FALSE(split.warped()) << warpMethodName(m);
    }
    const Frame f = renderAll(scene, small());
    const size_t c = f.centre();
    ASSERT_TRUE(f.in.receiver[c]);
    EXPECT_FALSE(f.truthShadowed(c));
    EXPECT_TRUE(f.lit(c)) << "s = " << f.in.shadow[c];
    EXPECT_LT(f.in.truth->falseLit, 0.02);
    EXPECT_GT(f.in.truth->count, 5000u);
}

// l = −v: the light faces the camera (the dueling frusta at their limit). Uniform again; every
// surface the centre ray sees faces away from the light, so it is no receiver, and it is drawn
// darker than the same pixel lit from behind the eye.
TEST(Degenerate, LightExactlyAntiParallelToTheView) {
    Scene scene = makePlaneScene();
    scene.lights[0].direction = -scene.camera.viewDir();
    const Frame f = renderAll(scene, small());
    EXPECT_EQ(f.plan.gammaDeg, 0.f);
    EXPECT_EQ(f.plan.lightViewAngleDeg, 180.f);
    for (const auto& split : f.plan.splits) EXPECT_FALSE(split.warped());
    const size_t c = f.centre();
    EXPECT_FALSE(f.in.receiver[c]);
    EXPECT_LT(f.in.truth->count, 200u) << "nothing the camera sees faces a light that shines into it";

    Scene behind = scene;
    behind.lights[0].direction = scene.camera.viewDir();
    const Frame lit = renderAll(behind, small());
    const glm::ivec2 px{f.in.width / 2, f.in.height / 2};
    EXPECT_LT(testutil::luminance(f.eye, px) + 0.1f, testutil::luminance(lit.eye, px));
}

// Light straight down, camera straight down (its up vector parallel to the view): γ = 0, the
// camera picks another up vector, the planner another light-space orientation, every warp is
// uniform and the ground around a pole is lit (its shadow hides right under it).
TEST(Degenerate, LightAndCameraStraightDown) {
    Scene scene = makePlaneScene();
    scene.camera.eye = {0.5f, 30.f, 0.5f};
    scene.camera.target = {0.5f, 0.f, 0.5f};
    scene.camera.up = {0.f, 1.f, 0.f};
    scene.lights[0].direction = {0.f, -1.f, 0.f};
    const Frame f = renderAll(scene, small());
    EXPECT_EQ(f.plan.gammaDeg, 0.f);
    for (const auto& split : f.plan.splits) EXPECT_FALSE(split.warped());
    const size_t c = f.centre();
    ASSERT_TRUE(f.in.receiver[c]);
    EXPECT_FALSE(f.truthShadowed(c));
    EXPECT_TRUE(f.lit(c));
    EXPECT_LT(misclassified(f), 0.02);
}

// The eye inside a closed box: every pixel sees the box's inside, the floor is a receiver under
// the box's own roof, and both truth and the shadow map call it shadowed (no lost caster: the
// roof is part of B's extrusion towards the light).
TEST(Degenerate, CameraInsideGeometry) {
    Scene scene = makePlaneScene();
    MeshBuilder box("box", glm::vec3(0.6f));
    box.addBox({20.f, 2.f, 20.f}, {2.f, 2.f, 2.f});
    scene.meshes.push_back(box.build());
    scene.camera.eye = {20.f, 2.5f, 20.f};
    scene.camera.target = {20.f, 0.f, 19.f};
    scene.camera.near = 0.05f;
    const Frame f = renderAll(scene, small());
    const size_t c = f.centre();
    ASSERT_TRUE(f.in.receiver[c]) << "the floor inside the box faces the light";
    EXPECT_TRUE(f.truthShadowed(c));
    EXPECT_FALSE(f.lit(c)) << "s = " << f.in.shadow[c];
    EXPECT_GT(f.in.truth->count, 3000u);
    EXPECT_LT(f.in.truth->falseLit, 0.02);
}

// n = 0.001, f = 1e5 (f/n = 1e8): the focus bodies are clipped to the scene, so the maps still
// cover the ground; a pixel in a pole's shadow is shadowed and the image agrees with truth.
TEST(Degenerate, TinyNearHugeFar) {
    Scene scene = makePlaneScene();
    scene.camera.near = 0.001f;
    scene.camera.far = 1e5f;
    ShadowSettings s = small(1024);
    s.splits.count = 4;
    s.splits.scheme = SplitScheme::Log;
    const Frame f = renderAll(scene, s);
    for (const auto& split : f.plan.splits) EXPECT_TRUE(std::isfinite(split.nPrime) || !split.warped());
    // Pole 0 stands at the origin, 4 high: 1.5 m along its shadow is shadowed ground.
    const glm::vec3 l = glm::normalize(scene.lights[0].direction);
    const glm::vec3 p = 1.5f * glm::normalize(glm::vec3(l.x, 0.f, l.z));
    const auto px = testutil::project(f.plan, p, f.in.width, f.in.height);
    ASSERT_TRUE(px);
    const size_t i = f.at(*px);
    ASSERT_TRUE(f.in.receiver[i]);
    EXPECT_TRUE(f.truthShadowed(i));
    EXPECT_FALSE(f.lit(i)) << "s = " << f.in.shadow[i];
    EXPECT_LT(misclassified(f), 0.1);
}

// No meshes: S is empty, so every focus body is empty and every split is too (identity
// matrices, nothing casts); the image is all sky, with no receiver and zero statistics.
TEST(Degenerate, EmptyScene) {
    Scene scene;
    scene.camera = makePlaneScene().camera;
    ASSERT_TRUE(scene.bounds().empty());
    ShadowSettings s = small();
    s.splits.count = 3;
    const Frame f = renderAll(scene, s);
    for (const auto& split : f.plan.splits) {
        EXPECT_TRUE(split.empty());
        EXPECT_FALSE(split.warped());
    }
    EXPECT_EQ(f.in.aliasing.count, 0u);
    EXPECT_EQ(f.in.truth->count, 0u);
    EXPECT_EQ(f.in.aliasing.p95, 0.0);
    for (float v : f.in.shadow) ASSERT_EQ(v, 1.f) << "sky is lit";
}

// One triangle: S has zero height, B is flat. The triangle is lit all over (it cannot shadow
// itself) and the flat map fit gives it no acne.
TEST(Degenerate, OneTriangleScene) {
    Scene scene;
    Mesh m;
    m.name = "triangle";
    m.positions = {{-10.f, 0.f, -10.f}, {0.f, 0.f, 10.f}, {10.f, 0.f, -10.f}};
    m.normals.assign(3, {0.f, 1.f, 0.f});
    m.indices = {0, 1, 2};
    chunkMesh(m);
    scene.meshes.push_back(m);
    scene.camera = makePlaneScene().camera;
    scene.lights[0] = makePlaneScene().lights[0];
    const Frame f = renderAll(scene, small());
    const size_t c = f.centre();
    ASSERT_TRUE(f.in.receiver[c]);
    EXPECT_FALSE(f.truthShadowed(c));
    EXPECT_TRUE(f.lit(c));
    EXPECT_GT(f.in.truth->count, 1000u);
    EXPECT_EQ(f.in.truth->falseShadow, 0.0);
    EXPECT_EQ(f.in.truth->falseLit, 0.0);
}

// A viewport with a zero side: the planner treats the aspect as 1 (or the frustum as flat) and
// stays finite. The renderer refuses it with a one-line error once it has eye buffers, and
// renders the next frame fine. (A renderer that has never rendered skips the size check and
// draws an empty frame: no pixels, no GL error. The command line refuses such sizes earlier.)
TEST(Degenerate, ZeroSizeViewport) {
    const Scene scene = makePlaneScene();
    for (const Viewport vp : {Viewport{0, 0}, Viewport{0, 120}, Viewport{160, 0}})
        for (const WarpMethod m : kMethods) {
            ShadowSettings s = small();
            s.warp.method = m;
            s.splits.count = 2;
            expectFinitePlan(planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp),
                             std::string(warpMethodName(m)) + " at " + std::to_string(vp.width) + "x" +
                                 std::to_string(vp.height));
        }
    context();
    ShadowSettings s = small();
    const Viewport zero{0, 0};
    const ShadowPlan p = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], zero);
    {
        renderer::Renderer fresh(scene);
        fresh.render(p, zero, 64);
        EXPECT_TRUE(renderer::inspect(fresh, p, nullptr).shadow.empty());
        EXPECT_EQ(renderer::takeGlErrors(), "");
    }
    renderer::Renderer r(scene);
    const ShadowPlan ok = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], kSize);
    r.render(ok, kSize, 64);
    for (const Viewport vp : {zero, Viewport{0, 120}, Viewport{160, 0}}) {
        try {
            r.render(planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp), vp, 64);
            ADD_FAILURE() << "a " << vp.width << "x" << vp.height << " view rendered";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("at least 1x1"), std::string::npos) << e.what();
        }
        EXPECT_EQ(renderer::takeGlErrors(), "");
    }
    r.render(ok, kSize, 64);
    EXPECT_EQ(renderer::takeGlErrors(), "");
    const geometry::analysis::Inspection in = renderer::inspect(r, ok, nullptr);
    EXPECT_EQ(in.width, kSize.width);
    EXPECT_GT(in.aliasing.count, 5000u);
}

// Eight splits over 1 mm of depth: the camera looks straight down at the ground 20 m below with
// n = 19.9995, f = 20.0005. Every split gets its own finite plan (boundaries in order, none NaN);
// the poles, all cut away by the near plane, still cast into the maps (B_i reaches towards the
// light) and the ground is shadowed where truth says so.
TEST(Degenerate, EightSplitsOverATinyDepthRange) {
    Scene scene = makePlaneScene();
    scene.camera.eye = {1.f, 20.f, -1.f};
    scene.camera.target = {1.f, 0.f, -1.f};
    scene.camera.near = 19.9995f;
    scene.camera.far = 20.0005f;
    for (const SplitScheme scheme :
         {SplitScheme::Uniform, SplitScheme::Log, SplitScheme::Practical, SplitScheme::Pssm, SplitScheme::Adaptive}) {
        ShadowSettings s = small();
        s.splits.count = 8;
        s.splits.scheme = scheme;
        const Frame f = renderAll(scene, s);
        const std::string what(splitSchemeName(scheme));
        ASSERT_EQ(f.plan.splits.size(), 8u) << what;
        for (size_t i = 1; i < 8; ++i) EXPECT_LE(f.plan.splits[i - 1].far, f.plan.splits[i].near) << what;
        EXPECT_EQ(f.plan.splits.back().far, scene.camera.far) << what;
        EXPECT_GT(f.in.truth->count, 15000u) << what;
        size_t shadowed = 0;
        for (size_t i = 0; i < f.in.receiver.size(); ++i) shadowed += f.in.receiver[i] && f.truthShadowed(i);
        EXPECT_GT(shadowed, 100u) << what << ": pole shadows in view";
        EXPECT_LT(misclassified(f), 0.05) << what;
    }
}
