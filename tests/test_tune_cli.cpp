// `shadowscope tune` end to end on the plane scene: a recommendation that the default settings do
// not meet is found with few full-size evaluations and, rendered again, meets the target; nothing
// meeting exits 3 with the closest configuration; bad arguments exit 2.
#include "cli_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

namespace fs = std::filesystem;
using testutil::freshDir;

namespace {

testutil::CommandResult run(const std::string& args) { return testutil::runShadowscope(args); }

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

size_t countLines(const fs::path& p) {
    std::ifstream in(p);
    size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

} // namespace

TEST(TuneCli, RecommendationMeetsTheTargetWhenRenderedAgain) {
    const std::string target = "p95=0.3,edge=0.001";
    // The defaults miss it: p95 ≈ 0.56 at this size.
    const fs::path before = freshDir("tune_defaults");
    ASSERT_EQ(run("render --backend osmesa --scene plane --size 160x120 --truth --views eye --out " + before.string())
                  .exitCode,
              0);
    EXPECT_GT(readJson(before / "metrics.json")["aliasing"]["p95"].get<double>(), 0.3);

    const fs::path dir = freshDir("tune");
    const auto r = run("tune --backend osmesa --scene plane --size 160x120 --target " + target +
                       " --budget-evals 30 --frames 1 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"recommended.json", "tune.csv", "tune.svg", "tune.png"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    // "N evaluations (F at full size, of a space of S configurations)": F < S.
    std::smatch m;
    const std::regex counts(R"((\d+) evaluations \((\d+) at full size, of a space of (\d+) configurations\))");
    ASSERT_TRUE(std::regex_search(r.output, m, counts)) << r.output;
    const int evaluations = std::stoi(m[1]), full = std::stoi(m[2]);
    EXPECT_GE(full, 1);
    EXPECT_LT(double(full), std::stod(m[3]));
    EXPECT_LE(evaluations, 30);
    EXPECT_EQ(countLines(dir / "tune.csv"), size_t(evaluations) + 1);
    std::ifstream csv(dir / "tune.csv");
    std::string header;
    std::getline(csv, header);
    EXPECT_NE(header.find(",meets,"), std::string::npos) << header;

    const fs::path again = freshDir("tune_again");
    const auto rr = run("render --backend osmesa --scene plane --size 160x120 --truth --views eye --preset " +
                        (dir / "recommended.json").string() + " --out " + again.string());
    ASSERT_EQ(rr.exitCode, 0) << rr.output;
    const auto j = readJson(again / "metrics.json");
    EXPECT_LE(j["aliasing"]["p95"].get<double>(), 0.3);
    EXPECT_LE(j["truth"]["edge_error"].get<double>(), 0.001);
}

TEST(TuneCli, NothingMeetsExitsThreeWithTheClosest) {
    const fs::path dir = freshDir("tune_none");
    const auto r = run("tune --backend osmesa --scene plane --size 96x72 --target p95=0.001 --space "
                       "shadow_map.resolution=256,512 --space warp.method=uniform --budget-evals 6 --frames 1 --out " +
                       dir.string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_TRUE(fs::exists(dir / "closest.json"));
    EXPECT_FALSE(fs::exists(dir / "recommended.json"));
    EXPECT_NE(r.output.find("misses p95"), std::string::npos) << r.output;
}

namespace {

/// tune.csv without its last column (frame_ms, measured: the one that may differ between runs).
std::string withoutMeasuredTime(const fs::path& p) {
    std::ifstream in(p);
    std::string out;
    for (std::string line; std::getline(in, line);) out += line.substr(0, line.rfind(',')) + '\n';
    return out;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

// A space holding absurd biases (10 m constant, a normal offset of 16 texels) on the deck: they
// lose the grating's shadows, which count as errors, so they are never recommended; and two runs
// of the same search write the same recommended.json and tune.csv (the measured time aside).
TEST(TuneCli, AbsurdBiasesAreNeverRecommendedAndTwoRunsAgree) {
    const std::string args =
        "tune --backend osmesa --scene " + std::string(SHADOWSCOPE_SOURCE_DIR) +
        "/resources/scenes/platform.json --view deck --size 160x90 --preset " + std::string(SHADOWSCOPE_SOURCE_DIR) +
        "/resources/presets/paper.json --target interior=0.01,edge=0.02 --space bias.type=constant,normal_offset "
        "--space filter.type=pcf --space shadow_map.resolution=1024 --space warp.method=glispsm --space "
        "splits.count=2 --space splits.scheme=adaptive --space splits.alpha=2 --space bias.constant=0.02,1,10 "
        "--space bias.normal_offset=1,16 --budget-evals 14 --frames 1 --out ";
    const fs::path a = freshDir("tune_absurd_a"), b = freshDir("tune_absurd_b");
    const auto ra = run(args + a.string());
    ASSERT_EQ(ra.exitCode, 0) << ra.output;
    const auto rec = readJson(a / "recommended.json");
    EXPECT_LE(rec["bias"]["constant"].get<double>(), 0.1);
    EXPECT_EQ(rec["bias"]["type"], "constant");
    std::ifstream csv(a / "tune.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.substr(header.rfind(',') + 1), "frame_ms") << "the measured time last";
    int absurd = 0;
    while (std::getline(csv, line))
        if (line.find("bias.constant=10\"") != std::string::npos ||
            line.find("bias.normal_offset=16\"") != std::string::npos) {
            ++absurd;
            EXPECT_NE(line.find(",0,0,\""), std::string::npos) << "misses, not chosen: " << line;
        }
    EXPECT_EQ(absurd, 2) << "both absurd biases were measured";
    const auto rb = run(args + b.string());
    ASSERT_EQ(rb.exitCode, 0) << rb.output;
    EXPECT_EQ(slurp(a / "recommended.json"), slurp(b / "recommended.json"));
    EXPECT_EQ(withoutMeasuredTime(a / "tune.csv"), withoutMeasuredTime(b / "tune.csv"));
}

TEST(TuneCli, BadArgumentsExitTwo) {
    for (const std::string args :
         {"tune --backend osmesa --scene plane --out /tmp/x",
          "tune --backend osmesa --scene plane --target speed=1 --out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --space bogus.key=1 --out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --space shadow_map.resolution=3 "
          "--out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --budget-evals 1 --out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --view nowhere --out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --truth-samples 0 --out /tmp/x",
          "tune --backend osmesa --scene plane --target p95=1 --truth-samples 65 --out /tmp/x",
          "tune --backend osmesa --scene plane --target soft=0.1 --out /tmp/x",
          "tune --backend osmesa --scene plane --target edge_width=-1 --out /tmp/x"}) {
        const auto r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
    }
}
