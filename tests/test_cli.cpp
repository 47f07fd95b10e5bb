// The shadowscope executable: `render` writes valid PNGs and JSON; bad input gives a one-line
// error and a non-zero exit.
#include "cli_test_util.h"
#include "geometry/analysis/heatmap.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/image.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

using testutil::CommandResult;
using testutil::freshDir;

namespace {
CommandResult run(const std::string& args) { return testutil::runShadowscope(args); }
} // namespace

TEST(Cli, RenderWritesPngsAndMetrics) {
    const fs::path dir = freshDir("render");
    const CommandResult r =
        run("render --backend osmesa --scene plane --size 160x120 --shadow-res 256 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find((dir / "eye.png").string()), std::string::npos) << "prints the paths it wrote";
    const geometry::analysis::Image eye = geometry::analysis::readImageFile((dir / "eye.png").string());
    EXPECT_EQ(eye.width, 160);
    EXPECT_EQ(eye.height, 120);
    const geometry::analysis::Image light = geometry::analysis::readImageFile((dir / "light.png").string());
    EXPECT_EQ(light.width, 256);
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    EXPECT_EQ(m.at("backend"), "osmesa");
    EXPECT_FALSE(m.at("renderer").get<std::string>().empty());
    EXPECT_EQ(m.at("size"), nlohmann::json::array({160, 120}));
    EXPECT_GT(m.at("triangles").get<int>(), 100);
    const double gamma = m.at("gamma_deg");
    EXPECT_GT(gamma, 0.0);
    EXPECT_LE(gamma, 90.0);
    for (const char* pass : {"shadow", "eye", "total"})
        EXPECT_GT(m.at("timing_ms").at(pass).get<double>(), 0.0) << pass;
    ASSERT_EQ(m.at("splits").size(), 1u);
    EXPECT_FALSE(m.contains("seam")) << "one split: no boundary, no seam figure";
}

TEST(Cli, CameraAndLightOptionsChangeTheFrame) {
    const fs::path dir = freshDir("camera");
    const CommandResult r =
        run("render --backend osmesa --scene plane --size 96x64 --shadow-res 128 --camera 0,30,0.1,0,0,0 "
            "--light 0,-1,0 --out " +
            dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    EXPECT_NEAR(m.at("gamma_deg").get<double>(), 0.19, 0.05); // looking almost straight down with the sun overhead
    EXPECT_NEAR(m.at("camera").at("eye")[1].get<double>(), 30.0, 1e-6);
}

TEST(Cli, BadInputGivesOneLineErrorAndNonZeroExit) {
    const char* cases[] = {
        "render --size 0x100",
        "render --size abc",
        "render --scene nosuchscene --backend osmesa",
        "render --camera 1,2,3",
        "render --camera 1,2,3,1,2,3",
        "render --light 0,0,0",
        "render --light nan,1,0",
        "render --shadow-res 5",
        "render --backend vulkan",
        "render --no-such-option",
        "render --backend osmesa --scene plane --size 16384x16384",
        "render --set splits.count=9",
        "render --preset /nonexistent.json",
    };
    for (const char* args : cases) {
        const CommandResult r = run(std::string(args) + " --out " + freshDir("bad").string());
        EXPECT_NE(r.exitCode, 0) << args;
        std::string text = r.output;
        while (!text.empty() && text.back() == '\n') text.pop_back();
        EXPECT_EQ(text.find('\n'), std::string::npos) << args << ": " << r.output;
        EXPECT_NE(text.find("error"), std::string::npos) << args << ": " << r.output;
    }
}

TEST(Cli, HelpListsTheSharedOptions) {
    const CommandResult r = run("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* opt : {"--scene", "--size", "--out", "--backend", "--camera", "--light", "--shadow-res"})
        EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

TEST(Cli, WithoutADisplayTheMainJobRendersHeadless) {
    const fs::path dir = freshDir("main");
    const CommandResult r =
        run("--scene plane --size 96x64 --shadow-res 128 --backend osmesa --out " + dir.string() + " </dev/null");
    // The test runs with DISPLAY unset (see tests/CMakeLists.txt).
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "eye.png"));
}

TEST(Cli, RenderWritesEveryViewAndRawValues) {
    const fs::path dir = freshDir("views");
    const CommandResult r =
        run("render --backend osmesa --scene plane --size 96x72 --shadow-res 256 --truth "
            "--views eye,light,light_unwarped,aliasing,truth,splits,texels --set splits.count=2 --out " +
            dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name :
         {"eye.png", "light.png", "light_unwarped.png", "aliasing.png", "truth.png", "splits.png", "texels.png"}) {
        const geometry::analysis::Image img = geometry::analysis::readImageFile((dir / name).string());
        EXPECT_GT(img.width, 0) << name;
    }
    int w = 0, h = 0;
    const auto m = geometry::analysis::readPfm((dir / "aliasing.pfm").string(), w, h);
    EXPECT_EQ(w, 96);
    EXPECT_EQ(h, 72);
    EXPECT_TRUE(std::any_of(m.begin(), m.end(), [](float v) { return std::isfinite(v) && v > 0.f; }));
    (void)geometry::analysis::readPfm((dir / "shadow.pfm").string(), w, h);
    (void)geometry::analysis::readPfm((dir / "truth.pfm").string(), w, h);
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const char* k : {"mean", "p50", "p95", "max", "undersampled"}) EXPECT_TRUE(j.at("aliasing").contains(k)) << k;
    for (const char* k : {"false_shadow", "false_lit", "mean_abs"}) EXPECT_TRUE(j.at("truth").contains(k)) << k;
    ASSERT_EQ(j.at("splits").size(), 2u);
    for (const auto& s : j.at("splits"))
        for (const char* k : {"near", "far", "n_prime", "lambda", "resolution", "triangles", "utilization"})
            EXPECT_TRUE(s.contains(k)) << k;
    // Two splits: the seam across their boundary (sweep path's seam_* columns), on the plane's ground.
    const nlohmann::json& seam = j.at("seam");
    ASSERT_GT(seam.at("pairs").get<int>(), 0);
    EXPECT_GE(seam.at("median").get<double>(), 1.0);
    EXPECT_GE(seam.at("p95").get<double>(), seam.at("median").get<double>());
    EXPECT_GE(seam.at("raw_median").get<double>(), 1.0);
    EXPECT_GT(seam.at("baseline_pairs").get<int>(), 0);
    EXPECT_LT(seam.at("baseline").get<double>(), 1.1) << "inside one split, m is smooth";
}

// render's metrics.json `seam` is the figure sweep path records: the path's first frame is the
// platform's `grazing` view, so the two commands measure the same frame with the same function.
TEST(Cli, RenderWritesTheSeamSweepPathRecords) {
    const std::string scene = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/platform.json";
    const std::string settings = "--backend osmesa --scene " + scene +
                                 " --size 160x120 --shadow-res 512 --set splits.count=3 --set splits.scheme=log "
                                 "--set warp.method=glispsm ";
    const fs::path path = freshDir("seam_path");
    const CommandResult walk = run("sweep path " + settings + "--path grazing_walk --frames 2 --out " + path.string());
    ASSERT_EQ(walk.exitCode, 0) << walk.output;
    std::ifstream csv(path / "path.csv");
    std::string header, first;
    ASSERT_TRUE(std::getline(csv, header) && std::getline(csv, first));
    std::map<std::string, double> row; // frame 0's columns
    std::stringstream names(header), values(first);
    for (std::string name, value; std::getline(names, name, ',') && std::getline(values, value, ',');)
        row[name] = std::stod(value);
    const fs::path frame = freshDir("seam_render");
    const CommandResult render = run("render " + settings + "--view grazing --views eye --out " + frame.string());
    ASSERT_EQ(render.exitCode, 0) << render.output;
    std::ifstream in(frame / "metrics.json");
    const nlohmann::json seam = nlohmann::json::parse(in).at("seam");
    ASSERT_GE(row.at("seam_pairs"), 3);
    EXPECT_EQ(seam.at("pairs").get<double>(), row.at("seam_pairs"));
    EXPECT_DOUBLE_EQ(seam.at("median").get<double>(), row.at("seam_median"));
    EXPECT_DOUBLE_EQ(seam.at("p95").get<double>(), row.at("seam_p95"));
    EXPECT_DOUBLE_EQ(seam.at("raw_median").get<double>(), row.at("seam_raw_median"));
    EXPECT_DOUBLE_EQ(seam.at("baseline").get<double>(), row.at("seam_baseline"));
    EXPECT_GT(seam.at("median").get<double>(), 2) << "log splits at a grazing sun leave a seam";
}

TEST(Cli, TruthViewWithoutTruthIsAnError) {
    const CommandResult r =
        run("render --backend osmesa --scene plane --size 32x32 --views truth --out " + freshDir("notruth").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--truth"), std::string::npos);
}

TEST(Cli, MeshInfoAndCleanReportTheCleanup) {
    const fs::path dir = freshDir("mesh");
    fs::create_directories(dir);
    // Two triangles sharing an edge written with duplicated vertices, plus a zero-area face.
    {
        std::ofstream obj(dir / "in.obj");
        obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 4 5 6\nf 1 2 7\n";
    }
    const CommandResult info = run("mesh info --json " + (dir / "in.obj").string());
    ASSERT_EQ(info.exitCode, 0) << info.output;
    const nlohmann::json j = nlohmann::json::parse(info.output);
    EXPECT_EQ(j.at("triangles"), 2);
    EXPECT_EQ(j.at("cleanup").at("merged_vertices"), 2);
    EXPECT_EQ(j.at("cleanup").at("degenerate_faces"), 1);
    // The GL form (geometry/scene/compact_vertices.h): largest coordinate 1, so 8 float spacings
    // there, 2^-20, half of it the error.
    const nlohmann::json& gl = j.at("gl_positions");
    EXPECT_EQ(gl.at("compact_meshes"), 1);
    EXPECT_EQ(gl.at("bits"), 16);
    EXPECT_EQ(gl.at("step").get<double>(), std::ldexp(1.0, -20));
    EXPECT_EQ(gl.at("max_error").get<double>(), std::ldexp(1.0, -21));
    const CommandResult clean = run("mesh clean " + (dir / "in.obj").string() + " " + (dir / "out.stl").string());
    ASSERT_EQ(clean.exitCode, 0) << clean.output;
    const CommandResult again = run("mesh info --json " + (dir / "out.stl").string());
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(nlohmann::json::parse(again.output).at("triangles"), 2);
    const CommandResult missing = run("mesh info " + (dir / "nope.stl").string());
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("nope.stl"), std::string::npos);
}

// mesh clean from a scene: the plane scene written as one binary STL (z up, every triangle as is)
// loads back with the scene's triangle count and bounds.
TEST(Cli, MeshCleanWritesAScene) {
    const fs::path dir = freshDir("mesh_scene");
    fs::create_directories(dir);
    const std::string stl = (dir / "plane.stl").string();
    const CommandResult clean = run("mesh clean plane " + stl);
    ASSERT_EQ(clean.exitCode, 0) << clean.output;
    const geometry::scene::Scene scene = geometry::scene::makePlaneScene();
    EXPECT_EQ(fs::file_size(stl), 84 + 50 * scene.triangleCount());
    const CommandResult info = run("mesh info --json " + stl);
    ASSERT_EQ(info.exitCode, 0) << info.output;
    const nlohmann::json j = nlohmann::json::parse(info.output);
    EXPECT_EQ(j.at("cleanup").at("input_faces"), scene.triangleCount());
    const geometry::scene::Aabb b = scene.bounds();
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(j.at("bounds").at("min")[a].get<float>(), b.lo[a], 1e-4f) << a;
        EXPECT_NEAR(j.at("bounds").at("max")[a].get<float>(), b.hi[a], 1e-4f) << a;
    }
}

