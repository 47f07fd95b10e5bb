// `shadowscope sweep gamma|path|check` end to end on the platform scene at CI size: a coarse γ
// sweep of every warp method passes --check, tight thresholds and broken CSVs make it fail,
// a short path writes flicker and seams, and bad input is a one-line error.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

const std::string kScene = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/platform.json";
/// CI size: the deck view at 160×120 with 512² maps.
const std::string kSmall = "--backend osmesa --scene " + kScene + " --view deck --size 160x120 --shadow-res 512 ";

CommandResult run(const std::string& args) { return testutil::runShadowscope(args); }

/// A CSV file as rows of column name → text.
std::vector<std::map<std::string, std::string>> readCsv(const fs::path& path, std::string* header = nullptr) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    if (header) *header = line;
    std::vector<std::string> names;
    std::stringstream hs(line);
    for (std::string n; std::getline(hs, n, ',');) names.push_back(n);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::stringstream ls(line);
        std::map<std::string, std::string> row;
        size_t i = 0;
        for (std::string v; std::getline(ls, v, ',') && i < names.size(); ++i) row[names[i]] = v;
        EXPECT_EQ(i, names.size()) << line;
        rows.push_back(row);
    }
    return rows;
}

double num(const std::map<std::string, std::string>& row, const std::string& key) {
    const std::string& v = row.at(key);
    if (v == "inf") return INFINITY;
    if (v == "nan") return NAN;
    return std::stod(v);
}

bool countLines(const std::string& text, const std::string& needle, int atLeast) {
    int n = 0;
    for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
    return n >= atLeast;
}

} // namespace

