// The soft truth through addTruth (geometry/analysis/inspection.h): a sun of non-zero size gives
// each receiver the fraction of its disk it sees, soft_mean_abs and, under a scene's straight
// occluder edge, the penumbra width errors in metrics.json; a point sun gives none of them. No GL:
// the frame read-back is made up from the truth's own primary rays, as test_inspection_cancel does.
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/inspection.h"
#include "geometry/analysis/metrics.h"
#include "geometry/shadow/shadow_plan.h"

#include "truth_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kHeight = 2.f;            // of the occluder's edge
const glm::vec3 kLight{-0.3f, -1.f, 0.f}; // the sun on the +x side, in the plane ⊥ the edge
constexpr double kPi = 3.14159265358979323846;

Mesh quad(const std::string& name, float x0, float x1, float y) {
    Mesh m;
    m.name = name;
    m.positions = {{x0, y, -50.f}, {x1, y, -50.f}, {x1, y, 50.f}, {x0, y, 50.f}};
    m.normals.assign(4, glm::vec3(0.f, 1.f, 0.f));
    m.indices = {0, 2, 1, 0, 3, 2};
    return m;
}

/// A ground at y = 0 and a half-plane at y = 2 over x < 0 whose edge, along z at x = 0, casts the
/// penumbra; the camera looks at that penumbra (around x = −0.6) from under the half-plane.
Scene edgeScene(bool withEdge) {
    Scene s;
    s.name = "edge";
    s.meshes.push_back(quad("ground", -50.f, 50.f, 0.f));
    s.meshes.push_back(quad("occluder", -100.f, 0.f, kHeight));
    s.camera.eye = {-0.1f, 0.35f, 0.f};
    s.camera.target = {-0.6f, 0.f, 0.f};
    s.camera.up = {0.f, 1.f, 0.f};
    s.camera.fovYDeg = 20.f;
    s.camera.near = 0.05f;
    s.camera.far = 200.f;
    s.lights[0].direction = kLight;
    if (withEdge)
        s.occluderEdge = std::array<glm::vec3, 2>{glm::vec3(0.f, kHeight, -50.f), glm::vec3(0.f, kHeight, 50.f)};
    return s;
}

/// The analytic fraction of a disk of angular diameter θ seen from ground point p past the edge:
/// the edge's offset from the ray towards the sun's centre, over the distance along it, in the
/// x–y plane (the light has no z component).
double analyticVisibility(const glm::vec3& p, double theta) {
    const glm::dvec2 toSun = -glm::normalize(glm::dvec2(kLight.x, kLight.y));
    const glm::dvec2 perp(toSun.y, -toSun.x); // towards the lit side (+x)
    const glm::dvec2 w(0.0 - p.x, double(kHeight) - p.y);
    const double x = -glm::dot(w, perp) / glm::dot(w, toSun) / std::tan(0.5 * theta);
    if (x <= -1.0) return 0.0;
    if (x >= 1.0) return 1.0;
    return 0.5 + (x * std::sqrt(1.0 - x * x) + std::asin(x)) / kPi;
}

using Frame = testutil::TracedFrame;

/// The scene's view at w × h as the eye pass would read it back, s = shadow(p) on every pixel.
Frame edgeFrame(const Scene& scene, const GroundTruth& truth, float sunDeg, int w, int h,
                const std::function<float(const glm::vec3&)>& shadow) {
    ShadowSettings settings;
    settings.light.angularDiameterDeg = sunDeg;
    const ShadowPlan plan = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], Viewport{w, h});
    return testutil::tracedFrame(scene.camera, truth, plan, w, h,
                                 [&](size_t, const glm::vec3& p) { return glm::vec2(shadow(p), 0.5f); });
}

constexpr int kW = 128, kH = 96;

} // namespace

