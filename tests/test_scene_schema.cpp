// resources/scene.schema.json and the scene-file loader agree (docs/scene-files.md): every scene
// file shipped or used by the tests passes both, and each kind of mistake fails both. What the
// schema cannot say (eye equal to target, far below near) is listed apart and fails the loader.
#include "geometry/io/scene_file.h"

#include "json_schema_util.h"
#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kSource = SHADOWSCOPE_SOURCE_DIR;

json readJson(const fs::path& p) {
    std::ifstream in(p);
    return json::parse(in);
}

const testutil::JsonSchema& schema() {
    static const testutil::JsonSchema s(readJson(kSource / "resources" / "scene.schema.json"));
    return s;
}

class SceneSchema : public testutil::TempDirTest {
protected:
    SceneSchema() : TempDirTest("shadowscope_schema_") {}

    /// The loader's error for `text`, or "" when it loads.
    std::string loaderError(const std::string& text) const {
        const std::string path = write("scene.json", text);
        try {
            (void)geometry::io::loadSceneFile(path);
            return "";
        } catch (const std::exception& e) {
            return e.what();
        }
    }
};

// A model file the entries can name (one triangle).
constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

} // namespace

TEST_F(SceneSchema, EveryShippedSceneFilePassesBoth) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(kSource / "resources" / "scenes"))
        if (e.path().extension() == ".json") files.push_back(e.path());
    { // the fuzzer's seed scene, after the byte that makes the fuzzer read it as a scene
        std::ifstream in(kSource / "tests" / "fuzz" / "corpus" / "json" / "scene.json", std::ios::binary);
        const std::string seed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_GT(seed.size(), 1u);
        files.push_back(write("seed.json", seed.substr(1)));
    }
    ASSERT_GE(files.size(), 6u);
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        EXPECT_EQ(schema().validate(readJson(f)), "");
        EXPECT_NO_THROW((void)geometry::io::loadSceneFile(f.string()));
    }
}

TEST_F(SceneSchema, ValidVariationsPassBoth) {
    write("tri.obj", kTriangleObj);
    const std::vector<std::string> good = {
        R"({"meshes": [{"builtin": "plane"}]})",
        R"({"name": "n", "description": "d", "meshes": [{"file": "tri.obj", "up": "z", "scale": [1, 2, 3],
            "rotate_deg": [0, 90, 0], "translate": [1, 2, 3], "color": [0.5, 0.5, 0.5]}],
            "ground": {"size": 10, "height": -1, "color": [0, 0, 0]}})",
        R"({"meshes": [{"file": "tri.obj", "instances": [{"translate": [5, 0, 0]}, {"scale": 2, "rotate_deg": [0, 0, 45]}]}]})",
        R"({"meshes": [{"file": "tri.obj", "grid": {"count": [2, 1, 3], "spacing": [2, 0, 2], "origin": [1, 0, 1]}}]})",
        R"({"meshes": [{"builtin": "platform", "params": {"triangles": 20000, "seed": 3}}]})",
        R"({"meshes": [{"builtin": "plane"}], "camera": {"eye": [0, 5, 9], "target": [0, 0, 0], "up": [0, 1, 0],
            "fov_y": 45, "near": 0.1, "far": 100}, "light": {"direction": [1, -1, 0]}})",
        R"({"meshes": [{"builtin": "plane"}], "lights": [{"type": "spot", "position": [0, 9, 0],
            "direction": [0, -1, 0], "cone_deg": 60, "range": 30, "radius": 0.2,
            "settings": {"shadow_map": {"resolution": 512}}}, {"type": "point", "position": [1, 3, 1]}],
            "views": {"v": {"camera": {"eye": [3, 3, 3]}, "light": {"direction": [0, -1, 1]}}},
            "paths": {"p": {"light_index": 1, "light_position": [[1, 3, 1], [2, 3, 1]]},
                      "q": {"camera": [{"eye": [1, 5, 5]}], "light": [[0, -1, 1]]}}})",
        R"({"meshes": [{"builtin": "plane"}], "occluder_edge": [[0, 0, 0], [0, 1, 0]]})",
        R"({"ground": {"size": 5}})",
    };
    for (const std::string& text : good) {
        SCOPED_TRACE(text);
        EXPECT_EQ(schema().validate(json::parse(text)), "");
        EXPECT_EQ(loaderError(text), "");
    }
}

