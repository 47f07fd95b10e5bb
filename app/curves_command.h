#pragma once
// `shadowscope curves`: the analytic curves of docs/design.md §3 (warp parameter n'(γ), aliasing error
// m_z(z), split boundaries against γ) as CSV tables and SVG charts, without rendering anything.
#include "geometry/shadow/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct CurvesOptions {
    double near = 1, far = 100, fovYDeg = 60; // eye frustum (--near, --far, --fov-y; required)
    double gammaStepDeg = 1;                  // sampling of γ for warp.csv and splits.csv
    double gammaDeg = 60;                     // γ of error.csv
    int screenRes = 1080;                     // res_screen_y of the error model
    std::optional<int> mapRes;                // res_map; default: the settings' shadow_map.resolution
    std::string out = "out";
    geometry::shadow::ShadowSettings settings; // --set key=value (warp options, split count and scheme options)
};

/// Adds the curves options (--near, --far, --fov-y, --gamma-step, --gamma, --screen-res, --map-res,
/// --set, --out) to `cmd`.
void addCurvesCommand(CLI::App& cmd, CurvesOptions& options);

/// Throws std::invalid_argument naming the first bad option.
void validateCurves(const CurvesOptions& options);

/// γ samples in degrees: 0, step, 2·step, … up to 90, always ending at 90 exactly.
[[nodiscard]] std::vector<double> gammaSamplesDeg(double stepDeg);

/// Writes DIR/warp.csv, error.csv, splits.csv, warp.svg, error.svg, splits.svg and prints their paths.
/// Throws on invalid options or when a file cannot be written.
int runCurves(const CurvesOptions& options);

} // namespace app