// The CI sweep: every warp method, 15° steps, --check on. Also checks the numbers it records
// against the formulas they come from.
TEST(SweepGamma, EveryMethodPassesTheCheckAtCiSize) {
    const fs::path dir = freshDir("sweep_gamma");
    const CommandResult r = run("sweep gamma " + kSmall + "--step 15 --check --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::string header;
    const auto rows = readCsv(dir / "sweep.csv", &header);
    EXPECT_EQ(header.rfind("angle_deg,method,n_prime,p95,max,false_lit,false_shadow", 0), 0u) << header;
    ASSERT_EQ(rows.size(), 13u * 5u);
    const double n = 0.5, f = 2000; // the deck view's frustum
    for (const auto& row : rows) {
        const double angle = num(row, "angle_deg");
        const std::string method = row.at("method");
        SCOPED_TRACE(method + " at " + row.at("angle_deg"));
        EXPECT_NEAR(num(row, "gamma_deg"), std::min(angle, 180 - angle), 1e-3);
        EXPECT_GT(num(row, "receivers"), 200);
        EXPECT_GT(num(row, "p95"), 0);
        EXPECT_GE(num(row, "max"), num(row, "p95"));
        EXPECT_EQ(num(row, "gl_errors"), 0);
        for (const char* k : {"false_lit", "false_shadow"}) {
            EXPECT_GE(num(row, k), 0);
            EXPECT_LE(num(row, k), 1);
        }
        // Light ∥ view (0° and 180°): every method falls back to uniform.
        if (angle == 0 || angle == 180 || method == "uniform") EXPECT_TRUE(std::isinf(num(row, "n_prime")));
        else EXPECT_TRUE(std::isfinite(num(row, "n_prime")));
        // γ = 90°: GLiSPSM and GMNPR both give n' = n + √(f·n) (Barroso eq 13, Zhang eq 8).
        if (angle == 90 && (method == "glispsm" || method == "gmnpr")) {
            EXPECT_NEAR(num(row, "n_prime"), n + std::sqrt(f * n), 1e-6);
        }
        if (angle == 90 && method == "psm") {
            EXPECT_NEAR(num(row, "n_prime"), n, 1e-9);
        }
    }
    // At 90°, a warp beats uniform by far (p95 m).
    double uniform90 = 0, glispsm90 = 0;
    for (const auto& row : rows)
        if (num(row, "angle_deg") == 90) {
            if (row.at("method") == "uniform") uniform90 = num(row, "p95");
            if (row.at("method") == "glispsm") glispsm90 = num(row, "p95");
        }
    EXPECT_LT(glispsm90 * 5, uniform90);
    for (const char* svg : {"n_prime.svg", "p95.svg", "gain.svg", "false_lit.svg", "false_shadow.svg"}) {
        std::ifstream in(dir / svg);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        EXPECT_NE(text.find("<svg"), std::string::npos) << svg;
        EXPECT_NE(text.find("glispsm"), std::string::npos) << svg << ": one series per method";
    }
}

// Fitted to the eye's samples, no caster is lost at any angle: the lost-caster check
// (false_lit_clipped, clipped_casters) stays 0 over a 30° γ sweep of every method, and --check passes.
// 30° steps suffice: a planner that loses casters does so over 0°–75° (docs/stability.md, rule 4).
TEST(SweepGamma, SampleFocusLosesNoCasterAtAnyAngle) {
    const fs::path dir = freshDir("sweep_gamma_samples");
    const CommandResult r =
        run("sweep gamma " + kSmall + "--step 30 --check --set focus.mode=samples --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "sweep.csv");
    ASSERT_EQ(rows.size(), 7u * 5u);
    for (const auto& row : rows) {
        SCOPED_TRACE(row.at("method") + " at " + row.at("angle_deg"));
        EXPECT_EQ(num(row, "false_lit_clipped"), 0);
        EXPECT_EQ(num(row, "clipped_casters"), 0);
        EXPECT_GT(num(row, "receivers"), 200);
    }
}

// Continuity is judged at 1° steps (docs/stability.md): the window on the dueling side where the
// gain of every continuity method changes fastest, across γ_lim ≈ 30.5° and φ = 30° (angles 149.5
// and 150), where GLiSPSM and GMNPR switch formulas; two steps either side of them.
TEST(SweepGamma, ContinuityMethodsPassAtOneDegreeAcrossTheirSwitchingAngles) {
    const fs::path dir = freshDir("sweep_gamma_window");
    const CommandResult r =
        run("sweep gamma " + kSmall + "--methods lispsm,glispsm,gmnpr --from 148 --to 152 --step 1 --check --out " +
            dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "sweep.csv");
    ASSERT_EQ(rows.size(), 5u * 3u);
    for (size_t i = 3; i < rows.size(); ++i) {
        const auto& a = rows[i - 3];
        const auto& b = rows[i];
        ASSERT_EQ(a.at("method"), b.at("method"));
        const double ga = num(a, "p95") / num(a, "p95_uniform"), gb = num(b, "p95") / num(b, "p95_uniform");
        EXPECT_LT(std::max(ga, gb) / std::min(ga, gb), 3.0) << b.at("method") << " at " << b.at("angle_deg");
    }
}

// Thresholds no real sweep meets: --check must fail, one stderr line per failure naming the
// method and the angle; without --check the same run succeeds.
TEST(SweepGamma, CheckFailsOnImpossibleThresholds) {
    const fs::path dir = freshDir("sweep_gamma_tight");
    const std::string args =
        "sweep gamma " + kSmall + "--methods lispsm --from 60 --to 90 --step 15 --out " + dir.string();
    EXPECT_EQ(run(args).exitCode, 0);
    const CommandResult r = run(args + " --check --max-p95-ratio 1 --continuity-step 15 --min-receivers 0");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(countLines(r.output, "check failed: method lispsm at ", 2)) << r.output;
    EXPECT_NE(r.output.find("p95 m / uniform's jumped"), std::string::npos) << r.output;
    // `sweep check` re-applies the rules to the written CSV with the same verdicts.
    const std::string csv = (dir / "sweep.csv").string();
    EXPECT_EQ(run("sweep check " + csv).exitCode, 0);
    const CommandResult again = run("sweep check " + csv + " --max-p95-ratio 1 --continuity-step 15 --min-receivers 0");
    EXPECT_EQ(again.exitCode, 1) << again.output;
    EXPECT_TRUE(countLines(again.output, "check failed: method lispsm at ", 2)) << again.output;
    // A correct plan keeps every caster: no receiver is false lit through a clipped caster.
    for (const auto& row : readCsv(dir / "sweep.csv"))
        EXPECT_EQ(num(row, "false_lit_clipped"), 0) << row.at("angle_deg");
}

TEST(SweepCheck, BrokenCsvFails) {
    const fs::path dir = freshDir("sweep_check");
    fs::create_directories(dir);
    const std::string header = "angle_deg,method,n_prime,p95,max,false_lit,false_shadow,gamma_deg,lambda,n_prime_min,"
                               "p50,mean,receivers,gl_errors,p95_uniform,clipped_casters,false_lit_clipped\n";
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    const std::string good =
        write("good.csv", header + "30,glispsm,15.8,13.9,224,0.03,0.2,30,0.008,15.8,3.2,5.1,13140,0,138,0,0\n");
    EXPECT_EQ(run("sweep check " + good).exitCode, 0);
    const CommandResult nan =
        run("sweep check " +
            write("nan.csv", header + "30,glispsm,nan,13.9,224,0.03,0.2,30,0.008,15.8,3.2,5.1,13140,0,138,0,0\n"));
    EXPECT_EQ(nan.exitCode, 1);
    EXPECT_NE(nan.output.find("method glispsm at 30.00 deg: n_prime is nan"), std::string::npos) << nan.output;
    const CommandResult gl =
        run("sweep check " +
            write("gl.csv", header + "30,glispsm,15.8,13.9,224,0.03,0.2,30,0.008,15.8,3.2,5.1,13140,1,138,0,0\n"));
    EXPECT_EQ(gl.exitCode, 1);
    EXPECT_NE(gl.output.find("GL error"), std::string::npos) << gl.output;
    const CommandResult lost = run(
        "sweep check " +
        write("lost.csv", header + "30,glispsm,15.8,13.9,224,0.03,0.2,30,0.008,15.8,3.2,5.1,13140,0,138,0.2,0.02\n"));
    EXPECT_EQ(lost.exitCode, 1);
    EXPECT_NE(lost.output.find("method glispsm at 30.00 deg: false_lit_clipped 0.0200"), std::string::npos)
        << lost.output;
    const CommandResult missing = run("sweep check " + write("missing.csv", "angle_deg,method\n0,uniform\n"));
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.output.find("no column 'n_prime'"), std::string::npos) << missing.output;
    EXPECT_NE(run("sweep check " + (dir / "absent.csv").string()).exitCode, 0);
}

TEST(SweepGamma, BadInputIsAOneLineError) {
    const std::string out = " --out " + freshDir("sweep_bad").string();
    for (const auto& [args, expect] :
         std::vector<std::pair<std::string, std::string>>{{"--methods lispsm,nosuch", "unknown warp method 'nosuch'"},
                                                          {"--methods lispsm,lispsm", "given twice"},
                                                          {"--step 0", "--step"},
                                                          {"--step -2", "--step"},
                                                          {"--from 100 --to 90", "--from"},
                                                          {"--to 200", "0..180"},
                                                          {"--step 0.001", "at most 3601"},
                                                          {"--view nosuch", "no such view"}}) {
        const CommandResult r = run("sweep gamma --backend osmesa --scene " + kScene + " " + args + out);
        EXPECT_NE(r.exitCode, 0) << args;
        EXPECT_NE(r.output.find(expect), std::string::npos) << args << ": " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << ": " << r.output;
    }
    const CommandResult noPath = run("sweep path --backend osmesa --scene " + kScene + " --path nosuch" + out);
    EXPECT_NE(noPath.exitCode, 0);
    EXPECT_NE(noPath.output.find("available: deck_dolly, deck_pan, grazing_walk, sun_arc"), std::string::npos)
        << noPath.output;
    const CommandResult frames =
        run("sweep path --backend osmesa --scene " + kScene + " --path sun_arc --frames 0" + out);
    EXPECT_NE(frames.exitCode, 0);
    EXPECT_NE(frames.output.find("--frames"), std::string::npos) << frames.output;
    EXPECT_NE(run("sweep path --backend osmesa --scene plane --path x" + out).exitCode, 0)
        << "built-in scenes have no paths";
}

// A short walk at small γ with three log splits: every frame has seams on screen, flicker is a
// fraction, the first frame has none (nothing to compare with), and the light stays at γ ≈ 6°.
TEST(SweepPath, ShortWalkRecordsFlickerAndSeams) {
    const fs::path dir = freshDir("sweep_path");
    const CommandResult r = run("sweep path " + kSmall +
                                "--path grazing_walk --frames 4 --set splits.count=3 "
                                "--set splits.scheme=log --set warp.method=glispsm --out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("summary: frames 4"), std::string::npos) << r.output;
    const auto rows = readCsv(dir / "path.csv");
    ASSERT_EQ(rows.size(), 4u);
    for (size_t i = 0; i < rows.size(); ++i) {
        const auto& row = rows[i];
        SCOPED_TRACE("frame " + std::to_string(i));
        EXPECT_EQ(num(row, "frame"), double(i));
        EXPECT_NEAR(num(row, "t"), i / 3.0, 1e-12);
        EXPECT_NEAR(num(row, "gamma_deg"), 6.1, 0.5);
        EXPECT_GE(num(row, "flicker"), 0);
        EXPECT_LE(num(row, "flicker"), 1);
        EXPECT_GE(num(row, "seam_pairs"), 3);
        EXPECT_GE(num(row, "seam_median"), 1);
        EXPECT_GE(num(row, "seam_p95"), num(row, "seam_median"));
        EXPECT_LT(num(row, "seam_p95"), 1e4) << "singular m (1e10) is left out";
        EXPECT_GE(num(row, "seam_raw_median"), 1);
        EXPECT_GE(num(row, "seam_baseline"), 1);
        EXPECT_LT(num(row, "seam_baseline"), 1.1) << "inside one split, m is smooth";
        // Log splits at γ ≈ 6°: the maps' texel sizes differ by ~(f/n)^(1/3) across boundaries.
        EXPECT_GT(num(row, "seam_median"), 2);
        EXPECT_EQ(num(row, "gl_errors"), 0);
        if (i == 0) EXPECT_EQ(num(row, "flicker_pixels"), 0);
        else EXPECT_GT(num(row, "flicker_pixels"), 1000);
    }
    std::ifstream in(dir / "path.svg");
    const std::string svg((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("Flicker"), std::string::npos);
}

// A point light walks through the camera's position (plane_lights.json: the camera's eye at t = 0.5,
// frame 2 of 5): every frame renders without a GL error or a NaN, and no caster is lost (the truth's
// shadowed receivers stay shadowed), the sun and the spot drawn in the same frames. The point light's
// own settings give it a slope-scaled bias (the constant default leaves acne where it grazes the ground).
TEST(SweepPath, APointLightPassingThroughTheCameraLosesNothing) {
    const fs::path dir = freshDir("sweep_path_light");
    const std::string scene = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/plane_lights.json";
    const CommandResult r = run("sweep path --backend osmesa --scene " + scene +
                                " --size 160x120 --shadow-res 512 --path point_through_camera --light 2 --frames 5 "
                                "--out " +
                                dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::string header;
    const auto rows = readCsv(dir / "path.csv", &header);
    ASSERT_EQ(rows.size(), 5u);
    for (size_t i = 0; i < rows.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        for (const auto& [key, value] : rows[i]) {
            EXPECT_NE(value, "nan") << key;
            EXPECT_NE(value, "-nan") << key;
        }
        EXPECT_EQ(num(rows[i], "gl_errors"), 0);
        EXPECT_LT(num(rows[i], "false_lit"), 0.02);
        EXPECT_LT(num(rows[i], "false_shadow"), 0.05);
    }
    // A path can only move a light that exists, and only a positional light's position.
    const std::string bad = dir.string() + "/bad.json";
    std::ofstream(bad)
        << R"({"meshes": [{"builtin": "plane"}], "paths": {"p": {"light_index": 1, "light": [[0, -1, 0]]}}})";
    const CommandResult r2 = run("sweep path --backend osmesa --scene " + bad + " --path p --out " + dir.string());
    EXPECT_EQ(r2.exitCode, 2) << r2.output;
    EXPECT_NE(r2.output.find("light_index"), std::string::npos) << r2.output;
    std::ofstream(bad) << R"({"meshes": [{"builtin": "plane"}], "paths": {"p": {"light_position": [[0, 5, 0]]}}})";
    const CommandResult r3 = run("sweep path --backend osmesa --scene " + bad + " --path p --out " + dir.string());
    EXPECT_EQ(r3.exitCode, 2) << r3.output;
    EXPECT_NE(r3.output.find("directional"), std::string::npos) << r3.output;
}
