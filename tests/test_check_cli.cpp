// `shadowscope check` end to end on the plane scene at 160x90 with 512² maps: acne on purpose fails
// its truth bound and its golden (with a diff whose magenta pixels are counted), renders repeat
// byte for byte, bad check files give one stderr line and exit 2, the JUnit file is well-formed
// XML with the right counts, and --update writes goldens that the next run passes.
#include "cli_test_util.h"
#include "geometry/analysis/image.h"
#include "xml_reader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using geometry::analysis::Image;
using testutil::freshDir;
using testutil::SplitResult;
using testutil::XmlElement;
using testutil::XmlReader;

namespace {

const std::string kPaper = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/paper.json";
/// Settings of the "good" case, as render's options.
const std::string kGoodRender =
    "--backend osmesa --scene plane --size 160x90 --preset " + kPaper + " --set shadow_map.resolution=512 --truth";

SplitResult check(const fs::path& file, const std::string& args) {
    return testutil::runShadowscopeSplit("check " + file.string() + " --backend osmesa " + args);
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFile(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

size_t magentaPixels(const Image& img) {
    size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.at(x, y);
            n += p[0] == 255 && p[1] == 0 && p[2] == 255;
        }
    return n;
}

/// A check file with a good case and an acne case on the plane, both compared with golden/good.png,
/// which is `render`'s eye.png of the good settings. bias.constant = −0.5 moves the receivers half
/// a unit away from the light, so the plane shadows itself nearly everywhere (interior false shadow).
/// The good case names paper.json as "resources/presets/paper.json", found in the source tree's
/// resources as an installation's would be; the acne case by its absolute path, in a list.
fs::path acneCheck(const std::string& name) {
    const fs::path dir = freshDir(name);
    const auto render = testutil::runShadowscope("render " + kGoodRender + " --out " + (dir / "render").string());
    EXPECT_EQ(render.exitCode, 0) << render.output;
    fs::create_directories(dir / "golden");
    fs::copy_file(dir / "render" / "eye.png", dir / "golden" / "good.png");
    const fs::path file = dir / "checks.json";
    writeFile(file, R"({ "cases": [
      { "name": "good", "scene": "plane", "size": "160x90", "preset": "resources/presets/paper.json",
        "set": { "shadow_map.resolution": 512 }, "truth": true,
        "expect": { "truth.interior_false_shadow": { "max": 0.002 }, "aliasing.p95": { "max": 6 } },
        "golden": "golden/good.png", "tolerance": { "channel": 8, "fraction": 0.001 } },
      { "name": "acne", "scene": "plane", "size": "160x90", "preset": [")" +
                        kPaper + R"("],
        "set": { "shadow_map.resolution": 512, "bias.constant": -0.5 }, "truth": true,
        "expect": { "truth.interior_false_shadow": { "max": 0.002 } },
        "golden": "golden/good.png", "tolerance": { "channel": 8, "fraction": 0.001 } } ] })");
    return file;
}

} // namespace

