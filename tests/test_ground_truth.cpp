// Ground truth by ray casting (Embree): known answers on the plane scene and tiny scenes,
// agreement with a brute-force tracer, the sun's visible fraction under a straight edge against the
// analytic disk, input validation, the platform as a whole, and cancellation through a std::stop_token.
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"

#include "cancel_test_util.h"
#include "truth_test_util.h"
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

using namespace geometry::scene;
using namespace geometry::analysis;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const glm::vec3 kUp{0.f, 1.f, 0.f};

const Scene& planeScene() {
    static const Scene scene = makePlaneScene();
    return scene;
}

const GroundTruth& planeTruth() {
    static const GroundTruth truth(planeScene());
    return truth;
}

/// One receiver: 1 if occluded.
uint8_t occludedAt(const GroundTruth& truth, const glm::vec3& p, const glm::vec3& n, const glm::vec3& l) {
    return truth.occluded({p}, {n}, l).at(0);
}

/// Horizontal unit vector along the light's ground shadow direction, and the one across it.
glm::vec3 shadowDir(const glm::vec3& l) { return glm::normalize(glm::vec3(l.x, 0.f, l.z)); }
glm::vec3 acrossShadow(const glm::vec3& l) { return glm::normalize(glm::cross(kUp, shadowDir(l))); }

/// Points on the ground inside pole `pole`'s geometric shadow: base + t·h·(l.x, 0, l.z)/(−l.y).
std::vector<glm::vec3> shadowPoints(const Pole& pole, const glm::vec3& l) {
    std::vector<glm::vec3> pts;
    for (float t = 0.2f; t <= 0.9001f; t += 0.1f)
        pts.push_back(pole.base + t * pole.height * glm::vec3(l.x, 0.f, l.z) / -l.y);
    return pts;
}

struct Face {
    glm::vec3 centroid;
    glm::vec3 normal; // geometric, unit, pointing out of the pole
};

glm::vec3 worldVertex(const Mesh& m, size_t corner) {
    return glm::vec3(m.transform * glm::vec4(m.positions[m.indices[corner]], 1.f));
}

/// The triangle of pole `pole` (in the plane scene's "poles" mesh) whose outward normal is
/// closest to `dir`: a point exactly on the traced geometry, not on the ideal cylinder.
Face poleFace(size_t pole, const glm::vec3& dir) {
    const Mesh* poles = nullptr;
    for (const Mesh& m : planeScene().meshes)
        if (m.name == "poles") poles = &m;
    if (!poles) throw std::logic_error("plane scene has no 'poles' mesh");
    const Pole& p = planeScenePoles().at(pole);
    std::optional<Face> best;
    for (size_t t = 0; t < poles->triangleCount(); ++t) {
        const glm::vec3 a = worldVertex(*poles, 3 * t), b = worldVertex(*poles, 3 * t + 1),
                        c = worldVertex(*poles, 3 * t + 2);
        Face f{(a + b + c) / 3.f, glm::normalize(glm::cross(b - a, c - a))};
        const glm::vec3 offAxis(f.centroid.x - p.base.x, 0.f, f.centroid.z - p.base.z);
        if (glm::length(offAxis) > p.radius * 1.01f) continue; // another pole
        // Outward whatever the winding: caps point away from the pole's middle, sides away from its axis.
        const glm::vec3 out =
            std::abs(f.normal.y) > 0.9f ? glm::vec3(0.f, f.centroid.y - p.base.y - 0.5f * p.height, 0.f) : offAxis;
        if (glm::dot(f.normal, out) < 0.f) f.normal = -f.normal;
        if (!best || glm::dot(f.normal, dir) > glm::dot(best->normal, dir)) best = f;
    }
    if (!best) throw std::logic_error("pole has no triangles");
    return *best;
}

/// A scene of one mesh holding the given triangles (one-sided winding irrelevant to Embree).
Scene trianglesScene(const std::vector<glm::vec3>& corners, const glm::mat4& transform = glm::mat4(1.f)) {
    Mesh m;
    m.name = "triangles";
    m.positions = corners;
    m.normals.assign(corners.size(), kUp);
    for (uint32_t i = 0; i < corners.size(); ++i) m.indices.push_back(i);
    m.transform = transform;
    Scene s;
    s.name = "triangles";
    s.meshes.push_back(std::move(m));
    return s;
}

/// Floats as their bits, so NaN compares equal to itself and −0 differs from 0.
std::vector<uint32_t> bitsOf(const std::vector<float>& v) {
    std::vector<uint32_t> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [](float f) { return std::bit_cast<uint32_t>(f); });
    return out;
}

/// A 2 × 2 m horizontal triangle at height 1 around the origin's vertical (covers (0, 0, 0)
/// seen straight from above, and, with light from straight above, shades the ground under it).
const std::vector<glm::vec3> kRoof{{-2.f, 1.f, -2.f}, {2.f, 1.f, -2.f}, {0.f, 1.f, 2.f}};
const glm::vec3 kStraightDown{0.f, -1.f, 0.f};

/// World-space corners of every triangle of a scene, three per triangle.
std::vector<glm::vec3> worldTriangles(const Scene& scene) {
    std::vector<glm::vec3> corners;
    for (const Mesh& m : scene.meshes)
        for (size_t i = 0; i < m.triangleCount() * 3; ++i) corners.push_back(worldVertex(m, i));
    return corners;
}

/// Brute-force reference: Möller–Trumbore against every triangle, with the same offset rule.
uint8_t bruteOccluded(const std::vector<glm::vec3>& tris, const GroundTruth& truth, const glm::vec3& p,
                      const glm::vec3& n, const glm::vec3& l) {
    if (!std::isfinite(p.x + p.y + p.z + n.x + n.y + n.z) || glm::length(n) == 0.f) return 0;
    const glm::vec3 d = -glm::normalize(l);
    const float eps = truth.epsilon(p);
    const glm::vec3 o = p + (glm::dot(n, d) > 0.f ? n : -n) * (eps / glm::length(n));
    for (size_t t = 0; t + 2 < tris.size(); t += 3) {
        const glm::vec3 a = tris[t], e1 = tris[t + 1] - a, e2 = tris[t + 2] - a;
        const glm::vec3 q = glm::cross(d, e2);
        const float det = glm::dot(e1, q);
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 s = o - a;
        const float u = glm::dot(s, q) / det;
        const glm::vec3 r = glm::cross(s, e1);
        const float v = glm::dot(d, r) / det;
        const float dist = glm::dot(e2, r) / det;
        if (u >= 0.f && v >= 0.f && u + v <= 1.f && dist > eps) return 1;
    }
    return 0;
}

size_t countDifferences(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t diff = 0;
    for (size_t i = 0; i < a.size(); ++i) diff += a[i] != b[i];
    return diff;
}

// ---- Plane scene: known answers --------------------------------------------------------------