// --up: a Z-up STL plate (10 × 6 × 0.1 in the file's x, y, z) lies flat by default and with --up z,
// stands on its edge with --up y; render puts the ground right under it; a bad axis is exit 2.
TEST(Cli, UpAxisTurnsAZUpPlateOntoItsBase) {
    const fs::path dir = freshDir("up");
    fs::create_directories(dir);
    {
        std::ofstream stl(dir / "plate.stl");
        const float x[2] = {0, 10}, y[2] = {0, 6}, z[2] = {0, 0.1f};
        const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        stl << "solid plate\n";
        for (const auto& q : faces)
            for (const auto& tri : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
                stl << "facet normal 0 0 0\nouter loop\n";
                for (int i : tri)
                    stl << "vertex " << x[i & 1] << ' ' << y[(i >> 1) & 1] << ' ' << z[(i >> 2) & 1] << '\n';
                stl << "endloop\nendfacet\n";
            }
        stl << "endsolid plate\n";
    }
    const std::string plate = (dir / "plate.stl").string();
    const auto heightWith = [&](const std::string& up) {
        const CommandResult r = run("mesh info --json " + up + plate);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        const nlohmann::json j = nlohmann::json::parse(r.output);
        return j.at("bounds").at("max")[1].get<double>() - j.at("bounds").at("min")[1].get<double>();
    };
    EXPECT_NEAR(heightWith(""), 0.1, 1e-5);
    EXPECT_NEAR(heightWith("--up z "), 0.1, 1e-5);
    EXPECT_NEAR(heightWith("--up y "), 6.0, 1e-5);
    const CommandResult r = run("render --backend osmesa --size 64x48 --shadow-res 128 --up z --scene " + plate +
                                " --out " + (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CommandResult bad = run("render --backend osmesa --up sideways --scene " + plate);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("--up"), std::string::npos) << bad.output;
}

// --views pixels: the per-pixel quantities behind the figures, one PFM each, consistent with each
// other; --truth-samples 3 gives 9 samples per pixel, so edges get a fractional coverage.
TEST(Cli, RenderWritesThePixelLayers) {
    const fs::path dir = freshDir("pixels");
    const CommandResult r = run("render --backend osmesa --scene plane --size 80x60 --shadow-res 256 --truth "
                                "--truth-samples 3 --views pixels --set splits.count=2 --out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::map<std::string, std::vector<float>> layer;
    for (const char* name :
         {"view_depth", "split", "normal_x", "normal_y", "normal_z", "n_dot_l", "m", "s", "coverage", "class"}) {
        int w = 0, h = 0;
        layer[name] = geometry::analysis::readPfm((dir / ("pixels_" + std::string(name) + ".pfm")).string(), w, h);
        ASSERT_EQ(w, 80) << name;
        ASSERT_EQ(h, 60) << name;
    }
    int receivers = 0, fractional = 0;
    for (size_t i = 0; i < layer["s"].size(); ++i) {
        const float split = layer["split"][i], cls = layer["class"][i];
        ASSERT_TRUE(split == -1.f || split == 0.f || split == 1.f) << split;
        ASSERT_TRUE(cls >= 0.f && cls <= 5.f && cls == std::round(cls)) << cls;
        if (split < 0.f) continue;
        const glm::vec3 n(layer["normal_x"][i], layer["normal_y"][i], layer["normal_z"][i]);
        EXPECT_NEAR(glm::length(n), 1.f, 1e-3f);
        EXPECT_GT(layer["view_depth"][i], 0.f);
        if (cls == 0.f) continue;
        ++receivers;
        const float c = layer["coverage"][i];
        ASSERT_TRUE(c >= 0.f && c <= 1.f) << c;
        if (c > 0.f && c < 1.f) {
            ++fractional;
            bool ratio = false; // k of the h ≤ 9 samples that hit something
            for (int h = 2; h <= 9; ++h) ratio = ratio || std::abs(std::round(c * float(h)) - c * float(h)) < 1e-4f;
            EXPECT_TRUE(ratio) << c;
        }
        EXPECT_GT(layer["n_dot_l"][i], -0.1f) << "receivers face the light (or graze it)";
    }
    EXPECT_GT(receivers, 1000);
    EXPECT_GT(fractional, 10);
    std::ifstream metrics(dir / "metrics.json");
    const auto j = nlohmann::json::parse(metrics);
    EXPECT_EQ(j.at("truth").at("samples_per_pixel"), 9);
    EXPECT_TRUE(j.at("meshes").at("ground").contains("truth"));
    const CommandResult zero = run("render --backend osmesa --scene plane --size 32x32 --truth --truth-samples 0 "
                                   "--out " +
                                   freshDir("pixels_zero").string());
    EXPECT_EQ(zero.exitCode, 2);
    EXPECT_NE(zero.output.find("--truth-samples"), std::string::npos) << zero.output;
    const CommandResult bad = run("render --backend osmesa --scene plane --size 32x32 --views pixels --out " +
                                  freshDir("pixels_notruth").string());
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("--views pixels needs --truth"), std::string::npos) << bad.output;
}

namespace {

/// A depth map written by --views shadow_map: w × h, every depth in [0, 1], more than 1/`share` of
/// the texels below 1 (casters).
void expectDepthMap(const fs::path& path, int w, int h, size_t share) {
    int width = 0, height = 0;
    const auto depth = geometry::analysis::readPfm(path.string(), width, height);
    EXPECT_EQ(width, w) << path;
    EXPECT_EQ(height, h) << path;
    size_t casters = 0;
    for (float d : depth) {
        ASSERT_TRUE(d >= 0.f && d <= 1.f) << path << ": " << d;
        casters += d < 1.f;
    }
    EXPECT_GT(casters, depth.size() / share) << path;
}

} // namespace

// --views shadow_map: each split's raw map, at its resolution, holding depths in [0, 1] (casters
// below 1, the cleared background at 1); a bad stabilize or blend value is refused naming its key.
TEST(Cli, RenderWritesTheRawShadowMaps) {
    const fs::path dir = freshDir("shadow_maps");
    const CommandResult r = run("render --backend osmesa --scene plane --size 80x60 --shadow-res 256 --views "
                                "shadow_map --set splits.count=2 --set stabilize.mode=snap --set splits.blend=0.1 "
                                "--out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name : {"shadow_map_0.pfm", "shadow_map_1.pfm"}) expectDepthMap(dir / name, 256, 256, 10);
    for (const std::string bad : {"splits.blend=2", "stabilize.mode=maybe"}) {
        const CommandResult b = run("render --backend osmesa --scene plane --size 32x32 --set " + bad + " --out " +
                                    freshDir("bad_stabilize").string());
        EXPECT_EQ(b.exitCode, 2) << bad;
        EXPECT_NE(b.output.find(bad.substr(0, bad.find('='))), std::string::npos) << b.output;
        EXPECT_EQ(std::count(b.output.begin(), b.output.end(), '\n'), 1) << "one line: " << b.output;
    }
}

// --views shadow_map under technique = virtual: the physical pages (the atlas, pages side by side), in
// [0, 1] with casters below 1.
TEST(Cli, RenderWritesTheVirtualMapsPages) {
    const fs::path dir = freshDir("virtual_pages");
    const CommandResult r = run("render --backend osmesa --scene plane --size 80x60 --views shadow_map --set "
                                "technique=virtual --set virtual.size=1024 --set virtual.page_size=32 --set "
                                "virtual.pool_pages=64 --out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectDepthMap(dir / "shadow_map_pages.pfm", 8 * 32, 8 * 32, 20); // ⌈√64⌉ pages a row
}

// Settings every value of which is in range but that validate() refuses together (a virtual size that
// is not a power of two) are refused by the commands, naming the key, before anything is drawn.
TEST(Cli, RenderRefusesAVirtualSizeThatIsNotAPowerOfTwo) {
    const CommandResult bad = run("render --backend osmesa --scene plane --size 32x32 --set technique=virtual --set "
                                  "virtual.size=3000 --out " +
                                  freshDir("virtual_bad").string());
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("virtual.size: 3000 is not a power of two"), std::string::npos) << bad.output;
}

// --views soft: s − v against the sun's disk, red where the render is darker than the sun allows,
// blue where lighter, white where they agree (checked against the pixel layers of the same frame);
// without a sun size it is a one-line error.
TEST(Cli, RenderWritesTheSoftTruthView) {
    const fs::path dir = freshDir("soft");
    const CommandResult r = run("render --backend osmesa --scene " + std::string(SHADOWSCOPE_SOURCE_DIR) +
                                "/resources/scenes/penumbra.json --view closeup --size 480x270 --truth --views "
                                "soft,pixels --set filter.type=pcf --set filter.kernel=5 --set "
                                "light.angular_diameter_deg=2 --out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    int w = 0, h = 0;
    const auto s = geometry::analysis::readPfm((dir / "pixels_s.pfm").string(), w, h);
    const auto v = geometry::analysis::readPfm((dir / "pixels_visibility.pfm").string(), w, h);
    const geometry::analysis::Image img = geometry::analysis::readImageFile((dir / "soft.png").string());
    ASSERT_EQ(img.width, w);
    int darker = 0, lighter = 0, agree = 0;
    for (int y = 0; y < h / 2; ++y) // the top half: the legend sits bottom left
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (!std::isfinite(s[i]) || !std::isfinite(v[i])) continue;
            const uint8_t* p = img.at(x, y);
            const float d = s[i] - v[i];
            if (d < -0.25f) {
                EXPECT_GT(p[0], p[2] + 40) << x << "," << y;
                ++darker;
            }
            if (d > 0.25f) {
                EXPECT_GT(p[2], p[0] + 40) << x << "," << y;
                ++lighter;
            }
            if (std::abs(d) < 0.01f) {
                EXPECT_GT(std::min({p[0], p[1], p[2]}), 200) << x << "," << y;
                ++agree;
            }
        }
    EXPECT_GT(darker + lighter, 5) << "a 5x5 PCF edge against a 2-degree sun differs somewhere";
    EXPECT_GT(agree, 1000);
    const CommandResult point = run("render --backend osmesa --scene plane --size 32x32 --truth --views soft --out " +
                                    freshDir("soft_point").string());
    EXPECT_EQ(point.exitCode, 2) << point.output;
    EXPECT_NE(point.output.find("light.angular_diameter_deg"), std::string::npos) << point.output;
}

// Bad lights in a scene file (issue 29): a cone of 0 or 180 degrees, a position out of float range, no
// lights, more than kMaxLights: one line naming the key, exit 2, for render, bench and sweep alike.
TEST(Cli, BadLightsAreOneLineErrorsWithExitTwo) {
    const fs::path dir = freshDir("bad_lights");
    fs::create_directories(dir);
    const std::string spot = R"({"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "cone_deg": )";
    std::string nine;
    for (int i = 0; i < 9; ++i) nine += std::string(i ? ", " : "") + R"({"direction": [0, -1, 0]})";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"[" + spot + "0}]", "lights[0].cone_deg"},
        {"[" + spot + "180}]", "lights[0].cone_deg"},
        {R"([{"type": "point", "position": [1e39, 0, 0]}])", "lights[0].position"},
        {"[]", "lights"},
        {"[" + nine + "]", "lights"},
    };
    for (const auto& [lights, key] : cases) {
        const fs::path file = dir / "scene.json";
        std::ofstream(file) << R"({"meshes": [{"builtin": "plane"}], "lights": )" << lights << "}";
        for (const std::string command : {"render", "bench", "sweep path --path x"}) {
            const CommandResult r = run(command + " --backend osmesa --scene " + file.string() +
                                        " --size 32x32 --out " + (dir / "out").string());
            EXPECT_EQ(r.exitCode, 2) << command << " " << lights << ": " << r.output;
            EXPECT_NE(r.output.find(key), std::string::npos) << command << " " << lights << ": " << r.output;
            EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        }
    }
}

