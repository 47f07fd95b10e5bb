#pragma once
// The analytic curves of the shadow math as tables and charts: n'(γ) and λ(γ) for every warp
// (Barroso Fig 7, Zhang Fig 5), m_z(z) for every warp at one γ (Zhang Fig 6), split boundaries
// against γ. The `curves` command writes them as CSV/SVG; the dashboard's Charts panel draws the
// same charts live with ImGui.
#include "geometry/shadow/settings.h"
#include "geometry/shadow/splits.h"
#include "geometry/shadow/warp.h"
#include "ui/charts/chart.h"

#include <optional>
#include <string>
#include <vector>

namespace ui::charts {

/// The frustum and model parameters the curves are drawn for.
struct CurveParams {
    double near = 1, far = 100, fovYDeg = 60;  // eye frustum
    double gammaStepDeg = 1;                   // sampling of γ for the warp and split tables
    double gammaDeg = 60;                      // γ of the error table
    int screenRes = 1080;                      // res_screen_y of the error model
    int mapRes = 2048;                         // res_map of the error model
    geometry::shadow::ShadowSettings settings; // warp options, split count and scheme options
};

struct WarpRow {
    double gammaDeg;
    geometry::shadow::WarpMethod method;
    double nPrime, lambda;
};
struct ErrorRow {
    double z;
    geometry::shadow::WarpMethod method;
    double mz;
};
struct SplitRow {
    double gammaDeg;
    geometry::shadow::SplitScheme scheme;
    std::vector<double> boundaries; // C_0 = n … C_k = f
};

/// γ from 0 to 90 by `stepDeg`, 90 always included.
[[nodiscard]] std::vector<double> gammaSamplesDeg(double stepDeg);
[[nodiscard]] std::vector<WarpRow> warpRows(const CurveParams& p);
[[nodiscard]] std::vector<ErrorRow> errorRows(const CurveParams& p);
[[nodiscard]] std::vector<SplitRow> splitRows(const CurveParams& p);

/// Shortest text that reads back as the same double; "inf", "-inf", "nan" otherwise.
[[nodiscard]] std::string formatNumber(double v);

/// n'(γ) per warp; with `markerGammaDeg`, a vertical marker at the current γ.
[[nodiscard]] Chart warpChart(const std::vector<WarpRow>& rows, const CurveParams& p,
                              std::optional<double> markerGammaDeg = std::nullopt);
/// λ(γ) = n'/(f'−n') per warp (Zhang's parameter), with the same optional marker.
[[nodiscard]] Chart lambdaChart(const std::vector<WarpRow>& rows, const CurveParams& p,
                                std::optional<double> markerGammaDeg = std::nullopt);
/// m_z(z) per warp at p.gammaDeg (Barroso eq 12).
[[nodiscard]] Chart errorChart(const std::vector<ErrorRow>& rows, const CurveParams& p);
/// One chart per split scheme: every boundary C_i against γ.
[[nodiscard]] std::vector<Chart> splitCharts(const std::vector<SplitRow>& rows, const CurveParams& p);
[[nodiscard]] std::string splitChartsTitle(const CurveParams& p);

} // namespace ui::charts
