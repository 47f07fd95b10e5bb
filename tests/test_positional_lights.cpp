// Spot and point lights rendered (docs/design.md §3.10): shadows where similar triangles put them,
// no seam at a point light's cube-face edges, and every filter and bias with every light type.
#include "render_test_util.h"

#include "app/headless_frame.h"
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/shadow/positional_plan.h"
#include "renderer/context.h"
#include "renderer/inspection.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geometry::scene;
using namespace geometry::shadow;

namespace {

app::RenderOptions smallOptions() {
    app::RenderOptions o;
    o.size = {320, 240};
    o.settings.resolution = 1024;
    o.settings.warp.method = WarpMethod::Uniform;
    o.settings.splits.count = 1;
    o.settings.filter.type = FilterType::None;
    o.backend = "osmesa";
    return o;
}

/// The occluders of the box room, as boxes (centre, half extents): the truth is a segment test.
const std::vector<std::pair<glm::vec3, glm::vec3>>& roomBlocks() {
    static const std::vector<std::pair<glm::vec3, glm::vec3>> blocks = {
        {{2.f, 1.f, 1.f}, {0.4f, 1.f, 0.4f}},
        {{-2.f, 2.f, -2.f}, {0.6f, 0.15f, 0.6f}},
        {{1.5f, 3.5f, -1.5f}, {0.3f, 0.3f, 0.3f}},
        {{-1.f, 0.5f, 2.5f}, {0.8f, 0.5f, 0.2f}},
    };
    return blocks;
}

/// A closed room (10 × 5 × 10) with four blocks, lit by a point light off its centre.
Scene boxRoom() {
    Scene s;
    s.name = "room";
    MeshBuilder room("room", {0.8f, 0.8f, 0.78f});
    room.addBox({0.f, 2.5f, 0.f}, {5.f, 2.5f, 5.f});
    s.meshes.push_back(room.build());
    MeshBuilder blocks("blocks", {0.7f, 0.4f, 0.3f});
    for (const auto& [c, h] : roomBlocks()) blocks.addBox(c, h);
    s.meshes.push_back(blocks.build());
    s.camera.eye = {-4.f, 4.f, 4.f};
    s.camera.target = {2.f, 0.5f, -3.f};
    s.camera.fovYDeg = 80.f;
    s.camera.near = 0.1f;
    s.camera.far = 30.f;
    Light light;
    light.type = LightType::Point;
    light.position = {0.3f, 3.2f, 0.4f};
    light.range = 40.f;
    s.lights = {light};
    return s;
}

/// Does the segment a → b pass through the box (slab test)?
bool segmentHitsBox(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& h) {
    const glm::vec3 d = b - a;
    float t0 = 0.f, t1 = 1.f;
    for (int k = 0; k < 3; ++k) {
        const float lo = c[k] - h[k], hi = c[k] + h[k];
        if (std::abs(d[k]) < 1e-9f) {
            if (a[k] < lo || a[k] > hi) return false;
            continue;
        }
        float u = (lo - a[k]) / d[k], v = (hi - a[k]) / d[k];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

struct RoomErrors {
    int band = 0, bandWrong = 0, rest = 0, restWrong = 0;
};

/// Pixels whose shadow factor disagrees with the segment test, near the cube-face boundaries (the
/// two largest |x − position| components within 3 %) and elsewhere; pixels within 0.1 of a shadow
/// boundary (as the truth sees it, by moving the light) do not count: edges belong to no side.
RoomErrors roomErrors(const app::HeadlessFrame& f) {
    const auto positions = f.renderer->readPositions();
    const auto normals = f.renderer->readNormals();
    const auto mask = f.renderer->readShadowMask();
    const glm::vec3 light = f.scene.lights[0].position;
    const auto shadowed = [&](const glm::vec3& p, const glm::vec3& from) {
        for (const auto& [c, h] : roomBlocks())
            if (segmentHitsBox(p, from, c, h)) return true;
        return false;
    };
    RoomErrors e;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!(normals[i].w > 0.02f)) continue; // not a receiver of the light
        const glm::vec3 n(normals[i]);
        const glm::vec3 p = glm::vec3(positions[i]) + 0.02f * n;
        const bool truth = shadowed(p, light);
        bool edge = false;
        for (const glm::vec3 o : {glm::vec3(0.1f, 0, 0), glm::vec3(0, 0.1f, 0), glm::vec3(0, 0, 0.1f)})
            edge |= shadowed(p, light + o) != truth || shadowed(p, light - o) != truth;
        if (edge) continue;
        const bool wrong = truth ? mask[i] > 0.5f : mask[i] < 0.5f;
        glm::vec3 a = glm::abs(glm::vec3(positions[i]) - light);
        std::sort(&a[0], &a[0] + 3);
        const bool nearSeam = a[2] - a[1] < 0.03f * a[2];
        (nearSeam ? e.band : e.rest) += 1;
        (nearSeam ? e.bandWrong : e.restWrong) += wrong;
    }
    return e;
}

} // namespace