// (a) Acne on purpose: the truth bound and the golden fail, with one stderr line each; the good case
// passes, which also shows that check renders exactly what render does.
TEST(CheckCli, AcneFailsItsTruthBoundAndItsGolden) {
    const fs::path file = acneCheck("check_acne");
    const fs::path out = file.parent_path() / "out";
    const SplitResult r = check(file, "--out " + out.string());
    ASSERT_EQ(r.exitCode, 1) << r.out << r.err;
    const auto err = lines(r.err);
    ASSERT_EQ(err.size(), 2u) << r.err;

    const double acne = readJson(out / "acne" / "metrics.json").at("truth").at("interior_false_shadow");
    EXPECT_GT(acne, 0.5) << "the plane shadows itself";
    const std::regex truthLine(R"(shadowscope: check: acne: truth\.interior_false_shadow = ([0-9.e+-]+) > max 0\.002)");
    std::smatch m;
    ASSERT_TRUE(std::regex_match(err[0], m, truthLine)) << err[0];
    EXPECT_NEAR(std::stod(m[1]), acne, 1e-5 * acne);

    const std::regex goldenLine(R"(shadowscope: check: acne: golden golden/good\.png: (\d+) of 14400 pixels )"
                                R"(\([0-9.]+%\) differ by more than 8 > fraction 0\.001)");
    ASSERT_TRUE(std::regex_match(err[1], m, goldenLine)) << err[1];
    const size_t differing = std::stoul(m[1]);
    const Image diff = geometry::analysis::readImageFile((out / "acne" / "diff.png").string());
    EXPECT_EQ(diff.width, 160);
    EXPECT_EQ(diff.height, 90);
    EXPECT_EQ(magentaPixels(diff), differing) << "the diff highlights exactly the pixels counted";
    EXPECT_GT(differing, 14400u / 4) << "acne covers the plane";

    const double good = readJson(out / "good" / "metrics.json").at("truth").at("interior_false_shadow");
    EXPECT_LE(good, 0.002);
    EXPECT_EQ(magentaPixels(geometry::analysis::readImageFile((out / "good" / "diff.png").string())), 0u);
    EXPECT_EQ(slurp(out / "good" / "eye.png"), slurp(file.parent_path() / "golden" / "good.png"))
        << "check renders a case exactly as render does";

    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(good\s+pass\s+0\s+[0-9.]+ s)"))) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(acne\s+FAIL\s+2\s+[0-9.]+ s)"))) << r.out;
    const std::string html = slurp(out / "report.html");
    for (const char* ref : {"\"good/eye.png\"", "\"acne/eye.png\"", "\"acne/golden.png\"", "\"acne/diff.png\""})
        EXPECT_NE(html.find(ref), std::string::npos) << ref;
    for (const char* image : {"eye.png", "golden.png", "diff.png", "metrics.json"})
        EXPECT_TRUE(fs::exists(out / "acne" / image)) << image;
}

// (b) Renders are deterministic: the same file twice gives the same eye.png bytes and verdicts.
TEST(CheckCli, RunningTwiceGivesIdenticalImagesAndVerdicts) {
    const fs::path file = acneCheck("check_twice");
    const fs::path a = file.parent_path() / "a", b = file.parent_path() / "b";
    const SplitResult first = check(file, "--out " + a.string());
    const SplitResult second = check(file, "--out " + b.string());
    EXPECT_EQ(first.exitCode, 1);
    EXPECT_EQ(second.exitCode, 1);
    for (const char* c : {"good", "acne"}) {
        const std::string eye = slurp(a / c / "eye.png");
        EXPECT_FALSE(eye.empty());
        EXPECT_EQ(eye, slurp(b / c / "eye.png")) << c;
        EXPECT_EQ(slurp(a / c / "diff.png"), slurp(b / c / "diff.png")) << c;
    }
    EXPECT_EQ(first.err, second.err);
    // The same summary but for the time column and the output folder.
    const auto summary = [](const std::string& out, const fs::path& dir) {
        std::string s = std::regex_replace(out, std::regex(R"([0-9]+\.[0-9]+ s)"), "T");
        for (size_t at = s.find(dir.string()); at != std::string::npos; at = s.find(dir.string()))
            s.replace(at, dir.string().size(), "DIR");
        return s;
    };
    EXPECT_EQ(summary(first.out, a), summary(second.out, b));
    EXPECT_NE(summary(first.out, a).find("acne  FAIL"), std::string::npos) << first.out;
}

