// The findable dashboard's pure parts (issue 32, item 5 and 6): the file browser's listing, filter,
// sort and recent files; the numbered screenshot folders; the recent files in the config; the
// gesture table the help overlay draws; fitting the camera to a box.
#include "temp_dir_test_util.h"
#include "ui/dashboard_config.h"
#include "ui/file_list.h"
#include "ui/gesture_table.h"
#include "ui/orbit_camera.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace ui;
namespace fs = std::filesystem;

namespace {

class FileList : public testutil::TempDirTest {
protected:
    FileList() : TempDirTest("shadowscope_file_list_") {}
};

std::vector<std::string> names(const std::vector<FileEntry>& entries) {
    std::vector<std::string> out;
    for (const auto& e : entries) out.push_back(e.folder ? e.name + "/" : e.name);
    return out;
}

} // namespace

TEST_F(FileList, FoldersFirstThenSceneAndModelFilesInNameOrder) {
    for (const char* f : {"b", "A", ".hidden", "models.obj"}) fs::create_directories(dir / f); // a folder named .obj
    for (const char* f : {"z.obj", "a.STL", "scene.json", "notes.txt", "x.glb", ".h.obj", "mesh.ply", "m.off", "g.gltf",
                          "README", "data.json.bak"})
        write(f, "x");
    std::string error;
    EXPECT_EQ(names(listFolder(dir, &error)),
              (std::vector<std::string>{"A/", "b/", "models.obj/", "a.STL", "g.gltf", "m.off", "mesh.ply", "scene.json",
                                        "x.glb", "z.obj"}));
    EXPECT_EQ(error, "");
}

TEST_F(FileList, AMissingFolderListsNothingAndSaysWhy) {
    std::string error;
    EXPECT_TRUE(listFolder(dir / "missing", &error).empty());
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
}

TEST(FileListPure, SceneAndModelExtensionsAreTheLoaders) {
    for (const char* yes : {"a.json", "a.JSON", "b.obj", "c.stl", "d.off", "e.ply", "f.gltf", "g.GLB", "/x/y.z/h.obj"})
        EXPECT_TRUE(isSceneOrModelFile(yes)) << yes;
    for (const char* no : {"a.txt", "json", "a.jsonl", "a.objx", "a.", "", "dir.obj/readme"})
        EXPECT_FALSE(isSceneOrModelFile(no)) << no;
}

TEST(FileListPure, RecentFilesNewestFirstWithoutDuplicatesAndCapped) {
    std::vector<std::string> recent;
    recent = withRecentFile(recent, "/a.obj");
    recent = withRecentFile(recent, "/b.obj");
    recent = withRecentFile(recent, "/a.obj"); // opened again: to the front, once
    EXPECT_EQ(recent, (std::vector<std::string>{"/a.obj", "/b.obj"}));
    for (int i = 0; i < 30; ++i) recent = withRecentFile(recent, "/f" + std::to_string(i) + ".obj");
    ASSERT_EQ(recent.size(), kMaxRecentFiles);
    EXPECT_EQ(recent.front(), "/f29.obj");
    EXPECT_EQ(recent.back(), "/f20.obj");
}

TEST_F(FileList, NumberedFoldersAreNeverReused) {
    const fs::path shots = dir / "screenshots";
    const fs::path a = createNumberedFolder(shots), b = createNumberedFolder(shots);
    EXPECT_EQ(a.filename(), "001");
    EXPECT_EQ(b.filename(), "002");
    EXPECT_TRUE(fs::is_directory(a));
    EXPECT_TRUE(fs::is_directory(b));
    // Gaps and other names: one more than the highest number, even after an earlier one was removed.
    fs::create_directories(shots / "041");
    fs::create_directories(shots / "notes");
    fs::create_directories(shots / "12"); // too short to be one of ours
    fs::remove(a);
    EXPECT_EQ(createNumberedFolder(shots).filename(), "042");
    fs::create_directories(shots / "999");
    EXPECT_EQ(createNumberedFolder(shots).filename(), "1000");
}

TEST(DashboardConfigRecent, RecentFilesRoundTripAndBadOnesAreRefused) {
    DashboardState state;
    state.recentFiles = {"/models/a.obj", "/scenes/b.json"};
    WindowGeometry window;
    const nlohmann::json j = dashboardToJson(state, window);
    DashboardState back;
    dashboardFromJson(j, back, window);
    EXPECT_EQ(back.recentFiles, state.recentFiles);
    nlohmann::json bad = j;
    bad["recent_files"] = {1, 2};
    DashboardState untouched;
    EXPECT_THROW(dashboardFromJson(bad, untouched, window), std::invalid_argument);
    EXPECT_TRUE(untouched.recentFiles.empty());
    bad["recent_files"] = nlohmann::json::array();
    for (size_t i = 0; i <= kMaxRecentFiles; ++i) bad["recent_files"].push_back("/f.obj");
    EXPECT_THROW(dashboardFromJson(bad, untouched, window), std::invalid_argument);
}

TEST(GestureTable, NamesEveryGestureAndKeyOnce) {
    const auto& table = gestureTable();
    std::set<std::string> inputs, rows;
    for (const Gesture& g : table) {
        EXPECT_FALSE(g.where.empty());
        EXPECT_FALSE(g.input.empty());
        EXPECT_FALSE(g.action.empty());
        inputs.insert(std::string(g.input));
        EXPECT_TRUE(rows.insert(std::string(g.where) + ":" + std::string(g.input)).second)
            << "twice: " << g.where << " " << g.input;
    }
    for (const char* needed : {"Drag", "Wheel", "Ctrl+wheel", "Right-drag", "Right-drag + W A S D, Q E", "Double-click",
                               "Shift+click", "Ctrl+click", "F1", "F12", "Ctrl+Q", "Escape", "Drop a file"})
        EXPECT_TRUE(inputs.count(needed)) << needed << " is not in the table";
}

TEST(OrbitCameraFit, TheBoxFitsTheViewAndTheDirectionStays) {
    OrbitCamera c;
    c.yawDeg = 35.f;
    c.pitchDeg = 25.f;
    c.distance = 500.f;
    c.target = {100.f, -20.f, 7.f};
    geometry::scene::Aabb box;
    box.add(glm::vec3(-3.f, 0.f, -2.f));
    box.add(glm::vec3(5.f, 4.f, 6.f));
    const float fov = 50.f, aspect = 0.6f; // a tall view: the width limits
    c.fit(box, fov, aspect);
    EXPECT_EQ(c.yawDeg, 35.f);
    EXPECT_EQ(c.pitchDeg, 25.f);
    EXPECT_EQ(c.target, (box.lo + box.hi) * 0.5f);
    // Every corner inside the frustum, and the sphere touching its narrower side.
    const glm::mat4 view = glm::lookAt(c.eye(), c.target, glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(fov), aspect, 0.01f, 1000.f);
    float widest = 0.f;
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec4 p = proj * view * glm::vec4(corner, 1.f);
        ASSERT_GT(p.w, 0.f);
        EXPECT_LE(std::abs(p.x / p.w), 1.f);
        EXPECT_LE(std::abs(p.y / p.w), 1.f);
        widest = std::max(widest, std::abs(p.x / p.w));
    }
    EXPECT_GT(widest, 0.5f) << "fitted, not merely inside";
    const OrbitCamera before = c;
    c.fit(geometry::scene::Aabb{}, fov, aspect); // empty: unchanged
    EXPECT_EQ(c.target, before.target);
    EXPECT_EQ(c.distance, before.distance);
}
