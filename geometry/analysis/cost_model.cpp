#include "geometry/analysis/cost_model.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geometry::analysis {

namespace {

using shadow::FilterType;

/// Shadow-map lookups per eye pixel: the filter's taps (PCSS: its blocker search and its filter).
double tapsPerPixel(const shadow::FilterSettings& f) noexcept {
    switch (f.type) {
    case FilterType::Pcf: return double(f.kernel) * f.kernel;
    case FilterType::Disk: return f.taps;
    case FilterType::Pcss: return 2.0 * f.taps;
    default: return 1.0;
    }
}

/// llvmpipe (LLVM 15, Mesa 22.3, 2 cores), ns per unit in workKindNames() order, fitted by
/// `tune --calibrate-cost --size 320x180 --frames 3` on the platform's four views (96 frames; the
/// fit's frames lie within −40 % / +70 % of their measured median; docs/design.md §4 "Cost model").
constexpr std::array<double, WorkCounts::kKinds> kLlvmpipe{131.0, 460.0, 1.21, 87.1, 3.56, 1.76};

} // namespace

const std::array<std::string_view, WorkCounts::kKinds>& workKindNames() noexcept {
    static const std::array<std::string_view, WorkCounts::kKinds> names{
        "eye_pixels", "eye_triangles", "eye_taps", "shadow_triangles", "shadow_texels", "blur_texels"};
    return names;
}

WorkCounts countWork(const shadow::ShadowSettings& s, const shadow::ShadowPlan& plan, uint64_t shadowTriangles,
                     uint64_t eyeTriangles, shadow::Viewport size) noexcept {
    WorkCounts w;
    w.eyePixels = double(size.width) * double(size.height);
    w.eyeTriangles = double(eyeTriangles);
    w.eyeTaps = w.eyePixels * (tapsPerPixel(s.filter) + 2.0 * s.filter.eyeBlurIterations);
    w.shadowTriangles = double(shadowTriangles);
    const bool peeling = s.bias.type == shadow::BiasType::Midpoint || s.bias.type == shadow::BiasType::DualDepth;
    const bool moments = shadow::isMomentFilter(s.filter.type);
    for (const shadow::SplitPlan& split : plan.splits) {
        if (split.empty() || split.skipped) continue;
        const double texels = double(split.resolution) * double(split.resolution);
        w.shadowTexels += texels * (peeling ? 3.0 : 1.0);
        if (moments) w.blurTexels += texels * (1.0 + 2.0 * s.filter.kernel);
    }
    return w;
}

double CostModel::costMs(const WorkCounts& w) const noexcept {
    const auto v = w.values();
    double ns = 0;
    for (int k = 0; k < WorkCounts::kKinds; ++k) ns += nsPerUnit[size_t(k)] * v[size_t(k)];
    return ns * 1e-6;
}

CostModel storedCostModel(std::string_view rendererString, bool* calibrated) {
    if (calibrated) *calibrated = rendererString.find("llvmpipe") != std::string_view::npos;
    return {"llvmpipe", kLlvmpipe};
}

CostModel fitCostModel(const std::vector<CostSample>& samples, std::string backend) {
    constexpr int K = WorkCounts::kKinds;
    if (samples.size() < size_t(K))
        throw std::invalid_argument("cost calibration: " + std::to_string(samples.size()) + " samples for " +
                                    std::to_string(K) + " kinds of work");
    std::array<bool, K> active{};
    active.fill(true);
    std::array<double, K> x{};
    // Each kind scaled to unit mean first, so that pixels (1e5) and texels (1e8) condition alike.
    std::array<double, K> scale{};
    for (const CostSample& s : samples)
        for (int k = 0; k < K; ++k) scale[size_t(k)] += s.work.values()[size_t(k)] / double(samples.size());
    for (int round = 0; round < K; ++round) {
        // Normal equations over the active kinds, solved by Gaussian elimination with pivoting.
        std::vector<int> idx;
        for (int k = 0; k < K; ++k)
            if (active[size_t(k)] && scale[size_t(k)] > 0) idx.push_back(k);
        const size_t n = idx.size();
        std::vector<std::vector<double>> a(n, std::vector<double>(n + 1, 0.0));
        for (const CostSample& s : samples) {
            const auto v = s.work.values();
            for (size_t i = 0; i < n; ++i) {
                const double vi = v[size_t(idx[i])] / scale[size_t(idx[i])];
                for (size_t j = 0; j < n; ++j) a[i][j] += vi * v[size_t(idx[j])] / scale[size_t(idx[j])];
                a[i][n] += vi * s.ms * 1e6;
            }
        }
        for (size_t c = 0; c < n; ++c) {
            size_t p = c;
            for (size_t r = c + 1; r < n; ++r)
                if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
            std::swap(a[c], a[p]);
            if (std::abs(a[c][c]) < 1e-12) continue;
            for (size_t r = 0; r < n; ++r) {
                if (r == c) continue;
                const double f = a[r][c] / a[c][c];
                for (size_t j = c; j <= n; ++j) a[r][j] -= f * a[c][j];
            }
        }
        x.fill(0.0);
        bool negative = false;
        for (size_t i = 0; i < n; ++i) {
            const double coef = std::abs(a[i][i]) < 1e-12 ? 0.0 : a[i][n] / a[i][i] / scale[size_t(idx[i])];
            x[size_t(idx[i])] = coef;
            if (coef < 0) {
                active[size_t(idx[i])] = false;
                negative = true;
            }
        }
        if (!negative) break;
    }
    for (double& c : x) c = std::max(c, 0.0);
    return {std::move(backend), x};
}

std::string costModelJson(const CostModel& model) {
    nlohmann::ordered_json j;
    j["backend"] = model.backend;
    for (int k = 0; k < WorkCounts::kKinds; ++k)
        j["ns_per_unit"][std::string(workKindNames()[size_t(k)])] = model.nsPerUnit[size_t(k)];
    return j.dump(2);
}

} // namespace geometry::analysis