// A spot light over `plane` casts pole 0's shadow where similar triangles put it: from the base to
// the tip's image (light → tip, extended to the ground), to within a texel of the map.
TEST(PositionalLights, SpotPoleShadowEndsWhereSimilarTrianglesPutIt) {
    Scene scene = makePlaneScene();
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {-6.f, 10.f, 1.f};
    spot.direction = glm::vec3(0.f, 0.f, 0.f) - spot.position;
    spot.coneDeg = 90.f;
    spot.range = 60.f;
    scene.lights = {spot};
    const app::HeadlessFrame f = app::renderHeadless(scene, smallOptions());
    EXPECT_EQ(renderer::takeGlErrors(), "");
    ASSERT_EQ(f.plan.splits.size(), 1u);
    const Pole& pole = planeScenePoles()[0];
    // The pole's top cap: its rim farthest from the light casts the shadow's far end.
    const glm::vec3 away = glm::normalize(glm::vec3(pole.base.x - spot.position.x, 0.f, pole.base.z - spot.position.z));
    const glm::vec3 top = pole.base + glm::vec3(0.f, pole.height, 0.f) + pole.radius * away;
    const glm::vec3 tip = spot.position + (top - spot.position) * (spot.position.y / (spot.position.y - top.y));
    const auto mask = f.renderer->readShadowMask();
    const auto aux = f.renderer->readAux();
    const auto positions = f.renderer->readPositions();
    const int w = 320, h = 240;
    // The pixel that shows ground point p (−1 when off screen or hidden behind something).
    const auto at = [&](const glm::vec3& p) -> int {
        const auto px = testutil::project(f.plan, p, w, h);
        if (!px) return -1;
        const int i = px->y * w + px->x;
        return glm::length(glm::vec3(positions[size_t(i)]) - p) < 0.2f ? i : -1;
    };
    const glm::vec3 along = tip - pole.base - pole.radius * away;
    const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 1, 0), along));
    const glm::vec3 start = pole.base + pole.radius * away;
    // Dark on the line, lit 0.6 m to either side.
    for (float t = 0.2f; t <= 0.85f; t += 0.05f) {
        const int p = at(start + t * along), a = at(start + t * along + 0.6f * side),
                  b = at(start + t * along - 0.6f * side);
        ASSERT_TRUE(p >= 0 && a >= 0 && b >= 0);
        EXPECT_LT(mask[size_t(p)], 0.5f) << "t " << t;
        EXPECT_GT(mask[size_t(a)], 0.5f) << "t " << t;
        EXPECT_GT(mask[size_t(b)], 0.5f) << "t " << t;
    }
    // The shadow's far end: the last dark sample along the line, in map texels, against the tip's.
    const glm::vec4 c = f.plan.splits[0].lightViewProj * glm::vec4(tip, 1.f);
    const glm::vec2 tipTexel = (glm::vec2(c) / c.w * 0.5f + 0.5f) * float(f.plan.splits[0].resolution);
    int lastDark = -1;
    for (float t = 0.8f; t <= 1.3f; t += 0.002f) {
        const int p = at(start + t * along);
        if (p < 0) continue;
        if (mask[size_t(p)] < 0.5f) lastDark = p;
    }
    ASSERT_GE(lastDark, 0);
    const glm::vec2 endTexel(aux[size_t(lastDark)]);
    // One texel, plus the span of one eye pixel in the map there.
    const glm::vec2 nextTexel(aux[size_t(lastDark + 1)]);
    const float tolerance = 1.f + glm::length(nextTexel - endTexel);
    EXPECT_LT(glm::length(endTexel - tipTexel), tolerance)
        << "end " << endTexel.x << "," << endTexel.y << " tip " << tipTexel.x << "," << tipTexel.y;
}

