// Scene files (geometry/io/scene_file.h): the shipped files, transforms, model references, every
// validation error, and resolveScene() for each kind of --scene argument.
#include "geometry/io/scene_file.h"
#include "geometry/scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

using namespace geometry::scene;
using namespace geometry::io;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(SHADOWSCOPE_SOURCE_DIR) / "resources" / "scenes";

/// An empty folder under the system temp folder, named for the test and this process (two runs at
/// once never share it).
fs::path freshDir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("shadowscope_scene_file_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

fs::path writeFile(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/// A 2 × 1 × 4 box from (0, 0, 0), as ASCII OBJ written by hand (no dependence on saveMesh).
std::string boxObj() {
    return "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 4\nv 2 0 4\nv 2 1 4\nv 0 1 4\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

/// The bounds of every mesh except the last (the ground plane resolveScene adds).
Aabb modelBounds(const Scene& s) {
    Aabb b;
    for (size_t i = 0; i + 1 < s.meshes.size(); ++i) b.add(s.meshes[i].worldBounds());
    return b;
}

/// True when every corner of `b` lies inside the camera's view frustum at `aspect`.
bool seesCorners(const Camera& c, const Aabb& b, float aspect) {
    const glm::mat4 vp = c.projection(aspect) * c.view();
    for (const auto& p : b.corners()) {
        const glm::vec4 q = vp * glm::vec4(p, 1.f);
        if (!(q.w > 0.f) || std::abs(q.x) > q.w || std::abs(q.y) > q.w || std::abs(q.z) > q.w) return false;
    }
    return true;
}

float elevationDeg(const glm::vec3& d) { return glm::degrees(std::asin(-glm::normalize(d).y)); }

} // namespace

// ---- Shipped scene files ----------------------------------------------------------------------

TEST(SceneFile, ShippedPlatformHasItsCanonicalViews) {
    const SceneFile f = loadSceneFile((kScenes / "platform.json").string());
    EXPECT_EQ(f.scene.name, "platform");
    const Scene builtin = makePlatformScene();
    EXPECT_EQ(f.scene.triangleCount(), builtin.triangleCount());
    expectNear(f.scene.camera.eye, builtin.camera.eye); // the built-in's camera is the default
    for (const char* name : {"deck", "overview", "grazing", "dueling"}) ASSERT_TRUE(f.views.count(name)) << name;
    const CanonicalView& deck = f.views.at("deck");
    expectNear(deck.camera.eye, builtin.camera.eye);
    expectNear(deck.camera.target, builtin.camera.target);
    expectNear(deck.light.direction, builtin.lights[0].direction);
    const auto gamma = [&](const char* n) { return gammaDeg(f.views.at(n).camera.viewDir(), f.views.at(n).light.l()); };
    EXPECT_GT(gamma("overview"), 70.f);
    EXPECT_GT(f.views.at("overview").camera.eye.y, 80.f);                   // well above the top deck (47 m)
    EXPECT_GT(elevationDeg(f.views.at("overview").camera.viewDir()), 25.f); // looking down on it
    EXPECT_LT(gamma("grazing"), 20.f);
    EXPECT_LT(elevationDeg(f.views.at("grazing").light.direction), 20.f);
    const CanonicalView& dueling = f.views.at("dueling");
    EXPECT_GT(lightViewAngleDeg(dueling.camera.viewDir(), dueling.light.l()), 150.f);
    ASSERT_TRUE(f.paths.count("sun_arc"));
    EXPECT_EQ(f.paths.at("sun_arc").lights.size(), 5u);
}

TEST(SceneFile, ShippedPiperackHasItsCanonicalViews) {
    const SceneFile f = loadSceneFile((kScenes / "piperack.json").string());
    EXPECT_EQ(f.scene.name, "piperack");
    EXPECT_NEAR(static_cast<double>(f.scene.triangleCount()), 1e6, 1e5); // the file's params reach the builder
    const Scene builtin = makePiperackScene({50'000, 1});                // its camera and light do not vary
    expectNear(f.scene.camera.eye, builtin.camera.eye);
    for (const char* name : {"walk", "overview", "grazing", "dueling"}) ASSERT_TRUE(f.views.count(name)) << name;
    const CanonicalView& walk = f.views.at("walk");
    expectNear(walk.camera.eye, builtin.camera.eye);
    expectNear(walk.camera.target, builtin.camera.target);
    expectNear(walk.light.direction, builtin.lights[0].direction);
    EXPECT_FLOAT_EQ(walk.camera.far, builtin.camera.far);
    const auto gamma = [&](const char* n) { return gammaDeg(f.views.at(n).camera.viewDir(), f.views.at(n).light.l()); };
    const CanonicalView& overview = f.views.at("overview");
    EXPECT_GT(gamma("overview"), 60.f);
    EXPECT_GT(elevationDeg(overview.camera.viewDir()), 25.f); // looking down on the rack
    Aabb rack;                                                // the whole rack, ground aside, in view
    for (const Mesh& m : f.scene.meshes)
        if (m.name != "ground") rack.add(m.worldBounds());
    EXPECT_TRUE(seesCorners(overview.camera, rack, 16.f / 9.f));
    EXPECT_LT(gamma("grazing"), 20.f);
    EXPECT_LT(elevationDeg(f.views.at("grazing").light.direction), 20.f);
    const CanonicalView& dueling = f.views.at("dueling");
    EXPECT_GT(lightViewAngleDeg(dueling.camera.viewDir(), dueling.light.l()), 150.f);
}

TEST(SceneFile, ShippedPlaneHasDefaultAndGamma90) {
    const SceneFile f = loadSceneFile((kScenes / "plane.json").string());
    const Scene builtin = makePlaneScene();
    EXPECT_EQ(f.scene.meshes.size(), builtin.meshes.size());
    ASSERT_TRUE(f.views.count("default"));
    expectNear(f.views.at("default").camera.eye, builtin.camera.eye);
    ASSERT_TRUE(f.views.count("gamma90"));
    const CanonicalView& v = f.views.at("gamma90");
    EXPECT_NEAR(gammaDeg(v.camera.viewDir(), v.light.l()), 90.f, 0.1f);
    EXPECT_NEAR(elevationDeg(v.camera.viewDir()), 45.f, 0.1f);
    EXPECT_NEAR(elevationDeg(v.light.direction), 45.f, 0.1f);
}

// ---- Transforms -------------------------------------------------------------------------------

TEST(SceneFile, TranslateAndScaleMoveBuiltinBoundsAndCamera) {
    const fs::path dir = freshDir("transform");
    const fs::path file = writeFile(dir / "moved.json", R"({"meshes": [{"builtin": "plane", "translate": [10, 2, -5],
                                                             "scale": 2, "color": [0.1, 0.2, 0.3]}]})");
    const SceneFile f = loadSceneFile(file.string());
    const Scene plane = makePlaneScene();
    const Aabb want{2.f * plane.bounds().lo + glm::vec3(10, 2, -5), 2.f * plane.bounds().hi + glm::vec3(10, 2, -5)};
    expectNear(f.scene.bounds().lo, want.lo);
    expectNear(f.scene.bounds().hi, want.hi);
    for (const Mesh& m : f.scene.meshes) {
        expectNear(m.color, {0.1f, 0.2f, 0.3f});
        // Chunk bounds follow the new transform exactly.
        Aabb chunks;
        for (const Chunk& c : m.chunks) chunks.add(c.bounds);
        expectNear(chunks.lo, m.worldBounds().lo);
        expectNear(chunks.hi, m.worldBounds().hi);
    }
    // The built-in's camera follows its meshes.
    expectNear(f.scene.camera.eye, 2.f * plane.camera.eye + glm::vec3(10, 2, -5));
    EXPECT_EQ(f.scene.name, "moved");
}

TEST(SceneFile, RotationAndPerAxisScaleComposeTRS) {
    const fs::path dir = freshDir("rotate");
    const fs::path file = writeFile(dir / "r.json", R"({"meshes": [{"builtin": "plane", "rotate_deg": [0, 90, 0],
                                                         "scale": [1, 3, 0.5], "translate": [0, 1, 0]}]})");
    const SceneFile f = loadSceneFile(file.string());
    const Aabb b = makePlaneScene().bounds();
    // S then R (90° about y maps x → -z, z → x) then T.
    const Aabb scaled{b.lo * glm::vec3(1, 3, 0.5f), b.hi * glm::vec3(1, 3, 0.5f)};
    const Aabb want{{scaled.lo.z, scaled.lo.y + 1.f, -scaled.hi.x}, {scaled.hi.z, scaled.hi.y + 1.f, -scaled.lo.x}};
    expectNear(f.scene.bounds().lo, want.lo, 1e-3f);
    expectNear(f.scene.bounds().hi, want.hi, 1e-3f);
}

