#include "geometry/scene/mesh_builder.h"

#include "geometry/scene/chunking.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <vector>

namespace geometry::scene {

MeshBuilder::MeshBuilder(std::string name, glm::vec3 color) {
    mesh_.name = std::move(name);
    mesh_.color = color;
}

uint32_t MeshBuilder::addVertex(const glm::vec3& p, const glm::vec3& n) {
    mesh_.positions.push_back(p);
    mesh_.normals.push_back(n);
    return static_cast<uint32_t>(mesh_.positions.size() - 1);
}

void MeshBuilder::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
}

void MeshBuilder::addFace(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3) {
    glm::vec3 n = glm::cross(p1 - p0, p3 - p0);
    const float len = glm::length(n);
    n = len > 0.f ? n / len : glm::vec3(0, 1, 0);
    const uint32_t a = addVertex(p0, n), b = addVertex(p1, n), c = addVertex(p2, n), d = addVertex(p3, n);
    addTriangle(a, b, c);
    addTriangle(a, c, d);
}

void orthonormalBasis(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(w.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u = glm::normalize(glm::cross(helper, w));
    v = glm::cross(w, u);
}

/// Hexahedron from 8 corners indexed as bits (x: 1, y: 2, z: 4) of a local frame.
void addHexahedron(MeshBuilder& mb, const glm::vec3 c[8]) {
    // Faces wound counter-clockwise seen from outside (for a right-handed frame).
    mb.addFace(c[0], c[4], c[6], c[2]); // -x
    mb.addFace(c[1], c[3], c[7], c[5]); // +x
    mb.addFace(c[0], c[1], c[5], c[4]); // -y
    mb.addFace(c[2], c[6], c[7], c[3]); // +y
    mb.addFace(c[0], c[2], c[3], c[1]); // -z
    mb.addFace(c[4], c[5], c[7], c[6]); // +z
}

void MeshBuilder::addBox(const glm::vec3& center, const glm::vec3& h) {
    glm::vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = center + glm::vec3((i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z);
    addHexahedron(*this, c);
}

void MeshBuilder::addBeam(const glm::vec3& a, const glm::vec3& b, float halfWidth) {
    const glm::vec3 d = b - a;
    const float len = glm::length(d);
    if (!(len > 0.f)) return;
    glm::vec3 u, v;
    const glm::vec3 w = d / len;
    orthonormalBasis(w, u, v);
    glm::vec3 c[8];
    // Local frame (u, v, w) is right-handed, so the hexahedron winding holds.
    for (int i = 0; i < 8; ++i)
        c[i] = ((i & 4) ? b : a) + ((i & 1) ? halfWidth : -halfWidth) * u + ((i & 2) ? halfWidth : -halfWidth) * v;
    addHexahedron(*this, c);
}

void MeshBuilder::addCylinder(const glm::vec3& a, const glm::vec3& b, float radius, int segments, bool caps) {
    const glm::vec3 d = b - a;
    const float len = glm::length(d);
    if (!(len > 0.f) || !(radius > 0.f)) return;
    segments = std::max(segments, 3);
    const glm::vec3 w = d / len;
    glm::vec3 u, v;
    orthonormalBasis(w, u, v);
    const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
    for (int s = 0; s < segments; ++s) {
        const float t = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
        const glm::vec3 n = std::cos(t) * u + std::sin(t) * v;
        addVertex(a + radius * n, n);
        addVertex(b + radius * n, n);
    }
    for (int s = 0; s < segments; ++s) {
        const uint32_t i0 = base + 2 * s, i1 = base + 2 * ((s + 1) % segments);
        addTriangle(i0, i1, i1 + 1);
        addTriangle(i0, i1 + 1, i0 + 1);
    }
    if (!caps) return;
    for (int end = 0; end < 2; ++end) {
        const glm::vec3 n = end ? w : -w;
        const glm::vec3 centre = end ? b : a;
        const uint32_t c = addVertex(centre, n);
        const uint32_t ring = static_cast<uint32_t>(mesh_.positions.size());
        for (int s = 0; s < segments; ++s) {
            const float t = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
            addVertex(centre + radius * (std::cos(t) * u + std::sin(t) * v), n);
        }
        for (int s = 0; s < segments; ++s) {
            const uint32_t p = ring + s, q = ring + (s + 1) % segments;
            if (end) addTriangle(c, p, q);
            else addTriangle(c, q, p);
        }
    }
}

void MeshBuilder::addGroundGrid(const glm::vec3& center, float size, int cells) {
    openSurfaces_ = true;
    cells = std::max(cells, 1);
    const float step = size / static_cast<float>(cells);
    const glm::vec3 origin = center - glm::vec3(0.5f * size, 0.f, 0.5f * size);
    const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) addVertex(origin + glm::vec3(i * step, 0.f, j * step), {0, 1, 0});
    const uint32_t row = static_cast<uint32_t>(cells + 1);
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const uint32_t p = base + j * row + i;
            // Counter-clockwise seen from +y: (x,z) → (x,z+1) → (x+1,z+1).
            addTriangle(p, p + row, p + row + 1);
            addTriangle(p, p + row + 1, p + 1);
        }
}

