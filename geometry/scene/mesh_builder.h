#pragma once
// Appends simple solids to one mesh; the built-in scenes are made of these.
#include "geometry/scene/scene.h"

namespace geometry::scene {

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

    [[nodiscard]] size_t triangleCount() const noexcept { return mesh_.indices.size() / 3; }
    /// Finishes the mesh: chunks it (chunkMesh) and hands it over.
    [[nodiscard]] Mesh build();

private:
    void addFace(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3);
    friend void addHexahedron(MeshBuilder& mb, const glm::vec3 c[8]);
    bool openSurfaces_ = false;
    uint32_t addVertex(const glm::vec3& p, const glm::vec3& n);
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    Mesh mesh_;
};

} // namespace geometry::scene
