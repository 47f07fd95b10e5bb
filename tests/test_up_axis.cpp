// Up axis (--up, "up" in scene files): a Z-up STL plate lies flat by default and with up z, stands on
// its edge with up y; each axis turns onto +y by a proper rotation; bad names are refused in one line.
#include "geometry/io/model_loader.h"
#include "geometry/io/scene_file.h"
#include "geometry/io/up_axis.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace geometry::io;
namespace fs = std::filesystem;

namespace {

/// A 10 × 6 × 0.1 box in its file's x, y, z: a plate lying flat in a Z-up file.
fs::path writePlate(const fs::path& dir) {
    const fs::path path = dir / "plate.stl";
    std::ofstream f(path);
    const float x[2] = {0, 10}, y[2] = {0, 6}, z[2] = {0, 0.1f};
    const auto v = [&](int i) { return glm::vec3(x[i & 1], y[(i >> 1) & 1], z[(i >> 2) & 1]); };
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    f << "solid plate\n";
    for (const auto& q : faces)
        for (const auto& tri : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
            f << "facet normal 0 0 0\nouter loop\n";
            for (int i : tri) f << "vertex " << v(i).x << ' ' << v(i).y << ' ' << v(i).z << '\n';
            f << "endloop\nendfacet\n";
        }
    f << "endsolid plate\n";
    return path;
}

geometry::scene::Aabb boundsOf(const LoadedModel& m) {
    geometry::scene::Aabb b;
    for (const auto& mesh : m.meshes) b.add(mesh.worldBounds());
    return b;
}

class UpAxisFiles : public ::testing::Test {
protected:
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("shadowscope_up_" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

} // namespace

TEST(UpAxis, EveryAxisTurnsOntoPlusYByARotation) {
    const std::pair<UpAxis, glm::vec3> cases[] = {{UpAxis::Y, {0, 1, 0}},     {UpAxis::Z, {0, 0, 1}},
                                                  {UpAxis::NegY, {0, -1, 0}}, {UpAxis::NegZ, {0, 0, -1}},
                                                  {UpAxis::X, {1, 0, 0}},     {UpAxis::NegX, {-1, 0, 0}}};
    for (const auto& [axis, v] : cases) {
        const glm::mat4 r = rotationToYUp(axis);
        const glm::vec3 up = glm::vec3(r * glm::vec4(v, 0.f));
        EXPECT_NEAR(glm::distance(up, glm::vec3(0, 1, 0)), 0.f, 1e-6f) << upAxisName(axis);
        EXPECT_NEAR(glm::determinant(glm::mat3(r)), 1.f, 1e-6f) << upAxisName(axis); // no mirror
        EXPECT_EQ(parseUpAxis(upAxisName(axis)), axis);
    }
    EXPECT_EQ(parseUpAxis("+z"), UpAxis::Z);
    EXPECT_FALSE(parseUpAxis("up"));
    EXPECT_FALSE(parseUpAxis(""));
    EXPECT_EQ(defaultUpAxis("stl"), UpAxis::Z);
    EXPECT_EQ(defaultUpAxis("gltf"), UpAxis::Y);
    EXPECT_EQ(defaultUpAxis("obj"), UpAxis::Y);
}

TEST_F(UpAxisFiles, AZUpStlPlateLiesFlatByDefaultAndWithUpZ) {
    const fs::path plate = writePlate(dir);
    for (const std::optional<UpAxis> up : {std::optional<UpAxis>{}, std::optional(UpAxis::Z)}) {
        const LoadedModel m = loadModel(plate.string(), {}, {}, up);
        EXPECT_EQ(m.up, UpAxis::Z);
        const glm::vec3 e = boundsOf(m).extent();
        EXPECT_NEAR(e.y, 0.1f, 1e-5f); // thickness is vertical
        EXPECT_NEAR(e.x, 10.f, 1e-5f);
        EXPECT_NEAR(e.z, 6.f, 1e-5f);
        for (const auto& mesh : m.meshes)
            for (const auto& c : mesh.chunks) EXPECT_NEAR(c.bounds.extent().y, 0.1f, 1e-5f); // chunks turned too
    }
    const LoadedModel standing = loadModel(plate.string(), {}, {}, UpAxis::Y);
    EXPECT_EQ(standing.up, UpAxis::Y);
    EXPECT_NEAR(boundsOf(standing).extent().y, 6.f, 1e-5f); // on its edge
}

TEST_F(UpAxisFiles, ModelScenesRestTheModelOnTheGroundWhateverItsUpAxis) {
    const fs::path plate = writePlate(dir);
    for (const auto& up : {std::optional<UpAxis>{}, std::optional(UpAxis::Y), std::optional(UpAxis::X)}) {
        const SceneFile f = resolveScene(plate.string(), {}, up);
        ASSERT_EQ(f.scene.meshes.size(), 2u); // the plate and the ground
        const auto& ground = f.scene.meshes.back();
        EXPECT_NEAR(ground.worldBounds().hi.y, f.scene.meshes.front().worldBounds().lo.y, 1e-4f);
    }
}

TEST_F(UpAxisFiles, SceneFileEntriesTakeAnUpAxis) {
    const fs::path plate = writePlate(dir);
    const fs::path scene = dir / "scene.json";
    {
        std::ofstream f(scene);
        f << R"({"meshes": [{"file": "plate.stl", "up": "y"}]})";
    }
    EXPECT_NEAR(loadSceneFile(scene.string()).scene.meshes.front().worldBounds().extent().y, 6.f, 1e-5f);
    EXPECT_NEAR(loadSceneFile(scene.string(), {}, UpAxis::Z).scene.meshes.front().worldBounds().extent().y, 6.f,
                1e-5f); // the entry's own "up" wins over the default
    {
        std::ofstream f(scene);
        f << R"({"meshes": [{"file": "plate.stl", "up": "sideways"}]})";
    }
    try {
        (void)loadSceneFile(scene.string());
        FAIL() << "a bad up axis loaded";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("meshes[0].up"), std::string::npos) << what;
        EXPECT_NE(what.find("sideways"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
}