TEST(GroundTruthPlane, CountsEveryTriangle) {
    EXPECT_EQ(planeTruth().triangleCount(), planeScene().triangleCount());
    EXPECT_GT(planeTruth().triangleCount(), 0u);
}

TEST(GroundTruthPlane, GroundInsideEachPoleShadowIsOccluded) {
    const glm::vec3 l = planeScene().lights[0].l();
    for (size_t i = 0; i < planeScenePoles().size(); ++i)
        for (const glm::vec3& p : shadowPoints(planeScenePoles()[i], l))
            EXPECT_EQ(occludedAt(planeTruth(), p, kUp, l), 1) << "pole " << i << " at " << p.x << ", " << p.z;
}

TEST(GroundTruthPlane, GroundBesideEachPoleShadowIsLit) {
    const glm::vec3 l = planeScene().lights[0].l();
    for (size_t i = 0; i < planeScenePoles().size(); ++i)
        for (const glm::vec3& p : shadowPoints(planeScenePoles()[i], l))
            for (float side : {-0.6f, 0.6f}) {
                const glm::vec3 q = p + side * acrossShadow(l);
                EXPECT_EQ(occludedAt(planeTruth(), q, kUp, l), 0) << "pole " << i << " at " << q.x << ", " << q.z;
            }
}

TEST(GroundTruthPlane, GroundFarFromPolesIsLit) {
    const glm::vec3 l = planeScene().lights[0].l();
    const std::vector<glm::vec3> far{
        {15.f, 0.f, 15.f}, {-20.f, 0.f, 20.f}, {25.f, 0.f, -25.f}, {-30.f, 0.f, -30.f}, {10.f, 0.f, 3.f}};
    const std::vector<glm::vec3> normals(far.size(), kUp);
    EXPECT_EQ(planeTruth().occluded(far, normals, l), std::vector<uint8_t>(far.size(), 0));
}

TEST(GroundTruthPlane, PoleFacesTowardsTheLightAreLit) {
    // No self-intersection acne: the cap and the side facing the light see the sky.
    const glm::vec3 l = planeScene().lights[0].l();
    for (size_t i = 0; i < planeScenePoles().size(); ++i) {
        const Face top = poleFace(i, kUp);
        ASSERT_GT(top.normal.y, 0.99f);
        EXPECT_EQ(occludedAt(planeTruth(), top.centroid, top.normal, l), 0) << "top of pole " << i;
        const Face lit = poleFace(i, -shadowDir(l));
        ASSERT_GT(glm::dot(lit.normal, -l), 0.5f);
        EXPECT_EQ(occludedAt(planeTruth(), lit.centroid, lit.normal, l), 0) << "lit side of pole " << i;
    }
}

TEST(GroundTruthPlane, PoleSideAwayFromTheLightIsOccludedByItsOwnPole) {
    // The side facing away (n·(−l) < 0): the ray starts just inside the pole and leaves through
    // its lit side, so the pole itself occludes it, as the geometry says (an attached shadow).
    const glm::vec3 l = planeScene().lights[0].l();
    for (size_t i = 0; i < planeScenePoles().size(); ++i) {
        const Face dark = poleFace(i, shadowDir(l));
        ASSERT_LT(glm::dot(dark.normal, -l), -0.5f);
        EXPECT_EQ(occludedAt(planeTruth(), dark.centroid, dark.normal, l), 1) << "dark side of pole " << i;
    }
}

TEST(GroundTruthPlane, CameraCentrePixelSeesTheTarget) {
    // A view of bare ground (the default one looks through pole 0 at its target). Odd size: the
    // centre pixel's ray is the view direction, and the target lies on the ground.
    Camera cam = planeScene().camera;
    cam.eye = {20.f, 6.f, 30.f};
    cam.target = {20.f, 0.f, 20.f};
    const PrimaryHits hits = planeTruth().primaryHits(cam, 101, 61);
    ASSERT_EQ(hits.points.size(), 101u * 61u);
    const size_t centre = 30 * 101 + 50;
    EXPECT_NEAR(glm::distance(hits.points[centre], cam.target), 0.f, 1e-3f);
    EXPECT_NEAR(hits.normals[centre].y, 1.f, 1e-5f);
    // Image order, top row first: a row above the centre sees further along −z.
    EXPECT_LT(hits.points[20 * 101 + 50].z, hits.points[centre].z);
    EXPECT_LT(hits.points[centre].z, hits.points[40 * 101 + 50].z);
    // Every pixel below the horizon sees the ground (all of the lower half here).
    for (size_t i = 30 * 101; i < hits.points.size(); ++i)
        ASSERT_TRUE(std::isfinite(hits.points[i].y)) << "pixel " << i;
    // Left column is at smaller x (the camera looks along −z, so +x is to the right).
    EXPECT_LT(hits.points[centre - 20].x, hits.points[centre + 20].x);
}

TEST(GroundTruthPlane, MatchesBruteForceOverTheCameraImage) {
    const Scene& scene = planeScene();
    const PrimaryHits hits = planeTruth().primaryHits(scene.camera, 120, 68);
    ASSERT_GT(hits.hitCount(), hits.points.size() / 2);
    const auto fast = planeTruth().occluded(hits.points, hits.normals, scene.lights[0].l());
    const std::vector<glm::vec3> tris = worldTriangles(scene);
    std::vector<uint8_t> slow(hits.points.size());
    size_t shadowed = 0;
    for (size_t i = 0; i < slow.size(); ++i) {
        slow[i] = bruteOccluded(tris, planeTruth(), hits.points[i], hits.normals[i], scene.lights[0].l());
        shadowed += slow[i];
    }
    EXPECT_GT(shadowed, 20u); // the poles' shadows are in view
    // Only pixels straddling a shadow edge may disagree (different float arithmetic).
    EXPECT_LE(countDifferences(fast, slow), 2u);
}

TEST(GroundTruthPlane, ReceiverOrderDoesNotMatter) {
    // Packets of 16 consecutive points: reversing the order regroups every packet (and the
    // 130 × 71 image is not a whole number of packets) but must not change any answer.
    const Scene& scene = planeScene();
    const PrimaryHits hits = planeTruth().primaryHits(scene.camera, 130, 71);
    const auto forward = planeTruth().occluded(hits.points, hits.normals, scene.lights[0].l());
    EXPECT_GT(std::count(forward.begin(), forward.end(), 1), 0);
    const std::vector<glm::vec3> pts(hits.points.rbegin(), hits.points.rend() - 3),
        nrm(hits.normals.rbegin(), hits.normals.rend() - 3);
    const auto backward = planeTruth().occluded(pts, nrm, scene.lights[0].l());
    EXPECT_EQ(backward, std::vector<uint8_t>(forward.rbegin(), forward.rend() - 3));
}

// ---- Tiny scenes -----------------------------------------------------------------------------

