#pragma once
// `shadowscope sweep gamma|path|check`: stability where methods fail (docs/stability.md).
//   gamma: turns the light about the eye through a range of light-view angles (0: light from
//          behind the eye, 180: facing the camera) and records n', aliasing and truth per method;
//   path:  walks a camera or light path of a scene file and records flicker and seams per frame;
//   check: re-applies gamma's --check rules to a written sweep.csv.
#include "render_options.h"
#include "sweep_check.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct SweepGammaOptions {
    RenderOptions render;
    double fromDeg = 0, toDeg = 180, stepDeg = 0.5;
    std::vector<std::string> methods{"uniform", "psm", "lispsm", "glispsm", "gmnpr"};
    bool check = false;
    SweepThresholds thresholds;
};

struct SweepPathOptions {
    RenderOptions render;
    std::string path;
    int frames = 30;
};

struct SweepCheckOptions {
    std::string file;
    SweepThresholds thresholds;
};

struct SweepOptions {
    SweepGammaOptions gamma;
    SweepPathOptions path;
    SweepCheckOptions check;
};

/// Most angles one gamma sweep may have, and most frames one path may have: beyond, a typo (a step
/// of 1e-6) would run for days instead of failing.
inline constexpr int kMaxSweepAngles = 3601;
inline constexpr int kMaxPathFrames = 10000;

/// Adds `sweep` with its `gamma`, `path` and `check` subcommands; returns `sweep`.
CLI::App* addSweepCommand(CLI::App& cli, SweepOptions& options);
/// Runs whichever subcommand of `sweep` was parsed; the exit code (1 when a --check failed).
int runSweep(const CLI::App& sweep, const SweepOptions& options);

/// The angles of a gamma sweep: from, from + step, …, and `to` itself as the last one.
/// Throws std::invalid_argument (one line) for a range outside [0, 180], from > to, step <= 0,
/// non-finite values, or more than kMaxSweepAngles angles.
[[nodiscard]] std::vector<double> sweepAngles(double fromDeg, double toDeg, double stepDeg);

int runSweepGamma(const SweepGammaOptions& options);
int runSweepPath(const SweepPathOptions& options);
int runSweepCheck(const SweepCheckOptions& options);

} // namespace app