// (c) Bad check files: exactly one stderr line naming the JSON path, exit 2, nothing on stdout.
TEST(CheckCli, BadCheckFilesGiveOneLineAndExitTwo) {
    const fs::path dir = freshDir("check_bad");
    struct Bad {
        std::string name, body, line;
        bool renders; // the mistake shows only in the rendered metrics
    };
    const std::vector<Bad> bad = {
        {"type", R"("expect": {"aliasing.p95": {"max": "6"}})",
         "shadowscope: check: cases[0].expect.aliasing.p95.max: expected a number, got string \"6\"", false},
        {"key", R"("expect": {"aliasing.p96": {"max": 6}})",
         "shadowscope: check: cases[0].expect.aliasing.p96: metrics.json has no such figure: no 'p96' in aliasing",
         true},
        {"golden", R"("golden": "golden/missing.png")",
         "shadowscope: check: cases[0].golden: no such file: " + (dir / "golden" / "missing.png").string(), false},
        {"samples", R"("truth_samples": 2)", "shadowscope: check: cases[0].truth_samples: needs \"truth\": true",
         false},
        {"camera", R"("camera": {"eye": [0, "x", 0]})",
         "shadowscope: check: " + (dir / "camera.json").string() + ": cases[0]: camera.eye", false},
        {"view", R"("views": {"top": {"camera": {"fov_y": 40}}}, "view": "side")",
         "shadowscope: check: cases[0].view: scene 'plane' has no view 'side' (available: default, top)", false},
        {"up", R"("up": "w")", "shadowscope: check: cases[0].up: expected one of y, z, -y, -z, x, -x, got 'w'", false},
    };
    for (const Bad& b : bad) {
        const fs::path file = dir / (b.name + ".json");
        writeFile(file, R"({"cases": [{"name": "a", "scene": "plane", "size": "160x90",
                                       "set": {"shadow_map.resolution": 512}, )" +
                            b.body + "}]}");
        const fs::path out = dir / ("out_" + b.name);
        const SplitResult r = check(file, "--out " + out.string());
        EXPECT_EQ(r.exitCode, 2) << b.name << ": " << r.err;
        const auto err = lines(r.err);
        ASSERT_EQ(err.size(), 1u) << b.name << ": " << r.err;
        EXPECT_EQ(err[0].rfind(b.line, 0), 0u) << "got:      " << err[0] << "\nexpected: " << b.line;
        EXPECT_EQ(r.out, "") << b.name;
        EXPECT_EQ(fs::exists(out / "a" / "eye.png"), b.renders) << b.name << ": validated before rendering";
    }
}

// A case carries its own camera, light, views and truth samples, read by the scene file's rules.
TEST(CheckCli, ACaseCarriesItsOwnCameraLightViewsAndSamples) {
    const fs::path dir = freshDir("check_view_keys");
    const fs::path file = dir / "checks.json";
    writeFile(file, R"({ "cases": [
      { "name": "top", "scene": "plane", "size": "64x36", "set": { "shadow_map.resolution": 256 },
        "light": { "direction": [0.3, -1, 0.1] }, "camera": { "fov_y": 40 },
        "views": { "top": { "camera": { "eye": [0, 30, 0.5], "target": [0, 0, 0] } } }, "view": "top",
        "truth": true, "truth_samples": 2 },
      { "name": "plain", "scene": "plane", "size": "64x36", "set": { "shadow_map.resolution": 256 } } ] })");
    const fs::path out = dir / "out";
    const SplitResult r = check(file, "--out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const nlohmann::json top = readJson(out / "top" / "metrics.json"), plain = readJson(out / "plain" / "metrics.json");
    EXPECT_EQ(top.at("camera").at("eye"), nlohmann::json::parse("[0.0, 30.0, 0.5]"));
    EXPECT_EQ(top.at("camera").at("target"), nlohmann::json::parse("[0.0, 0.0, 0.0]"));
    EXPECT_EQ(top.at("truth").at("samples_per_pixel"), 4);
    EXPECT_NE(top.at("light"), plain.at("light")); // the case's light, not the scene's
    EXPECT_NE(plain.at("camera").at("eye"), top.at("camera").at("eye"));
}