TEST(GroundTruthTriangle, ShadesTheGroundUnderItOnly) {
    const GroundTruth truth(trianglesScene(kRoof));
    EXPECT_EQ(truth.triangleCount(), 1u);
    const std::vector<glm::vec3> pts{
        {0.f, 0.f, 0.f}, {0.f, 0.f, -1.5f}, {5.f, 0.f, 0.f}, {0.f, 2.f, 0.f}, {-1.5f, 0.f, 1.5f}};
    const std::vector<glm::vec3> nrm(pts.size(), kUp);
    EXPECT_EQ(truth.occluded(pts, nrm, kStraightDown), (std::vector<uint8_t>{1, 1, 0, 0, 0}));
    // Slanted light (travelling towards +x) moves the shadow 3 m along +x: (0, 0, 0) is now lit,
    // (3, 0, 0) shaded.
    const glm::vec3 slanted = glm::normalize(glm::vec3(3.f, -1.f, 0.f));
    EXPECT_EQ(occludedAt(truth, {0.f, 0.f, 0.f}, kUp, slanted), 0);
    EXPECT_EQ(occludedAt(truth, {3.f, 0.f, 0.f}, kUp, slanted), 1);
}

// A point light 1 m above the roof (y = 1) at (0, 2, 0): by similar triangles the roof's shadow on
// the ground is the roof scaled 2× about the origin, corners (−4, −4), (4, −4), (0, 4) in x, z.
TEST(GroundTruthPositional, APointLightsShadowIsTheOccluderScaledBySimilarTriangles) {
    const GroundTruth truth(trianglesScene(kRoof));
    Light point;
    point.type = LightType::Point;
    point.position = {0.f, 2.f, 0.f};
    point.range = 50.f;
    const TruthLight light(point);
    // At z = −3.5 the scaled triangle spans |x| ≤ 3.75; the roof itself only |x| ≤ 1.75 at z = −2.
    const std::vector<glm::vec3> pts{
        {0.f, 0.f, 0.f}, {3.f, 0.f, -3.5f}, {3.9f, 0.f, -3.5f}, {0.f, 0.f, 4.5f}, {5.f, 0.f, 0.f}};
    const std::vector<glm::vec3> up(pts.size(), kUp);
    EXPECT_EQ(truth.occluded(pts, up, light), (std::vector<uint8_t>{1, 1, 0, 0, 0}));
    // Straight down from the sun, (3, 0, −3.5) is lit: the light's position made the difference.
    EXPECT_EQ(occludedAt(truth, {3.f, 0.f, -3.5f}, kUp, kStraightDown), 0);
    // Rays end at the light: above it, looking down through it at the roof, nothing is in between.
    EXPECT_EQ(truth.occluded({{0.f, 3.f, 0.f}}, {-kUp}, light), (std::vector<uint8_t>{0}));
    EXPECT_EQ(occludedAt(truth, {0.f, 3.f, 0.f}, -kUp, glm::vec3(0.f, 1.f, 0.f)), 1); // a sun below does hit it
    // At the light's own position there is no direction: never traced.
    EXPECT_EQ(truth.occluded({point.position}, {kUp}, light), (std::vector<uint8_t>{0}));
    // The occluder distance runs along the ray to the light: from (0, 0, 0) the roof is 1 m away.
    const auto d = truth.occluderDistance({{0.f, 0.f, 0.f}}, {kUp}, light, {kInf});
    EXPECT_NEAR(d.at(0), 1.f, 1e-3f);
}

// A spot light reaches its cone (full angle coneDeg) within its range; a point light its range.
TEST(GroundTruthPositional, ASpotReachesItsConeAndRangeOnly) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.f, 2.f, 0.f};
    spot.direction = {0.f, -1.f, 0.f};
    spot.coneDeg = 60.f; // 30° half angle: tan 30° · 2 m = 1.155 m on the ground
    spot.range = 10.f;
    const TruthLight light(spot);
    EXPECT_TRUE(light.valid());
    EXPECT_TRUE(light.reaches({0.f, 0.f, 0.f}));
    EXPECT_TRUE(light.reaches({1.1f, 0.f, 0.f}));
    EXPECT_FALSE(light.reaches({1.2f, 0.f, 0.f}));
    EXPECT_FALSE(light.reaches({0.f, 3.f, 0.f}));   // behind it
    EXPECT_FALSE(light.reaches({0.f, -8.5f, 0.f})); // beyond its range
    EXPECT_FALSE(light.reaches({kNaN, 0.f, 0.f}));
    EXPECT_TRUE(TruthLight(kStraightDown).reaches({1e6f, -1e6f, 0.f}));
    EXPECT_FLOAT_EQ(light.reach({0.f, -1.f, 0.f}), 3.f);
    EXPECT_EQ(light.toLight({0.f, -1.f, 0.f}), kUp);
    Light broken = spot;
    broken.position.x = kNaN;
    EXPECT_FALSE(TruthLight(broken).valid());
    EXPECT_THROW((void)planeTruth().occluded({{0.f, 0.f, 0.f}}, {kUp}, TruthLight(broken)), std::invalid_argument);
}

// A positional light of radius r = 0.2 at (0, 2, 0) over the roof's edge z = −2 (y = 1). The emitter's
// disk faces each receiver; by hand, the lines from (0, 0, −3.5) to the disk's top and bottom cross
// y = 1 at z = −1.94 and −1.53 (both under the roof: none of the disk seen), those from (0, 0, −5) at
// z = −2.75 and −2.20 (both beside it: all seen); from z = −4 the edge's image passes through the
// disk's centre (similar triangles: 2 × the edge's z), cutting it in half.
TEST(GroundTruthPositional, AnEmittersRadiusGivesThePenumbraSimilarTrianglesPredict) {
    const GroundTruth truth(trianglesScene(kRoof));
    Light point;
    point.type = LightType::Point;
    point.position = {0.f, 2.f, 0.f};
    point.range = 50.f;
    point.radius = 0.2f;
    const TruthLight light(point);
    std::vector<glm::vec3> umbra, lit, half;
    for (int k = 0; k < 16; ++k) {
        const float x = -0.4f + 0.05f * float(k);
        umbra.emplace_back(x, 0.f, -3.5f);
        lit.emplace_back(x, 0.f, -5.f);
        half.emplace_back(x, 0.f, -4.f);
    }
    const std::vector<glm::vec3> up(16, kUp);
    constexpr int kSamples = GroundTruth::kSunSamplesPerAxis;
    EXPECT_EQ(truth.sunVisibility(umbra, up, light, 0.f, kSamples), std::vector<float>(16, 0.f));
    EXPECT_EQ(truth.sunVisibility(lit, up, light, 0.f, kSamples), std::vector<float>(16, 1.f));
    double mean = 0.0;
    for (const float v : truth.sunVisibility(half, up, light, 0.f, kSamples)) {
        EXPECT_NEAR(v, 0.5, 0.1);
        mean += v / 16.0;
    }
    EXPECT_NEAR(mean, 0.5, 0.03);
    // Radius 0: exactly 1 − occluded(), whatever angular diameter is passed (it is the sun's).
    point.radius = 0.f;
    const auto occ = truth.occluded(half, up, TruthLight(point));
    const auto v = truth.sunVisibility(half, up, TruthLight(point), 0.1f, kSamples);
    for (size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], occ[i] ? 0.f : 1.f) << i;
}

