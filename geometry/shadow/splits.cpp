#include "geometry/shadow/splits.h"

#include "geometry/scene/invariant.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geometry::shadow {

std::vector<double> splitDistances(const SplitParams& p, double n, double f, double gamma) {
    // Validated settings and frustum (settings.h) guarantee these; a caller that passes others has a
    // bug to find, not a value to be quietly replaced.
    SHADOWSCOPE_EXPECTS(p.count >= 1 && p.count <= kMaxSplits);
    SHADOWSCOPE_EXPECTS(n > 0.0 && f > n);
    const int k = p.count;
    std::vector<double> c(static_cast<size_t>(k) + 1);
    c[0] = n;
    c[k] = f;
    const auto uniform = [&](int i) { return n + (f - n) * i / k; };
    const auto logarithmic = [&](int i) { return n * std::pow(f / n, double(i) / k); }; // Barroso eq 5
    switch (p.scheme) {
    case SplitScheme::Uniform:
        for (int i = 1; i < k; ++i) c[i] = uniform(i);
        break;
    case SplitScheme::Log:
        for (int i = 1; i < k; ++i) c[i] = logarithmic(i);
        break;
    case SplitScheme::Practical: // λ·log + (1 − λ)·uniform: the blend engines ship (docs/design.md §3.4)
        for (int i = 1; i < k; ++i) c[i] = p.lambda * logarithmic(i) + (1.0 - p.lambda) * uniform(i);
        break;
    case SplitScheme::Pssm: { // lengths L_i = L_1·r^(i−1), ΣL_i = f − n
        const double r = p.ratio;
        const double first = std::abs(r - 1.0) < 1e-9 ? (f - n) / k : (f - n) * (r - 1.0) / (std::pow(r, k) - 1.0);
        double len = first;
        for (int i = 1; i < k; ++i, len *= r) c[i] = c[i - 1] + len;
        break;
    }
    case SplitScheme::Adaptive: { // Barroso eq 19, from the far end down
        const double lambda = std::clamp(gamma / (std::numbers::pi / 2.0), 0.0, 1.0);
        for (int i = k; i >= 2; --i)
            c[i - 1] = lambda * n * std::pow(c[i] / n, double(i - 1) / i) + (1.0 - lambda) * c[i] / p.alpha;
        break;
    }
    }
    for (int i = 1; i < k; ++i) c[i] = std::clamp(std::isfinite(c[i]) ? c[i] : n, n, f);
    for (int i = 1; i < k; ++i) c[i] = std::max(c[i], c[i - 1]); // never decreasing
    return c;
}

int splitResolution(const SplitParams& p, int resolution, int i) noexcept {
    if (!p.resolutionFalloff) return resolution;
    return std::max(16, resolution >> std::clamp(i, 0, 30));
}

} // namespace geometry::shadow
