#pragma once
// Ground truth for shadow inspection (docs/design.md §4): for each visible receiver point, does a ray
// from it towards the light (a directional light's −l, or a spot or point light's position) hit any
// triangle of the scene? Traced with Embree 3 on
// the CPU, so it is independent of the GL renderer whose shadows it judges. No GL, no ImGui.
#include "geometry/analysis/cancelled.h"
#include "geometry/scene/scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace geometry::analysis {

/// Where truth rays go (docs/design.md §3.10 "Truth per light"): towards −l to infinity for a
/// directional light (implicit from l, so a direction still names one), or to a spot or point light's
/// position, ending there. A point a positional light does not reach (outside a spot's cone, beyond
/// the range: the shaders' lightReach is 0) is not its receiver: the light has no shadow to judge there.
struct TruthLight {
    scene::LightType type = scene::LightType::Directional;
    glm::vec3 l{0.f, -1.f, 0.f}; // directional: l; spot: the cone's axis (unit once valid)
    glm::vec3 position{0.f};
    float cosOuter = -1.f; // a spot's half-angle cosine; −1: every direction
    float range = std::numeric_limits<float>::infinity();
    float radius = 0.f; // a positional emitter's radius (the soft truth's disk)

    TruthLight(const glm::vec3& direction) noexcept; // NOLINT(google-explicit-constructor): directional
    explicit TruthLight(const scene::Light& light) noexcept;

    [[nodiscard]] bool operator==(const TruthLight&) const = default;
    [[nodiscard]] bool positional() const noexcept { return type != scene::LightType::Directional; }
    /// l finite and non-zero; a positional light's position, range and radius finite too.
    [[nodiscard]] bool valid() const noexcept;
    /// The unit direction from p towards the light; (0, 0, 0) at a positional light's position.
    [[nodiscard]] glm::vec3 toLight(const glm::vec3& p) const noexcept;
    /// How far a shadow ray from p runs: +∞ for a directional light, else the distance to the position.
    [[nodiscard]] float reach(const glm::vec3& p) const noexcept;
    /// Whether the light reaches p at all (the cone and the range; always for a directional light).
    [[nodiscard]] bool reaches(const glm::vec3& p) const noexcept;
};

/// What a camera sees: one entry per pixel, row-major, top row first (image order).
struct PrimaryHits {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> points;  // world space; NaN where the pixel sees nothing (sky)
    std::vector<glm::vec3> normals; // unit geometric normal facing the camera; (0,0,0) on a miss

    [[nodiscard]] size_t hitCount() const noexcept;
};

class GroundTruth {
public:
    /// Builds a BVH over all meshes' triangles in world space (Mesh::transform applied).
    /// Throws std::runtime_error (one line) on Embree errors or out-of-range indices. An empty
    /// scene is valid: nothing occludes.
    explicit GroundTruth(const scene::Scene& scene);
    /// The same truth, traced from the scene's own vertex and index arrays (Embree shared buffers)
    /// instead of a world-space copy: a mesh with a transform becomes an Embree instance. `scene`'s
    /// meshes must outlive the result unchanged (moving the Scene keeps its arrays where they are).
    /// A mesh whose positions have no spare capacity (Embree reads 4 bytes past the last vertex) is
    /// copied. Same answers as the copying constructor (docs/design.md §5).
    [[nodiscard]] static GroundTruth borrowing(const scene::Scene& scene);
    static GroundTruth borrowing(const scene::Scene&& scene) = delete; // a temporary would dangle
    ~GroundTruth();
    GroundTruth(GroundTruth&&) noexcept;
    GroundTruth& operator=(GroundTruth&&) noexcept;
    GroundTruth(const GroundTruth&) = delete;
    GroundTruth& operator=(const GroundTruth&) = delete;