TEST(GroundTruthTriangle, OwnSurfaceHasNoAcneAndItsBackIsJudgedByTheGeometry) {
    const GroundTruth truth(trianglesScene(kRoof));
    const glm::vec3 onIt{0.2f, 1.f, -0.3f};
    const glm::vec3 slanted = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
    // Seen from above, facing the light: lit, though the point lies exactly on the triangle.
    EXPECT_EQ(occludedAt(truth, onIt, kUp, slanted), 0);
    // Seen from below (normal away from the light): the origin moves to the light's side of this
    // open surface, and nothing else is there, so it is not occluded.
    EXPECT_EQ(occludedAt(truth, onIt, -kUp, slanted), 0);
    // Grazing light (n·(−l) = 0 exactly): still no acne.
    EXPECT_EQ(occludedAt(truth, onIt, kUp, glm::vec3(1.f, 0.f, 0.f)), 0);
}

TEST(GroundTruthTriangle, MeshTransformIsApplied) {
    // The roof moved 10 m along +x: the origin is lit, (10, 0, 0) is shaded.
    const GroundTruth truth(trianglesScene(kRoof, glm::translate(glm::mat4(1.f), glm::vec3(10.f, 0.f, 0.f))));
    EXPECT_EQ(occludedAt(truth, {0.f, 0.f, 0.f}, kUp, kStraightDown), 0);
    EXPECT_EQ(occludedAt(truth, {10.f, 0.f, 0.f}, kUp, kStraightDown), 1);
}

TEST(GroundTruthTriangle, PrimaryHitNormalsFaceTheCamera) {
    // The same triangle seen from above and from below: its geometric normal flips to face the eye.
    const GroundTruth truth(trianglesScene(kRoof));
    Camera cam;
    cam.up = {0.f, 0.f, -1.f};
    cam.fovYDeg = 10.f;
    for (float eyeY : {5.f, -3.f}) {
        cam.eye = {0.f, eyeY, 0.f};
        cam.target = {0.f, 1.f, 0.f};
        const PrimaryHits hits = truth.primaryHits(cam, 5, 5);
        ASSERT_EQ(hits.hitCount(), 25u) << "eye at y = " << eyeY;
        for (size_t i = 0; i < hits.points.size(); ++i) {
            EXPECT_NEAR(hits.points[i].y, 1.f, 1e-5f);
            EXPECT_NEAR(hits.normals[i].y, eyeY > 1.f ? 1.f : -1.f, 1e-6f) << "eye at y = " << eyeY;
        }
    }
}

// The truth judges a receiver with the geometric normal of its surface, whatever shading normal
// the renderer interpolated: surfaceNormals() finds the triangle under each point.
TEST(GroundTruthTriangle, SurfaceNormalsAreGeometricAndFallBackOffTheSurface) {
    const GroundTruth truth(trianglesScene(kRoof));
    const glm::vec3 eye{0.5f, 6.f, 0.3f};
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.8f, 0.6f, 0.f)); // a smooth-shading normal
    const std::vector<glm::vec3> points{
        {0.f, 1.f, 0.f}, {0.5f, 1.f, -1.f}, {0.f, 3.f, 0.f}, {5.f, 1.f, 5.f}, glm::vec3(kNaN)};
    const std::vector<glm::vec3> shading(points.size(), tilted);
    const auto n = truth.surfaceNormals(eye, points, shading);
    ASSERT_EQ(n.size(), points.size());
    EXPECT_NEAR(glm::distance(n[0], kUp), 0.f, 1e-5f) << "on the roof, seen from above: +y";
    EXPECT_NEAR(glm::distance(n[1], kUp), 0.f, 1e-5f);
    EXPECT_EQ(n[2], tilted) << "in the air above the roof: no surface, the given normal stays";
    EXPECT_EQ(n[3], tilted) << "off the roof";
    EXPECT_EQ(n[4], tilted) << "not finite";
    // Seen from below, the same point's geometric normal faces down (towards that eye).
    const auto below = truth.surfaceNormals({0.f, -3.f, 0.f}, {points[0]}, {tilted});
    EXPECT_NEAR(glm::distance(below[0], -kUp), 0.f, 1e-5f);
    EXPECT_THROW((void)truth.surfaceNormals(eye, points, {kUp}), std::invalid_argument);
}

TEST(GroundTruthTriangle, PrimaryHitsClipAtNearAndFar) {
    // Roof at y = 1 over a floor at y = 0; the camera looks straight down from y = 5 (depth 4 to
    // the roof, 5 to the floor).
    std::vector<glm::vec3> corners = kRoof;
    for (const glm::vec3& c : kRoof) corners.push_back(c * 3.f - glm::vec3(0.f, 3.f, 0.f)); // floor, bigger
    const GroundTruth truth(trianglesScene(corners));
    Camera cam;
    cam.eye = {0.f, 5.f, 0.f};
    cam.target = {0.f, 0.f, 0.f};
    cam.up = {0.f, 0.f, -1.f};
    cam.fovYDeg = 5.f;
    const auto centreY = [&](float near, float far) {
        cam.near = near;
        cam.far = far;
        return truth.primaryHits(cam, 3, 3).points[4].y;
    };
    EXPECT_NEAR(centreY(0.5f, 100.f), 1.f, 1e-5f); // the roof
    EXPECT_NEAR(centreY(4.5f, 100.f), 0.f, 1e-5f); // near plane past the roof: the floor
    EXPECT_TRUE(std::isnan(centreY(0.5f, 3.5f)));  // far plane short of both
}

// ---- Coverage: N × N samples per pixel --------------------------------------------------------

namespace {

constexpr int kCoverageW = 320, kCoverageH = 240;

glm::mat4 planeViewProj() {
    const Camera& cam = planeScene().camera;
    return cam.projection(float(kCoverageW) / float(kCoverageH)) * cam.view();
}

/// Where a world point lands in the image, in pixels (x right, y down; pixel centres at k + 0.5).
glm::vec2 toPixel(const glm::vec3& p) {
    const glm::vec4 c = planeViewProj() * glm::vec4(p, 1.f);
    return {(c.x / c.w * 0.5f + 0.5f) * float(kCoverageW), (0.5f - c.y / c.w * 0.5f) * float(kCoverageH)};
}

} // namespace