TEST(SceneFile, ReferencesAModelFileRelativeToItsFolder) {
    const fs::path dir = freshDir("model");
    fs::create_directories(dir / "models");
    writeFile(dir / "models" / "box.obj", boxObj());
    const fs::path file = writeFile(dir / "s.json", R"({
        "name": "boxes",
        "meshes": [{"file": "models/box.obj", "translate": [1, 0, 0]},
                   {"file": ")" + (dir / "models" / "box.obj").string() +
                                                        R"(", "translate": [0, 5, 0], "color": [1, 0, 0]}],
        "ground": {"size": 50, "height": -1},
        "light": {"direction": [0, -1, 0]}})");
    const SceneFile f = loadSceneFile(file.string());
    EXPECT_EQ(f.scene.name, "boxes");
    ASSERT_EQ(f.scene.meshes.size(), 3u);
    expectNear(f.scene.meshes[0].worldBounds().lo, {1, 0, 0});
    expectNear(f.scene.meshes[0].worldBounds().hi, {3, 1, 4});
    expectNear(f.scene.meshes[1].worldBounds().lo, {0, 5, 0});
    expectNear(f.scene.meshes[1].color, {1, 0, 0});
    const Aabb ground = f.scene.meshes[2].worldBounds();
    EXPECT_FLOAT_EQ(ground.lo.y, -1.f);
    EXPECT_FLOAT_EQ(ground.hi.x - ground.lo.x, 50.f);
    expectNear(f.scene.lights[0].direction, {0, -1, 0});
    // No camera given and no built-in: framed on the models.
    Aabb models = f.scene.meshes[0].worldBounds();
    models.add(f.scene.meshes[1].worldBounds());
    EXPECT_TRUE(seesCorners(f.scene.camera, models, 1.f));
}

