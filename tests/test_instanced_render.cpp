// Instanced meshes drawn with GPU instancing (renderer/gpu_scene.h) and traced through Embree
// instances give the picture and the verdicts of the same scene flattened into one mesh per
// placement: the eye image, the shadow mask and every pixel's truth class identical. The flattened
// meshes draw from compact vertices, the instanced ones from floats (geometry/scene/compact_vertices.h),
// so this compares those too; and a chunked scene draws the pixels its unchunked twin (floats) does.
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/inspection.h"
#include "geometry/io/preset.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/compact_vertices.h"
#include "geometry/scene/instancing.h"
#include "renderer/context.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

const std::string kResources = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/";

/// The plane scene's poles on a 3 × 2 grid, one column turned and stretched: some placements lie
/// outside the view, so per-instance culling skips some and draws runs of the rest.
Scene instancedPlane() {
    Scene s = makePlaneScene();
    Mesh& poles = s.meshes.back();
    poles.instances = gridInstances({3, 1, 2}, {7.f, 0.f, -9.f}, {-7.f, 0.f, 0.f});
    poles.instances[2] = glm::scale(glm::rotate(poles.instances[2], glm::radians(25.f), glm::vec3(0.f, 1.f, 0.f)),
                                    glm::vec3(1.f, 1.4f, 1.f));
    poles.instances.push_back(glm::translate(glm::mat4(1.f), glm::vec3(0.f, 0.f, 500.f))); // behind the camera
    for (Mesh& m : s.meshes) reserveSpareVertex(m);
    return s;
}

struct Frame {
    Image eye;
    Inspection inspection;
    uint64_t eyeTriangles = 0;
};

Frame render(const Scene& scene, const ShadowSettings& settings) {
    const Viewport vp{192, 108};
    renderer::Renderer r(scene);
    const GroundTruth truth = GroundTruth::borrowing(scene);
    const ShadowPlan plan = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp);
    r.render(plan, vp, renderer::ViewOptions{.lightViewSize = 16, .overlays = false, .unwarped = false});
    Frame f;
    f.eye = r.readEye();
    f.eyeTriangles = r.stats().eyeTriangles;
    f.inspection = renderer::inspect(r, plan, &truth, 2);
    return f;
}

} // namespace

TEST(InstancedRender, EqualsTheFlattenedScenePixelForPixel) {
    const auto context = renderer::createOSMesaContext();
    const Scene instanced = instancedPlane();
    const Scene flat = flattenInstances(instanced);
    for (const char* preset : {"paper.json", "pssm3.json"}) {
        SCOPED_TRACE(preset);
        const ShadowSettings settings = geometry::io::loadPreset(kResources + "presets/" + preset);
        const Frame a = render(instanced, settings), b = render(flat, settings);
        ASSERT_EQ(a.eye.width, b.eye.width);
        ASSERT_EQ(a.eye.rgba.size(), b.eye.rgba.size());
        EXPECT_EQ(0, std::memcmp(a.eye.rgba.data(), b.eye.rgba.data(), a.eye.rgba.size()));
        ASSERT_EQ(a.inspection.shadow.size(), b.inspection.shadow.size());
        EXPECT_EQ(0, std::memcmp(a.inspection.shadow.data(), b.inspection.shadow.data(),
                                 a.inspection.shadow.size() * sizeof(float)));
        ASSERT_EQ(a.inspection.classes.size(), b.inspection.classes.size());
        EXPECT_TRUE(a.inspection.classes == b.inspection.classes);
        ASSERT_TRUE(a.inspection.truthClasses && b.inspection.truthClasses);
        EXPECT_EQ(a.inspection.truthClasses->ambiguous, b.inspection.truthClasses->ambiguous);
        EXPECT_EQ(a.inspection.truthClasses->edgeError, b.inspection.truthClasses->edgeError);
        // The same triangles reach the eye pass: whole placements for the instanced mesh, and the
        // one behind the camera culled (the flattened poles cull chunk by chunk, so not equal).
        const uint64_t poles = instanced.meshes.back().triangleCount();
        EXPECT_LE(a.eyeTriangles, instanced.placedTriangleCount() - poles);
        EXPECT_GE(a.eyeTriangles, instanced.meshes.front().triangleCount() / 4 + poles);
        // The poles' shadows are in view: some pixels are truly shadowed.
        ASSERT_TRUE(a.inspection.occluded.has_value());
        size_t shadowed = 0;
        for (const uint8_t o : *a.inspection.occluded) shadowed += o;
        EXPECT_GT(shadowed, 50u);
    }
}

TEST(CompactRender, DrawsThePixelsOfTheSameTrianglesInFloats) {
    const auto context = renderer::createOSMesaContext();
    const Scene chunked = makePlatformScene();
    for (const Mesh& m : chunked.meshes) ASSERT_TRUE(compactVertices(m).has_value()) << m.name; // drawn compact
    Scene floats = chunked; // one run of the same triangles in the same order: GpuScene keeps floats
    for (Mesh& m : floats.meshes) {
        m.chunks.clear();
        m.parts.clear();
        reserveSpareVertex(m);
    }
    ShadowSettings settings = geometry::io::loadPreset(kResources + "presets/pssm3.json");
    const Frame a = render(chunked, settings), b = render(floats, settings);
    ASSERT_EQ(a.eye.rgba.size(), b.eye.rgba.size());
    EXPECT_EQ(0, std::memcmp(a.eye.rgba.data(), b.eye.rgba.data(), a.eye.rgba.size()));
    ASSERT_EQ(a.inspection.shadow.size(), b.inspection.shadow.size());
    EXPECT_EQ(0, std::memcmp(a.inspection.shadow.data(), b.inspection.shadow.data(),
                             a.inspection.shadow.size() * sizeof(float)));
    EXPECT_TRUE(a.inspection.classes == b.inspection.classes);
    EXPECT_LT(a.eyeTriangles, b.eyeTriangles); // the chunks culled
}