// A pixel whose centre lies on a pole shadow's edge (the line the pole's extreme vertex casts, which
// bounds the shadow of the faceted pole exactly) is partly lit: 4 × 4 samples give 0.3 ≤ c ≤ 0.7.
TEST(GroundTruthCoverage, APixelOnAPoleShadowEdgeIsPartlyLit) {
    const glm::vec3 l = glm::normalize(planeScene().lights[0].direction);
    const auto c = planeTruth().coverage(planeViewProj(), kCoverageW, kCoverageH, l, 4);
    ASSERT_EQ(c.size(), size_t(kCoverageW * kCoverageH));
    const Pole& pole = planeScenePoles().at(0);
    float reach = 0.f; // the pole mesh's extent across the shadow, from its axis
    for (const Mesh& m : planeScene().meshes)
        if (m.name == "poles")
            for (size_t i = 0; i < m.indices.size(); ++i) {
                const glm::vec3 v = worldVertex(m, i);
                if (glm::length(glm::vec2(v.x - pole.base.x, v.z - pole.base.z)) < pole.radius * 1.01f)
                    reach = std::max(reach, glm::dot(v - pole.base, acrossShadow(l)));
            }
    ASSERT_GT(reach, pole.radius * 0.9f);
    // Along the edge, the point that projects closest to a pixel centre.
    float best = 1e9f;
    glm::ivec2 pixel{-1};
    for (float t = 0.3f; t <= 0.8f; t += 0.0005f) {
        const glm::vec3 p = pole.base + t * pole.height * glm::vec3(l.x, 0.f, l.z) / -l.y + reach * acrossShadow(l);
        const glm::vec2 q = toPixel(p);
        const glm::vec2 centre = glm::floor(q) + 0.5f;
        if (glm::distance(q, centre) < best) {
            best = glm::distance(q, centre);
            pixel = glm::ivec2(glm::floor(q));
        }
    }
    ASSERT_LT(best, 0.05f);
    ASSERT_TRUE(pixel.x >= 0 && pixel.y >= 0 && pixel.x < kCoverageW && pixel.y < kCoverageH);
    const float edge = c[size_t(pixel.y) * kCoverageW + size_t(pixel.x)];
    EXPECT_GE(edge, 0.3f) << "pixel " << pixel.x << "," << pixel.y;
    EXPECT_LE(edge, 0.7f) << "pixel " << pixel.x << "," << pixel.y;
}

// Pixels whose 3 × 3 neighbourhood sees only the ground and agrees at every centre (one ray each)
// lie away from every straight shadow edge and silhouette (a line through a pixel leaves one of its
// eight neighbours' centres on its other side): their coverage is exactly 0 or 1. Seen from 6 m
// above pole 0's shadow, so the 0.3 m wide shadow spans ~16 pixels.
TEST(GroundTruthCoverage, PixelsAwayFromEdgesAreWhollyLitOrShadowed) {
    const glm::vec3 l = glm::normalize(planeScene().lights[0].direction);
    const Pole& pole = planeScenePoles().at(0);
    Camera cam = planeScene().camera;
    cam.target = pole.base + 0.5f * pole.height * glm::vec3(l.x, 0.f, l.z) / -l.y;
    cam.eye = cam.target + glm::vec3(0.f, 6.f, 0.5f);
    cam.fovYDeg = 40.f;
    const glm::mat4 vp = cam.projection(float(kCoverageW) / float(kCoverageH)) * cam.view();
    const auto c = planeTruth().coverage(vp, kCoverageW, kCoverageH, l, 4);
    const PrimaryHits hits = planeTruth().primaryHits(cam, kCoverageW, kCoverageH);
    const auto occ = planeTruth().occluded(hits.points, hits.normals, l);
    size_t away = 0, lit = 0, shadowed = 0, fractional = 0;
    for (int y = 1; y + 1 < kCoverageH; ++y)
        for (int x = 1; x + 1 < kCoverageW; ++x) {
            const size_t i = size_t(y) * kCoverageW + size_t(x);
            bool uniform = true;
            for (int dy = -1; dy <= 1 && uniform; ++dy)
                for (int dx = -1; dx <= 1 && uniform; ++dx) {
                    const size_t j = size_t(y + dy) * kCoverageW + size_t(x + dx);
                    uniform = std::abs(hits.points[j].y) < 1e-3f && hits.normals[j].y > 0.99f && occ[j] == occ[i];
                }
            if (!uniform) continue;
            ++away;
            if (c[i] == 1.f) ++lit;
            else if (c[i] == 0.f) ++shadowed;
            else ++fractional;
        }
    EXPECT_GT(away, 30000u);
    EXPECT_GT(shadowed, 1000u);
    EXPECT_GT(lit, 10000u);
    EXPECT_EQ(fractional, 0u);
}

TEST(GroundTruthCoverage, OneSampleIsTheCentreRayAndBadInputsThrow) {
    const glm::vec3 l = glm::normalize(planeScene().lights[0].direction);
    const Camera& cam = planeScene().camera;
    const glm::mat4 vp = cam.projection(80.f / 60.f) * cam.view();
    const auto same = planeTruth().coverage(vp, 80, 60, l, 1);
    ASSERT_EQ(same.size(), size_t(80 * 60));
    const PrimaryHits hits = planeTruth().primaryHits(cam, 80, 60);
    const auto occ = planeTruth().occluded(hits.points, hits.normals, l);
    size_t differ = 0, seen = 0;
    for (size_t i = 0; i < same.size(); ++i) {
        if (!std::isfinite(hits.points[i].x)) {
            EXPECT_TRUE(std::isnan(same[i]));
            continue;
        }
        ++seen;
        const bool facing = glm::dot(hits.normals[i], -l) > 0.f;
        differ += same[i] != ((facing && !occ[i]) ? 1.f : 0.f);
    }
    EXPECT_GT(seen, 3000u);
    EXPECT_LE(differ, seen / 500) << "rays through the same pixel centres, unprojected another way";
    EXPECT_THROW((void)planeTruth().coverage(vp, 80, 60, l, 0), std::invalid_argument);
    EXPECT_THROW((void)planeTruth().coverage(vp, 80, 60, l, GroundTruth::kMaxSamplesPerAxis + 1),
                 std::invalid_argument);
    EXPECT_THROW((void)planeTruth().coverage(vp, 0, 60, l, 2), std::invalid_argument);
    EXPECT_THROW((void)planeTruth().coverage(vp, 80, 60, glm::vec3(0.f), 2), std::invalid_argument);
}

// A contact ray ends at its distance: the ground just beside a pole's base has its occluder within
// a metre, a point 2 m down its shadow does not (the pole is 3.5 m along its ray); the distance found
// is the occluder's.
TEST(GroundTruthContact, OccluderDistanceStopsAtTheDistance) {
    const glm::vec3 l = glm::normalize(planeScene().lights[0].direction);
    const Pole& pole = planeScenePoles().at(0);
    const glm::vec3 nearBase = pole.base + shadowDir(l) * (pole.radius + 0.02f);
    const glm::vec3 down = pole.base + shadowDir(l) * 2.f;
    const auto d = planeTruth().occluderDistance({nearBase, down, down}, {kUp, kUp, kUp}, l, {1.f, 1.f, 100.f});
    EXPECT_LT(d.at(0), 1.f);
    EXPECT_TRUE(std::isinf(d.at(1)));
    EXPECT_GT(d.at(2), 1.f);
    EXPECT_LT(d.at(2), 100.f);
    EXPECT_TRUE(std::isinf(planeTruth().occluderDistance({nearBase}, {kUp}, l, {kNaN}).at(0)));
    EXPECT_THROW((void)planeTruth().occluderDistance({nearBase}, {kUp}, l, {}), std::invalid_argument);
}

