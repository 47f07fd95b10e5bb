#pragma once
// The scene model: a flat list of meshes, one camera, 1 to kMaxLights lights (directional, spot or
// point). Nothing more (docs/design.md §2: "model no more of a scene than it needs"; §3.10 for lights).
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
    /// Instancing (docs/design.md §2 "Instances"): where not empty, the mesh is placed once per
    /// entry, at instances[i] · transform, all placements drawing and tracing the same arrays. Its
    /// chunk bounds then lie in the space `transform` maps to, not in world space.
    std::vector<glm::mat4> instances;

    [[nodiscard]] size_t triangleCount() const noexcept { return indices.size() / 3; }
    [[nodiscard]] Aabb worldBounds() const noexcept; // under `transform` alone
    [[nodiscard]] bool instanced() const noexcept { return !instances.empty(); }
    /// Placements: 1 without instances.
    [[nodiscard]] size_t placementCount() const noexcept { return instanced() ? instances.size() : 1; }
    /// Placement i's object-to-world matrix.
    [[nodiscard]] glm::mat4 placement(size_t i) const noexcept {
        return instanced() ? instances[i] * transform : transform;
    }
    /// Placement i's world box: its chunks' boxes, each carried by the instance matrix (so a
    /// flattened copy, flattenInstances(), has exactly these bounds).
    [[nodiscard]] Aabb placementBounds(size_t i) const noexcept;
    /// The first placement whose box reaches beyond the float range (transforms that compose to
    /// infinity), or placementCount() when there is none: such a mesh cannot be framed, culled or traced.
    [[nodiscard]] size_t firstPlacementBeyondFloat() const noexcept;
    /// Triangles drawn when every placement is: triangleCount() × placementCount().
    [[nodiscard]] uint64_t placedTriangleCount() const noexcept { return uint64_t(triangleCount()) * placementCount(); }
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

enum class LightType { Directional, Spot, Point };

/// A light (docs/design.md §3.10). Directional: `direction` is l, from the light into the scene.
/// Spot: at `position`, shining along `direction` within a cone of full angle `coneDeg`, reaching
/// `range`. Point: at `position`, in every direction up to `range` (`direction` only orients its
/// cube faces' report). `radius`: the emitter's size for the soft truth (positional lights; the sun's
/// size is the setting light.angular_diameter_deg).
struct Light {
    glm::vec3 direction{-0.4f, -1.f, -0.3f}; // first: Light{l} is a directional light along l
    LightType type = LightType::Directional;
    glm::vec3 position{0.f};
    float coneDeg = 60.f;
    float range = 100.f;
    float radius = 0.f;
    /// This light's overrides of the shared shadow settings, as `key=value` (a scene file's
    /// "settings"; geometry/shadow applies them when it plans the light, docs/design.md §3.10).
    std::vector<std::string> settings = {};
    [[nodiscard]] bool operator==(const Light&) const = default;
    [[nodiscard]] bool positional() const noexcept { return type != LightType::Directional; }
    /// The unit direction (directional: l; spot: the cone's axis); (0, −1, 0) when degenerate.
    [[nodiscard]] glm::vec3 l() const noexcept;
    /// The unit direction light travels to reach x: l for a directional light, from the position
    /// to x otherwise (l() where x is the position).
    [[nodiscard]] glm::vec3 lAt(const glm::vec3& x) const noexcept;
};

/// Lights a scene may hold: each has its own maps and eye pass (docs/design.md §3.10).
inline constexpr size_t kMaxLights = 8;

/// "directional", "spot", "point".
[[nodiscard]] const char* lightTypeName(LightType t) noexcept;

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    Camera camera;
    /// Never empty in a valid scene; lights[0] is the light single-light commands use unless told
    /// otherwise (--light).
    std::vector<Light> lights{Light{}};
    /// A straight occluder edge (two distinct points, world space) whose shadow the truth's
    /// penumbra-width metric measures (docs/design.md §4 "Soft truth"); none by default.
    std::optional<std::array<glm::vec3, 2>> occluderEdge;

    [[nodiscard]] Aabb bounds() const noexcept; // S, world space, every placement
    /// Triangles held in memory (each instanced mesh once).
    [[nodiscard]] size_t triangleCount() const noexcept;
    /// Triangles placed in the world (an instanced mesh once per placement).
    [[nodiscard]] uint64_t placedTriangleCount() const noexcept;
};

/// γ (Barroso) = θ (Zhang): the smallest angle between light and view directions,
/// acos(|v·l|) in degrees, in [0, 90]. NaN-safe: degenerate input gives 0.
[[nodiscard]] float gammaDeg(const glm::vec3& v, const glm::vec3& l) noexcept;
/// acos(v·l) in degrees, in [0, 180]: 0 when the light shines from behind the eye along the
/// view, 90 perpendicular, 180 when it faces the camera (the dueling frusta).
[[nodiscard]] float lightViewAngleDeg(const glm::vec3& v, const glm::vec3& l) noexcept;

} // namespace geometry::scene