// Instancing (docs/design.md §2 "Instances"): a grid and a list place the same arrays several
// times, after the entry's own placement; bounds, the ground and the triangle counts see every placement.
TEST(SceneFile, GridAndInstancesPlaceAModelSeveralTimes) {
    const fs::path dir = freshDir("instances");
    writeFile(dir / "box.obj", boxObj());
    const fs::path file = writeFile(dir / "i.json", R"({
        "meshes": [{"file": "box.obj", "translate": [0, 1, 0],
                    "grid": {"count": [3, 1, 2], "spacing": [10, 0, 20], "origin": [-10, 0, 0]}},
                   {"file": "box.obj", "instances": [{"translate": [100, 0, 0]},
                                                      {"translate": [0, 0, 100], "rotate_deg": [0, 90, 0]}]}],
        "ground": {}})");
    const SceneFile f = loadSceneFile(file.string());
    ASSERT_EQ(f.scene.meshes.size(), 3u); // two instanced boxes and the ground
    const Mesh& grid = f.scene.meshes[0];
    ASSERT_EQ(grid.instances.size(), 6u);
    EXPECT_EQ(grid.triangleCount(), 12u);
    EXPECT_EQ(grid.placedTriangleCount(), 72u);
    // x fastest: placement 4 is (i, k) = (1, 1); the entry's translate applies first.
    expectNear(grid.placementBounds(4).lo, {0, 1, 20});
    expectNear(grid.placementBounds(4).hi, {2, 2, 24});
    const Mesh& listed = f.scene.meshes[1];
    ASSERT_EQ(listed.instances.size(), 2u);
    expectNear(listed.placementBounds(0).lo, {100, 0, 0});
    // 90° about y turns (x, z) into (z, −x): the 2 × 4 footprint becomes 4 × 2 at x ≥ 0, z ≤ 100.
    expectNear(listed.placementBounds(1).lo, {0, 0, 98});
    expectNear(listed.placementBounds(1).hi, {4, 1, 100});
    EXPECT_EQ(f.scene.triangleCount(), 24u + f.scene.meshes[2].triangleCount());
    EXPECT_EQ(f.scene.placedTriangleCount(), 96u + f.scene.meshes[2].triangleCount());
    const Aabb all = f.scene.meshes[0].placementBounds(0);
    EXPECT_FLOAT_EQ(all.lo.x, -10.f);
    // The ground spans every placement (4 × the footprint, centred on the models).
    const Aabb ground = f.scene.meshes[2].worldBounds();
    EXPECT_LT(ground.lo.x, -10.f);
    EXPECT_GT(ground.hi.z, 100.f);
}

