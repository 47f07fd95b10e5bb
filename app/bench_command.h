#pragma once
// `shadowscope bench`: configurations (presets × --sweep values) × canonical views, N timed frames
// each after warm-up; results.csv, and the speed/accuracy trade-off chart with its Pareto front.
#include "geometry/shadow/settings.h"
#include "geometry/scene/scene.h"
#include "geometry/shadow/shadow_plan.h"

#include <string>
#include <vector>

namespace CLI { class App; }

namespace app {

struct BenchOptions {
    std::string scene = "resources/scenes/platform.json";
    std::vector<std::string> views;        // canonical views; empty: all of the scene's
    std::vector<std::string> sweeps;       // "key=v1,v2,..."
    std::vector<std::string> presets;      // each preset is a configuration; none: the defaults
    std::vector<std::string> assignments;  // --set key=value on every configuration
    int frames = 10;
    int warmup = 2;
    geometry::shadow::Viewport size{1280, 720};
    std::string out = "out/bench";
    std::string backend = "auto";
    bool truth = false;
};

/// One configuration: a label ("paper", "ssm filter.kernel=5") and its settings.
struct BenchConfiguration {
    std::string label;
    std::string preset;                    // the preset's file stem ("" for the defaults)
    geometry::shadow::ShadowSettings settings;
};

/// Every preset × every combination of sweep values, in command-line order (the last sweep varies
/// fastest). Throws std::invalid_argument (one line) for a malformed sweep, an unknown key or an
/// out-of-range value, or more than 4096 configurations.
[[nodiscard]] std::vector<BenchConfiguration> benchConfigurations(const BenchOptions& options);

void addBenchCommand(CLI::App& cmd, BenchOptions& options);
int runBench(const BenchOptions& options);

} // namespace app
