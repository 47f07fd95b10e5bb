// `shadowscope bench`: configurations × views, results.csv, the trade-off chart with its Pareto front.
#include "cli_test_util.h"
#include "renderer/image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

using testutil::runShadowscope;

namespace {

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& p) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::string cell;
        bool quoted = false;
        for (char c : line) {
            if (c == '"') quoted = !quoted;
            else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
            else cell += c;
        }
        cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(Bench, WritesOneRowPerConfigurationAndViewAndTheTradeoffChart) {
    const auto dir = testutil::freshDir("bench");
    const std::string presets = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/";
    const auto r = runShadowscope("bench --backend osmesa --scene " + std::string(SHADOWSCOPE_SOURCE_DIR) +
                                  "/resources/scenes/plane.json --preset " + presets + "ssm.json --preset " + presets +
                                  "paper.json --sweep filter.kernel=1,5 --set filter.type=pcf --frames 2 --warmup 1 "
                                  "--size 160x120 --truth --out " +
                                  dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "results.csv");
    ASSERT_FALSE(rows.empty());
    const auto& header = rows[0];
    const auto col = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return size_t(it - header.begin());
    };
    // plane.json has 2 canonical views: 2 presets × 2 kernels × 2 views.
    ASSERT_EQ(rows.size(), 1u + 2 * 2 * 2) << slurp(dir / "results.csv");
    double ssmP95 = 0, paperP95 = 0;
    for (size_t i = 1; i < rows.size(); ++i) {
        const auto& row = rows[i];
        ASSERT_EQ(row.size(), header.size());
        EXPECT_GT(std::stod(row[col("gpu_ms_median")]), 0.0);
        EXPECT_GT(std::stod(row[col("cpu_ms_median")]), 0.0);
        EXPECT_GT(std::stod(row[col("shadow_memory_mib")]), 0.0);
        const double mis = std::stod(row[col("misclassified")]);
        EXPECT_GE(mis, 0.0);
        EXPECT_LE(mis, 1.0);
        // The classes split the misclassified pixels (ambiguous ones are counted apart).
        const double parts = std::stod(row[col("interior_false_shadow")]) + std::stod(row[col("interior_false_lit")]) +
                             std::stod(row[col("edge_error")]);
        EXPECT_LE(parts, mis + 1e-9);
        EXPECT_GE(parts + std::stod(row[col("ambiguous")]), mis - 1e-9);
        if (row[col("preset")] == "ssm") ssmP95 += std::stod(row[col("p95")]);
        if (row[col("preset")] == "paper") paperP95 += std::stod(row[col("p95")]);
    }
    EXPECT_GT(ssmP95, paperP95) << "the warped, split maps alias less than the uniform one";
    const std::string svg = slurp(dir / "tradeoff.svg");
    EXPECT_NE(svg.find("Pareto front"), std::string::npos);
    EXPECT_NE(svg.find("ssm.json / paper.json"), std::string::npos);
    EXPECT_NE(svg.find("paper filter.kernel=5"), std::string::npos);
    const geometry::analysis::Image png = geometry::analysis::readImageFile((dir / "tradeoff.png").string());
    EXPECT_EQ(png.width, 1000);
    EXPECT_EQ(png.height, 620);
    size_t red = 0; // the highlighted ssm/paper markers
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const uint8_t* p = png.at(x, y);
            red += p[0] > 190 && p[1] < 80 && p[2] < 80;
        }
    EXPECT_GT(red, 100u);
}