// A point light in a closed room: no crack or seam where the cube faces meet. The shadow factor
// disagrees with a segment test against the blocks no more often along the face boundaries than
// elsewhere.
TEST(PositionalLights, PointLightCubeFacesShowNoSeam) {
    for (const FilterType filter : {FilterType::None, FilterType::Pcf}) {
        app::RenderOptions o = smallOptions();
        o.settings.filter.type = filter;
        const app::HeadlessFrame f = app::renderHeadless(boxRoom(), o);
        EXPECT_EQ(renderer::takeGlErrors(), "");
        ASSERT_EQ(f.plan.splits.size(), 6u);
        const RoomErrors e = roomErrors(f);
        EXPECT_GT(e.band, 300);
        EXPECT_GT(e.rest, 10000);
        const double bandRate = double(e.bandWrong) / std::max(e.band, 1);
        const double restRate = double(e.restWrong) / std::max(e.rest, 1);
        EXPECT_LE(bandRate, restRate + 0.01)
            << enumName(filter) << ": " << e.bandWrong << "/" << e.band << " vs " << e.restWrong << "/" << e.rest;
        EXPECT_LT(restRate, 0.02);
    }
}

// The ray-traced truth (Embree, rays ending at the light) agrees with the room's own segment test at
// every receiver away from shadow edges, and the frame's truth classes are those of a correct map.
TEST(PositionalLights, TruthTracesToThePointLightAsTheSegmentTestDoes) {
    const Scene room = boxRoom();
    app::HeadlessFrame f = app::renderHeadless(room, smallOptions());
    const geometry::analysis::GroundTruth truth(f.scene);
    const geometry::analysis::Inspection in = renderer::inspect(*f.renderer, f.plan, &truth);
    EXPECT_EQ(renderer::takeGlErrors(), "");
    ASSERT_TRUE(in.occluded && in.truth);
    const glm::vec3 light = room.lights[0].position;
    const auto shadowed = [&](const glm::vec3& p, const glm::vec3& from) {
        for (const auto& [c, h] : roomBlocks())
            if (segmentHitsBox(p, from, c, h)) return true;
        return false;
    };
    int counted = 0, disagree = 0, occluded = 0;
    for (size_t i = 0; i < in.positions.size(); ++i) {
        if (!in.receiver[i]) continue;
        const glm::vec3 p = in.positions[i] + 0.02f * in.normals[i];
        const bool segment = shadowed(p, light);
        bool edge = false;
        for (const glm::vec3 o : {glm::vec3(0.1f, 0, 0), glm::vec3(0, 0.1f, 0), glm::vec3(0, 0, 0.1f)})
            edge |= shadowed(p, light + o) != segment || shadowed(p, light - o) != segment;
        if (edge) continue;
        ++counted;
        occluded += segment;
        disagree += segment != ((*in.occluded)[i] != 0);
    }
    EXPECT_GT(counted, 20000);
    EXPECT_GT(occluded, 1000);
    EXPECT_LT(double(disagree) / counted, 0.002) << disagree << " of " << counted;
    EXPECT_LT(in.truth->falseShadow + in.truth->falseLit, 0.03);
}