TEST_F(SceneSchema, EachMistakeFailsBoth) {
    write("tri.obj", kTriangleObj);
    const std::vector<std::string> bad = {
        R"({"meshes": [{"builtin": "plane"}], "colour": 1})",                   // unknown top-level key
        R"({"meshes": {"builtin": "plane"}})",                                  // not an array
        R"({"meshes": [{"builtin": "plane", "scale": -1}]})",                   // scale must be positive
        R"({"meshes": [{"builtin": "plane", "scale": [1, 0, 1]}]})",            // every component
        R"({"meshes": [{"builtin": "plane", "file": "tri.obj"}]})",             // both sources
        R"({"meshes": [{"translate": [0, 0, 0]}]})",                            // no source
        R"({"meshes": [{"builtin": "moon"}]})",                                 // unknown built-in
        R"({"meshes": [{"file": "tri.obj", "params": {"triangles": 9}}]})",     // params on a file
        R"({"meshes": [{"builtin": "plane", "up": "z"}]})",                     // up on a built-in
        R"({"meshes": [{"file": "tri.obj", "up": "w"}]})",                      // unknown axis
        R"({"meshes": [{"builtin": "platform", "params": {"triangles": 0}}]})", // out of range
        R"({"meshes": [{"builtin": "platform", "params": {"size": 9}}]})",      // unknown param
        R"({"meshes": [{"builtin": "plane", "color": [1, 2, 0]}]})",            // colour above 1
        R"({"meshes": [{"builtin": "plane", "translate": [1, 2]}]})",           // two numbers
        R"({"meshes": [{"builtin": "plane", "translate": [1e39, 0, 0]}]})",     // beyond float
        R"({"meshes": [{"file": "tri.obj", "instances": []}]})",                // empty list
        R"({"meshes": [{"file": "tri.obj", "instances": [{"move": [1, 0, 0]}]}]})",
        R"({"meshes": [{"file": "tri.obj", "instances": [{"scale": 1}], "grid": {"count": [1, 1, 1], "spacing": [1, 1, 1]}}]})",
        R"({"meshes": [{"file": "tri.obj", "grid": {"count": [1, 1, 1]}}]})", // no spacing
        R"({"meshes": [{"file": "tri.obj", "grid": {"count": [0, 1, 1], "spacing": [1, 1, 1]}}]})",
        R"({"meshes": [{"builtin": "plane"}], "ground": {"size": 0}})",
        R"({"meshes": [{"builtin": "plane"}], "ground": {"width": 3}})",
        R"({"meshes": [{"builtin": "plane"}], "camera": {"fov_y": 180}})",
        R"({"meshes": [{"builtin": "plane"}], "camera": {"near": 0}})",
        R"({"meshes": [{"builtin": "plane"}], "camera": {"eye": "here"}})",
        R"({"meshes": [{"builtin": "plane"}], "light": {"type": "area"}})",
        R"({"meshes": [{"builtin": "plane"}], "light": {"type": "spot", "cone_deg": 0}})",
        R"({"meshes": [{"builtin": "plane"}], "light": {"radius": -1}})",
        R"({"meshes": [{"builtin": "plane"}], "light": {"direction": [0, -1, 0]}, "lights": [{"direction": [0, -1, 0]}]})",
        R"({"meshes": [{"builtin": "plane"}], "lights": []})",
        R"({"meshes": [{"builtin": "plane"}], "lights": [{},{},{},{},{},{},{},{},{}]})", // 9 lights
        R"({"meshes": [{"builtin": "plane"}], "occluder_edge": [[0, 0, 0]]})",
        R"({"meshes": [{"builtin": "plane"}], "views": {"v": {"fov": 3}}})",
        R"({"meshes": [{"builtin": "plane"}], "views": {"": {}}})",
        R"({"meshes": [{"builtin": "plane"}], "paths": {"p": {}}})",
        R"({"meshes": [{"builtin": "plane"}], "paths": {"p": {"camera": []}}})",
        R"({"meshes": [{"builtin": "plane"}], "paths": {"p": {"light": [[0, -1, 0]], "light_index": 8}}})",
        R"({"name": 3, "meshes": [{"builtin": "plane"}]})",
        R"([1, 2])",
    };
    for (const std::string& text : bad) {
        SCOPED_TRACE(text);
        EXPECT_NE(schema().validate(json::parse(text)), "");
        const std::string error = loaderError(text);
        EXPECT_NE(error, "");
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

TEST_F(SceneSchema, WhatOnlyTheLoaderChecks) {
    // Relations between values, files and results a schema cannot express: the schema passes
    // them, the loader refuses them (docs/scene-files.md lists them).
    const std::vector<std::string> loaderOnly = {
        R"({"meshes": [{"builtin": "plane"}], "camera": {"eye": [1, 2, 3], "target": [1, 2, 3]}})",
        R"({"meshes": [{"builtin": "plane"}], "camera": {"near": 5, "far": 2}})",
        R"({"meshes": [{"builtin": "plane"}], "light": {"direction": [0, 0, 0]}})",
        R"({"meshes": [{"builtin": "plane"}], "occluder_edge": [[1, 1, 1], [1, 1, 1]]})",
        R"({"meshes": [{"file": "missing.obj"}]})",
        R"({"meshes": [{"builtin": "plane", "scale": 1e37, "translate": [3e38, 0, 0]}]})",
        R"({})",
    };
    for (const std::string& text : loaderOnly) {
        SCOPED_TRACE(text);
        EXPECT_EQ(schema().validate(json::parse(text)), "");
        EXPECT_NE(loaderError(text), "");
    }
}
