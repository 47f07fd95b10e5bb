#include "ui/charts/analytic_charts.h"

#include "geometry/shadow/analytic_error.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

namespace ui::charts {

using geometry::shadow::SplitScheme;
using geometry::shadow::WarpMethod;

namespace {

constexpr std::array kWarpMethods{WarpMethod::Uniform, WarpMethod::Psm, WarpMethod::Lispsm, WarpMethod::Glispsm,
                                  WarpMethod::Gmnpr};
constexpr std::array kSplitSchemes{SplitScheme::Uniform, SplitScheme::Log, SplitScheme::Practical, SplitScheme::Pssm,
                                   SplitScheme::Adaptive};
constexpr int kErrorSamples = 200; // enough for a smooth log-log curve, small enough to read as CSV

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

} // namespace

/// Shortest text that reads back as the same double (so CSV consumers see exact values);
/// non-finite values as "inf" / "-inf" / "nan".
std::string formatNumber(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

namespace {

/// The eye frustum as the formulas take it.
struct Frustum {
    double n, f;
    double phi; // vertical half field of view, radians
    // The extent d of the focus body B along the warp direction V_P (only lispsm reads it). The
    // curves have no scene, so they use the frustum depth f − n: that is exactly B's extent along
    // V_P for the whole frustum at γ = 90° (V_P = v), the case LiSPSM's n' is designed for.
    double d;
};

Frustum frustumOf(const CurveParams& o) { return {o.near, o.far, radians(o.fovYDeg) / 2.0, o.far - o.near}; }

double nPrimeOf(const CurveParams& o, const Frustum& fr, WarpMethod m, double gamma) {
    geometry::shadow::WarpParams p = o.settings.warp; // keeps falloff, multiplier, visible_far from --set
    p.method = m;
    return geometry::shadow::warpNPrime(p, fr.n, fr.f, fr.phi, gamma, fr.d);
}

// ---- the three tables -------------------------------------------------------------------------

} // namespace

std::vector<WarpRow> warpRows(const CurveParams& o) {
    const Frustum fr = frustumOf(o);
    std::vector<WarpRow> rows;
    for (const double g : gammaSamplesDeg(o.gammaStepDeg))
        for (const WarpMethod m : kWarpMethods) {
            const double np = nPrimeOf(o, fr, m, radians(g));
            rows.push_back({g, m, np, geometry::shadow::lambdaFromNPrime(np, fr.n, fr.f, fr.phi, radians(g))});
        }
    return rows;
}

/// count samples from n to f, evenly spaced in log z; the ends are exactly n and f, so that
/// m_z(n) and m_z(f) (whose equality defines the optimal n') are both in the table.
static std::vector<double> logSamples(double n, double f, int count) {
    std::vector<double> z(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) z[i] = n * std::pow(f / n, double(i) / (count - 1));
    z.front() = n;
    z.back() = f;
    return z;
}

std::vector<ErrorRow> errorRows(const CurveParams& o) {
    const Frustum fr = frustumOf(o);
    const double gamma = radians(o.gammaDeg);
    const geometry::shadow::ErrorModel model{fr.n, fr.f, fr.phi, gamma, double(o.screenRes), double(o.mapRes)};
    std::array<double, kWarpMethods.size()> nPrimes{};
    for (size_t k = 0; k < kWarpMethods.size(); ++k) nPrimes[k] = nPrimeOf(o, fr, kWarpMethods[k], gamma);
    std::vector<ErrorRow> rows;
    for (const double z : logSamples(fr.n, fr.f, kErrorSamples))
        for (size_t k = 0; k < kWarpMethods.size(); ++k)
            rows.push_back(
                {z, kWarpMethods[k], geometry::shadow::aliasingErrorZ(model, nPrimes[k], z)}); // Barroso eq 12
    return rows;
}

std::vector<SplitRow> splitRows(const CurveParams& o) {
    std::vector<SplitRow> rows;
    for (const double g : gammaSamplesDeg(o.gammaStepDeg))
        for (const SplitScheme s : kSplitSchemes) {
            geometry::shadow::SplitParams p = o.settings.splits; // keeps count, λ, ratio, α from --set
            p.scheme = s;
            rows.push_back({g, s, geometry::shadow::splitDistances(p, o.near, o.far, radians(g))});
        }
    return rows;
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

namespace {

std::string frustumText(const CurveParams& o) {
    return "n = " + formatNumber(o.near) + ", f = " + formatNumber(o.far) + ", fov-y = " + formatNumber(o.fovYDeg) +
           "°";
}

/// One series per method, x and y picked from the rows.
template <class Row, class X, class Y>
std::vector<ChartSeries> methodSeries(const std::vector<Row>& rows, X x, Y y, bool skipUniform) {
    std::vector<ChartSeries> series;
    for (size_t k = 0; k < kWarpMethods.size(); ++k) {
        if (skipUniform && kWarpMethods[k] == WarpMethod::Uniform) continue;
        ChartSeries s{std::string(geometry::shadow::warpMethodName(kWarpMethods[k])),
                      paletteColour(int(k)),
                      {},
                      SeriesStyle::Lines,
                      3.f,
                      {}};
        for (const Row& r : rows)
            if (r.method == kWarpMethods[k]) s.points.push_back({x(r), y(r)});
        series.push_back(std::move(s));
    }
    return series;
}

} // namespace

namespace {
void addMarker(Chart& c, std::optional<double> markerGammaDeg, double lo, double hi) {
    if (!markerGammaDeg || !std::isfinite(*markerGammaDeg)) return;
    ChartSeries m{"current γ = " + formatNumber(std::round(*markerGammaDeg * 10.0) / 10.0) + "°",
                  Rgb{0, 0, 0},
                  {},
                  SeriesStyle::Lines,
                  3.f,
                  {}};
    m.points = {{*markerGammaDeg, lo}, {*markerGammaDeg, hi}};
    c.series.push_back(std::move(m));
}
std::pair<double, double> yExtent(const Chart& c) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& s : c.series)
        for (const auto& p : s.points)
            if (plottable(p.y, c.y.log)) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    return {lo, hi};
}
} // namespace

Chart warpChart(const std::vector<WarpRow>& rows, const CurveParams& o, std::optional<double> markerGammaDeg) {
    Chart c;
    // Uniform is n' = ∞ everywhere, so it has no point on a log axis; the title says so instead.
    c.title = "Warp parameter n'(γ), " + frustumText(o) + " (uniform: n' = ∞, not drawn)";
    c.x = {"γ (degrees)", false, 0.0, 90.0};
    c.y = {"n'", true, std::nullopt, std::nullopt};
    c.series = methodSeries(
        rows, [](const WarpRow& r) { return r.gammaDeg; }, [](const WarpRow& r) { return r.nPrime; }, true);
    const auto [lo, hi] = yExtent(c);
    addMarker(c, markerGammaDeg, lo, hi);
    return c;
}

Chart lambdaChart(const std::vector<WarpRow>& rows, const CurveParams& o, std::optional<double> markerGammaDeg) {
    Chart c;
    c.title = "Zhang's λ(θ) = n'/(f'−n'), " + frustumText(o) + " (uniform: λ = 0, not drawn)";
    c.x = {"θ = γ (degrees)", false, 0.0, 90.0};
    c.y = {"λ", true, std::nullopt, std::nullopt};
    c.series = methodSeries(
        rows, [](const WarpRow& r) { return r.gammaDeg; }, [](const WarpRow& r) { return r.lambda; }, true);
    const auto [lo, hi] = yExtent(c);
    addMarker(c, markerGammaDeg, lo, hi);
    return c;
}

Chart errorChart(const std::vector<ErrorRow>& rows, const CurveParams& o) {
    Chart c;
    c.title = "Aliasing error m_z(z) at γ = " + formatNumber(o.gammaDeg) + "°, " + frustumText(o) + ", " +
              std::to_string(o.screenRes) + " px / " + std::to_string(o.mapRes) + " texels";
    c.x = {"z (eye depth)", true, std::nullopt, std::nullopt};
    c.y = {"m_z (pixels per texel)", true, std::nullopt, std::nullopt};
    c.series = methodSeries(
        rows, [](const ErrorRow& r) { return r.z; }, [](const ErrorRow& r) { return r.mz; }, false);
    return c;
}

namespace {
std::string schemeTitle(SplitScheme s, const geometry::shadow::SplitParams& p) {
    std::string t(geometry::shadow::splitSchemeName(s));
    switch (s) {
    case SplitScheme::Practical: return t + " (λ = " + formatNumber(p.lambda) + ")";
    case SplitScheme::Pssm: return t + " (ratio " + formatNumber(p.ratio) + ")";
    case SplitScheme::Adaptive: return t + " (α = " + formatNumber(p.alpha) + ")";
    default: return t;
    }
}

} // namespace

/// Small multiples, one panel per scheme: every boundary C_i against γ, on a log distance axis
/// (the schemes are geometric, so equal ratios read as equal gaps).
std::vector<Chart> splitCharts(const std::vector<SplitRow>& rows, const CurveParams& o) {
    const int k = std::max(1, o.settings.splits.count);
    std::vector<Chart> panels;
    for (const SplitScheme s : kSplitSchemes) {
        Chart c;
        c.title = schemeTitle(s, o.settings.splits);
        c.x = {"γ (degrees)", false, 0.0, 90.0};
        // A margin around [n, f] keeps the C_0 = n and C_k = f lines off the frame.
        c.y = {"split boundary z", true, o.near / 1.25, o.far * 1.25};
        for (int i = 0; i <= k; ++i) {
            std::string name = "C" + std::to_string(i) + (i == 0 ? " = n" : i == k ? " = f" : "");
            ChartSeries series{std::move(name), paletteColour(i), {}, SeriesStyle::Lines, 3.f, {}};
            for (const SplitRow& r : rows)
                if (r.scheme == s) series.points.push_back({r.gammaDeg, r.boundaries[static_cast<size_t>(i)]});
            c.series.push_back(std::move(series));
        }
        panels.push_back(std::move(c));
    }
    return panels;
}

std::string splitChartsTitle(const CurveParams& o) {
    return "Split boundaries against γ, k = " + std::to_string(std::max(1, o.settings.splits.count)) + ", " +
           frustumText(o);
}

} // namespace ui::charts