// metrics.json with several lights and --truth: every light's block holds its own truth (rays to a
// spot's and a point light's position), the inspected one's equal to the top level, and
// truth_all_lights pools them.
TEST(Cli, EveryLightsBlockHoldsItsTruth) {
    const fs::path dir = freshDir("lights_truth");
    const std::string scene = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/plane_lights.json";
    const CommandResult r = run("render --backend osmesa --scene " + scene +
                                " --light 1 --size 96x72 --shadow-res 512 --truth --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "metrics.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j.at("lights").size(), 3u);
    EXPECT_TRUE(j["lights"][1]["inspected"].get<bool>());
    EXPECT_EQ(j["lights"][1]["truth"]["false_lit"], j["truth"]["false_lit"]);
    // The spot light's own settings draw its map at 1024² over the shared 512² (--shadow-res).
    EXPECT_EQ(j["lights"][0]["maps"][0]["resolution"], 512);
    EXPECT_EQ(j["lights"][1]["maps"][0]["resolution"], 1024);
    EXPECT_EQ(j["lights"][1]["settings"], nlohmann::json::array({"shadow_map.resolution=1024"}));
    double sum = 0, largest = 0;
    for (const auto& block : j["lights"]) {
        SCOPED_TRACE(block["type"].get<std::string>());
        ASSERT_TRUE(block.contains("truth"));
        const double pixels = block["truth"]["pixels"].get<double>();
        EXPECT_GT(pixels, 300);
        EXPECT_LT(block["truth"]["false_lit"].get<double>(), 0.03);
        EXPECT_LT(block["truth"]["false_shadow"].get<double>(), 0.05);
        sum += pixels;
        largest = std::max(largest, pixels);
    }
    const double pairs = j.at("truth_all_lights").at("pairs").get<double>();
    EXPECT_GE(pairs, largest);
    EXPECT_LE(pairs, sum);
}