TEST(GroundTruthEmpty, NothingOccludesAndNothingIsSeen) {
    const Scene empty;
    const GroundTruth truth(empty);
    EXPECT_EQ(truth.triangleCount(), 0u);
    const std::vector<glm::vec3> pts{{0.f, 0.f, 0.f}, {1.f, -3.f, 2.f}};
    EXPECT_EQ(truth.occluded(pts, {kUp, -kUp}, kStraightDown), (std::vector<uint8_t>{0, 0}));
    EXPECT_TRUE(truth.occluded({}, {}, kStraightDown).empty());
    EXPECT_EQ(truth.primaryHits(empty.camera, 8, 4).hitCount(), 0u);
}

TEST(GroundTruthEmpty, MeshesWithoutTrianglesAreSkipped) {
    Scene s = trianglesScene({});
    s.meshes.front().positions = {{0.f, 0.f, 0.f}};
    const GroundTruth truth(s);
    EXPECT_EQ(truth.triangleCount(), 0u);
    EXPECT_EQ(occludedAt(truth, {0.f, -1.f, 0.f}, kUp, kStraightDown), 0);
}

// ---- The sun's disk (sunVisibility) --------------------------------------------------------------

/// A 100 × 100 horizontal quad at height h over x < 0: a straight occluder edge along z at x = 0.
Scene halfPlaneScene(float h) {
    return trianglesScene(
        {{-100.f, h, -50.f}, {0.f, h, -50.f}, {0.f, h, 50.f}, {-100.f, h, -50.f}, {0.f, h, 50.f}, {-100.f, h, 50.f}});
}

/// The visible fraction of a uniform disk whose part beyond the normalized offset −x is hidden.
double diskEdge(double x) {
    x = std::clamp(x, -1.0, 1.0);
    return 0.5 + (x * std::sqrt(1.0 - x * x) + std::asin(x)) / 3.14159265358979323846;
}

// A receiver under a half-plane's edge, the sun straight above: the disk cut by the edge at the
// normalized offset x = (receiver's distance from the edge's shadow) / (h·tan(θ/2)). 16 receivers
// along the edge per offset, each with its own jitter: one receiver's 64 rays carry a sampling
// error of ~0.017 (1σ), their mean ~0.004.
TEST(GroundTruthSun, AStraightEdgeCutsTheDiskAsTheAnalyticProfile) {
    constexpr float kHeight = 2.f;
    const float theta = glm::radians(2.f);
    const float halfWidth = kHeight * std::tan(0.5f * theta);
    const GroundTruth truth(halfPlaneScene(kHeight));
    double worst = 0.0, worstMean = 0.0;
    for (const double x : {-0.8, -0.4, 0.0, 0.4, 0.8}) {
        std::vector<glm::vec3> pts;
        for (int k = 0; k < 16; ++k) pts.emplace_back(float(x) * halfWidth, 0.f, -1.f + 0.13f * float(k));
        const std::vector<float> v = truth.sunVisibility(pts, std::vector<glm::vec3>(pts.size(), kUp), kStraightDown,
                                                         theta, GroundTruth::kSunSamplesPerAxis);
        double mean = 0.0;
        for (const float vi : v) {
            EXPECT_NEAR(vi, diskEdge(x), 0.075) << "x = " << x; // 4.5σ
            worst = std::max(worst, std::abs(double(vi) - diskEdge(x)));
            mean += vi / double(v.size());
        }
        EXPECT_NEAR(mean, diskEdge(x), 0.03) << "x = " << x;
        worstMean = std::max(worstMean, std::abs(mean - diskEdge(x)));
        ::testing::Test::RecordProperty("v_mean_at_" + std::to_string(x), std::to_string(mean));
        std::printf("x = %+.1f: analytic %.4f, mean v %.4f, one receiver %.4f\n", x, diskEdge(x), mean, double(v[0]));
    }
    ::testing::Test::RecordProperty("worst_single", std::to_string(worst));
    ::testing::Test::RecordProperty("worst_mean", std::to_string(worstMean));
    std::printf("worst single receiver %.4f, worst mean %.4f\n", worst, worstMean);
}

TEST(GroundTruthSun, WhollyUnderOrBesideTheEdgeIsExactlyZeroOrOne) {
    constexpr float kHeight = 2.f;
    const float theta = glm::radians(2.f);
    const float halfWidth = kHeight * std::tan(0.5f * theta);
    const GroundTruth truth(halfPlaneScene(kHeight));
    const std::vector<glm::vec3> pts{
        {-1.05f * halfWidth, 0.f, 0.f}, {-10.f, 0.f, 3.f}, {1.05f * halfWidth, 0.f, 0.f}, {10.f, 0.f, -3.f}};
    const std::vector<glm::vec3> up(pts.size(), kUp);
    EXPECT_EQ(truth.sunVisibility(pts, up, kStraightDown, theta, 8), (std::vector<float>{0.f, 0.f, 1.f, 1.f}));
    EXPECT_EQ(truth.sunVisibility(pts, up, kStraightDown, theta, 3), (std::vector<float>{0.f, 0.f, 1.f, 1.f}));
    // Above the quad (it faces the sun) and a receiver facing down under it: judged as occluded().
    EXPECT_EQ(truth.sunVisibility({{-5.f, kHeight, 0.f}, {-5.f, 1.f, 0.f}}, {kUp, -kUp}, kStraightDown, theta, 4),
              (std::vector<float>{1.f, 0.f}));
}

// θ = 0: every sample is the ray along −l, so v is exactly 1 − occluded() (3 × 3 = 9 samples: a
// partial packet too).
TEST(GroundTruthSun, APointSunIsOneMinusOccluded) {
    const Scene& scene = testutil::platformScene();
    const GroundTruth& truth = testutil::platformTruth();
    const PrimaryHits hits = truth.primaryHits(scene.camera, 96, 54);
    const glm::vec3 l = scene.lights[0].l();
    const std::vector<uint8_t> occ = truth.occluded(hits.points, hits.normals, l);
    ASSERT_GT(std::count(occ.begin(), occ.end(), 1), 500);
    for (const int samples : {1, 3, 8}) {
        const std::vector<float> v = truth.sunVisibility(hits.points, hits.normals, l, 0.f, samples);
        ASSERT_EQ(v.size(), occ.size());
        for (size_t i = 0; i < v.size(); ++i) {
            const float expected = std::isfinite(hits.points[i].x) ? 1.f - float(occ[i]) : 0.f; // sky: not traced
            ASSERT_EQ(v[i], expected) << "pixel " << i << ", " << samples << " samples per axis";
        }
    }
}

