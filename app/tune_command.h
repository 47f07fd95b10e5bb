#pragma once
// `shadowscope tune`: the cheapest configuration that meets an accuracy target on a scene's views
// (geometry/analysis/tuner.h searches; this measures, reports progress and writes the results).
#include "app/render_options.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct TuneCommandOptions {
    /// --scene --view --size --out --backend --preset --set (OptionUse::Bench): `views` empty = every
    /// canonical view of the scene file (none: the scene's camera); at most one --preset, the start;
    /// --set applies to the start.
    RenderOptions common = defaults();
    std::string target;              // --target p95=2,interior=0.001,...
    std::vector<std::string> spaces; // --space key=v1,v2,...
    TruthOptions truth{true, 1};
    int budgetEvals = 120;
    int frames = 3;
    bool calibrateCost = false; // --calibrate-cost: fit the cost model on this backend instead of searching

    [[nodiscard]] static RenderOptions defaults() {
        RenderOptions o;
        o.scene = "resources/scenes/platform.json";
        o.size = {640, 360};
        o.out = "out/tune";
        return o;
    }
};

void addTuneCommand(CLI::App& cmd, TuneCommandOptions& options);

/// Runs the search. Writes DIR/tune.csv, DIR/tune.svg and .png, and DIR/recommended.json (exit 0)
/// or, when nothing meets the target, DIR/closest.json (exit 3, naming each view's misses). The same
/// inputs write the same recommended.json and tune.csv (but its measured frame_ms column). With
/// --calibrate-cost, measures the calibration set and writes DIR/cost_model.json instead (exit 0).
/// Bad arguments throw std::invalid_argument (exit 2).
int runTune(const TuneCommandOptions& options);

} // namespace app