TEST(SoftTruth, MeanAbsIsOverReceiversWithBothValuesFinite) {
    const std::vector<float> s{1.f, 0.5f, 0.f, 0.25f, 0.f, kNaN};
    const std::vector<float> v{0.5f, 0.5f, 0.25f, kNaN, 1.f, 0.f};
    const std::vector<uint8_t> receiver{1, 1, 1, 1, 0, 1};
    EXPECT_DOUBLE_EQ(softMeanAbs(s, v, receiver), (0.5 + 0.0 + 0.25) / 3.0);
    EXPECT_TRUE(std::isnan(softMeanAbs(s, v, std::vector<uint8_t>(6, 0))));
    EXPECT_THROW((void)softMeanAbs(s, {}, receiver), std::invalid_argument);
}

// The metrics.json keys from a hand-made inspection: present with a soft truth, NaN as null, absent
// without one.
TEST(SoftTruth, MetricsWriteTheSoftFiguresOnlyWithASun) {
    Inspection in;
    in.truth = TruthStats{};
    nlohmann::json point;
    addInspectionMetrics(point, in);
    ASSERT_TRUE(point.contains("truth"));
    for (const char* key : {"soft_mean_abs", "sun_angular_diameter_deg", "sun_rays_per_pixel", "penumbra_width_error",
                            "penumbra_width_error_truth"})
        EXPECT_FALSE(point["truth"].contains(key)) << key;

    in.softTruth = SoftTruthStats{0.25, 0.5, 64, std::numeric_limits<double>::quiet_NaN(), 0.125};
    nlohmann::json j;
    addInspectionMetrics(j, in);
    const nlohmann::json back = nlohmann::json::parse(j.dump()); // as metrics.json is read
    EXPECT_EQ(back["truth"]["soft_mean_abs"], 0.25);
    EXPECT_EQ(back["truth"]["sun_angular_diameter_deg"], 0.5);
    EXPECT_EQ(back["truth"]["sun_rays_per_pixel"], 64);
    EXPECT_TRUE(back["truth"]["penumbra_width_error"].is_null());
    EXPECT_EQ(back["truth"]["penumbra_width_error_truth"], 0.125);

    in.softTruth->penumbraWidthError.reset(); // no occluder edge
    in.softTruth->penumbraWidthErrorTruth.reset();
    nlohmann::json noEdge;
    addInspectionMetrics(noEdge, in);
    EXPECT_TRUE(noEdge["truth"].contains("soft_mean_abs"));
    EXPECT_FALSE(noEdge["truth"].contains("penumbra_width_error"));
    EXPECT_FALSE(noEdge["truth"].contains("penumbra_width_error_truth"));
}

TEST(SoftTruth, APointSunAddsNothing) {
    const Scene scene = edgeScene(true);
    const GroundTruth truth(scene);
    const Frame f = edgeFrame(scene, truth, 0.f, kW, kH, [](const glm::vec3&) { return 1.f; });
    const Inspection in = makeInspection(f.readback, f.plan, &truth);
    EXPECT_TRUE(in.sunVisibility.empty());
    EXPECT_FALSE(in.softTruth.has_value());
    nlohmann::json j;
    addInspectionMetrics(j, in);
    EXPECT_FALSE(j["truth"].contains("soft_mean_abs"));
    EXPECT_FALSE(j["truth"].contains("penumbra_width_error"));
    bool layer = false;
    for (const PixelLayer& l : pixelLayers(in, f.plan.eye, f.plan.v, f.plan.l)) {
        if (l.name != "visibility") continue;
        layer = true;
        for (const float v : l.values) ASSERT_TRUE(std::isnan(v));
    }
    EXPECT_TRUE(layer);
}

