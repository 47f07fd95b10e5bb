#pragma once
// `shadowscope bench`: configurations (presets × --sweep values) × canonical views, N timed frames
// each after warm-up; results.csv, and the speed/accuracy trade-off chart with its Pareto front.
#include "app/render_options.h"
#include "app/shard.h"
#include "geometry/shadow/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct BenchOptions {
    /// --scene --view --size --out --backend --preset --set, declared with every other command's
    /// (OptionUse::Bench): `common.views` empty = all of the scene's views; each of `common.presets`
    /// is a configuration (none: the defaults); `common.assignments` apply to every configuration.
    RenderOptions common = benchDefaults();
    std::vector<std::string> sweeps; // "key=v1,v2,..."
    int frames = 10;
    int warmup = 2;
    TruthOptions truth;
    std::string path;         // a camera/light path of the scene file, walked in `frames` frames
    std::string x = "gpu_ms"; // the trade-off chart's axes (ui/charts/tradeoff_chart.h)
    std::string y = "p95";
    std::optional<Shard> shard; // --shard I/N: only this share of the configurations

    [[nodiscard]] static RenderOptions benchDefaults() {
        RenderOptions o;
        o.scene = "resources/scenes/platform.json";
        o.out = "out/bench";
        return o;
    }
};

/// One configuration: a label ("paper", "ssm filter.kernel=5") and its settings.
struct BenchConfiguration {
    std::string label;
    std::string preset; // the preset's file stem ("" for the defaults)
    geometry::shadow::ShadowSettings settings;
};

/// Every preset × every combination of sweep values, in command-line order (the last sweep varies
/// fastest). Throws std::invalid_argument (one line) for a malformed sweep, an unknown key or an
/// out-of-range value, or more than 4096 configurations.
[[nodiscard]] std::vector<BenchConfiguration> benchConfigurations(const BenchOptions& options);

void addBenchCommand(CLI::App& cmd, BenchOptions& options);
int runBench(const BenchOptions& options);

/// `merge` of bench folders: their results.json (kind "bench"), every configuration in exactly one,
/// into OUT's results.csv, tradeoff.svg/png and results.json as one unsharded run writes them.
/// Throws std::invalid_argument for folders of different runs, a configuration missing or twice.
int mergeBench(const std::vector<nlohmann::json>& shards, const std::string& out);

} // namespace app
