#include "geometry/analysis/penumbra_width.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace geometry::analysis {

double diskEdgeVisibility(double x) noexcept {
    if (!(x > -1.0)) return x <= -1.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    if (x >= 1.0) return 1.0;
    return 0.5 + (x * std::sqrt(1.0 - x * x) + std::asin(x)) / std::numbers::pi;
}

PenumbraWidth penumbraWidth(std::span<const glm::vec3> positions, std::span<const float> litFraction,
                            std::span<const uint8_t> receiver, const glm::vec3& l, const std::array<glm::vec3, 2>& edge,
                            double angularDiameterRad) {
    if (litFraction.size() != positions.size() || receiver.size() != positions.size())
        throw std::invalid_argument("penumbraWidth: " + std::to_string(positions.size()) + " positions, " +
                                    std::to_string(litFraction.size()) + " lit fractions and " +
                                    std::to_string(receiver.size()) + " receiver flags");
    PenumbraWidth out;
    if (!(angularDiameterRad > 0.0) || !std::isfinite(angularDiameterRad)) return out;
    const glm::dvec3 L(l), a(edge[0]), b(edge[1]);
    const double lLength = glm::length(L), edgeLength = glm::length(b - a);
    if (!(lLength > 0.0) || !std::isfinite(lLength) || !(edgeLength > 0.0) || !std::isfinite(edgeLength)) return out;
    const glm::dvec3 toSun = -L / lLength, along = (b - a) / edgeLength;
    const glm::dvec3 across = glm::cross(toSun, along);
    const double acrossLength = glm::length(across); // sin of the angle between the light and the edge
    if (!(acrossLength > 1e-9)) return out;          // the edge points at the sun: it casts no line
    const glm::dvec3 side = across / acrossLength;
    const double cosine = glm::dot(toSun, along), denom = 1.0 - cosine * cosine;

    const double R = std::tan(0.5 * angularDiameterRad);
    const double lo = -kPenumbraSpan * R, du = 2.0 * kPenumbraSpan * R / double(kPenumbraBins);
    std::array<double, kPenumbraBins> sum{};
    std::array<size_t, kPenumbraBins> count{};
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3 p(positions[i]);
        const double f = litFraction[i];
        if (!receiver[i] || !std::isfinite(p.x + p.y + p.z) || !std::isfinite(f)) continue;
        // Closest approach of p + t·toSun and a + s·along (both unit): the usual two-line solution.
        const glm::dvec3 w = p - a;
        const double dw = glm::dot(toSun, w), ew = glm::dot(along, w);
        const double t = (cosine * ew - dw) / denom, s = (ew - cosine * dw) / denom;
        if (!(t > 0.0) || s < 0.1 * edgeLength || s > 0.9 * edgeLength) continue;
        const double d = glm::dot(p + t * toSun - (a + s * along), side);
        const double bin = std::floor((d / t - lo) / du);
        if (!(bin >= 0.0 && bin < double(kPenumbraBins))) continue;
        sum[size_t(bin)] += f;
        ++count[size_t(bin)];
        ++out.pixels;
    }
    out.fewestInBin = *std::min_element(count.begin(), count.end());
    out.reference = R * kDiskEdgeWidth;
    if (out.fewestInBin < kMinPixelsPerPenumbraBin) return out;
    double width = 0.0;
    for (int k = 0; k < kPenumbraBins; ++k) {
        const double mean = sum[size_t(k)] / double(count[size_t(k)]);
        width += 4.0 * mean * (1.0 - mean) * du;
    }
    out.width = width;
    out.error = width / out.reference - 1.0;
    return out;
}

} // namespace geometry::analysis