// The filters of issue 20 in a bench sweep with a soft sun: each row has soft_mean_abs and
// umbra_light, PCSS's soft error is below hard PCF's, PCSS leaves the disk's umbra dark while ESM
// leaks into it, and --y soft draws the chart from them.
TEST(Bench, SweepsTheNewFiltersAgainstASoftSun) {
    const auto dir = testutil::freshDir("bench_filters");
    const auto r = runShadowscope("bench --backend osmesa --scene " + std::string(SHADOWSCOPE_SOURCE_DIR) +
                                  "/resources/scenes/penumbra.json --sweep filter.type=pcf,pcss,esm,evsm2,evsm4,msm "
                                  "--set light.angular_diameter_deg=2 --frames 1 --warmup 1 --size 240x135 --truth "
                                  "--y soft --out " +
                                  dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "results.csv");
    ASSERT_EQ(rows.size(), 1u + 6) << slurp(dir / "results.csv");
    const auto& header = rows[0];
    const auto col = [&](const std::string& name) {
        return size_t(std::find(header.begin(), header.end(), name) - header.begin());
    };
    ASSERT_LT(col("soft_mean_abs"), header.size());
    ASSERT_LT(col("umbra_light"), header.size());
    double pcf = NAN, pcss = NAN, pcssUmbra = NAN, esmUmbra = NAN;
    for (size_t i = 1; i < rows.size(); ++i) {
        const double soft = std::stod(rows[i][col("soft_mean_abs")]);
        EXPECT_GE(soft, 0.0);
        EXPECT_LT(soft, 0.5);
        const double umbra = std::stod(rows[i][col("umbra_light")]);
        EXPECT_GE(umbra, 0.0);
        EXPECT_LE(umbra, 1.0);
        if (rows[i][0].find("filter.type=pcf") != std::string::npos) pcf = soft;
        if (rows[i][0].find("filter.type=pcss") != std::string::npos) pcss = soft, pcssUmbra = umbra;
        if (rows[i][0].find("filter.type=esm") != std::string::npos) esmUmbra = umbra;
    }
    EXPECT_LT(pcss, pcf);
    // umbra_light is measured where the sun's disk is hidden (v = 0): PCSS's correct penumbra is no
    // leak there, ESM's light bleeding still is.
    EXPECT_LE(pcssUmbra, 0.005);
    EXPECT_GT(esmUmbra, 0.02);
    EXPECT_NE(slurp(dir / "tradeoff.svg").find("soft_mean_abs"), std::string::npos) << "the chart's y axis";
    // soft needs ground truth.
    const auto noTruth = runShadowscope("bench --backend osmesa --scene plane --frames 1 --size 64x48 --y soft --out " +
                                        (dir / "x").string());
    EXPECT_EQ(noTruth.exitCode, 2) << noTruth.output;
}

TEST(Bench, BadSweepsAreOneLineErrors) {
    for (const std::string bad : {"--sweep filter.kernel", "--sweep nonsense=1,2", "--sweep filter.kernel=2",
                                  "--sweep shadow_map.resolution=abc"}) {
        const auto r = runShadowscope("bench --backend osmesa --scene plane --frames 1 --out /tmp/unused " + bad);
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_NE(r.output.find("error"), std::string::npos) << bad << ": " << r.output;
        EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 2) << r.output;
    }
    const auto unknownView =
        runShadowscope("bench --backend osmesa --scene plane --view nowhere --frames 1 --out /tmp/unused");
    EXPECT_NE(unknownView.exitCode, 0);
    EXPECT_NE(unknownView.output.find("nowhere"), std::string::npos);
}

// bench takes --scene --size --out --preset --set from the declaration render uses: the same help
// text (a copy of its own would drift), and nothing bench-specific in render.
TEST(Bench, SharesTheRenderOptionsDeclaration) {
    const auto bench = runShadowscope("bench --help");
    const auto render = runShadowscope("render --help");
    ASSERT_EQ(bench.exitCode, 0) << bench.output;
    ASSERT_EQ(render.exitCode, 0) << render.output;
    const auto lineOf = [](const std::string& help, const std::string& option) {
        std::istringstream in(help);
        for (std::string line; std::getline(in, line);)
            if (line.find(option) != std::string::npos && line.find(option) < 8) return line;
        return std::string();
    };
    for (const std::string option : {"--scene", "--out", "--size"}) {
        const std::string r = lineOf(render.output, option);
        // The description: after the option column (its default differs: bench measures the
        // platform's views into out/bench).
        const size_t gap = r.find("   ", r.find(option));
        ASSERT_NE(gap, std::string::npos) << r;
        std::string words = r.substr(r.find_first_not_of(' ', gap));
        EXPECT_FALSE(lineOf(bench.output, option).empty()) << option << " missing from bench --help";
        EXPECT_NE(bench.output.find(words), std::string::npos) << option << ": '" << words << "' not in\n"
                                                               << bench.output;
    }
    EXPECT_NE(bench.output.find("--set KEY=VALUE"), std::string::npos) << bench.output;
    EXPECT_NE(bench.output.find("--preset"), std::string::npos);
    EXPECT_EQ(render.output.find("--sweep"), std::string::npos);
    // Each --preset is one configuration and --set applies to all of them.
    const auto dir = testutil::freshDir("bench_shared_options");
    const auto r =
        runShadowscope("bench --backend osmesa --scene plane --frames 1 --warmup 1 --size 64x48 --out " + dir.string() +
                       " --preset " + SHADOWSCOPE_SOURCE_DIR "/resources/presets/ssm.json --preset " +
                       SHADOWSCOPE_SOURCE_DIR "/resources/presets/lispsm.json --set shadow_map.resolution=256");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "results.csv");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[1][0], "ssm");
    EXPECT_EQ(rows[2][0], "lispsm");
}