TEST(SceneFile, ViewsAndPathsArePartialOverTheSceneCamera) {
    const fs::path dir = freshDir("views");
    const fs::path file = writeFile(dir / "v.json", R"({"meshes": [{"builtin": "plane"}],
        "camera": {"far": 300},
        "views": {"top": {"camera": {"eye": [0, 50, 0.1], "target": [0, 0, 0]}}, "sun": {"light": {"direction": [1, -1, 0]}}},
        "paths": {"orbit": {"camera": [{"eye": [10, 5, 0]}, {"eye": [0, 5, 10], "fov_y": 40}]}}})");
    const SceneFile f = loadSceneFile(file.string());
    const Scene plane = makePlaneScene();
    EXPECT_FLOAT_EQ(f.scene.camera.far, 300.f);
    expectNear(f.scene.camera.eye, plane.camera.eye);
    const CanonicalView& top = f.views.at("top");
    expectNear(top.camera.eye, {0, 50, 0.1f});
    EXPECT_FLOAT_EQ(top.camera.far, 300.f);
    expectNear(top.light.direction, plane.lights[0].direction);
    expectNear(f.views.at("sun").camera.eye, plane.camera.eye);
    const ScenePath& orbit = f.paths.at("orbit");
    ASSERT_EQ(orbit.cameras.size(), 2u);
    expectNear(orbit.cameras[0].target, plane.camera.target);
    EXPECT_FLOAT_EQ(orbit.cameras[1].fovYDeg, 40.f);
    EXPECT_TRUE(orbit.lights.empty());
}

TEST(SceneFile, ProgressCoversEveryEntryInOrder) {
    const fs::path dir = freshDir("progress");
    const fs::path file = writeFile(dir / "p.json", R"({"meshes": [{"builtin": "plane"}, {"builtin": "plane"}]})");
    std::vector<float> fractions;
    (void)loadSceneFile(file.string(), [&](float f, std::string_view) { fractions.push_back(f); });
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GE(fractions.front(), 0.f);
    EXPECT_FLOAT_EQ(fractions.back(), 1.f);
    EXPECT_NE(std::find(fractions.begin(), fractions.end(), 0.5f), fractions.end()); // first entry done
}

TEST(SceneFile, GroundAloneIsAScene) {
    const fs::path dir = freshDir("ground");
    const SceneFile f = loadSceneFile(writeFile(dir / "g.json", R"({"ground": {"size": 20}})").string());
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    EXPECT_FLOAT_EQ(f.scene.bounds().extent().x, 20.f);
    EXPECT_GT(f.scene.camera.far, f.scene.camera.near);
}

TEST(SceneFile, OccluderEdgeIsReadInWorldSpace) {
    const fs::path dir = freshDir("edge");
    const SceneFile f = loadSceneFile(
        writeFile(dir / "edge.json", R"({"ground": {}, "occluder_edge": [[-2, 1.5, 0.25], [3, 1.5, -0.5]]})").string());
    ASSERT_TRUE(f.scene.occluderEdge.has_value());
    expectNear((*f.scene.occluderEdge)[0], {-2.f, 1.5f, 0.25f}, 0.f);
    expectNear((*f.scene.occluderEdge)[1], {3.f, 1.5f, -0.5f}, 0.f);
    const SceneFile none = loadSceneFile(writeFile(dir / "none.json", R"({"ground": {}})").string());
    EXPECT_FALSE(none.scene.occluderEdge.has_value());
}

// ---- Errors -----------------------------------------------------------------------------------

struct BadScene {
    const char* json;
    const char* expected; // the key path, or the problem for file-level errors
};