// (d) The JUnit file is well-formed XML with one testsuite, a testcase per case and a failure per
// failing case.
TEST(CheckCli, JUnitFileIsWellFormedWithTheRightCounts) {
    const fs::path file = acneCheck("check_junit");
    const fs::path junit = file.parent_path() / "reports" / "junit.xml"; // its folder is created
    const SplitResult r = check(file, "--out " + (file.parent_path() / "out").string() + " --junit " + junit.string());
    ASSERT_EQ(r.exitCode, 1) << r.err;
    const std::string text = slurp(junit);
    XmlElement root;
    ASSERT_NO_THROW(root = XmlReader(text).document()) << text;
    EXPECT_EQ(root.name, "testsuites");
    ASSERT_EQ(root.children.size(), 1u);
    const XmlElement& suite = root.children[0];
    EXPECT_EQ(suite.name, "testsuite");
    EXPECT_EQ(suite.attributes.at("name"), "checks");
    EXPECT_EQ(suite.attributes.at("tests"), "2");
    EXPECT_EQ(suite.attributes.at("failures"), "1");
    EXPECT_EQ(suite.attributes.at("errors"), "0");
    EXPECT_EQ(root.count("testcase"), 2u);
    EXPECT_EQ(root.count("failure"), 1u);
    std::map<std::string, const XmlElement*> cases;
    for (const auto& c : suite.children) {
        EXPECT_EQ(c.name, "testcase");
        cases[c.attributes.at("name")] = &c;
        EXPECT_FALSE(c.attributes.at("classname").empty());
        EXPECT_GE(std::stod(c.attributes.at("time")), 0.0);
    }
    ASSERT_EQ(cases.count("acne"), 1u);
    ASSERT_EQ(cases.count("good"), 1u);
    EXPECT_EQ(cases["good"]->count("failure"), 0u);
    const auto failure = std::find_if(cases["acne"]->children.begin(), cases["acne"]->children.end(),
                                      [](const XmlElement& e) { return e.name == "failure"; });
    ASSERT_NE(failure, cases["acne"]->children.end());
    // The escaped '>' reads back as '>'.
    EXPECT_NE(failure->attributes.at("message").find("truth.interior_false_shadow = "), std::string::npos);
    EXPECT_NE(failure->attributes.at("message").find(" > max 0.002"), std::string::npos);
    EXPECT_EQ(lines(failure->text).size(), 2u) << failure->text;
    // The reader itself refuses what is not well-formed.
    EXPECT_THROW((void)XmlReader("<a><b></a></b>").document(), std::runtime_error);
    EXPECT_THROW((void)XmlReader("<a x=\"1 < 2\"/>").document(), std::runtime_error);
    EXPECT_THROW((void)XmlReader("<a>&nope;</a>").document(), std::runtime_error);
}