// bench --path: each configuration also walks a path of the scene file; results.csv gains world-
// and screen-space flicker and the seam, and the trade-off chart takes its axes from --x / --y.
// A snapped uniform map does not shimmer along deck_dolly; the unsnapped one does.
TEST(Bench, PathFlickerColumnsAndChartAxes) {
    const std::string scene = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/platform.json";
    const std::string preset = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/ssm.json";
    const auto dir = testutil::freshDir("bench_path");
    const auto r =
        runShadowscope("bench --backend osmesa --scene " + scene + " --view deck --size 160x120 --preset " + preset +
                       " --set shadow_map.resolution=512 --sweep stabilize.mode=off,snap --path deck_dolly "
                       "--frames 6 --warmup 1 --x memory_mib --y flicker --out " +
                       dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = readCsv(dir / "results.csv");
    ASSERT_EQ(rows.size(), 3u);
    const auto column = [&](const std::string& name) {
        const auto it = std::find(rows[0].begin(), rows[0].end(), name);
        EXPECT_NE(it, rows[0].end()) << name;
        return size_t(it - rows[0].begin());
    };
    const size_t mean = column("flicker_mean"), p95 = column("flicker_p95"), screen = column("flicker_screen");
    (void)column("seam");
    ASSERT_EQ(rows[1].size(), rows[0].size());
    const double off = std::stod(rows[1][mean]), snap = std::stod(rows[2][mean]);
    EXPECT_GT(off, 1e-3) << "unsnapped: " << rows[1][0];
    EXPECT_LE(snap, off / 10) << rows[2][0];
    EXPECT_GE(std::stod(rows[1][p95]), off);
    EXPECT_GT(std::stod(rows[1][screen]), 0.0);
    const std::string svg = slurp(dir / "tradeoff.svg");
    EXPECT_NE(svg.find("world-space flicker"), std::string::npos);
    EXPECT_NE(svg.find("shadow-map memory (MiB)"), std::string::npos);
    for (const std::string bad : {"--y edge", "--y flicker", "--path nosuch", "--x speed"}) {
        const auto b = runShadowscope("bench --backend osmesa --scene " + scene + " --view deck --size 32x32 " + bad +
                                      " --frames 1 --warmup 1 --out " + testutil::freshDir("bench_bad").string());
        EXPECT_EQ(b.exitCode, 2) << bad << ": " << b.output;
    }
}

// --shard I/N and merge: three shards merged give one run's chart byte for byte (memory on x: no
// timing in it) and its results.csv but for the timing columns.
TEST(Bench, ThreeShardsMergedEqualOneRun) {
    const auto dir = testutil::freshDir("bench_shards");
    const std::string presets = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/";
    const std::string args = "bench --backend osmesa --scene " + std::string(SHADOWSCOPE_SOURCE_DIR) +
                             "/resources/scenes/plane.json --preset " + presets + "ssm.json --preset " + presets +
                             "lispsm.json --preset " + presets +
                             "paper.json --frames 1 --warmup 1 --size 96x64 --truth --x memory_mib --y misclassified";
    auto r = runShadowscope(args + " --out " + (dir / "all").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::string shards;
    for (int s = 1; s <= 3; ++s) {
        const auto out = dir / ("shard" + std::to_string(s));
        r = runShadowscope(args + " --shard " + std::to_string(s) + "/3 --out " + out.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(readCsv(out / "results.csv").size(), 3u) << "header and one configuration at two views";
        shards += " " + out.string();
    }
    r = runShadowscope("merge" + shards + " --out " + (dir / "merged").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(slurp(dir / "merged" / "tradeoff.svg"), slurp(dir / "all" / "tradeoff.svg"));
    const auto merged = readCsv(dir / "merged" / "results.csv"), all = readCsv(dir / "all" / "results.csv");
    ASSERT_EQ(merged.size(), 7u);
    ASSERT_EQ(merged.size(), all.size());
    for (size_t row = 0; row < all.size(); ++row) {
        ASSERT_EQ(merged[row].size(), all[row].size());
        for (size_t c = 0; c < all[row].size(); ++c) {
            const std::string& column = all[0][c];
            if (column.find("_ms_") != std::string::npos) continue; // timings
            EXPECT_EQ(merged[row][c], all[row][c]) << "row " << row << " " << column;
        }
    }
}