/// Unit circle in `segments` steps: (cos, sin) of each step's angle, computed once per solid.
static std::vector<glm::vec2> unitCircle(int segments) {
    std::vector<glm::vec2> c(static_cast<size_t>(segments));
    for (int s = 0; s < segments; ++s) {
        const float t = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
        c[static_cast<size_t>(s)] = {std::cos(t), std::sin(t)};
    }
    return c;
}

/// `u` carried from tangent t0 to t1 by the smallest rotation between them (Rodrigues): along a
/// planar arc this is exact, so a full torus closes without a twist at its seam.
static glm::vec3 transportFrame(const glm::vec3& u, const glm::vec3& t0, const glm::vec3& t1) {
    const glm::vec3 k = glm::cross(t0, t1);
    const float s2 = glm::dot(k, k), c = glm::dot(t0, t1);
    glm::vec3 r = s2 > 1e-12f ? u * c + glm::cross(k, u) + k * (glm::dot(k, u) * (1.f - c) / s2) : u;
    r -= glm::dot(r, t1) * t1; // keeps the frame orthogonal despite rounding
    const float len = glm::length(r);
    if (len > 1e-6f) return r / len;
    glm::vec3 v;
    orthonormalBasis(t1, r, v);
    return r;
}

void MeshBuilder::addDisc(const glm::vec3& center, const glm::vec3& normal, const glm::vec3& u, float innerRadius,
                          float outerRadius, int segments) {
    // (u, v, normal) is right-handed, so increasing angles run counter-clockwise seen from the front.
    const glm::vec3 v = glm::cross(normal, u);
    const std::vector<glm::vec2> circle = unitCircle(segments);
    const auto ring = [&](float radius) {
        const uint32_t first = static_cast<uint32_t>(mesh_.positions.size());
        for (const glm::vec2& cs : circle) addVertex(center + radius * (cs.x * u + cs.y * v), normal);
        return first;
    };
    const uint32_t outer = ring(outerRadius);
    if (innerRadius > 0.f) {
        const uint32_t inner = ring(innerRadius);
        for (int s = 0; s < segments; ++s) {
            const uint32_t next = static_cast<uint32_t>((s + 1) % segments);
            addTriangle(inner + s, outer + s, outer + next);
            addTriangle(inner + s, outer + next, inner + next);
        }
        return;
    }
    const uint32_t c = addVertex(center, normal);
    for (int s = 0; s < segments; ++s) addTriangle(c, outer + s, outer + static_cast<uint32_t>((s + 1) % segments));
}

void MeshBuilder::addSweep(std::span<const glm::vec3> centers, std::span<const glm::vec3> tangents, float radius,
                           int segments, bool closedLoop, bool caps) {
    const std::vector<glm::vec2> circle = unitCircle(segments);
    const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
    const uint32_t seg = static_cast<uint32_t>(segments);
    glm::vec3 u, v, firstU;
    orthonormalBasis(tangents[0], u, v);
    firstU = u;
    for (size_t i = 0; i < centers.size(); ++i) {
        if (i > 0) u = transportFrame(u, tangents[i - 1], tangents[i]);
        v = glm::cross(tangents[i], u); // (u, v, tangent) right-handed: outward-facing triangles below
        for (const glm::vec2& cs : circle) {
            const glm::vec3 n = cs.x * u + cs.y * v;
            addVertex(centers[i] + radius * n, n);
        }
    }
    const uint32_t rings = static_cast<uint32_t>(centers.size());
    for (uint32_t i = 0; i + (closedLoop ? 0 : 1) < rings; ++i) {
        const uint32_t a = base + i * seg, b = base + ((i + 1) % rings) * seg;
        for (uint32_t s = 0; s < seg; ++s) {
            const uint32_t next = (s + 1) % seg;
            addTriangle(a + s, a + next, b + next);
            addTriangle(a + s, b + next, b + s);
        }
    }
    if (closedLoop || !caps) return;
    addDisc(centers.front(), -tangents.front(), firstU, 0.f, radius, segments);
    addDisc(centers.back(), tangents.back(), u, 0.f, radius, segments);
}

void MeshBuilder::addTube(std::span<const glm::vec3> path, float radius, int segments, bool caps) {
    if (!(radius > 0.f)) return;
    std::vector<glm::vec3> points;
    points.reserve(path.size());
    for (const glm::vec3& p : path)
        if (points.empty() || glm::length(p - points.back()) > 0.f) points.push_back(p);
    if (points.size() < 2) return;
    // A ring's plane bisects the path's turn at its point.
    std::vector<glm::vec3> tangents(points.size());
    glm::vec3 before = glm::normalize(points[1] - points[0]);
    tangents[0] = before;
    for (size_t i = 1; i + 1 < points.size(); ++i) {
        const glm::vec3 after = glm::normalize(points[i + 1] - points[i]);
        const glm::vec3 bisector = before + after;
        tangents[i] = glm::length(bisector) > 1e-6f ? glm::normalize(bisector) : after;
        before = after;
    }
    tangents.back() = before;
    addSweep(points, tangents, radius, std::max(segments, 3), false, caps);
}

