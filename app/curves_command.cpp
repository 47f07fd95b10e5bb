#include "curves_command.h"
#include "app/output_folder.h"

#include "render_options.h"

#include "geometry/shadow/analytic_error.h"
#include "geometry/shadow/splits.h"
#include "geometry/shadow/warp.h"
#include "ui/charts/analytic_charts.h"

#include <CLI/CLI.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <stdexcept>

namespace app {

namespace {

using geometry::shadow::SplitScheme;
using geometry::shadow::WarpMethod;

constexpr double kMinGammaStepDeg = 0.01; // 9001 γ samples at most
using ui::charts::ErrorRow;
using ui::charts::formatNumber;
using ui::charts::SplitRow;
using ui::charts::WarpRow;

int mapResOf(const CurvesOptions& o) { return o.mapRes.value_or(o.settings.resolution); }

ui::charts::CurveParams paramsOf(const CurvesOptions& o) {
    return {o.near, o.far, o.fovYDeg, o.gammaStepDeg, o.gammaDeg, o.screenRes, mapResOf(o), o.settings};
}

// ---- CSV --------------------------------------------------------------------------------------

std::string warpCsv(const std::vector<WarpRow>& rows) {
    std::string out = "gamma_deg,method,n_prime,lambda\n";
    for (const WarpRow& r : rows)
        out += formatNumber(r.gammaDeg) + "," + std::string(geometry::shadow::warpMethodName(r.method)) + "," +
               formatNumber(r.nPrime) + "," + formatNumber(r.lambda) + "\n";
    return out;
}

std::string errorCsv(const std::vector<ErrorRow>& rows) {
    std::string out = "z,method,m_z\n";
    for (const ErrorRow& r : rows)
        out += formatNumber(r.z) + "," + std::string(geometry::shadow::warpMethodName(r.method)) + "," +
               formatNumber(r.mz) + "\n";
    return out;
}

std::string splitsCsv(const std::vector<SplitRow>& rows) {
    std::string out = "gamma_deg,scheme,i,near,far\n";
    for (const SplitRow& r : rows)
        for (size_t i = 0; i + 1 < r.boundaries.size(); ++i)
            out += formatNumber(r.gammaDeg) + "," + std::string(geometry::shadow::splitSchemeName(r.scheme)) + "," +
                   std::to_string(i) + "," + formatNumber(r.boundaries[i]) + "," + formatNumber(r.boundaries[i + 1]) +
                   "\n";
    return out;
}

} // namespace

void addCurvesCommand(CLI::App& cmd, CurvesOptions& o) {
    cmd.add_option("--near", o.near, "Camera near distance n (> 0)")->required();
    cmd.add_option("--far", o.far, "Camera far distance f (> near)")->required();
    cmd.add_option("--fov-y", o.fovYDeg, "Camera vertical field of view in degrees (0..180, exclusive)")->required();
    cmd.add_option("--gamma-step", o.gammaStepDeg, "Step of gamma in degrees (0.01..90) for warp.csv and splits.csv")
        ->capture_default_str();
    cmd.add_option("--gamma", o.gammaDeg, "Light/view angle gamma in degrees (0..90) for error.csv")
        ->capture_default_str();
    cmd.add_option("--screen-res", o.screenRes, "Screen height in pixels (res_screen_y of the error model)")
        ->capture_default_str();
    cmd.add_option_function<int>(
        "--map-res", [&o](int r) { o.mapRes = r; },
        "Shadow-map resolution res_map of the error model (default: shadow_map.resolution, 2048)");
    cmd.add_option("--out", o.out, "Output folder")->capture_default_str();
    addSettingOption(cmd, o.settings);
}

void validateCurves(const CurvesOptions& o) {
    geometry::shadow::validateFrustum(o.near, o.far, o.fovYDeg);
    // A floor on the step keeps a typo like 1e-9 from asking for 10^11 rows (a hang, not an error).
    if (!(o.gammaStepDeg >= kMinGammaStepDeg && o.gammaStepDeg <= 90))
        throw std::invalid_argument("gamma-step: " + formatNumber(o.gammaStepDeg) + " must be within " +
                                    formatNumber(kMinGammaStepDeg) + "..90 degrees");
    if (!(o.gammaDeg >= 0 && o.gammaDeg <= 90))
        throw std::invalid_argument("gamma: " + formatNumber(o.gammaDeg) + " must be within [0, 90] degrees");
    if (o.screenRes < 1) throw std::invalid_argument("screen-res: " + std::to_string(o.screenRes) + " must be >= 1");
    if (mapResOf(o) < 1) throw std::invalid_argument("map-res: " + std::to_string(mapResOf(o)) + " must be >= 1");
    geometry::shadow::validateOrThrow(o.settings);
}

std::vector<double> gammaSamplesDeg(double stepDeg) { return ui::charts::gammaSamplesDeg(stepDeg); }

int runCurves(const CurvesOptions& o) {
    validateCurves(o);
    createOutputFolder(o.out);
    const std::filesystem::path dir(o.out);

    const ui::charts::CurveParams p = paramsOf(o);
    const auto warp = ui::charts::warpRows(p);
    const auto error = ui::charts::errorRows(p);
    const auto splits = ui::charts::splitRows(p);
    const std::vector<std::pair<std::filesystem::path, std::string>> files{
        {dir / "warp.csv", warpCsv(warp)},
        {dir / "error.csv", errorCsv(error)},
        {dir / "splits.csv", splitsCsv(splits)},
        {dir / "warp.svg", ui::charts::chartToSvg(ui::charts::warpChart(warp, p), 860, 520)},
        {dir / "lambda.svg", ui::charts::chartToSvg(ui::charts::lambdaChart(warp, p), 860, 520)},
        {dir / "error.svg", ui::charts::chartToSvg(ui::charts::errorChart(error, p), 860, 520)},
        {dir / "splits.svg",
         ui::charts::chartsToSvg(ui::charts::splitChartsTitle(p), ui::charts::splitCharts(splits, p), 3, 440, 330)},
    };
    for (const auto& [path, text] : files) writeTextFile(path, text);
    for (const auto& [path, text] : files) std::cout << path.string() << '\n';
    return 0;
}

} // namespace app
