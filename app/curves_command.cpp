#include "curves_command.h"

#include "render_options.h"

#include "geometry/analytic_error.h"
#include "geometry/splits.h"
#include "geometry/warp.h"
#include "ui/chart.h"

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

using geometry::SplitScheme;
using geometry::WarpMethod;

constexpr std::array kWarpMethods{WarpMethod::Uniform, WarpMethod::Psm, WarpMethod::Lispsm, WarpMethod::Glispsm,
                                  WarpMethod::Gmnpr};
constexpr std::array kSplitSchemes{SplitScheme::Uniform, SplitScheme::Log, SplitScheme::Practical, SplitScheme::Pssm,
                                   SplitScheme::Adaptive};
constexpr double kMinGammaStepDeg = 0.01; // 9001 γ samples at most
constexpr int kErrorSamples = 200; // enough for a smooth log-log curve, small enough to read as CSV

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

/// Shortest text that reads back as the same double (so CSV consumers see exact values);
/// non-finite values as "inf" / "-inf" / "nan".
std::string formatNumber(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

/// The eye frustum as the formulas take it.
struct Frustum {
    double n, f;
    double phi; // vertical half field of view, radians
    // The extent d of the focus body B along the warp direction V_P (only lispsm reads it). The
    // curves have no scene, so they use the frustum depth f − n: that is exactly B's extent along
    // V_P for the whole frustum at γ = 90° (V_P = v), the case LiSPSM's n' is designed for.
    double d;
};

Frustum frustumOf(const CurvesOptions& o) { return {o.near, o.far, radians(o.fovYDeg) / 2.0, o.far - o.near}; }

double nPrimeOf(const CurvesOptions& o, const Frustum& fr, WarpMethod m, double gamma) {
    geometry::WarpParams p = o.settings.warp; // keeps falloff, multiplier, visible_far from --set
    p.method = m;
    return geometry::warpNPrime(p, fr.n, fr.f, fr.phi, gamma, fr.d);
}

// ---- the three tables -------------------------------------------------------------------------

struct WarpRow {
    double gammaDeg;
    WarpMethod method;
    double nPrime, lambda;
};

std::vector<WarpRow> warpRows(const CurvesOptions& o) {
    const Frustum fr = frustumOf(o);
    std::vector<WarpRow> rows;
    for (const double g : gammaSamplesDeg(o.gammaStepDeg))
        for (const WarpMethod m : kWarpMethods) {
            const double np = nPrimeOf(o, fr, m, radians(g));
            rows.push_back({g, m, np, geometry::lambdaFromNPrime(np, fr.n, fr.f, fr.phi, radians(g))});
        }
    return rows;
}

struct ErrorRow {
    double z;
    WarpMethod method;
    double mz;
};

/// count samples from n to f, evenly spaced in log z; the ends are exactly n and f, so that
/// m_z(n) and m_z(f) (whose equality defines the optimal n') are both in the table.
std::vector<double> logSamples(double n, double f, int count) {
    std::vector<double> z(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) z[i] = n * std::pow(f / n, double(i) / (count - 1));
    z.front() = n;
    z.back() = f;
    return z;
}

int mapResOf(const CurvesOptions& o) { return o.mapRes.value_or(o.settings.resolution); }

std::vector<ErrorRow> errorRows(const CurvesOptions& o) {
    const Frustum fr = frustumOf(o);
    const double gamma = radians(o.gammaDeg);
    const geometry::ErrorModel model{fr.n, fr.f, fr.phi, gamma, double(o.screenRes), double(mapResOf(o))};
    std::array<double, kWarpMethods.size()> nPrimes{};
    for (size_t k = 0; k < kWarpMethods.size(); ++k) nPrimes[k] = nPrimeOf(o, fr, kWarpMethods[k], gamma);
    std::vector<ErrorRow> rows;
    for (const double z : logSamples(fr.n, fr.f, kErrorSamples))
        for (size_t k = 0; k < kWarpMethods.size(); ++k)
            rows.push_back({z, kWarpMethods[k], geometry::aliasingErrorZ(model, nPrimes[k], z)}); // Barroso eq 12
    return rows;
}

struct SplitRow {
    double gammaDeg;
    SplitScheme scheme;
    std::vector<double> boundaries; // C_0 = n … C_k = f
};

std::vector<SplitRow> splitRows(const CurvesOptions& o) {
    std::vector<SplitRow> rows;
    for (const double g : gammaSamplesDeg(o.gammaStepDeg))
        for (const SplitScheme s : kSplitSchemes) {
            geometry::SplitParams p = o.settings.splits; // keeps count, λ, ratio, α from --set
            p.scheme = s;
            rows.push_back({g, s, geometry::splitDistances(p, o.near, o.far, radians(g))});
        }
    return rows;
}

// ---- CSV --------------------------------------------------------------------------------------

std::string warpCsv(const std::vector<WarpRow>& rows) {
    std::string out = "gamma_deg,method,n_prime,lambda\n";
    for (const WarpRow& r : rows)
        out += formatNumber(r.gammaDeg) + "," + std::string(geometry::warpMethodName(r.method)) + "," +
               formatNumber(r.nPrime) + "," + formatNumber(r.lambda) + "\n";
    return out;
}

std::string errorCsv(const std::vector<ErrorRow>& rows) {
    std::string out = "z,method,m_z\n";
    for (const ErrorRow& r : rows)
        out += formatNumber(r.z) + "," + std::string(geometry::warpMethodName(r.method)) + "," + formatNumber(r.mz) + "\n";
    return out;
}

std::string splitsCsv(const std::vector<SplitRow>& rows) {
    std::string out = "gamma_deg,scheme,i,near,far\n";
    for (const SplitRow& r : rows)
        for (size_t i = 0; i + 1 < r.boundaries.size(); ++i)
            out += formatNumber(r.gammaDeg) + "," + std::string(geometry::splitSchemeName(r.scheme)) + "," +
                   std::to_string(i) + "," + formatNumber(r.boundaries[i]) + "," + formatNumber(r.boundaries[i + 1]) + "\n";
    return out;
}

// ---- charts -----------------------------------------------------------------------------------

std::string frustumText(const CurvesOptions& o) {
    return "n = " + formatNumber(o.near) + ", f = " + formatNumber(o.far) + ", fov-y = " + formatNumber(o.fovYDeg) + "°";
}

/// One series per method, x and y picked from the rows.
template <class Row, class X, class Y>
std::vector<ui::ChartSeries> methodSeries(const std::vector<Row>& rows, X x, Y y, bool skipUniform) {
    std::vector<ui::ChartSeries> series;
    for (size_t k = 0; k < kWarpMethods.size(); ++k) {
        if (skipUniform && kWarpMethods[k] == WarpMethod::Uniform) continue;
        ui::ChartSeries s{std::string(geometry::warpMethodName(kWarpMethods[k])), ui::paletteColour(int(k)), {}};
        for (const Row& r : rows)
            if (r.method == kWarpMethods[k]) s.points.push_back({x(r), y(r)});
        series.push_back(std::move(s));
    }
    return series;
}

ui::Chart warpChart(const std::vector<WarpRow>& rows, const CurvesOptions& o) {
    ui::Chart c;
    // Uniform is n' = ∞ everywhere, so it has no point on a log axis; the title says so instead.
    c.title = "Warp parameter n'(γ), " + frustumText(o) + " (uniform: n' = ∞, not drawn)";
    c.x = {"γ (degrees)", false, 0.0, 90.0};
    c.y = {"n'", true, std::nullopt, std::nullopt};
    c.series = methodSeries(rows, [](const WarpRow& r) { return r.gammaDeg; }, [](const WarpRow& r) { return r.nPrime; }, true);
    return c;
}

ui::Chart errorChart(const std::vector<ErrorRow>& rows, const CurvesOptions& o) {
    ui::Chart c;
    c.title = "Aliasing error m_z(z) at γ = " + formatNumber(o.gammaDeg) + "°, " + frustumText(o) + ", " +
              std::to_string(o.screenRes) + " px / " + std::to_string(mapResOf(o)) + " texels";
    c.x = {"z (eye depth)", true, std::nullopt, std::nullopt};
    c.y = {"m_z (pixels per texel)", true, std::nullopt, std::nullopt};
    c.series = methodSeries(rows, [](const ErrorRow& r) { return r.z; }, [](const ErrorRow& r) { return r.mz; }, false);
    return c;
}

std::string schemeTitle(SplitScheme s, const geometry::SplitParams& p) {
    std::string t(geometry::splitSchemeName(s));
    switch (s) {
    case SplitScheme::Practical: return t + " (λ = " + formatNumber(p.lambda) + ")";
    case SplitScheme::Pssm: return t + " (ratio " + formatNumber(p.ratio) + ")";
    case SplitScheme::Adaptive: return t + " (α = " + formatNumber(p.alpha) + ")";
    default: return t;
    }
}

/// Small multiples, one panel per scheme: every boundary C_i against γ, on a log distance axis
/// (the schemes are geometric, so equal ratios read as equal gaps).
std::string splitsSvg(const std::vector<SplitRow>& rows, const CurvesOptions& o) {
    const int k = std::max(1, o.settings.splits.count);
    std::vector<ui::Chart> panels;
    for (const SplitScheme s : kSplitSchemes) {
        ui::Chart c;
        c.title = schemeTitle(s, o.settings.splits);
        c.x = {"γ (degrees)", false, 0.0, 90.0};
        // A margin around [n, f] keeps the C_0 = n and C_k = f lines off the frame.
        c.y = {"split boundary z", true, o.near / 1.25, o.far * 1.25};
        for (int i = 0; i <= k; ++i) {
            std::string name = "C" + std::to_string(i) + (i == 0 ? " = n" : i == k ? " = f" : "");
            ui::ChartSeries series{std::move(name), ui::paletteColour(i), {}};
            for (const SplitRow& r : rows)
                if (r.scheme == s) series.points.push_back({r.gammaDeg, r.boundaries[static_cast<size_t>(i)]});
            c.series.push_back(std::move(series));
        }
        panels.push_back(std::move(c));
    }
    return ui::chartsToSvg("Split boundaries against γ, k = " + std::to_string(k) + ", " + frustumText(o), panels, 3, 440, 330);
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

} // namespace

void addCurvesCommand(CLI::App& cmd, CurvesOptions& o) {
    cmd.add_option("--near", o.near, "Camera near distance n (> 0)")->required();
    cmd.add_option("--far", o.far, "Camera far distance f (> near)")->required();
    cmd.add_option("--fov-y", o.fovYDeg, "Camera vertical field of view in degrees (0..180, exclusive)")->required();
    cmd.add_option("--gamma-step", o.gammaStepDeg, "Step of gamma in degrees (0.01..90) for warp.csv and splits.csv")
        ->capture_default_str();
    cmd.add_option("--gamma", o.gammaDeg, "Light/view angle gamma in degrees (0..90) for error.csv")->capture_default_str();
    cmd.add_option("--screen-res", o.screenRes, "Screen height in pixels (res_screen_y of the error model)")
        ->capture_default_str();
    cmd.add_option_function<int>(
        "--map-res", [&o](int r) { o.mapRes = r; },
        "Shadow-map resolution res_map of the error model (default: shadow_map.resolution, 2048)");
    cmd.add_option("--out", o.out, "Output folder")->capture_default_str();
    addSettingOption(cmd, o.settings);
}

void validateCurves(const CurvesOptions& o) {
    geometry::validateFrustum(o.near, o.far, o.fovYDeg);
    // A floor on the step keeps a typo like 1e-9 from asking for 10^11 rows (a hang, not an error).
    if (!(o.gammaStepDeg >= kMinGammaStepDeg && o.gammaStepDeg <= 90))
        throw std::invalid_argument("gamma-step: " + formatNumber(o.gammaStepDeg) + " must be within " +
                                    formatNumber(kMinGammaStepDeg) + "..90 degrees");
    if (!(o.gammaDeg >= 0 && o.gammaDeg <= 90))
        throw std::invalid_argument("gamma: " + formatNumber(o.gammaDeg) + " must be within [0, 90] degrees");
    if (o.screenRes < 1) throw std::invalid_argument("screen-res: " + std::to_string(o.screenRes) + " must be >= 1");
    if (mapResOf(o) < 1) throw std::invalid_argument("map-res: " + std::to_string(mapResOf(o)) + " must be >= 1");
    geometry::validateOrThrow(o.settings);
}

std::vector<double> gammaSamplesDeg(double stepDeg) {
    std::vector<double> g;
    // i·step rather than a running sum, so 0.1-degree steps do not drift.
    for (int i = 0;; ++i) {
        const double v = i * stepDeg;
        if (v > 90.0 - 1e-9) break;
        g.push_back(v);
    }
    g.push_back(90.0); // γ = 90° (the classic LiSPSM case) is always on the curve, whatever the step
    return g;
}

int runCurves(const CurvesOptions& o) {
    validateCurves(o);
    std::error_code ec;
    std::filesystem::create_directories(o.out, ec);
    if (ec) throw std::runtime_error("cannot create output folder " + o.out + ": " + ec.message());
    const std::filesystem::path dir(o.out);

    const auto warp = warpRows(o);
    const auto error = errorRows(o);
    const auto splits = splitRows(o);
    const std::vector<std::pair<std::filesystem::path, std::string>> files{
        {dir / "warp.csv", warpCsv(warp)},
        {dir / "error.csv", errorCsv(error)},
        {dir / "splits.csv", splitsCsv(splits)},
        {dir / "warp.svg", ui::chartToSvg(warpChart(warp, o), 860, 520)},
        {dir / "error.svg", ui::chartToSvg(errorChart(error, o), 860, 520)},
        {dir / "splits.svg", splitsSvg(splits, o)},
    };
    for (const auto& [path, text] : files) writeText(path, text);
    for (const auto& [path, text] : files) std::cout << path.string() << '\n';
    return 0;
}

} // namespace app