    /// For each receiver point p (world space) with its unit geometric normal n (facing the
    /// viewer; it may face away from the light), 1 if the ray from p towards the light
    /// (direction −l, to infinity; or to a positional light's position: TruthLight) hits any
    /// triangle, else 0. A point at a positional light's position gives 0.
    ///
    /// Self-intersection: the origin moves by epsilon(p) along the side of the surface that faces
    /// the light (n if n·(−l) > 0, else −n) and hits closer than epsilon(p) are ignored. So a
    /// surface facing away from the light is judged by what lies behind it: the far side of a
    /// solid pole is occluded by the pole itself, the back of an open quad is not.
    ///
    /// Points or normals with NaN/Inf, or a zero normal, give 0 and are never traced. Throws
    /// std::invalid_argument if points.size() != normals.size() or l is zero or not finite.
    /// threads = 0 means std::thread::hardware_concurrency(); the result does not depend on it.
    ///
    /// Rays go in packets of 16 consecutive points, so keep neighbours together: image order
    /// (row-major) is good, a shuffled order is slower but gives the same result.
    /// Once `stop` is requested the workers take no new packets and the call throws Cancelled.
    [[nodiscard]] std::vector<uint8_t> occluded(const std::vector<glm::vec3>& points,
                                                const std::vector<glm::vec3>& normals, const TruthLight& light,
                                                int threads = 0, std::stop_token stop = {}) const;

    /// The unit geometric normal of the surface under each point, as seen from `eye`: a ray from the
    /// eye towards the point; where its nearest hit lies within max(4·epsilon(p), 1e-4·distance) of
    /// the point, that triangle's normal, turned to face the eye. Elsewhere (the point is on no
    /// triangle, something nearer hides it, or it is not finite) fallback[i], as given. Use it to
    /// give occluded() the geometric normals it documents when a renderer supplies shading ones.
    /// Throws std::invalid_argument if points.size() != fallback.size() or eye is not finite.
    /// `meshes`, when given, receives the scene index of the mesh found under each point (−1 where
    /// the fallback was used). Throws Cancelled once `stop` is requested (`meshes` then partly filled).
    [[nodiscard]] std::vector<glm::vec3> surfaceNormals(const glm::vec3& eye, const std::vector<glm::vec3>& points,
                                                        const std::vector<glm::vec3>& fallback, int threads = 0,
                                                        std::vector<int>* meshes = nullptr,
                                                        std::stop_token stop = {}) const;

    /// The distance along the light from each point to the first triangle between it and
    /// maxDistance[i] (occluded()'s rays, each ending there); +∞ where nothing lies that close, and
    /// where a point is not traced (as occluded(), or its distance not above epsilon(p), or NaN).
    /// Throws std::invalid_argument as occluded(), or when the sizes differ; Cancelled as occluded().
    [[nodiscard]] std::vector<float> occluderDistance(const std::vector<glm::vec3>& points,
                                                      const std::vector<glm::vec3>& normals, const TruthLight& light,
                                                      const std::vector<float>& maxDistance, int threads = 0,
                                                      std::stop_token stop = {}) const;

    /// Casts one ray per pixel centre of a width × height image from `camera` (aspect
    /// width/height, as Camera::projection) and returns the nearest hits between the near and far
    /// planes (view depth, as GL clips). Throws std::invalid_argument for a non-positive size.
    [[nodiscard]] PrimaryHits primaryHits(const scene::Camera& camera, int width, int height, int threads = 0) const;

    static constexpr int kMaxSamplesPerAxis = 16;
    /// The soft truth's sun samples per axis (addTruth): 8 × 8 = 64 rays per pixel.
    static constexpr int kSunSamplesPerAxis = 8;

