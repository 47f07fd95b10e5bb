#include "geometry/lod/lod_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace geometry::lod::detail {

namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) noexcept {
    while (parent[v] != v) v = parent[v] = parent[parent[v]]; // path halving
    return v;
}

float extentAlong(std::span<const glm::vec3> points, const glm::dvec3& axis) noexcept {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const glm::vec3& p : points) {
        const double d = glm::dot(glm::dvec3(p), axis);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    return static_cast<float>(hi - lo);
}

} // namespace

std::vector<uint32_t> connectedParts(size_t vertexCount, std::span<const uint32_t> triangles) {
    std::vector<uint32_t> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3)
        for (int k = 1; k < 3; ++k) {
            const uint32_t a = findRoot(parent, triangles[t]), b = findRoot(parent, triangles[t + k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<uint32_t> part(vertexCount);
    std::vector<uint32_t> number(vertexCount, UINT32_MAX);
    uint32_t parts = 0;
    for (uint32_t v = 0; v < vertexCount; ++v) {
        const uint32_t r = findRoot(parent, v);
        if (number[r] == UINT32_MAX) number[r] = parts++;
        part[v] = number[r];
    }
    return part;
}

glm::dmat3 symmetricEigen(const glm::dmat3& input, glm::dvec3& values) noexcept {
    glm::dmat3 a = input, v(1.0);
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-30 * diag)) break; // converged (or NaN)
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.) continue;
                // The rotation in the (p, q) plane that zeroes a[p][q] (Golub & Van Loan 8.4).
                const double theta = (a[q][q] - a[p][p]) / (2. * a[p][q]);
                const double t = (theta >= 0. ? 1. : -1.) / (std::abs(theta) + std::sqrt(theta * theta + 1.));
                const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
                glm::dmat3 r(1.0);
                r[p][p] = c, r[q][q] = c, r[q][p] = s, r[p][q] = -s;
                a = glm::transpose(r) * a * r;
                v = v * r;
            }
    }
    values = {a[0][0], a[1][1], a[2][2]};
    return v;
}

float partThickness(std::span<const glm::vec3> points) noexcept {
    if (points.size() < 2) return 0.f;
    glm::dvec3 mean(0.);
    for (const glm::vec3& p : points) mean += glm::dvec3(p);
    mean /= double(points.size());
    if (std::isnan(glm::dot(mean, mean))) return std::numeric_limits<float>::quiet_NaN();
    glm::dmat3 cov(0.);
    for (const glm::vec3& p : points) {
        const glm::dvec3 d = glm::dvec3(p) - mean;
        cov += glm::outerProduct(d, d);
    }
    glm::dvec3 values;
    const glm::dmat3 axes = symmetricEigen(cov, values);
    std::array<float, 3> principal{}; // extents along the principal axes, by ascending variance
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
    for (int i = 0; i < 3; ++i) {
        const double len = glm::length(axes[order[i]]);
        principal[i] = len > 0. ? extentAlong(points, axes[order[i]] / len) : 0.f;
    }
    // Flat within rounding (a sheet, even one far from the origin or turned by a transform).
    if (principal[0] <= 1e-4f * principal[1]) return principal[1];
    float thinnest = std::min({principal[0], principal[1], principal[2]});
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 unit(0.);
        unit[i] = 1.;
        thinnest = std::min(thinnest, extentAlong(points, unit));
    }
    return thinnest;
}

float largestStretch(const glm::mat4& m) noexcept {
    const glm::dmat3 a(m);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(glm::dot(a[c], a[c]))) return std::numeric_limits<float>::quiet_NaN();
    glm::dvec3 values;
    (void)symmetricEigen(glm::transpose(a) * a, values); // eigenvalues of AᵀA: squared singular values
    const double largest = std::max({values.x, values.y, values.z, 0.});
    return static_cast<float>(std::sqrt(largest));
}

} // namespace geometry::lod::detail
