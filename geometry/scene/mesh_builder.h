#pragma once
// Appends simple solids to one mesh; the built-in scenes are made of these.
#include "geometry/scene/scene.h"

#include <span>

namespace geometry::scene {

/// Two unit vectors u, v such that (u, v, w) is right-handed, for the unit vector `w`.
void orthonormalBasis(const glm::vec3& w, glm::vec3& u, glm::vec3& v);

class MeshBuilder {
public:
    MeshBuilder(std::string name, glm::vec3 color);

    /// Axis-aligned box, flat shaded (12 triangles).
    void addBox(const glm::vec3& center, const glm::vec3& halfExtents);
    /// Box of square cross-section `halfWidth` from a to b (a bar/beam), flat shaded (12 triangles).
    void addBeam(const glm::vec3& a, const glm::vec3& b, float halfWidth);
    /// Cylinder of `radius` from a to b with `segments` sides (≥ 3), smooth sides;
    /// caps add 2·segments triangles. 2·segments side triangles.
    void addCylinder(const glm::vec3& a, const glm::vec3& b, float radius, int segments, bool caps = true);
    /// Horizontal square grid at height y, `cells`×`cells` quads, facing +y.
    void addGroundGrid(const glm::vec3& center, float size, int cells);
    /// Tube of `radius` swept along `path` (a smooth centreline, e.g. sampled arcs): a ring of
    /// `segments` (≥ 3) shared, smoothly shaded vertices at every point, perpendicular to the path
    /// there, twisting no more than the path does. Sharp corners pinch: make bends with addTorus.
    void addTube(std::span<const glm::vec3> path, float radius, int segments, bool caps = true);
    /// Torus section (a pipe elbow, a handwheel rim): a tube of `minorRadius` along the arc of
    /// `majorRadius` about `axis` through `center`, from the unit direction `start` (⊥ axis)
    /// turning `sweepRad` counter-clockwise about `axis`, in `majorSegments` steps. A full turn
    /// (sweepRad ≥ 2π) closes on itself and has no caps.
    void addTorus(const glm::vec3& center, const glm::vec3& axis, const glm::vec3& start, float majorRadius,
                  float minorRadius, float sweepRad, int majorSegments, int minorSegments, bool caps = true);
    /// Hollow cylinder from a to b (a flange, a collar): smooth outer side and bore, flat annular
    /// ends; a closed solid of 8·segments triangles.
    void addRing(const glm::vec3& a, const glm::vec3& b, float innerRadius, float outerRadius, int segments);

    // Triangles the helpers above add, so that a scene can solve its detail for a triangle budget
    // before building anything.
    [[nodiscard]] static size_t cylinderTriangles(int segments, bool caps);
    [[nodiscard]] static size_t tubeTriangles(size_t pathPoints, int segments, bool caps);
    [[nodiscard]] static size_t torusTriangles(float sweepRad, int majorSegments, int minorSegments, bool caps);
    [[nodiscard]] static size_t ringTriangles(int segments);

    [[nodiscard]] size_t triangleCount() const noexcept { return mesh_.indices.size() / 3; }
    /// Finishes the mesh: chunks it (chunkMesh) and hands it over.
    [[nodiscard]] Mesh build();

private:
    void addFace(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3);
    friend void addHexahedron(MeshBuilder& mb, const glm::vec3 c[8]);
    bool openSurfaces_ = false;
    uint32_t addVertex(const glm::vec3& p, const glm::vec3& n);
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    void addSweep(std::span<const glm::vec3> centers, std::span<const glm::vec3> tangents, float radius, int segments,
                  bool closedLoop, bool caps);
    void addDisc(const glm::vec3& center, const glm::vec3& normal, const glm::vec3& u, float innerRadius,
                 float outerRadius, int segments);
    Mesh mesh_;
};

} // namespace geometry::scene