// Outside a spot's cone the light has no shadow to judge: those pixels are not its receivers.
TEST(PositionalLights, PixelsOutsideTheSpotsConeAreNotItsReceivers) {
    Scene scene = makePlaneScene();
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.f, 12.f, 0.f};
    spot.direction = {0.f, -1.f, 0.f};
    spot.coneDeg = 40.f;
    spot.range = 60.f;
    scene.lights = {spot};
    app::HeadlessFrame f = app::renderHeadless(scene, smallOptions());
    const geometry::analysis::GroundTruth truth(f.scene);
    const geometry::analysis::Inspection in = renderer::inspect(*f.renderer, f.plan, &truth);
    const float cosHalf = std::cos(glm::radians(20.f));
    int inside = 0, outsideSeen = 0;
    for (size_t i = 0; i < in.positions.size(); ++i) {
        if (!(in.aux[i].z >= 0.f)) continue; // sky
        const glm::vec3 d = glm::normalize(in.positions[i] - spot.position);
        const bool inCone = glm::dot(d, spot.direction) > cosHalf;
        if (in.receiver[i]) {
            EXPECT_TRUE(inCone) << i;
            ++inside;
        } else if (!inCone) {
            ++outsideSeen;
        }
    }
    EXPECT_GT(inside, 2000);
    EXPECT_GT(outsideSeen, 2000);
    ASSERT_TRUE(in.truth);
    EXPECT_EQ(in.truth->count, size_t(inside));
}

// Every filter and every bias works with spot and point lights: no GL error, a finite shadow factor
// everywhere, and the room's shadows where the segment test puts them (edges aside).
TEST(PositionalLights, EveryFilterAndBiasWorksWithEveryLightType) {
    for (const LightType type : {LightType::Spot, LightType::Point}) {
        Scene room = boxRoom();
        room.lights[0].type = type;
        room.lights[0].direction = {0.1f, -1.f, -0.2f}; // the spot looks at the floor
        room.lights[0].coneDeg = 150.f;
        room.lights[0].radius = 0.05f;
        std::vector<app::RenderOptions> cases;
        for (const auto& e : kEnumEntries<FilterType>) {
            app::RenderOptions o = smallOptions();
            o.settings.filter.type = e.value;
            cases.push_back(o);
        }
        for (const auto& e : kEnumEntries<BiasType>) {
            app::RenderOptions o = smallOptions();
            o.settings.bias.type = e.value;
            o.settings.filter.type = e.value == BiasType::ReceiverPlane ? FilterType::Pcf : FilterType::None;
            cases.push_back(o);
        }
        for (const auto& o : cases) {
            const std::string what = std::string(lightTypeName(type)) + " filter " +
                                     std::string(enumName(o.settings.filter.type)) + " bias " +
                                     std::string(enumName(o.settings.bias.type));
            const app::HeadlessFrame f = app::renderHeadless(room, o, 0);
            EXPECT_EQ(renderer::takeGlErrors(), "") << what;
            const auto mask = f.renderer->readShadowMask();
            int finite = 0;
            for (const float s : mask) finite += std::isfinite(s) && s >= 0.f && s <= 1.f;
            EXPECT_EQ(finite, int(mask.size())) << what;
            const RoomErrors e = roomErrors(f);
            const double rate = double(e.bandWrong + e.restWrong) / std::max(e.band + e.rest, 1);
            // No bias at all shows acne (Scherzer Fig. 6), and so does second depth here: a light inside
            // a closed room sees the walls' back faces, which are the receivers themselves. Everything
            // else stays within a few per cent.
            const BiasType bias = o.settings.bias.type;
            const double allowed = bias == BiasType::None || bias == BiasType::SecondDepth ? 0.6 : 0.06;
            EXPECT_LT(rate, allowed) << what << ": " << e.bandWrong + e.restWrong << " of " << e.band + e.rest;
            EXPECT_GT(e.band + e.rest, type == LightType::Spot ? 8000 : 20000) << what;
        }
    }
}

