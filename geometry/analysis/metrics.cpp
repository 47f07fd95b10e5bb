#include "geometry/analysis/metrics.h"

#include "geometry/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace geometry::analysis {
namespace {

void requireSameSize(size_t a, size_t b, const char* what) {
    if (a != b)
        throw std::invalid_argument(std::string(what) + ": per-pixel inputs differ in size (" + std::to_string(a) +
                                    " vs " + std::to_string(b) + ")");
}

constexpr int kMaxMapResolution = 16384;

void validateTexelInputs(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver, int resolution) {
    requireSameSize(aux.size(), receiver.size(), "texel utilization");
    if (resolution < 1 || resolution > kMaxMapResolution)
        throw std::invalid_argument("texel utilization: map resolution " + std::to_string(resolution) +
                                    " outside [1, " + std::to_string(kMaxMapResolution) + "]");
}

/// Calls mark(texel index) for every receiver pixel of `split` whose (u, v) lies on the map.
/// Inputs must have passed validateTexelInputs().
template <class Mark>
void forEachUsedTexel(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver, int split, int resolution,
                      Mark&& mark) {
    const double res = resolution;
    for (size_t i = 0; i < aux.size(); ++i) {
        if (!receiver[i]) continue;
        const glm::vec4 a = aux[i];
        // The split index travels as a float through a float render target: round, don't
        // truncate. Comparing the distance (not lround) keeps NaN and huge values harmless.
        if (!(std::abs(double(a.z) - split) < 0.5)) continue;
        // Written as negated ranges so NaN fails them too.
        const double u = std::floor(double(a.x)), v = std::floor(double(a.y));
        if (!(u >= 0 && u < res && v >= 0 && v < res)) continue;
        mark(size_t(v) * size_t(resolution) + size_t(u));
    }
}

} // namespace

AliasingStats aliasingStats(std::span<const float> m, std::span<const uint8_t> receiver) {
    requireSameSize(m.size(), receiver.size(), "aliasingStats");
    AliasingStats st;
    std::vector<float> values;
    double sum = 0;
    size_t under = 0;
    size_t singular = 0;
    for (size_t i = 0; i < m.size(); ++i) {
        if (!receiver[i]) continue;
        if (!std::isfinite(m[i])) {
            ++st.skipped;
            continue;
        }
        if (!(m[i] < kSingularM)) {
            ++singular;
            continue;
        }
        values.push_back(m[i]);
        sum += m[i];
        under += m[i] > 1.f;
    }
    st.count = values.size();
    if (st.count + singular > 0) st.singular = double(singular) / double(st.count + singular);
    if (st.count == 0) return st;
    st.mean = sum / double(st.count);
    st.undersampled = double(under) / double(st.count);
    st.p50 = percentile(std::span(values), 50);
    st.p95 = percentile(std::span(values), 95);
    st.max = *std::max_element(values.begin(), values.end());
    return st;
}

TruthStats truthStats(std::span<const float> s, std::span<const uint8_t> occluded, std::span<const uint8_t> receiver) {
    requireSameSize(s.size(), occluded.size(), "truthStats");
    requireSameSize(s.size(), receiver.size(), "truthStats");
    TruthStats st;
    size_t falseShadow = 0, falseLit = 0;
    double absSum = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (!receiver[i]) continue;
        if (!std::isfinite(s[i])) {
            ++st.skipped;
            continue;
        }
        ++st.count;
        const bool lit = s[i] >= 0.5f; // the rendered verdict; docs/design.md §4 thresholds at 0.5
        const double truth = occluded[i] ? 0.0 : 1.0;
        falseShadow += !occluded[i] && !lit;
        falseLit += occluded[i] && lit;
        absSum += std::abs(double(s[i]) - truth);
    }
    if (st.count == 0) return st;
    const double n = double(st.count);
    st.falseShadow = double(falseShadow) / n;
    st.falseLit = double(falseLit) / n;
    st.meanAbs = absSum / n;
    return st;
}

double softMeanAbs(std::span<const float> s, std::span<const float> v, std::span<const uint8_t> receiver) {
    requireSameSize(s.size(), v.size(), "softMeanAbs");
    requireSameSize(s.size(), receiver.size(), "softMeanAbs");
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (!receiver[i] || !std::isfinite(s[i]) || !std::isfinite(v[i])) continue;
        sum += std::abs(double(s[i]) - double(v[i]));
        ++count;
    }
    return count ? sum / double(count) : std::numeric_limits<double>::quiet_NaN();
}

double texelUtilization(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver, int split, int resolution) {
    // A bit per texel (32 MiB at 16384²) rather than texelUsageMask's byte per texel.
    validateTexelInputs(aux, receiver, resolution);
    std::vector<bool> used;
    size_t count = 0;
    bool sized = false;
    forEachUsedTexel(aux, receiver, split, resolution, [&](size_t t) {
        if (!sized) { // allocate only once a pixel hits the map: an unused split costs nothing
            used.assign(size_t(resolution) * size_t(resolution), false);
            sized = true;
        }
        if (!used[t]) {
            used[t] = true;
            ++count;
        }
    });
    return double(count) / (double(resolution) * double(resolution));
}

std::vector<uint8_t> texelUsageMask(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver, int split,
                                    int resolution) {
    validateTexelInputs(aux, receiver, resolution); // before allocating resolution² bytes
    std::vector<uint8_t> mask(size_t(resolution) * size_t(resolution), 0);
    forEachUsedTexel(aux, receiver, split, resolution, [&](size_t t) { mask[t] = 1; });
    return mask;
}

} // namespace geometry::analysis