TEST(SceneFile, EveryErrorIsOneLineNamingTheFileAndTheKey) {
    const BadScene cases[] = {
        {"", "file is empty"},
        {"{", "not valid JSON"},
        {"[1, 2]", "expected a JSON object"},
        {R"({"meshes": [{"builtin": "plane"}], "camra": {}})", "camra: unknown key"},
        {R"({"meshes": [{"builtin": "plane", "tranlsate": [1, 2, 3]}]})", "meshes[0].tranlsate: unknown key"},
        {R"({"meshes": [{"builtin": "plane"}, {"builtin": "plane"}, {"builtin": "plane", "translate": [1, 2]}]})",
         "meshes[2].translate: expected 3 numbers"},
        {R"({"meshes": [{"builtin": "plane", "translate": "up"}]})", "meshes[0].translate: expected 3 numbers"},
        {R"({"meshes": [{"builtin": "plane", "translate": [1, "2", 3]}]})",
         "meshes[0].translate[1]: expected a number"},
        {R"({"meshes": [{"builtin": "plane", "scale": 1e999}]})", "1e999"},
        {R"({"meshes": [{"builtin": "plane", "scale": 1e300}]})", "meshes[0].scale: number out of range"},
        {R"({"meshes": [{"builtin": "plane", "scale": 0}]})", "meshes[0].scale: expected a positive number"},
        {R"({"meshes": [{"builtin": "plane", "scale": [1, -1, 1]}]})", "meshes[0].scale[1]"},
        {R"({"meshes": [{"builtin": "plane", "color": [0.5, 2, 0]}]})", "meshes[0].color[1]"},
        {R"({"meshes": [{"builtin": "plane", "rotate_deg": null}]})", "meshes[0].rotate_deg"},
        {R"({"meshes": {"builtin": "plane"}})", "meshes: expected an array"},
        {R"({"meshes": [42]})", "meshes[0]: expected an object"},
        {R"({"meshes": [{}]})", "meshes[0]: expected exactly one of"},
        {R"({"meshes": [{"builtin": "plane", "file": "a.stl"}]})", "meshes[0]: expected exactly one of"},
        {R"({"meshes": [{"builtin": "ship"}]})", "meshes[0].builtin: unknown built-in scene 'ship'"},
        {R"({"meshes": [{"builtin": 3}]})", "meshes[0].builtin: expected a string"},
        {R"({"meshes": [{"builtin": "plane", "params": {}}]})", "meshes[0].params"},
        {R"({"meshes": [{"file": "x.obj", "params": {}}]})", "meshes[0].params"},
        {R"({"meshes": [{"builtin": "platform", "params": {"triangles": "many"}}]})", "meshes[0].params.triangles"},
        {R"({"meshes": [{"builtin": "platform", "params": {"triangles": 0}}]})", "meshes[0].params.triangles"},
        {R"({"meshes": [{"builtin": "platform", "params": {"seed": -1}}]})", "meshes[0].params.seed"},
        {R"({"meshes": [{"builtin": "platform", "params": {"seed": 1.5}}]})", "meshes[0].params.seed"},
        {R"({"meshes": [{"builtin": "platform", "params": {"tris": 5}}]})", "meshes[0].params.tris: unknown key"},
        {R"({"meshes": [{"builtin": "piperack", "params": {"triangles": 64000001}}]})", "meshes[0].params.triangles"},
        {R"({"meshes": [{"builtin": "piperack", "params": {"seed": "one"}}]})", "meshes[0].params.seed"},
        {R"({"meshes": [{"builtin": "piperack", "params": []}]})", "meshes[0].params: expected an object"},
        {R"({"meshes": [{"file": "missing.stl"}]})", "meshes[0].file: "},
        {R"({"meshes": [{"file": ""}]})", "meshes[0].file"},
        {R"({})", "empty scene"},
        {R"({"meshes": []})", "empty scene"},
        {R"({"name": 5, "ground": {}})", "name: expected a string"},
        {R"({"description": [], "ground": {}})", "description: expected a string"},
        {R"({"ground": {"size": -1}})", "ground.size"},
        {R"({"ground": {"height": "low"}})", "ground.height"},
        {R"({"ground": {"colour": [1, 1, 1]}})", "ground.colour: unknown key"},
        {R"({"ground": 1})", "ground: expected an object"},
        {R"({"ground": {}, "camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}})", "camera.target: eye and target"},
        {R"({"ground": {}, "camera": {"near": 0}})", "camera.near"},
        {R"({"ground": {}, "camera": {"near": -1}})", "camera.near"},
        {R"({"ground": {}, "camera": {"near": 5, "far": 5}})", "camera.far: far"},
        {R"({"ground": {}, "camera": {"near": 5, "far": 1}})", "camera.far: far"},
        {R"({"ground": {}, "camera": {"fov_y": 0}})", "camera.fov_y"},
        {R"({"ground": {}, "camera": {"fov_y": 180}})", "camera.fov_y"},
        {R"({"ground": {}, "camera": {"fov_y": -20}})", "camera.fov_y"},
        {R"({"ground": {}, "camera": {"up": [0, 0, 0]}})", "camera.up"},
        {R"({"ground": {}, "camera": {"fov": 50}})", "camera.fov: unknown key"},
        {R"({"ground": {}, "light": {"direction": [0, 0, 0]}})", "light.direction: direction must not be zero"},
        {R"({"ground": {}, "light": {"direction": [0, -1]}})", "light.direction: expected 3 numbers"},
        {R"({"ground": {}, "light": [0, -1, 0]})", "light: expected an object"},
        {R"({"ground": {}, "lights": []})", "lights: expected an array of 1 to 8 lights"},
        {R"({"ground": {}, "lights": [{}, {}, {}, {}, {}, {}, {}, {}, {}]})", "lights: expected an array of 1 to 8"},
        {R"({"ground": {}, "light": {}, "lights": [{}]})", "lights: give \"light\" or \"lights\", not both"},
        {R"({"ground": {}, "lights": [{}, {"type": "area"}]})", "lights[1].type: unknown light type \"area\""},
        {R"({"ground": {}, "lights": [{"type": "spot", "cone_deg": 0}]})", "lights[0].cone_deg: expected a cone angle"},
        {R"({"ground": {}, "lights": [{"type": "spot", "cone_deg": 180}]})", "lights[0].cone_deg: expected a cone"},
        {R"({"ground": {}, "lights": [{"type": "point", "position": [0, null, 0]}]})",
         "lights[0].position[1]: expected a number"},
        {R"({"ground": {}, "lights": [{"type": "point", "position": [1e39, 0, 0]}]})",
         "lights[0].position[0]: number out of range"},
        {R"({"ground": {}, "lights": [{"type": "point", "range": 0}]})", "lights[0].range: expected a positive"},
        {R"({"ground": {}, "lights": [{"type": "point", "radius": -1}]})", "lights[0].radius: expected a radius"},
        {R"({"ground": {}, "lights": [{"colour": [1, 1, 1]}]})", "lights[0].colour: unknown key"},
        {R"({"ground": {}, "views": []})", "views: expected an object"},
        {R"({"ground": {}, "views": {"a": {"camera": {"eye": [1, 2]}}}})", "views.a.camera.eye: expected 3 numbers"},
        {R"({"ground": {}, "views": {"a": {"light": {"direction": [0, 0, 0]}}}})", "views.a.light.direction"},
        {R"({"ground": {}, "views": {"a": {"cam": {}}}})", "views.a.cam: unknown key"},
        {R"({"ground": {}, "views": {"a": {"camera": {"near": 10, "far": 2}}}})", "views.a.camera.far"},
        {R"({"ground": {}, "paths": {"p": {}}})", "paths.p: expected \"camera\", \"light\" or \"light_position\""},
        {R"({"ground": {}, "paths": {"p": {"light": [[0, -1, 0], [0, 0, 0]]}}})", "paths.p.light[1]"},
        {R"({"ground": {}, "paths": {"p": {"light": []}}})", "paths.p.light: expected a non-empty array"},
        {R"({"ground": {}, "paths": {"p": {"light_index": 1, "light": [[0, -1, 0]]}}})",
         "paths.p.light_index: expected an integer in 0..0"},
        {R"({"ground": {}, "paths": {"p": {"light_position": [[0, 5, 0]]}}})",
         "paths.p.light_position: light 0 is directional"},
        {R"({"ground": {}, "lights": [{"type": "point", "position": [0, 5, 0]}], "paths": {"p": {"light_position": [[0, 5]]}}})",
         "paths.p.light_position[0]"},
        {R"({"ground": {}, "paths": {"p": {"camera": [{"eye": [0, 0, 0], "target": [0, 0, 0]}]}}})",
         "paths.p.camera[0].target"},
        // A NaN as nlohmann writes it (null), beyond float's range (infinite as a float), one point, the
        // same point twice.
        {R"({"ground": {}, "occluder_edge": [[0, null, 0], [1, 1, 0]]})", "occluder_edge[0][1]: expected a number"},
        {R"({"ground": {}, "occluder_edge": [[0, 1, 0], [1e39, 1, 0]]})", "occluder_edge[1][0]: number out of range"},
        {R"({"ground": {}, "occluder_edge": [[0, 1, 0]]})", "occluder_edge: expected 2 points"},
        {R"({"ground": {}, "occluder_edge": [[0, 1, 0], [0, 1, 0]]})", "occluder_edge: the two points are the same"},
        {R"({"ground": {}, "occluder_edge": [[0, 1, 0], [1, 1]]})", "occluder_edge[1]: expected 3 numbers"},
        {R"({"ground": {}, "occluder_edge": "x"})", "occluder_edge: expected 2 points"},
        {R"({"meshes": [{"builtin": "plane", "instances": [], "grid": {}}]})",
         "meshes[0].grid: expected one of \"instances\" or \"grid\""},
        {R"({"meshes": [{"builtin": "plane", "instances": []}]})", "meshes[0].instances: expected an array of 1 to"},
        {R"({"meshes": [{"builtin": "plane", "instances": [{"move": [1, 0, 0]}]}]})",
         "meshes[0].instances[0].move: unknown key"},
        {R"({"meshes": [{"builtin": "plane", "grid": {"count": [2, 2]}}]})",
         "meshes[0].grid: expected \"count\" and \"spacing\""},
        {R"({"meshes": [{"builtin": "plane", "grid": {"count": [0, 1, 1], "spacing": [1, 1, 1]}}]})",
         "meshes[0].grid.count[0]: expected an integer in 1..1048576"},
        {R"({"meshes": [{"builtin": "plane", "grid": {"count": [1024, 1024, 2], "spacing": [1, 1, 1]}}]})",
         "meshes[0].grid.count: 2097152 placements; at most 1048576"},
        {R"({"meshes": [{"builtin": "plane", "translate": [3e38, 0, 0], "instances": [{"translate": [3e38, 0, 0]}]}]})",
         "meshes[0]: 'ground' placement 0 lies beyond the float range"},
    };
    const fs::path dir = freshDir("errors");
    int index = 0;
    for (const BadScene& c : cases) {
        const fs::path file = writeFile(dir / ("bad" + std::to_string(index++) + ".json"), c.json);
        try {
            (void)loadSceneFile(file.string());
            ADD_FAILURE() << "no error for " << c.json;
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.filename().string()), std::string::npos) << what;
            EXPECT_NE(what.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST(SceneFile, MissingModelFilePropagatesTheLoadersMessage) {
    const fs::path dir = freshDir("missing");
    const fs::path file = writeFile(dir / "m.json", R"({"meshes": [{"file": "sub/gone.stl"}]})");
    try {
        (void)loadSceneFile(file.string());
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("m.json: meshes[0].file: "), std::string::npos) << what;
        EXPECT_NE(what.find("gone.stl"), std::string::npos) << what; // loadModel names the file
    }
}