namespace {

/// Linear colour of an eye-image pixel (the image is gamma encoded, 1/2.2).
glm::vec3 linearColour(const geometry::analysis::Image& img, size_t i) {
    const uint8_t* px = img.at(int(i % size_t(img.width)), int(i / size_t(img.width)));
    return glm::pow(glm::vec3(px[0], px[1], px[2]) / 255.f, glm::vec3(2.2f));
}

} // namespace

// Two lights give two shadows, and the eye image adds their direct terms: where light A's map says
// "shadow" the two-light frame shows light B's frame alone (ambient + B), and the other way round.
TEST(PositionalLights, TwoLightsAddUpPixelByPixel) {
    Scene scene = makePlaneScene();
    Light a;
    a.type = LightType::Spot;
    a.position = {-6.f, 10.f, 1.f};
    a.direction = -a.position;
    a.coneDeg = 100.f;
    a.range = 60.f;
    const Light b{glm::vec3(0.7f, -1.f, -0.2f)}; // the sun, from the other side
    // Each frame read back at once, while its context is current.
    struct Read {
        size_t plans = 0;
        std::vector<float> mask;
        std::vector<glm::vec4> normals;
        geometry::analysis::Image eye;
    };
    const auto frame = [&](std::vector<Light> lights, size_t inspected) {
        Scene s = scene;
        s.lights = std::move(lights);
        app::RenderOptions o = smallOptions();
        o.lightIndex = inspected;
        const app::HeadlessFrame f = app::renderHeadless(s, o, 0);
        EXPECT_EQ(renderer::takeGlErrors(), "");
        return Read{f.plans.size(), f.renderer->readShadowMask(), f.renderer->readNormals(), f.renderer->readEye()};
    };
    const Read onlyA = frame({a}, 0), onlyB = frame({b}, 0), both = frame({a, b}, 0), bothB = frame({a, b}, 1);
    ASSERT_EQ(both.plans, 2u);
    const auto &maskA = onlyA.mask, &maskB = onlyB.mask;
    const auto &normalsA = onlyA.normals, &normalsB = onlyB.normals;
    // The read-backs describe the inspected light, whichever it is.
    EXPECT_EQ(both.mask, maskA);
    EXPECT_EQ(bothB.mask, maskB);
    const auto &imgA = onlyA.eye, &imgB = onlyB.eye, &imgBoth = both.eye;
    EXPECT_EQ(bothB.eye.rgba, imgBoth.rgba) << "the order the lights are drawn in changes nothing";
    int inA = 0, inB = 0, lit = 0, brighter = 0;
    float worst = 0.f;
    for (size_t i = 0; i < maskA.size(); ++i) {
        const bool receiverA = normalsA[i].w > 0.05f, receiverB = normalsB[i].w > 0.05f;
        if (!receiverA || !receiverB) continue;
        const glm::vec3 c = linearColour(imgBoth, i), cA = linearColour(imgA, i), cB = linearColour(imgB, i);
        if (maskA[i] < 0.01f && maskB[i] > 0.99f) { // in A's shadow only: B's light alone
            ++inA;
            worst = std::max(worst, glm::length(c - cB));
        } else if (maskB[i] < 0.01f && maskA[i] > 0.99f) {
            ++inB;
            worst = std::max(worst, glm::length(c - cA));
        } else if (maskA[i] > 0.99f && maskB[i] > 0.99f) {
            ++lit;
            EXPECT_GT(c.g, std::max(cA.g, cB.g) - 0.01f) << "lit by both: never darker than by either";
            brighter += c.g > std::max(cA.g, cB.g) + 0.02f;
        }
    }
    EXPECT_GT(inA, 100) << "light A's pole shadows";
    EXPECT_GT(inB, 100) << "light B's pole shadows";
    EXPECT_GT(brighter, lit * 9 / 10) << "lit by both: brighter than by either";
    EXPECT_GT(lit, 10000) << inA << " " << inB << " " << worst;
    EXPECT_LT(worst, 0.03f) << "a pixel lit by one light gets that light's colour (8-bit encoding aside)";
}