// The jitter hashes the point, not its index or thread: 1 and 2 threads, and the points reversed,
// give the same values bit for bit; a 2° sun gives fractional values along the platform's shadow edges.
TEST(GroundTruthSun, ResultDoesNotDependOnThreadsOrOrder) {
    const Scene& scene = testutil::platformScene();
    const GroundTruth& truth = testutil::platformTruth();
    const PrimaryHits hits = truth.primaryHits(scene.camera, 96, 54);
    const glm::vec3 l = scene.lights[0].l();
    const float theta = glm::radians(2.f);
    const std::vector<float> one = truth.sunVisibility(hits.points, hits.normals, l, theta, 8, 1);
    const std::vector<float> two = truth.sunVisibility(hits.points, hits.normals, l, theta, 8, 2);
    EXPECT_EQ(bitsOf(one), bitsOf(two));
    std::vector<glm::vec3> pts(hits.points.rbegin(), hits.points.rend()),
        nrm(hits.normals.rbegin(), hits.normals.rend());
    std::vector<float> reversed = truth.sunVisibility(pts, nrm, l, theta, 8, 2);
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_EQ(bitsOf(reversed), bitsOf(one));
    const auto partial = std::count_if(one.begin(), one.end(), [](float v) { return v > 0.f && v < 1.f; });
    EXPECT_GT(partial, 50);
    for (const float v : one) ASSERT_TRUE(v >= 0.f && v <= 1.f) << v;
}

TEST(GroundTruthSun, BadInputsThrowAndBrokenReceiversGiveZero) {
    const GroundTruth truth(halfPlaneScene(2.f));
    const std::vector<glm::vec3> pts{{1.f, 0.f, 0.f}}, up{kUp};
    const float theta = 0.01f;
    EXPECT_THROW((void)truth.sunVisibility(pts, {}, kStraightDown, theta, 8), std::invalid_argument);
    EXPECT_THROW((void)truth.sunVisibility(pts, up, glm::vec3(0.f), theta, 8), std::invalid_argument);
    EXPECT_THROW((void)truth.sunVisibility(pts, up, glm::vec3(kNaN, -1.f, 0.f), theta, 8), std::invalid_argument);
    for (const float bad : {-0.01f, kNaN, kInf, 3.1416f})
        EXPECT_THROW((void)truth.sunVisibility(pts, up, kStraightDown, bad, 8), std::invalid_argument) << bad;
    for (const int bad : {0, -1, GroundTruth::kMaxSamplesPerAxis + 1})
        EXPECT_THROW((void)truth.sunVisibility(pts, up, kStraightDown, theta, bad), std::invalid_argument) << bad;
    try {
        (void)truth.sunVisibility(pts, up, kStraightDown, theta, 0);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("sunVisibility"), std::string::npos) << e.what();
    }
    const std::vector<glm::vec3> broken{{kNaN, 0.f, 0.f}, {0.f, kInf, 0.f}, {1.f, 0.f, 0.f}, {1.f, 0.f, 0.f}};
    const std::vector<glm::vec3> normals{kUp, kUp, {0.f, kNaN, 0.f}, glm::vec3(0.f)};
    EXPECT_EQ(truth.sunVisibility(broken, normals, kStraightDown, theta, 4), (std::vector<float>(4, 0.f)));
    EXPECT_EQ(truth.sunVisibility(pts, up, kStraightDown, theta, GroundTruth::kMaxSamplesPerAxis),
              (std::vector<float>{1.f}));
    EXPECT_TRUE(truth.sunVisibility({}, {}, kStraightDown, theta, 8).empty());
}

// ---- Input validation ------------------------------------------------------------------------

TEST(GroundTruthInput, NonFiniteReceiversGiveZeroAndLeaveTheirNeighboursAlone) {
    const GroundTruth truth(trianglesScene(kRoof));
    // 40 receivers (more than one packet), shaded ones interleaved with broken ones.
    std::vector<glm::vec3> pts, nrm;
    std::vector<uint8_t> expected;
    const std::vector<std::pair<glm::vec3, glm::vec3>> broken{{{kNaN, 0.f, 0.f}, kUp},
                                                              {{0.f, kInf, 0.f}, kUp},
                                                              {{0.f, 0.f, 0.f}, {0.f, kNaN, 0.f}},
                                                              {{0.f, 0.f, 0.f}, {-kInf, 1.f, 0.f}},
                                                              {{0.f, 0.f, 0.f}, glm::vec3(0.f)}};
    for (int i = 0; i < 40; ++i) {
        if (i % 3 == 1) {
            const auto& [p, n] = broken[static_cast<size_t>(i) % broken.size()];
            pts.push_back(p);
            nrm.push_back(n);
            expected.push_back(0);
        } else {
            pts.push_back({0.01f * static_cast<float>(i), 0.f, 0.f});
            nrm.push_back(kUp);
            expected.push_back(1);
        }
    }
    EXPECT_EQ(truth.occluded(pts, nrm, kStraightDown), expected);
}

TEST(GroundTruthInput, MismatchedSizesThrow) {
    const GroundTruth truth(trianglesScene(kRoof));
    EXPECT_THROW((void)truth.occluded({{0.f, 0.f, 0.f}}, {}, kStraightDown), std::invalid_argument);
    EXPECT_THROW((void)truth.occluded({}, {kUp}, kStraightDown), std::invalid_argument);
    EXPECT_THROW((void)truth.occluded({{0.f, 0.f, 0.f}}, {kUp, kUp}, kStraightDown), std::invalid_argument);
}

TEST(GroundTruthInput, BadLightOrImageSizeThrow) {
    const GroundTruth truth(trianglesScene(kRoof));
    EXPECT_THROW((void)truth.occluded({}, {}, glm::vec3(0.f)), std::invalid_argument);
    EXPECT_THROW((void)truth.occluded({}, {}, glm::vec3(kNaN, -1.f, 0.f)), std::invalid_argument);
    EXPECT_THROW((void)truth.primaryHits(Camera{}, 0, 10), std::invalid_argument);
    EXPECT_THROW((void)truth.primaryHits(Camera{}, 10, -1), std::invalid_argument);
}

TEST(GroundTruthInput, IndexOutOfRangeThrowsRuntimeError) {
    Scene s = trianglesScene(kRoof);
    s.meshes.front().indices[2] = 3;
    EXPECT_THROW(GroundTruth{s}, std::runtime_error);
}

TEST(GroundTruthInput, MovedTruthStillTraces) {
    GroundTruth a(trianglesScene(kRoof));
    GroundTruth b(std::move(a));
    EXPECT_EQ(b.triangleCount(), 1u);
    EXPECT_EQ(occludedAt(b, {0.f, 0.f, 0.f}, kUp, kStraightDown), 1);
}

