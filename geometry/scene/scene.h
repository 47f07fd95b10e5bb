#pragma once
// The scene model: a flat list of meshes, one camera, one directional light. Nothing more
// (docs/design.md §2: "model no more of a scene than it needs").
#include "geometry/scene/aabb.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace geometry::scene {

/// A contiguous run of triangles in a mesh's index buffer, with world-space bounds, so that
/// shadow and eye passes can cull casters per split (docs/design.md §3.4).
struct TriangleRun {
    uint32_t firstTriangle = 0;
    uint32_t triangleCount = 0;
    Aabb bounds; // world space
};

/// The unit of culling and of caster level of detail (geometry/lod): a spatially coherent run.
/// Its parts, finer runs that tile it in order, let a pass that draws its original triangles
/// cull again where the chunk straddles the clip volume.
struct Chunk : TriangleRun {
    uint32_t firstPart = 0; // in Mesh::parts
    uint32_t partCount = 0; // 0: not subdivided
};

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions; // object space
    std::vector<glm::vec3> normals;   // object space, one per position
    std::vector<uint32_t> indices;    // triangles
    glm::vec3 color{0.7f};
    glm::mat4 transform{1.f};       // object → world
    std::vector<Chunk> chunks;      // filled by chunkMesh()
    std::vector<TriangleRun> parts; // the chunks' parts, chunk by chunk (chunkMesh())
    /// Holds open surfaces (quads, grids) that must cast from both faces. Solids cast from their
    /// faces towards the light alone, which halves shadow-pass rasterization.
    bool twoSided = true;

    [[nodiscard]] size_t triangleCount() const noexcept { return indices.size() / 3; }
    [[nodiscard]] Aabb worldBounds() const noexcept;
};

struct Camera {
    glm::vec3 eye{0.f, 2.f, 10.f};
    glm::vec3 target{0.f};
    glm::vec3 up{0.f, 1.f, 0.f};
    float fovYDeg = 60.f; // full vertical field of view (φ = fovY/2)
    float near = 0.5f;    // n
    float far = 1000.f;   // f
    [[nodiscard]] bool operator==(const Camera&) const = default;

    [[nodiscard]] glm::vec3 viewDir() const noexcept; // v, unit
    [[nodiscard]] glm::mat4 view() const noexcept;
    [[nodiscard]] glm::mat4 projection(float aspect) const noexcept;
};

/// Directional light; `direction` is l, pointing from the light into the scene.
struct DirectionalLight {
    glm::vec3 direction{-0.4f, -1.f, -0.3f};
    [[nodiscard]] glm::vec3 l() const noexcept;
};

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    Camera camera;
    DirectionalLight light;
    /// A straight occluder edge (two distinct points, world space) whose shadow the truth's
    /// penumbra-width metric measures (docs/design.md §4 "Soft truth"); none by default.
    std::optional<std::array<glm::vec3, 2>> occluderEdge;

    [[nodiscard]] Aabb bounds() const noexcept; // S, world space
    [[nodiscard]] size_t triangleCount() const noexcept;
};

/// γ (Barroso) = θ (Zhang): the smallest angle between light and view directions,
/// acos(|v·l|) in degrees, in [0, 90]. NaN-safe: degenerate input gives 0.
[[nodiscard]] float gammaDeg(const glm::vec3& v, const glm::vec3& l) noexcept;
/// acos(v·l) in degrees, in [0, 180]: 0 when the light shines from behind the eye along the
/// view, 90 perpendicular, 180 when it faces the camera (the dueling frusta).
[[nodiscard]] float lightViewAngleDeg(const glm::vec3& v, const glm::vec3& l) noexcept;

} // namespace geometry::scene
