#include "geometry/scene/mesh_builder.h"

#include "geometry/scene/chunking.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

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

/// Two unit vectors perpendicular to the unit vector `w`.
static void orthonormalBasis(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
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

Mesh MeshBuilder::build() {
    Mesh m = std::move(mesh_);
    m.twoSided = openSurfaces_;
    openSurfaces_ = false;
    chunkMesh(m);
    mesh_ = Mesh{};
    return m;
}

} // namespace geometry::scene