TEST(SceneFile, FileLevelLimits) {
    const fs::path dir = freshDir("limits");
    const auto messageFor = [](const fs::path& file) {
        try {
            (void)loadSceneFile(file.string());
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string big = R"({"ground": {}, "description": ")" + std::string(kMaxSceneFileBytes, 'x') + "\"}";
    EXPECT_NE(messageFor(writeFile(dir / "big.json", big)).find("big.json: larger than 1 MiB"), std::string::npos);
    std::string deep = R"({"ground": {}, "description": )";
    for (int i = 0; i < 20; ++i) deep += "[";
    for (int i = 0; i < 20; ++i) deep += "]";
    deep += "}";
    EXPECT_NE(messageFor(writeFile(dir / "deep.json", deep)).find("deep.json: nested deeper than 16"),
              std::string::npos);
    EXPECT_NE(messageFor(dir / "absent.json").find("absent.json: no such file"), std::string::npos);
    EXPECT_NE(messageFor(dir).find("is a directory"), std::string::npos);
}

// ---- Framing and resolveScene -------------------------------------------------------------------

TEST(SceneFile, FrameCameraSeesTheWholeBox) {
    const Aabb boxes[] = {
        {{-1, -1, -1}, {1, 1, 1}}, {{0, 0, 0}, {100, 1, 100}},    {{-5, 0, -5}, {5, 200, 5}},
        {{3, 3, 3}, {3, 3, 3}},    {{-1000, 0, 0}, {1000, 2, 3}},
    };
    for (const Aabb& b : boxes) {
        for (float fov : {30.f, 60.f, 90.f}) {
            const Camera c = frameCamera(b, fov);
            EXPECT_TRUE(seesCorners(c, b, 1.f)) << fov;
            EXPECT_TRUE(seesCorners(c, b, 16.f / 9.f)) << fov;
            EXPECT_GT(c.eye.y, b.center().y); // from above
            EXPECT_GT(c.near, 0.f);
            EXPECT_GT(c.far, c.near);
        }
    }
    const Aabb unit{{0, 0, 0}, {1, 2, 2}}; // diagonal 3
    EXPECT_FLOAT_EQ(frameCamera(unit).near, 0.003f);
    EXPECT_FLOAT_EQ(frameCamera(unit).far, 9.f);
    // The default light lets the framed view see shadows: neither along nor against the view.
    const float gamma = gammaDeg(frameCamera(unit).viewDir(), defaultLight().l());
    EXPECT_GT(gamma, 45.f);
    EXPECT_LT(elevationDeg(defaultLight().direction), 80.f);
    EXPECT_GT(elevationDeg(defaultLight().direction), 20.f);
}

TEST(SceneFile, ResolveBuiltinName) {
    const SceneFile f = resolveScene("plane");
    EXPECT_EQ(f.scene.name, "plane");
    EXPECT_EQ(f.scene.meshes.size(), makePlaneScene().meshes.size());
    ASSERT_EQ(f.views.size(), 1u);
    expectNear(f.views.at("default").camera.eye, makePlaneScene().camera.eye);
}

TEST(SceneFile, ResolveSceneFile) {
    const SceneFile f = resolveScene((kScenes / "plane.json").string());
    EXPECT_TRUE(f.views.count("gamma90"));
}

TEST(SceneFile, ResolveModelFileAddsGroundAndFramesIt) {
    const fs::path dir = freshDir("resolve_model");
    const fs::path obj = writeFile(dir / "Box.OBJ", boxObj());
    const SceneFile f = resolveScene(obj.string());
    EXPECT_EQ(f.scene.name, "Box");
    ASSERT_GE(f.scene.meshes.size(), 2u);
    const Aabb model = modelBounds(f.scene);
    expectNear(model.lo, {0, 0, 0});
    expectNear(model.hi, {2, 1, 4});
    const Aabb ground = f.scene.meshes.back().worldBounds();
    EXPECT_FLOAT_EQ(ground.lo.y, 0.f);
    EXPECT_FLOAT_EQ(ground.hi.y, 0.f);
    EXPECT_NEAR(ground.hi.x - ground.lo.x, 16.f, 1e-4f); // 4 × the 4 m footprint
    expectNear(ground.center(), {1, 0, 2});
    EXPECT_TRUE(seesCorners(f.scene.camera, model, 1.f));
    EXPECT_TRUE(seesCorners(f.scene.camera, model, 16.f / 9.f));
    // far reaches the ground's far corners too.
    for (const auto& corner : ground.corners()) EXPECT_LT(glm::length(corner - f.scene.camera.eye), f.scene.camera.far);
    EXPECT_TRUE(f.views.count("default"));
    expectNear(f.scene.lights[0].direction, defaultLight().direction);
}

TEST(SceneFile, ResolveUnknownNameListsWhatIsAccepted) {
    try {
        (void)resolveScene("nosuchscene");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        for (const char* part : {"nosuchscene", "platform", "plane", ".json", ".obj", ".stl", ".glb"})
            EXPECT_NE(what.find(part), std::string::npos) << part << " in: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
    EXPECT_THROW((void)resolveScene("/nonexistent/scene.json"), std::runtime_error);
    EXPECT_THROW((void)resolveScene("/nonexistent/model.stl"), std::runtime_error);
}

// "lights": a directional, a spot and a point light, members read as given, the rest defaulted.
TEST(SceneFile, LightsArrayReadsEveryType) {
    const fs::path file = writeFile(freshDir("lights") / "lights.json", R"({"ground": {}, "lights": [
        {"direction": [0, -1, 0]},
        {"type": "spot", "position": [1, 8, 2], "direction": [0, -1, 0.5], "cone_deg": 45, "range": 30},
        {"type": "point", "position": [0, 3, 0], "range": 12, "radius": 0.25}]})");
    const SceneFile f = loadSceneFile(file.string());
    ASSERT_EQ(f.scene.lights.size(), 3u);
    EXPECT_EQ(f.scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(f.scene.lights[1].type, LightType::Spot);
    expectNear(f.scene.lights[1].position, {1, 8, 2});
    EXPECT_FLOAT_EQ(f.scene.lights[1].coneDeg, 45.f);
    EXPECT_FLOAT_EQ(f.scene.lights[1].range, 30.f);
    EXPECT_EQ(f.scene.lights[2].type, LightType::Point);
    EXPECT_FLOAT_EQ(f.scene.lights[2].radius, 0.25f);
    EXPECT_FLOAT_EQ(f.scene.lights[2].range, 12.f);
    EXPECT_TRUE(f.scene.lights[2].settings.empty());
    // The old single "light" still loads, as one directional light.
    const fs::path old =
        writeFile(freshDir("light") / "light.json", R"({"ground": {}, "light": {"direction": [1, -1, 0]}})");
    const SceneFile g = loadSceneFile(old.string());
    ASSERT_EQ(g.scene.lights.size(), 1u);
    EXPECT_EQ(g.scene.lights[0].type, LightType::Directional);
}

// A light's "settings" override the shared ones, written as a preset is (groups or dotted keys), each
// checked against the settings declaration and kept as key=value in the order applied.
TEST(SceneFile, ALightsSettingsAreCheckedOverrides) {
    const fs::path file = writeFile(freshDir("light_settings") / "lights.json", R"({"ground": {}, "lights": [
        {"direction": [0, -1, 0], "settings": {"shadow_map": {"resolution": 512}, "filter.type": "pcf"}}]})");
    const SceneFile f = loadSceneFile(file.string());
    EXPECT_EQ(f.scene.lights[0].settings, (std::vector<std::string>{"filter.type=pcf", "shadow_map.resolution=512"}));
    for (const auto& [settings, expected] : std::vector<std::pair<std::string, std::string>>{
             {R"({"nosuch": 1})", "lights[0].settings: unknown setting 'nosuch'"},
             {R"({"shadow_map": {"resolution": "big"}})", "lights[0].settings: shadow_map.resolution"},
             {R"([1])", "lights[0].settings: expected a JSON object"}}) {
        const fs::path bad = writeFile(freshDir("light_settings_bad") / "bad.json",
                                       R"({"ground": {}, "lights": [{"settings": )" + settings + "}]}");
        try {
            (void)loadSceneFile(bad.string());
            ADD_FAILURE() << settings << " loaded";
        } catch (const SceneFileError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    }
}