// (e) --update writes the goldens (folders created) and says which changed; the next run passes.
TEST(CheckCli, UpdateWritesGoldensThatTheNextRunPasses) {
    const fs::path dir = freshDir("check_update");
    const fs::path file = dir / "checks.json";
    writeFile(file, R"({ "cases": [
      { "name": "paper", "scene": "plane", "size": "160x90", "preset": ")" +
                        kPaper + R"(", "set": { "shadow_map.resolution": 512 },
        "expect": { "aliasing.p95": { "max": 6 } }, "golden": "golden/paper.png" },
      { "name": "uniform", "scene": "plane", "size": "160x90", "set": { "shadow_map.resolution": 512 },
        "expect": { "aliasing.p95": { "min_ratio_to": "paper", "min": 1 } }, "golden": "golden/more/uniform.png" } ] })");
    const fs::path out = dir / "out";
    const fs::path paper = dir / "golden" / "paper.png", uniform = dir / "golden" / "more" / "uniform.png";

    SplitResult r = check(file, "--update --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("golden new: " + paper.string() + "\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("golden new: " + uniform.string() + "\n"), std::string::npos) << r.out;
    EXPECT_EQ(slurp(paper), slurp(out / "paper" / "eye.png"));
    EXPECT_EQ(slurp(uniform), slurp(out / "uniform" / "eye.png"));
    EXPECT_NE(slurp(paper), slurp(uniform));

    r = check(file, "--out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("2 case(s): 2 passed, 0 failed"), std::string::npos) << r.out;

    r = check(file, "--update --out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("golden unchanged: " + paper.string() + "\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("golden unchanged: " + uniform.string() + "\n"), std::string::npos) << r.out;

    // A golden that no longer matches: the plain run fails, --update rewrites it and says so.
    Image grey = geometry::analysis::readImageFile(paper.string());
    std::fill(grey.rgba.begin(), grey.rgba.end(), uint8_t(128));
    geometry::analysis::writePng(paper.string(), grey);
    r = check(file, "--out " + out.string());
    EXPECT_EQ(r.exitCode, 1);
    r = check(file, "--update --out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("golden changed: " + paper.string() + " (14400 of 14400 pixels)\n"), std::string::npos)
        << r.out;
    EXPECT_EQ(slurp(paper), slurp(out / "paper" / "eye.png"));
    EXPECT_EQ(magentaPixels(geometry::analysis::readImageFile((out / "paper" / "diff.png").string())), 14400u);
}

// (e2) --update leaves the golden of a case whose expectations fail alone (a regression must not
// become the reference); --update --force writes it.
TEST(CheckCli, UpdateKeepsTheGoldenOfAFailingCase) {
    const fs::path dir = freshDir("check_update_failing");
    const fs::path file = dir / "checks.json";
    const auto writeCheck = [&](const char* bound) {
        writeFile(file, std::string(R"({ "cases": [
          { "name": "plane", "scene": "plane", "size": "64x36", "set": { "shadow_map.resolution": 256 },
            "expect": { "aliasing.p95": )") +
                            bound + R"( }, "golden": "golden/plane.png" } ] })");
    };
    const fs::path out = dir / "out", golden = dir / "golden" / "plane.png";
    writeCheck(R"({ "max": 0.000001 })"); // no render meets this
    SplitResult r = check(file, "--update --out " + out.string());
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("golden not written: " + golden.string()), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(golden));

    writeCheck(R"({ "min": 0 })"); // passes: written
    r = check(file, "--update --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    ASSERT_TRUE(fs::exists(golden));
    Image grey = geometry::analysis::readImageFile(golden.string());
    std::fill(grey.rgba.begin(), grey.rgba.end(), uint8_t(128));
    geometry::analysis::writePng(golden.string(), grey);
    const std::string before = slurp(golden);

    writeCheck(R"({ "max": 0.000001 })");
    r = check(file, "--update --out " + out.string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.out.find("golden kept: " + golden.string()), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("kept, as the case's expectations fail"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(golden), before);

    r = check(file, "--update --force --out " + out.string());
    EXPECT_EQ(r.exitCode, 1); // the expectation still fails; the golden is written all the same
    EXPECT_NE(r.out.find("golden changed: " + golden.string()), std::string::npos) << r.out;
    EXPECT_EQ(slurp(golden), slurp(out / "plane" / "eye.png"));
    EXPECT_NE(slurp(golden), before);

    r = check(file, "--force --out " + out.string()); // --force alone means nothing: refused
    EXPECT_NE(r.exitCode, 0);
}

// (f) --shard I/N and merge: three shards merged give what one run gives, byte for byte once the
// timings are taken out; cases compared with each other stay in one shard.
namespace {

/// `text` without what a run's timing changes: "1.23 s" in report.html, time="..." in JUnit.
std::string withoutTimings(std::string text) {
    text = std::regex_replace(text, std::regex(R"([0-9]+\.[0-9]+ s<)"), "T s<");
    text = std::regex_replace(text, std::regex(R"([0-9]+\.[0-9]+ s\n)"), "T s\n");
    return std::regex_replace(text, std::regex(R"(time="[0-9.]+")"), "time=\"T\"");
}

nlohmann::json withoutSeconds(nlohmann::json j) {
    for (auto& c : j.at("cases")) c.erase("seconds");
    return j;
}

} // namespace

TEST(CheckCli, ThreeShardsMergedEqualOneRun) {
    const fs::path dir = freshDir("check_shards");
    const fs::path file = dir / "checks.json";
    std::string cases;
    const std::vector<std::pair<std::string, int>> specs = {{"a", 256}, {"b", 512}, {"c", 128}, {"d", 384}, {"e", 640}};
    for (const auto& [name, res] : specs) {
        cases += std::string(cases.empty() ? "" : ",\n") + R"({ "name": ")" + name +
                 R"(", "scene": "plane", "size": "64x36", "set": { "shadow_map.resolution": )" + std::to_string(res) +
                 R"( }, "expect": { "aliasing.p95": )" +
                 (name == "b" ? R"({ "max_ratio_to": "a", "max": 10 })" : R"({ "max": 1000 })") + " } }";
    }
    writeFile(file, "{ \"cases\": [\n" + cases + "\n] }");

    const fs::path all = dir / "all";
    SplitResult r = check(file, "--out " + all.string() + " --junit " + (all / "junit.xml").string());
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    std::vector<fs::path> shards;
    std::string shardCases;
    for (int s = 1; s <= 3; ++s) {
        shards.push_back(dir / ("shard" + std::to_string(s)));
        r = check(file, "--shard " + std::to_string(s) + "/3 --out " + shards.back().string());
        ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
        const nlohmann::json results = readJson(shards.back() / "results.json");
        for (const auto& c : results.at("cases"))
            shardCases += std::to_string(s) + ":" + c.at("name").get<std::string>() + " ";
    }
    // a and b compare with each other: one group; groups dealt round robin in file order.
    EXPECT_EQ(shardCases, "1:a 1:b 1:e 2:c 3:d ");

    const fs::path merged = dir / "merged";
    const SplitResult m = testutil::runShadowscopeSplit("merge " + shards[0].string() + " " + shards[1].string() + " " +
                                                        shards[2].string() + " --out " + merged.string() + " --junit " +
                                                        (merged / "junit.xml").string());
    ASSERT_EQ(m.exitCode, 0) << m.out << m.err;
    EXPECT_EQ(withoutTimings(slurp(merged / "report.html")), withoutTimings(slurp(all / "report.html")));
    EXPECT_EQ(withoutTimings(slurp(merged / "junit.xml")), withoutTimings(slurp(all / "junit.xml")));
    EXPECT_EQ(withoutSeconds(readJson(merged / "results.json")), withoutSeconds(readJson(all / "results.json")));
    for (const auto& [name, res] : specs) {
        EXPECT_EQ(slurp(merged / name / "eye.png"), slurp(all / name / "eye.png")) << name;
        EXPECT_FALSE(slurp(merged / name / "eye.png").empty()) << name;
    }

    // A shard missing, or one given twice: one line, exit 2.
    const SplitResult missing = testutil::runShadowscopeSplit("merge " + shards[0].string() + " " + shards[1].string() +
                                                              " --out " + (dir / "partial").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("is in no folder (a shard missing?)"), std::string::npos) << missing.err;
    const SplitResult twice = testutil::runShadowscopeSplit("merge " + shards[0].string() + " " + shards[0].string() +
                                                            " --out " + (dir / "twice").string());
    EXPECT_EQ(twice.exitCode, 2);
    EXPECT_NE(twice.err.find("is in two folders"), std::string::npos) << twice.err;
    EXPECT_EQ(check(file, "--shard 4/3").exitCode, 2);
}