// A 2° sun: s drawn as the analytic disk profile agrees with the traced v to within the 64 rays'
// noise, and both measure the penumbra's width right; a hard shadow (the point sun's truth)
// measures −1. Without the scene's edge, no width.
TEST(SoftTruth, AStraightEdgesPenumbraIsMeasuredAgainstTheDisk) {
    constexpr float kSunDeg = 2.f;
    const double theta = kSunDeg * kPi / 180.0;
    const Scene scene = edgeScene(true);
    const GroundTruth truth(scene);
    ASSERT_TRUE(truth.occluderEdge().has_value());

    const Frame soft = edgeFrame(scene, truth, kSunDeg, kW, kH,
                                 [&](const glm::vec3& p) { return float(analyticVisibility(p, theta)); });
    const Inspection in = makeInspection(soft.readback, soft.plan, &truth);
    ASSERT_TRUE(in.softTruth.has_value());
    ASSERT_EQ(in.sunVisibility.size(), in.shadow.size());
    size_t receivers = 0, penumbra = 0;
    for (size_t i = 0; i < in.shadow.size(); ++i) {
        if (!in.receiver[i]) {
            ASSERT_TRUE(std::isnan(in.sunVisibility[i]));
            continue;
        }
        ++receivers;
        ASSERT_TRUE(in.sunVisibility[i] >= 0.f && in.sunVisibility[i] <= 1.f);
        penumbra += in.sunVisibility[i] > 0.f && in.sunVisibility[i] < 1.f;
    }
    EXPECT_GT(receivers, size_t(kW * kH / 2));
    EXPECT_GT(penumbra, 500u);
    const SoftTruthStats& st = *in.softTruth;
    EXPECT_EQ(st.raysPerPixel, 64);
    EXPECT_DOUBLE_EQ(st.angularDiameterDeg, 2.0);
    EXPECT_LT(st.meanAbs, 0.01);
    ASSERT_TRUE(st.penumbraWidthError && st.penumbraWidthErrorTruth);
    EXPECT_NEAR(*st.penumbraWidthError, 0.0, 0.05);
    EXPECT_NEAR(*st.penumbraWidthErrorTruth, 0.0, 0.05);
    std::printf("analytic s: soft_mean_abs %.4f over %zu receivers (%zu in the penumbra), width error %+.4f, "
                "truth's %+.4f\n",
                st.meanAbs, receivers, penumbra, *st.penumbraWidthError, *st.penumbraWidthErrorTruth);
    nlohmann::json j;
    addInspectionMetrics(j, in);
    EXPECT_DOUBLE_EQ(j["truth"]["soft_mean_abs"].get<double>(), st.meanAbs);
    EXPECT_EQ(j["truth"]["sun_rays_per_pixel"], 64);
    EXPECT_DOUBLE_EQ(j["truth"]["penumbra_width_error"].get<double>(), *st.penumbraWidthError);
    bool layer = false;
    for (const PixelLayer& l : pixelLayers(in, soft.plan.eye, soft.plan.v, soft.plan.l))
        if (l.name == "visibility") {
            layer = true;
            for (size_t i = 0; i < l.values.size(); ++i)
                ASSERT_EQ(std::isnan(l.values[i]) ? -1.f : l.values[i],
                          std::isnan(in.sunVisibility[i]) ? -1.f : in.sunVisibility[i]);
        }
    EXPECT_TRUE(layer);

    // s = the point sun's verdict: a hard edge, whose width is none.
    const Frame hard = edgeFrame(scene, truth, kSunDeg, kW, kH,
                                 [&](const glm::vec3& p) { return analyticVisibility(p, theta) >= 0.5 ? 1.f : 0.f; });
    const Inspection hin = makeInspection(hard.readback, hard.plan, &truth);
    ASSERT_TRUE(hin.softTruth && hin.softTruth->penumbraWidthError);
    EXPECT_NEAR(*hin.softTruth->penumbraWidthError, -1.0, 0.05);
    EXPECT_EQ(*hin.softTruth->penumbraWidthErrorTruth, *st.penumbraWidthErrorTruth); // the same v
    EXPECT_GT(hin.softTruth->meanAbs, 2.0 * st.meanAbs);
    std::printf("hard s: soft_mean_abs %.4f, width error %+.4f\n", hin.softTruth->meanAbs,
                *hin.softTruth->penumbraWidthError);

    const Scene bare = edgeScene(false);
    const GroundTruth bareTruth(bare);
    const Inspection nin = makeInspection(soft.readback, soft.plan, &bareTruth);
    ASSERT_TRUE(nin.softTruth.has_value());
    EXPECT_FALSE(nin.softTruth->penumbraWidthError.has_value());
    EXPECT_EQ(nin.softTruth->meanAbs, st.meanAbs);
}