TEST(GroundTruthInput, EpsilonFollowsThePointsMagnitude) {
    const GroundTruth truth(planeScene());
    const float diag = glm::length(planeScene().bounds().extent());
    EXPECT_NEAR(truth.epsilon(glm::vec3(0.f)), 1e-7f * diag, 1e-6f * 1e-7f * diag * 10.f);
    EXPECT_FLOAT_EQ(truth.epsilon({0.f, 0.f, -1000.f}), 1e-2f);
    EXPECT_GE(GroundTruth(Scene{}).epsilon(glm::vec3(0.f)), 1e-6f);
}

// ---- Platform --------------------------------------------------------------------------------

TEST(GroundTruthPlatform, DefaultViewHasLitAndShadowedReceiversAndIsDeterministic) {
    const Scene scene = makePlatformScene();
    const GroundTruth truth(scene);
    EXPECT_EQ(truth.triangleCount(), scene.triangleCount());
    const PrimaryHits hits = truth.primaryHits(scene.camera, 160, 90);
    ASSERT_GT(hits.hitCount(), hits.points.size() / 2);
    const glm::vec3 l = scene.lights[0].l();
    const auto one = truth.occluded(hits.points, hits.normals, l, 1);
    const auto two = truth.occluded(hits.points, hits.normals, l, 2);
    EXPECT_EQ(one, two);
    const PrimaryHits single = truth.primaryHits(scene.camera, 160, 90, 1);
    EXPECT_EQ(single.normals, hits.normals);
    EXPECT_EQ(truth.occluded(single.points, single.normals, l, 1), one);

    size_t facing = 0, shadowed = 0;
    for (size_t i = 0; i < one.size(); ++i) {
        if (!std::isfinite(hits.points[i].x) || glm::dot(hits.normals[i], -l) <= 0.f) continue;
        ++facing;
        shadowed += one[i];
    }
    ASSERT_GT(facing, 0u);
    const double shadowedShare = static_cast<double>(shadowed) / static_cast<double>(facing);
    EXPECT_GT(shadowedShare, 0.02) << shadowed << " of " << facing;
    EXPECT_LT(shadowedShare, 0.98) << shadowed << " of " << facing;
}

// ---- Cancellation (std::stop_token) ------------------------------------------------------------

using testutil::platformScene;
using testutil::platformTruth;

/// The platform's default view at w × h (what coverage() takes).
glm::mat4 platformViewProj(int w, int h) {
    const Camera& cam = platformScene().camera;
    return cam.projection(float(w) / float(h)) * cam.view();
}

/// Floats as their bits: NaN (sky in coverage) compares equal to itself.
std::vector<uint32_t> bits(const std::vector<float>& v) {
    std::vector<uint32_t> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [](float f) { return std::bit_cast<uint32_t>(f); });
    return out;
}

TEST(GroundTruthCancel, AStopRequestedBeforeTheCallThrowsCancelled) {
    const GroundTruth& truth = platformTruth();
    const Scene& scene = platformScene();
    const glm::vec3 l = scene.lights[0].l();
    const PrimaryHits hits = truth.primaryHits(scene.camera, 64, 36);
    const std::vector<float> reach(hits.points.size(), 1.f);
    std::stop_source source;
    source.request_stop();
    const std::stop_token stop = source.get_token();
    EXPECT_THROW((void)truth.occluded(hits.points, hits.normals, l, 0, stop), Cancelled);
    EXPECT_THROW((void)truth.occluderDistance(hits.points, hits.normals, l, reach, 0, stop), Cancelled);
    std::vector<int> meshes;
    EXPECT_THROW((void)truth.surfaceNormals(scene.camera.eye, hits.points, hits.normals, 0, &meshes, stop), Cancelled);
    EXPECT_THROW((void)truth.coverage(platformViewProj(64, 36), 64, 36, l, 2, 0, stop), Cancelled);
    EXPECT_THROW((void)truth.sunVisibility(hits.points, hits.normals, l, 0.01f, 8, 0, stop), Cancelled);
    // Bad input is still reported as such, and Cancelled is a runtime_error a caller may catch as one.
    EXPECT_THROW((void)truth.coverage(platformViewProj(64, 36), 64, 36, l, 0, 0, stop), std::invalid_argument);
    try {
        (void)truth.occluded(hits.points, hits.normals, l, 0, stop);
        FAIL() << "not cancelled";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "cancelled");
    }
}

// The dashboard abandons a stale truth: a stop ~20 ms into a run of 5.3M coverage samples (two
// threads) ends it within a task of a few hundred rays, long before the run would have finished.
TEST(GroundTruthCancel, AStopFromAnotherThreadEndsCoverageEarly) {
    constexpr int kW = 384, kH = 216, kSamples = 8, kThreads = 2;
    const GroundTruth& truth = platformTruth();
    const glm::mat4 vp = platformViewProj(kW, kH);
    const glm::vec3 l = platformScene().lights[0].l();
    size_t size = 0;
    const testutil::CancelTiming t = testutil::timeCancellation(
        [&](std::stop_token stop) { size = truth.coverage(vp, kW, kH, l, kSamples, kThreads, stop).size(); });
    ASSERT_EQ(size, size_t(kW * kH));
    testutil::expectCancelledEarly(t);
}

// A token that is never stopped changes nothing: every result equals the call without one, bit for bit.
TEST(GroundTruthCancel, ANeverStoppedTokenGivesTheSameResults) {
    const GroundTruth& truth = platformTruth();
    const Scene& scene = platformScene();
    const glm::vec3 l = scene.lights[0].l();
    const PrimaryHits hits = truth.primaryHits(scene.camera, 160, 90);
    const std::stop_source source; // can be stopped, never is
    const std::stop_token live = source.get_token();
    ASSERT_TRUE(live.stop_possible());

    const auto occ = truth.occluded(hits.points, hits.normals, l);
    EXPECT_GT(std::count(occ.begin(), occ.end(), 1), 0);
    EXPECT_EQ(truth.occluded(hits.points, hits.normals, l, 0, live), occ);

    std::vector<int> meshes, liveMeshes;
    const auto normals = truth.surfaceNormals(scene.camera.eye, hits.points, hits.normals, 0, &meshes);
    EXPECT_EQ(truth.surfaceNormals(scene.camera.eye, hits.points, hits.normals, 0, &liveMeshes, live), normals);
    EXPECT_EQ(liveMeshes, meshes);

    std::vector<float> reach(hits.points.size());
    for (size_t i = 0; i < reach.size(); ++i) reach[i] = 0.05f * float(i % 40);
    const auto within = truth.occluderDistance(hits.points, normals, l, reach);
    EXPECT_EQ(truth.occluderDistance(hits.points, normals, l, reach, 0, live), within);

    const glm::mat4 vp = platformViewProj(160, 90);
    const auto c = truth.coverage(vp, 160, 90, l, 4);
    EXPECT_EQ(bits(truth.coverage(vp, 160, 90, l, 4, 0, live)), bits(c));
    EXPECT_EQ(bits(truth.coverage(vp, 160, 90, l, 4, 0, std::stop_token{})), bits(c));
}
} // namespace
