// Ear clipping after mapbox earcut's rules: a doubly linked ring of corners projected to 2D
// (counter-clockwise), an ear is a convex corner whose triangle holds no reflex corner of the
// rest (inclusively, so touching the triangle counts, except at the ear's first corner where a
// ring's bridge repeats it). When no ear is left, duplicate and collinear corners are removed
// and the search is tried once more; then the rest is fanned and counted.
//
// Index
//   [SECTION] Plane and projection ....... newellNormal, diameter, projectToPlane
//   [SECTION] Ear clipping ............... Ring, cross, isEar, filterPoints, clipEars
//   [SECTION] Triangulating a polygon .... triangulatePolygon, appendPolygon, addPolygonCounts
#include "geometry/io/polygon_triangulation.h"

#include "geometry/io/model_loader.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace geometry::io {

namespace {

using Tri = std::array<uint32_t, 3>;

// Ear clipping costs O(n²) (O(n³) at worst); larger faces are fanned and counted as fallbacks.
constexpr size_t kMaxEarClipCorners = 4096;
// The worst case is real (a thin spiral band has ears only at its two ends, so every clip walks
// the ring testing corners against the ring), and a hostile file can ask for it. Work is capped
// at this many steps per corner; the rest of the face is then fanned and counted as a fallback.
// A spiral band of 1000 corners over 100 turns needs 4.2·10⁴ steps per corner; 4000 corners
// would need 6.2·10⁵ (2.5·10⁹ in all, 6 s) and are fanned (tests/test_polygon_loading.cpp).
constexpr uint64_t kEarClipStepsPerCorner = 65536;
constexpr double kNonPlanarFraction = 1e-3;

// ---- [SECTION] Plane and projection ---------------------------------------------------------

/// Newell's method: the area-weighted normal, robust for concave and slightly warped faces.
glm::dvec3 newellNormal(const std::vector<glm::dvec3>& p) {
    glm::dvec3 n(0.0);
    for (size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3& a = p[i];
        const glm::dvec3& b = p[(i + 1) % p.size()];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

/// Largest distance between two corners (exact for small faces, the bounds' diagonal above:
/// at most √3 times more, which only makes the planarity test looser).
double diameter(const std::vector<glm::dvec3>& p) {
    if (p.size() <= 256) {
        double d2 = 0;
        for (size_t i = 0; i < p.size(); ++i)
            for (size_t j = i + 1; j < p.size(); ++j) d2 = std::max(d2, glm::dot(p[i] - p[j], p[i] - p[j]));
        return std::sqrt(d2);
    }
    glm::dvec3 lo = p[0], hi = p[0];
    for (const glm::dvec3& q : p) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    return glm::length(hi - lo);
}

/// Coordinates in the plane through `origin` with unit normal `n`, in a basis (u, v) with
/// u × v = n, so that the polygon's winding is counter-clockwise in 2D.
std::vector<glm::dvec2> projectToPlane(const std::vector<glm::dvec3>& p, const glm::dvec3& origin,
                                       const glm::dvec3& n) {
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 v = glm::cross(n, u);
    std::vector<glm::dvec2> out(p.size());
    for (size_t i = 0; i < p.size(); ++i) out[i] = {glm::dot(p[i] - origin, u), glm::dot(p[i] - origin, v)};
    return out;
}

// ---- [SECTION] Ear clipping -----------------------------------------------------------------

/// The corners still to clip, as a doubly linked ring over positions 0..n-1, and the work left.
struct Ring {
    const std::vector<glm::dvec2>& pt;
    std::vector<uint32_t> prev, next;
    size_t size;
    uint64_t stepsLeft; // corners visited by isEar before the face is given up and fanned

    explicit Ring(const std::vector<glm::dvec2>& points)
        : pt(points), prev(points.size()), next(points.size()), stepsLeft(kEarClipStepsPerCorner * points.size()) {
        size = points.size();
        for (uint32_t i = 0; i < size; ++i) {
            prev[i] = static_cast<uint32_t>((i + size - 1) % size);
            next[i] = static_cast<uint32_t>((i + 1) % size);
        }
    }
    void remove(uint32_t i) {
        next[prev[i]] = next[i];
        prev[next[i]] = prev[i];
        --size;
    }
};

/// Twice the signed area of (a, b, c): positive when counter-clockwise.
double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool inTriangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

/// A convex corner whose triangle holds no reflex (or flat) corner of the rest of the ring.
/// Each corner visited spends one step of the ring's budget (checked by the caller).
bool isEar(Ring& r, uint32_t ear) {
    const glm::dvec2 &a = r.pt[r.prev[ear]], &b = r.pt[ear], &c = r.pt[r.next[ear]];
    if (cross(a, b, c) <= 0) return false; // reflex or flat
    const glm::dvec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    for (uint32_t p = r.next[r.next[ear]]; p != r.prev[ear]; p = r.next[p]) {
        r.stepsLeft -= r.stepsLeft > 0;
        const glm::dvec2& q = r.pt[p];
        if (q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y || q == a) continue;
        if (inTriangle(a, b, c, q) && cross(r.pt[r.prev[p]], q, r.pt[r.next[p]]) <= 0) return false;
    }
    return true;
}

/// Removes corners equal to the next one and flat corners (collinear, or zero-width spikes).
/// Returns a corner still in the ring.
uint32_t filterPoints(Ring& r, uint32_t start) {
    uint32_t p = start, end = start;
    while (r.size > 3) {
        const uint32_t nx = r.next[p];
        if (r.pt[p] == r.pt[nx] || cross(r.pt[r.prev[p]], r.pt[p], r.pt[nx]) == 0) {
            const uint32_t pv = r.prev[p];
            r.remove(p);
            p = end = pv;
            continue;
        }
        p = nx;
        if (p == end) break;
    }
    return p;
}

/// Clips ears into `out` (as positions in the ring); false when it got stuck, or ran out of
/// budget, with corners left.
bool clipEars(Ring& r, uint32_t ear, std::vector<Tri>& out) {
    for (int pass = 0; pass < 2; ++pass) {
        uint32_t stop = ear;
        while (r.size > 3) {
            if (r.stepsLeft == 0) return false;
            const uint32_t pv = r.prev[ear], nx = r.next[ear];
            if (isEar(r, ear)) {
                out.push_back({pv, ear, nx});
                r.remove(ear);
                ear = stop = r.next[nx];
                continue;
            }
            ear = nx;
            if (ear == stop) break;
        }
        if (r.size <= 3) break;
        ear = filterPoints(r, ear); // then once more: dropping flat corners can free an ear
    }
    if (r.size == 3) {
        const uint32_t a = r.prev[ear], c = r.next[ear];
        if (cross(r.pt[a], r.pt[ear], r.pt[c]) != 0) out.push_back({a, ear, c}); // flat leftovers add nothing
        return true;
    }
    return r.size < 3;
}

} // namespace

// ---- [SECTION] Triangulating a polygon ------------------------------------------------------

std::vector<Tri> triangulatePolygon(std::span<const glm::vec3> points, std::span<const uint32_t> indices,
                                    PolygonStats& stats) {
    const size_t n = indices.size();
    if (n < 3) return {};
    if (n == 3) return {Tri{indices[0], indices[1], indices[2]}};
    ++stats.polygons;
    std::vector<glm::dvec3> p(n);
    glm::dvec3 centroid(0.0);
    for (size_t i = 0; i < n; ++i) centroid += p[i] = glm::dvec3(points[indices[i]]);
    centroid /= static_cast<double>(n);
    auto fan = [&](std::vector<Tri> tris, const std::vector<uint32_t>& rest) {
        ++stats.fallbacks;
        for (size_t i = 2; i < rest.size(); ++i) tris.push_back({rest[0], rest[i - 1], rest[i]});
        return tris;
    };
    std::vector<uint32_t> all(indices.begin(), indices.end());
    const glm::dvec3 normal = newellNormal(p);
    const double len = glm::length(normal);
    if (!(len > 0) || !std::isfinite(len)) return fan({}, all); // no area or NaN: nothing to clip

    const glm::dvec3 unit = normal / len;
    double offPlane = 0;
    for (const glm::dvec3& q : p) offPlane = std::max(offPlane, std::abs(glm::dot(q - centroid, unit)));
    if (offPlane > kNonPlanarFraction * diameter(p)) ++stats.nonPlanar;
    if (n > kMaxEarClipCorners) return fan({}, all);

    const std::vector<glm::dvec2> flat = projectToPlane(p, centroid, unit);
    Ring ring(flat);
    std::vector<Tri> local;
    local.reserve(n - 2);
    const bool done = clipEars(ring, 0, local);
    std::vector<Tri> tris;
    tris.reserve(n - 2);
    for (const Tri& t : local) tris.push_back({indices[t[0]], indices[t[1]], indices[t[2]]});
    if (done) return tris;
    std::vector<uint32_t> rest; // the stuck ring, in order, from any corner still in it
    uint32_t start = 0;
    while (ring.next[ring.prev[start]] != start) ++start; // first corner not removed
    for (uint32_t q = start;;) {
        rest.push_back(indices[q]);
        q = ring.next[q];
        if (q == start) break;
    }
    return fan(std::move(tris), rest);
}

void appendPolygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                   std::vector<uint32_t>& indices, PolygonStats& stats) {
    if (corners.size() == 3) {
        indices.insert(indices.end(), corners.begin(), corners.end());
        return;
    }
    for (const Tri& tri : triangulatePolygon(positions, corners, stats))
        indices.insert(indices.end(), tri.begin(), tri.end());
}

void addPolygonCounts(const PolygonStats& stats, CleanupReport& report) {
    report.polygonsTriangulated += stats.polygons;
    report.nonPlanarFaces += stats.nonPlanar;
    report.earClipFallbacks += stats.fallbacks;
}

} // namespace geometry::io