void MeshBuilder::addTorus(const glm::vec3& center, const glm::vec3& axis, const glm::vec3& start, float majorRadius,
                           float minorRadius, float sweepRad, int majorSegments, int minorSegments, bool caps) {
    if (!(majorRadius > 0.f) || !(minorRadius > 0.f) || !(sweepRad > 0.f)) return;
    const glm::vec3 a = glm::normalize(axis);
    const glm::vec3 s = glm::normalize(start - glm::dot(start, a) * a);
    const glm::vec3 w = glm::cross(a, s); // direction of travel at the start
    const bool fullTurn = sweepRad >= glm::two_pi<float>();
    majorSegments = std::max(majorSegments, fullTurn ? 3 : 1);
    const float step = (fullTurn ? glm::two_pi<float>() : sweepRad) / static_cast<float>(majorSegments);
    const size_t rings = static_cast<size_t>(majorSegments) + (fullTurn ? 0 : 1);
    std::vector<glm::vec3> centers(rings), tangents(rings);
    for (size_t k = 0; k < rings; ++k) {
        const float phi = step * static_cast<float>(k);
        const float c = std::cos(phi), sn = std::sin(phi);
        centers[k] = center + majorRadius * (c * s + sn * w);
        tangents[k] = c * w - sn * s;
    }
    addSweep(centers, tangents, minorRadius, std::max(minorSegments, 3), fullTurn, caps);
}

void MeshBuilder::addRing(const glm::vec3& a, const glm::vec3& b, float innerRadius, float outerRadius, int segments) {
    const glm::vec3 d = b - a;
    const float len = glm::length(d);
    if (!(len > 0.f) || !(innerRadius > 0.f) || !(outerRadius > innerRadius)) return;
    segments = std::max(segments, 3);
    const glm::vec3 w = d / len;
    glm::vec3 u, v;
    orthonormalBasis(w, u, v);
    const std::vector<glm::vec2> circle = unitCircle(segments);
    const uint32_t seg = static_cast<uint32_t>(segments);
    // Outer side faces out, the bore faces the axis: its winding is the outer side's reversed.
    for (int side = 0; side < 2; ++side) {
        const float radius = side == 0 ? outerRadius : innerRadius;
        const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
        for (const glm::vec2& cs : circle) {
            const glm::vec3 n = cs.x * u + cs.y * v;
            addVertex(a + radius * n, side == 0 ? n : -n);
            addVertex(b + radius * n, side == 0 ? n : -n);
        }
        for (uint32_t s = 0; s < seg; ++s) {
            const uint32_t i0 = base + 2 * s, i1 = base + 2 * ((s + 1) % seg);
            if (side == 0) {
                addTriangle(i0, i1, i1 + 1);
                addTriangle(i0, i1 + 1, i0 + 1);
            } else {
                addTriangle(i0, i1 + 1, i1);
                addTriangle(i0, i0 + 1, i1 + 1);
            }
        }
    }
    addDisc(a, -w, u, innerRadius, outerRadius, segments);
    addDisc(b, w, u, innerRadius, outerRadius, segments);
}

size_t MeshBuilder::cylinderTriangles(int segments, bool caps) {
    return static_cast<size_t>(std::max(segments, 3)) * (caps ? 4 : 2);
}

size_t MeshBuilder::tubeTriangles(size_t pathPoints, int segments, bool caps) {
    if (pathPoints < 2) return 0;
    const size_t seg = static_cast<size_t>(std::max(segments, 3));
    return 2 * seg * (pathPoints - 1) + (caps ? 2 * seg : 0);
}

size_t MeshBuilder::torusTriangles(float sweepRad, int majorSegments, int minorSegments, bool caps) {
    const bool fullTurn = sweepRad >= glm::two_pi<float>();
    const size_t major = static_cast<size_t>(std::max(majorSegments, fullTurn ? 3 : 1));
    const size_t minor = static_cast<size_t>(std::max(minorSegments, 3));
    return 2 * minor * major + (caps && !fullTurn ? 2 * minor : 0);
}

size_t MeshBuilder::ringTriangles(int segments) { return 8 * static_cast<size_t>(std::max(segments, 3)); }

Mesh MeshBuilder::build() {
    Mesh m = std::move(mesh_);
    m.twoSided = openSurfaces_;
    openSurfaces_ = false;
    chunkMesh(m);
    mesh_ = Mesh{};
    return m;
}

} // namespace geometry::scene
