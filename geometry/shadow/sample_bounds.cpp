#include "geometry/shadow/sample_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geometry::shadow {

std::array<glm::vec3, kSampleDirections> sampleDirections(const glm::vec3& l) noexcept {
    const glm::vec3 helper = std::abs(l.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 e1 = glm::normalize(glm::cross(l, helper)), e2 = glm::cross(l, e1);
    const float h = std::sqrt(0.5f);
    return {e1, h * (e1 + e2), e2, h * (e2 - e1), l};
}

int sampleBin(double z, double n, double f) noexcept {
    if (!(z > n) || !(f > n) || !(n > 0.0)) return 0; // NaN and below n: the first bin
    const double t = std::log(z / n) / std::log(f / n);
    return std::clamp(int(std::floor(t * kSampleBins)), 0, kSampleBins - 1);
}

double sampleBinStart(int i, double n, double f) noexcept { return n * std::pow(f / n, double(i) / kSampleBins); }

std::vector<double> sampleQuantiles(const SampleBounds& bounds, double a, double b, int k) {
    std::vector<double> out;
    if (bounds.empty() || k < 2 || !(b > a)) return out;
    const int first = sampleBin(a, bounds.n, bounds.f), last = sampleBin(b, bounds.n, bounds.f);
    uint64_t total = 0;
    for (int i = first; i <= last; ++i) total += bounds.bins[size_t(i)].count;
    if (total == 0) return out;
    uint64_t below = 0;
    int bin = first;
    for (int q = 1; q < k; ++q) {
        const double want = double(total) * q / k;
        while (bin < last && double(below + bounds.bins[size_t(bin)].count) < want)
            below += bounds.bins[size_t(bin++)].count;
        const double count = std::max<double>(bounds.bins[size_t(bin)].count, 1.0);
        const double t = std::clamp((want - double(below)) / count, 0.0, 1.0);
        const double lo = std::max(a, sampleBinStart(bin, bounds.n, bounds.f));
        const double hi = std::min(b, sampleBinStart(bin + 1, bounds.n, bounds.f));
        out.push_back(std::clamp(lo * std::pow(hi / lo, t), a, b));
    }
    for (size_t i = 1; i < out.size(); ++i) out[i] = std::max(out[i], out[i - 1]);
    return out;
}

SampleSlab samplesWithin(const SampleBounds& bounds, double a, double b, double margin) {
    SampleSlab out;
    if (bounds.empty() || !(b >= a)) return out;
    std::array<float, kSampleDirections> lo, hi;
    lo.fill(std::numeric_limits<float>::max());
    hi.fill(std::numeric_limits<float>::lowest());
    const int first = sampleBin(a, bounds.n, bounds.f), last = sampleBin(b, bounds.n, bounds.f);
    for (int i = first; i <= last; ++i) {
        const SampleBin& bin = bounds.bins[size_t(i)];
        if (bin.count == 0) continue;
        out.count += bin.count;
        for (int k = 0; k < kSampleDirections; ++k)
            lo[k] = std::min(lo[k], bin.lo[k]), hi[k] = std::max(hi[k], bin.hi[k]);
    }
    if (out.count == 0) return out;
    const auto d = sampleDirections(bounds.l);
    for (int k = 0; k < kSampleDirections; ++k) {
        // A relative margin, and one that float reconstruction of far samples cannot undercut.
        const float pad = float(margin) * (hi[k] - lo[k]) + 1e-5f * std::max(std::abs(lo[k]), std::abs(hi[k])) + 1e-4f;
        out.planes.push_back({d[k], -(hi[k] + pad)}); // d·x ≤ hi
        out.planes.push_back({-d[k], lo[k] - pad});   // d·x ≥ lo
    }
    return out;
}

SampleBounds reduceSamples(std::span<const glm::vec3> world, std::span<const float> viewDepth, float n, float f,
                           const glm::vec3& l) {
    SampleBounds out;
    out.n = n;
    out.f = f;
    out.l = l;
    out.bins.resize(kSampleBins);
    for (auto& bin : out.bins) {
        bin.lo.fill(std::numeric_limits<float>::max());
        bin.hi.fill(std::numeric_limits<float>::lowest());
    }
    out.zMin = std::numeric_limits<float>::max();
    out.zMax = std::numeric_limits<float>::lowest();
    const auto d = sampleDirections(l);
    for (size_t i = 0; i < std::min(world.size(), viewDepth.size()); ++i) {
        const float z = viewDepth[i];
        if (!std::isfinite(z) || !std::isfinite(world[i].x + world[i].y + world[i].z)) continue;
        SampleBin& bin = out.bins[size_t(sampleBin(z, n, f))];
        ++bin.count;
        for (int k = 0; k < kSampleDirections; ++k) {
            const float t = glm::dot(world[i], d[k]);
            bin.lo[k] = std::min(bin.lo[k], t);
            bin.hi[k] = std::max(bin.hi[k], t);
        }
        out.zMin = std::min(out.zMin, z);
        out.zMax = std::max(out.zMax, z);
        ++out.count;
    }
    if (out.count == 0) out.zMin = out.zMax = 0.f;
    return out;
}

} // namespace geometry::shadow