    /// The fraction v ∈ [0, 1] of the sun's disk (angular diameter θ = angularDiameterRad, centred
    /// on −l) visible from each point (docs/design.md §4 "Soft truth"): samplesPerAxis² rays on a
    /// jittered stratified grid over the unit square, mapped onto the disk by Shirley's concentric
    /// map, each towards normalize(−l + tan(θ/2)·(x·e1 + y·e2)) with e1, e2 ⊥ l (uniform over the
    /// disk's projection on the plane ⊥ l, which is uniform in solid angle within 1 − cos³(θ/2):
    /// 3e-5 for the real sun, 4.5 % at 20°). The jitter comes from a hash of the point's coordinates and the
    /// sample's index, so the result depends neither on the thread count nor on the order of the
    /// points. A point's rays go in packets of 16.
    ///
    /// Every ray starts from the same origin as occluded()'s and ignores hits as close: the part of
    /// the disk below a receiver's horizon is hidden by the receiver itself when it is in the scene.
    /// θ = 0 gives exactly 1 − occluded() (every sample is then the ray along −l). A positional
    /// light's disk is its emitter: radius TruthLight::radius at its position, facing each point (θ is
    /// then 2·atan(radius / distance) per point and angularDiameterRad is not used); rays end on it. Points or normals
    /// with NaN/Inf, or a zero normal, give 0 and are never traced. Throws std::invalid_argument as
    /// occluded(), and for θ outside [0, π) or not finite, or samplesPerAxis outside
    /// 1..kMaxSamplesPerAxis; Cancelled once `stop` is requested (within a few hundred rays per thread).
    [[nodiscard]] std::vector<float> sunVisibility(const std::vector<glm::vec3>& points,
                                                   const std::vector<glm::vec3>& normals, const TruthLight& light,
                                                   float angularDiameterRad, int samplesPerAxis, int threads = 0,
                                                   std::stop_token stop = {}) const;

    /// The truth's lit fraction c ∈ [0, 1] of each pixel of a width × height image seen through
    /// `viewProj` (GL clip space; top row first): samplesPerAxis² primary rays on a stratified grid
    /// over the pixel's footprint, each from the near to the far plane; c = the fraction of the
    /// samples that hit a surface whose geometric normal faces the light and whose shadow ray
    /// (occluded()) escapes. Samples that see nothing, or that a positional light does not reach
    /// (TruthLight::reaches), are left out; a pixel none of whose samples
    /// hits anything gets NaN. Memory stays ~1M samples whatever the size (traced in row bands).
    /// Throws std::invalid_argument for a non-positive size, samplesPerAxis outside
    /// 1..kMaxSamplesPerAxis or a zero or non-finite l. Throws Cancelled once `stop` is requested
    /// (within a few hundred rays per thread).
    [[nodiscard]] std::vector<float> coverage(const glm::mat4& viewProj, int width, int height, const TruthLight& light,
                                              int samplesPerAxis, int threads = 0, std::stop_token stop = {}) const;

    /// The self-intersection offset used for a receiver at p, in scene units:
    /// max(1e-6, 1e-5 · max(‖p‖∞, 0.01 · scene diagonal)). Why relative to ‖p‖∞ rather than to
    /// the diagonal alone: the float error of a point (from rasterization or ray casting) grows
    /// with its coordinates, ~1e-7·‖p‖∞ per rounding, so 1e-5·‖p‖∞ leaves a ~100× margin. A pure
    /// 1e-5 · diagonal would be 3.4 cm on the platform (its 2.4 km sea sets the diagonal): more
    /// than a 2.4 cm grating bar, letting rays from a bar's shaded side tunnel through it, and
    /// hiding contact shadows. The 0.01 · diagonal floor covers points near the origin seen from
    /// far away (their error follows the camera's coordinates, not their own).
    [[nodiscard]] float epsilon(const glm::vec3& p) const noexcept;

    [[nodiscard]] size_t triangleCount() const noexcept;
    /// Of triangleCount(), those traced from the scene's own arrays (borrowing()).
    [[nodiscard]] size_t sharedTriangleCount() const noexcept;
    /// Triangles in the world: an instanced mesh's once per placement (Mesh::instances).
    [[nodiscard]] uint64_t placedTriangleCount() const noexcept;
    /// The scene's mesh names, by scene index (what surfaceNormals' `meshes` indexes).
    [[nodiscard]] const std::vector<std::string>& meshNames() const noexcept;
    /// A copy of the scene's Scene::occluderEdge (world space), for the penumbra-width metric.
    [[nodiscard]] const std::optional<std::array<glm::vec3, 2>>& occluderEdge() const noexcept;

private:
    GroundTruth() = default;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace geometry::analysis
