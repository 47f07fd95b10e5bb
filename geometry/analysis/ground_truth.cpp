// Index
//   [SECTION] Small helpers ............................... finite, maxAbs, resolveThreads, errorName, parallelFor
//   [SECTION] Packet layouts .............................. RunLayout, TileLayout, forEachPacket, setLane, checkInputs
//   [SECTION] Impl: device, scene and the error channel ... onError, throwIfError, addMesh, build
//   [SECTION] TruthLight .................................. toLight, reach, reaches
//   [SECTION] GroundTruth ................................. PrimaryHits::hitCount, GroundTruth, epsilon
//   [SECTION] Tracing rays ................................ traceOccluded, occluded, surfaceNormals, primaryHits,
//                                                           coverage
//   [SECTION] The sun's disk .............................. mix32, concentricDisk, sunVisibility

#include "geometry/analysis/ground_truth.h"

#include <embree3/rtcore.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace geometry::analysis {
namespace {

// ---- Tuning ---------------------------------------------------------------------------------

constexpr int kLanes = 16;             // rtcOccluded16 / rtcIntersect16: AVX-512 width
constexpr int kTileSide = 4;           // 4×4 pixel tiles for primary rays
constexpr size_t kPacketsPerTask = 16; // 256 rays per grab from the shared work counter
constexpr float kRelativeEpsilon = 1e-5f;
constexpr float kMinEpsilon = 1e-6f;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr size_t kNoPoint = std::numeric_limits<size_t>::max();
constexpr size_t kCompactAboveTriangles = 8'000'000; // Impl::build: BVH memory against speed

// ---- [SECTION] Small helpers ----------------------------------------------------------------

using scene::finite;

float maxAbs(const glm::vec3& v) noexcept { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

int resolveThreads(int threads) noexcept {
    if (threads > 0) return threads;
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

const char* errorName(RTCError code) noexcept {
    switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "unrecognized error";
}

/// Runs fn(task) for task in [0, tasks) on `threads` threads (the caller is one of them). Tasks
/// are handed out through an atomic counter, so the sky-heavy and geometry-heavy parts of an
/// image balance themselves; results are independent of who runs what. Once `stop` is requested
/// no worker takes another task (one check per task: a task is a few hundred rays), and the
/// call throws Cancelled when they have all finished.
template <class Fn> void parallelFor(size_t tasks, int threads, const std::stop_token& stop, const Fn& fn) {
    std::atomic<size_t> next{0};
    const auto worker = [&] {
        for (size_t t = next.fetch_add(1, std::memory_order_relaxed); t < tasks && !stop.stop_requested();
             t = next.fetch_add(1, std::memory_order_relaxed))
            fn(t);
    };
    const size_t helpers = std::min(tasks, static_cast<size_t>(threads)) - (tasks > 0 ? 1 : 0);
    std::vector<std::jthread> pool;
    pool.reserve(helpers);
    for (size_t i = 0; i < helpers; ++i) pool.emplace_back(worker);
    worker();
    for (std::jthread& helper : pool) helper.join();
    throwIfStopped(stop);
}

// ---- [SECTION] Packet layouts: which point each lane of packet k traces ---------------------

using Lanes = std::array<size_t, kLanes>;

/// Packet k holds points [16k, 16k + 16): the order the caller gave. For shadow rays of an image
/// these 1×16 strips traced as fast as 4×4, 8×2 or 2×8 tiles (within 5 %), so occluded() needs
/// no image width.
struct RunLayout {
    size_t count;
    [[nodiscard]] size_t packets() const noexcept { return (count + kLanes - 1) / kLanes; }
    [[nodiscard]] Lanes lanes(size_t k) const noexcept {
        Lanes out;
        for (size_t i = 0; i < kLanes; ++i) {
            const size_t p = k * kLanes + i;
            out[i] = p < count ? p : kNoPoint;
        }
        return out;
    }
};

/// Packet k holds a 4×4 tile of a row-major image `width` wide; tiles go row by row. For primary
/// rays, which share their origin, a square tile keeps the directions of a packet closest.
struct TileLayout {
    size_t count;
    size_t width;
    [[nodiscard]] size_t tilesX() const noexcept { return (width + kTileSide - 1) / kTileSide; }
    [[nodiscard]] size_t tilesY() const noexcept {
        const size_t rows = (count + width - 1) / width;
        return (rows + kTileSide - 1) / kTileSide;
    }
    [[nodiscard]] size_t packets() const noexcept { return tilesX() * tilesY(); }
    [[nodiscard]] Lanes lanes(size_t k) const noexcept {
        const size_t x0 = (k % tilesX()) * kTileSide, y0 = (k / tilesX()) * kTileSide;
        Lanes out;
        for (size_t i = 0; i < kLanes; ++i) {
            const size_t x = x0 + i % kTileSide, y = y0 + i / kTileSide;
            const size_t p = y * width + x;
            out[i] = x < width && p < count ? p : kNoPoint;
        }
        return out;
    }
};

/// Calls fn(packetLanes) for every packet of `layout`, in parallel; throws Cancelled as parallelFor.
template <class Layout, class Fn>
void forEachPacket(const Layout& layout, int threads, const std::stop_token& stop, const Fn& fn) {
    const size_t packets = layout.packets();
    const size_t tasks = (packets + kPacketsPerTask - 1) / kPacketsPerTask;
    parallelFor(tasks, resolveThreads(threads), stop, [&](size_t task) {
        const size_t end = std::min(packets, (task + 1) * kPacketsPerTask);
        for (size_t k = task * kPacketsPerTask; k < end; ++k) fn(layout.lanes(k));
    });
}

RTCIntersectContext coherentContext() noexcept {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT; // packets hold neighbouring pixels: ~20 % faster
    return ctx;
}

/// A lane Embree ignores; filled anyway so no uninitialized or NaN data reaches its SIMD loads.
template <class Packet> void setIdleLane(Packet& ray, int lane) noexcept {
    ray.org_x[lane] = ray.org_y[lane] = ray.org_z[lane] = 0.f;
    ray.dir_x[lane] = ray.dir_z[lane] = 0.f;
    ray.dir_y[lane] = 1.f;
    ray.tnear[lane] = 0.f;
    ray.tfar[lane] = 0.f;
    ray.time[lane] = 0.f;
    ray.mask[lane] = ~0u;
    ray.id[lane] = 0;
    ray.flags[lane] = 0;
}

template <class Packet>
void setLane(Packet& ray, int lane, const glm::vec3& org, const glm::vec3& dir, float tnear, float tfar) noexcept {
    ray.org_x[lane] = org.x;
    ray.org_y[lane] = org.y;
    ray.org_z[lane] = org.z;
    ray.dir_x[lane] = dir.x;
    ray.dir_y[lane] = dir.y;
    ray.dir_z[lane] = dir.z;
    ray.tnear[lane] = tnear;
    ray.tfar[lane] = tfar;
    ray.time[lane] = 0.f;
    ray.mask[lane] = ~0u; // the device supports ray masks: a zero mask would hit nothing
    ray.id[lane] = static_cast<unsigned>(lane);
    ray.flags[lane] = 0;
}

void checkLight(const TruthLight& light, const std::string& who) {
    if (!light.valid())
        throw std::invalid_argument(who + ": light direction must be finite and non-zero" +
                                    (light.positional() ? ", its position, range and radius finite" : ""));
}

void checkInputs(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals, const TruthLight& light,
                 const std::string& who = "GroundTruth::occluded") {
    if (points.size() != normals.size())
        throw std::invalid_argument(who + ": " + std::to_string(points.size()) + " points but " +
                                    std::to_string(normals.size()) + " normals");
    checkLight(light, who);
}

} // namespace

namespace detail {

/// Which scene mesh a hit lies on, and its geometric normal in world space. A mesh traced from
/// the scene's own arrays with a non-identity transform is an Embree instance: Embree reports its
/// hits' Ng in the mesh's object space and names it by instID, so both go through this table.
struct HitFrames {
    std::vector<int> geomMesh;         // top-level geometry ID → scene mesh index (−1: none)
    std::vector<glm::mat3> instNormal; // top-level geometry ID → object-to-world normal matrix

    void add(unsigned id, int mesh, const glm::mat4* transform) {
        if (id >= geomMesh.size()) {
            geomMesh.resize(id + 1, -1);
            instNormal.resize(id + 1, glm::mat3(1.f));
        }
        geomMesh[id] = mesh;
        if (transform) instNormal[id] = glm::transpose(glm::inverse(glm::mat3(*transform)));
    }
    /// Lane i's hit: the top-level geometry is the instance when there is one.
    template <class Hit> [[nodiscard]] unsigned topId(const Hit& hit, int i) const noexcept {
        return hit.instID[0][i] != RTC_INVALID_GEOMETRY_ID ? hit.instID[0][i] : hit.geomID[i];
    }
    template <class Hit> [[nodiscard]] int mesh(const Hit& hit, int i) const noexcept {
        const unsigned id = topId(hit, i);
        return id < geomMesh.size() ? geomMesh[id] : -1;
    }
    template <class Hit> [[nodiscard]] glm::vec3 normal(const Hit& hit, int i) const noexcept {
        const glm::vec3 ng(hit.Ng_x[i], hit.Ng_y[i], hit.Ng_z[i]);
        const unsigned inst = hit.instID[0][i];
        return inst < instNormal.size() ? instNormal[inst] * ng : ng; // RTC_INVALID_GEOMETRY_ID: not instanced
    }
};

} // namespace detail
using detail::HitFrames;

// ---- [SECTION] Impl: device, scene and the error channel ------------------------------------

struct GroundTruth::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    size_t triangles = 0;
    std::vector<std::string> meshNames; // per scene mesh
    HitFrames frames;                   // empty meshes get no geometry ID
    std::vector<RTCScene> meshScenes;   // one per instanced mesh (GroundTruth::borrowing)
    size_t sharedTriangles = 0;         // traced from the scene's own arrays
    uint64_t placedTriangles = 0;       // triangles × placements
    RTCSceneFlags sceneFlags = RTC_SCENE_FLAG_NONE;
    std::optional<std::array<glm::vec3, 2>> occluderEdge; // the scene's, copied
    float epsilonScale = 0.f; // 0.01 · scene diagonal: the floor of ‖p‖∞ in epsilon()

    std::mutex errorMutex;
    std::string error; // first Embree error since the last check

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        for (RTCScene s : meshScenes) rtcReleaseScene(s);
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    /// Embree calls this instead of aborting; it must not throw through Embree's C API, so the
    /// message is kept and throwIfError() raises it on our side.
    static void onError(void* user, RTCError code, const char* message) {
        auto* self = static_cast<Impl*>(user);
        const std::lock_guard lock(self->errorMutex);
        if (!self->error.empty()) return;
        self->error = std::string(errorName(code)) + (message && *message ? std::string(": ") + message : "");
        std::replace(self->error.begin(), self->error.end(), '\n', ' ');
    }

    void throwIfError(const char* during) {
        std::string message;
        {
            const std::lock_guard lock(errorMutex);
            message.swap(error);
        }
        const RTCError code = rtcGetDeviceError(device); // also clears Embree's own error state
        if (message.empty() && code != RTC_ERROR_NONE) message = errorName(code);
        if (!message.empty()) throw std::runtime_error(std::string("Embree error ") + during + ": " + message);
    }

    void createDevice() {
        // Embree 3.13.5's AVX-512 kernels never returned from rtcOccluded16 on an instanced scene on an
        // AMD EPYC machine with AVX-512 (InstancedRender.EqualsTheFlattenedScenePixelForPixel ran for
        // 15 minutes; with AVX2 or SSE4.2 it passes in a second): the ISA is capped at AVX2, which costs
        // about 5 % of a 1280×720 piperack render with truth there.
        device = rtcNewDevice("max_isa=avx2");
        if (!device)
            throw std::runtime_error(std::string("Embree error creating the device: ") +
                                     errorName(rtcGetDeviceError(nullptr)));
        rtcSetDeviceErrorFunction(device, &Impl::onError, this);
    }

    /// The mesh's indices must name its vertices: Embree would read out of bounds otherwise.
    static void checkIndices(const scene::Mesh& mesh) {
        const size_t n = mesh.positions.size();
        for (size_t i = 0; i < mesh.triangleCount() * 3; ++i)
            if (mesh.indices[i] >= n)
                throw std::runtime_error("GroundTruth: mesh '" + mesh.name + "' has index " +
                                         std::to_string(mesh.indices[i]) + " out of range (" + std::to_string(n) +
                                         " vertices)");
    }

    /// Embree reads a shared vertex buffer with 16-byte loads, 4 bytes past the last vertex: the
    /// array's spare capacity must cover them (a full vector is copied instead).
    static bool shareable(const scene::Mesh& mesh) noexcept {
        return mesh.positions.capacity() > mesh.positions.size();
    }

    /// Our reference to a new geometry, dropped at the end of the scope: the scene it is attached
    /// to keeps its own.
    struct Geometry {
        RTCGeometry g;
        Geometry(Impl& impl, RTCGeometryType type) : g(rtcNewGeometry(impl.device, type)) {
            impl.throwIfError("creating a geometry");
        }
        Geometry(const Geometry&) = delete;
        Geometry& operator=(const Geometry&) = delete;
        ~Geometry() {
            if (g) rtcReleaseGeometry(g);
        }
    };

    /// Attaches `geom` (committed) to `into`; in the top-level scene it stands for scene mesh `index`.
    void attach(RTCGeometry geom, RTCScene into, int index, const glm::mat4* transform) {
        const unsigned id = rtcAttachGeometry(into, geom);
        if (into == scene) frames.add(id, index, transform);
        throwIfError(("adding mesh '" + meshNames[size_t(index)] + "'").c_str());
    }

    /// A copy, its vertices through `bake` (world space) or as they are (an instanced mesh's own
    /// scene): Embree owns the buffers (rtcSetNewGeometryBuffer pads them as its SIMD loads
    /// require), so the Scene need not outlive us.
    RTCGeometry copiedGeometry(const Geometry& owned, const scene::Mesh& mesh, const glm::mat4& bake) {
        const size_t tris = mesh.triangleCount();
        RTCGeometry geom = owned.g;
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), mesh.positions.size()));
        auto* indices = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), tris));
        throwIfError(("allocating buffers for mesh '" + mesh.name + "'").c_str());
        if (!vertices || !indices) throw std::runtime_error("Embree error: no buffers for mesh '" + mesh.name + "'");
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3 w(bake * glm::vec4(mesh.positions[i], 1.f));
            vertices[3 * i] = w.x;
            vertices[3 * i + 1] = w.y;
            vertices[3 * i + 2] = w.z;
        }
        std::copy_n(mesh.indices.data(), tris * 3, indices);
        rtcCommitGeometry(geom);
        return geom;
    }

    /// The mesh's own arrays (Embree shared buffers, no copy), in object space.
    RTCGeometry sharedGeometry(const Geometry& owned, const scene::Mesh& mesh) {
        RTCGeometry geom = owned.g;
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                                   sizeof(glm::vec3), mesh.positions.size());
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                                   3 * sizeof(uint32_t), mesh.triangleCount());
        throwIfError(("sharing the buffers of mesh '" + mesh.name + "'").c_str());
        rtcCommitGeometry(geom);
        sharedTriangles += mesh.triangleCount();
        return geom;
    }

    /// The world box of the mesh's vertices under `m` (the truth's epsilon scale).
    static void addBounds(const scene::Mesh& mesh, const glm::mat4& m, scene::Aabb& bounds) noexcept {
        for (const glm::vec3& p : mesh.positions)
            if (const glm::vec3 w(m * glm::vec4(p, 1.f)); finite(w)) bounds.add(w);
    }

    /// `geom` in a scene of its own, placed once per placement by an Embree instance (a hit names
    /// the instance by instID, and its normal comes back in object space: HitFrames).
    void addInstances(RTCGeometry geom, const scene::Mesh& mesh, int index, scene::Aabb& bounds) {
        RTCScene own = rtcNewScene(device);
        throwIfError("creating a mesh scene");
        meshScenes.push_back(own);
        rtcSetSceneBuildQuality(own, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneFlags(own, sceneFlags);
        attach(geom, own, index, nullptr);
        rtcCommitScene(own);
        throwIfError(("building the BVH of mesh '" + mesh.name + "'").c_str());
        for (size_t i = 0; i < mesh.placementCount(); ++i) {
            const glm::mat4 placement = mesh.placement(i);
            addBounds(mesh, placement, bounds);
            const Geometry placed(*this, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(placed.g, own);
            rtcSetGeometryTransform(placed.g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &placement[0][0]);
            rtcCommitGeometry(placed.g);
            attach(placed.g, scene, index, &placement);
        }
    }

    /// Borrowing, a shareable mesh is traced from its own arrays: in world space as they are under
    /// an identity transform, else through instances. A copy is baked into world space unless the
    /// mesh is instanced.
    void addMesh(const scene::Mesh& mesh, bool borrow, scene::Aabb& bounds) {
        const size_t tris = mesh.triangleCount();
        if (tris == 0 || mesh.positions.empty()) return;
        checkIndices(mesh);
        const int index = int(meshNames.size()) - 1;
        const bool share = borrow && shareable(mesh);
        const bool instance = mesh.instanced() || (share && mesh.transform != glm::mat4(1.f));
        const Geometry owned(*this, RTC_GEOMETRY_TYPE_TRIANGLE);
        const RTCGeometry geom = share ? sharedGeometry(owned, mesh)
                                       : copiedGeometry(owned, mesh, instance ? glm::mat4(1.f) : mesh.transform);
        if (instance) addInstances(geom, mesh, index, bounds);
        else {
            addBounds(mesh, mesh.transform, bounds);
            attach(geom, scene, index, nullptr);
        }
        triangles += tris;
        placedTriangles += uint64_t(tris) * mesh.placementCount();
    }

    void build(const scene::Scene& input, bool borrow) {
        createDevice();
        scene = rtcNewScene(device);
        throwIfError("creating the scene");
        // Measured on the 250k platform, 1280×720, 2 cores: HIGH (spatial splits) doubles the
        // one-off build (100 ms vs 50) and traces shadow rays no faster, but primary rays 1.5×
        // faster (22 ms vs 33). ROBUST traces ~40 % slower and changed no pixel of that view.
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        // COMPACT keeps triangles as indices into the vertex array instead of copies in the BVH's
        // leaves. Measured on piperack 2M (render --truth, 640×360): peak RSS 536 → 435 MB (50 B per
        // triangle) and the same verdicts; on the 250k platform the build 2.6× faster, but primary
        // rays 3.7× slower (32 → 118 ms), shadow rays 1.15×: worth it where memory runs out.
        size_t total = 0;
        for (const scene::Mesh& mesh : input.meshes) total += mesh.triangleCount(); // instances add no BVH leaves
        sceneFlags = total > kCompactAboveTriangles ? RTC_SCENE_FLAG_COMPACT : RTC_SCENE_FLAG_NONE;
        rtcSetSceneFlags(scene, sceneFlags);
        scene::Aabb bounds;
        for (const scene::Mesh& mesh : input.meshes) {
            meshNames.push_back(mesh.name);
            addMesh(mesh, borrow, bounds);
        }
        rtcCommitScene(scene);
        throwIfError("building the BVH");
        epsilonScale = 0.01f * glm::length(bounds.extent());
        occluderEdge = input.occluderEdge;
    }
};

// ---- [SECTION] TruthLight -------------------------------------------------------------------

TruthLight::TruthLight(const glm::vec3& direction) noexcept : l(direction) {
    if (finite(l) && glm::length(l) > 0.f) l = glm::normalize(l);
}

TruthLight::TruthLight(const scene::Light& light) noexcept
    : type(light.type), l(light.l()), position(light.position), radius(light.positional() ? light.radius : 0.f) {
    if (!light.positional()) return;
    range = light.range;
    // The shaders' smoothstep reaches 0 at the outer cone: coneDeg is the full angle.
    if (light.type == scene::LightType::Spot) cosOuter = std::cos(glm::radians(0.5f * light.coneDeg));
}

bool TruthLight::valid() const noexcept {
    if (!finite(l) || !(glm::length(l) > 0.f)) return false;
    return !positional() || (finite(position) && range > 0.f && std::isfinite(range) && radius >= 0.f &&
                             std::isfinite(radius) && std::isfinite(cosOuter));
}

glm::vec3 TruthLight::toLight(const glm::vec3& p) const noexcept {
    if (!positional()) return -l;
    const glm::vec3 d = position - p;
    const float len = glm::length(d);
    return len > 0.f && std::isfinite(len) ? d / len : glm::vec3(0.f);
}

float TruthLight::reach(const glm::vec3& p) const noexcept { return positional() ? glm::distance(position, p) : kInf; }

bool TruthLight::reaches(const glm::vec3& p) const noexcept {
    if (!positional()) return true;
    const glm::vec3 d = p - position;
    const float len = glm::length(d);
    if (!(len < range)) return false; // NaN: no
    return !(len > 0.f) || glm::dot(d / len, l) > cosOuter;
}

// ---- [SECTION] GroundTruth ------------------------------------------------------------------

size_t PrimaryHits::hitCount() const noexcept {
    return static_cast<size_t>(
        std::count_if(points.begin(), points.end(), [](const glm::vec3& p) { return finite(p); }));
}

GroundTruth::GroundTruth(const scene::Scene& scene) : impl_(std::make_unique<Impl>()) { impl_->build(scene, false); }

GroundTruth GroundTruth::borrowing(const scene::Scene& scene) {
    GroundTruth truth;
    truth.impl_ = std::make_unique<Impl>();
    truth.impl_->build(scene, true);
    return truth;
}

size_t GroundTruth::sharedTriangleCount() const noexcept { return impl_ ? impl_->sharedTriangles : 0; }
uint64_t GroundTruth::placedTriangleCount() const noexcept { return impl_ ? impl_->placedTriangles : 0; }
GroundTruth::~GroundTruth() = default;
GroundTruth::GroundTruth(GroundTruth&&) noexcept = default;
GroundTruth& GroundTruth::operator=(GroundTruth&&) noexcept = default;

size_t GroundTruth::triangleCount() const noexcept { return impl_ ? impl_->triangles : 0; }

const std::vector<std::string>& GroundTruth::meshNames() const noexcept {
    static const std::vector<std::string> none;
    return impl_ ? impl_->meshNames : none;
}

const std::optional<std::array<glm::vec3, 2>>& GroundTruth::occluderEdge() const noexcept {
    static const std::optional<std::array<glm::vec3, 2>> none;
    return impl_ ? impl_->occluderEdge : none;
}

float GroundTruth::epsilon(const glm::vec3& p) const noexcept {
    const float scale = impl_ ? impl_->epsilonScale : 0.f;
    return std::max(kMinEpsilon, kRelativeEpsilon * std::max(maxAbs(p), scale));
}

// ---- [SECTION] Tracing rays -----------------------------------------------------------------

namespace {

/// Lane i of `ray` as occluded()'s shadow ray for point idx: from the point moved epsilon(p) off the
/// surface on the light's side, towards the light, hits closer than epsilon ignored, up to `reach`
/// (and no further than a positional light). False, the lane idle, where the point or its normal is
/// unusable, the point is at the light, or the reach does not clear epsilon (NaN included: nothing
/// can lie in between).
template <class Ray>
bool setShadowLane(Ray& ray, int i, const GroundTruth& truth, size_t idx, const std::vector<glm::vec3>& points,
                   const std::vector<glm::vec3>& normals, const TruthLight& light, float reach) noexcept {
    const glm::vec3 p = idx != kNoPoint ? points[idx] : glm::vec3(0.f);
    const glm::vec3 n = idx != kNoPoint ? normals[idx] : glm::vec3(0.f);
    const float len = glm::length(n);
    const float eps = truth.epsilon(p);
    const glm::vec3 toLight = light.toLight(p);
    reach = std::min(reach, light.reach(p)); // NaN stays NaN: idle
    if (idx == kNoPoint || !finite(p) || !finite(n) || !(len > 0.f) || !std::isfinite(len) || !(reach > eps) ||
        toLight == glm::vec3(0.f)) {
        setIdleLane(ray, i);
        return false;
    }
    const glm::vec3 side = glm::dot(n, toLight) > 0.f ? n : -n; // the light's side of the surface
    setLane(ray, i, p + side * (eps / len), toLight, eps, reach);
    return true;
}

/// One rtcOccluded16 per packet: 2.6× faster than rtcOccluded1 ray by ray on AVX-512.
std::vector<uint8_t> traceOccluded(const GroundTruth& truth, RTCScene scene, const RunLayout& layout,
                                   const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                   const TruthLight& light, int threads, const std::stop_token& stop) {
    std::vector<uint8_t> result(points.size(), 0);
    forEachPacket(layout, threads, stop, [&](const Lanes& lanes) {
        RTCRay16 ray;
        alignas(64) std::array<int, kLanes> valid{};
        bool any = false;
        for (int i = 0; i < kLanes; ++i)
            if (setShadowLane(ray, i, truth, lanes[i], points, normals, light, kInf)) valid[i] = -1, any = true;
        if (!any) return;
        RTCIntersectContext ctx = coherentContext();
        rtcOccluded16(valid.data(), scene, &ctx, &ray);
        for (int i = 0; i < kLanes; ++i)
            if (valid[i] && ray.tfar[i] < 0.f) result[lanes[i]] = 1; // Embree sets tfar = −inf on a hit
    });
    return result;
}

} // namespace

std::vector<uint8_t> GroundTruth::occluded(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                           const TruthLight& light, int threads, std::stop_token stop) const {
    checkInputs(points, normals, light);
    if (!impl_) throw std::logic_error("GroundTruth::occluded on a moved-from object");
    auto result = traceOccluded(*this, impl_->scene, RunLayout{points.size()}, points, normals, light, threads, stop);
    impl_->throwIfError("tracing shadow rays");
    return result;
}

std::vector<float> GroundTruth::occluderDistance(const std::vector<glm::vec3>& points,
                                                 const std::vector<glm::vec3>& normals, const TruthLight& light,
                                                 const std::vector<float>& maxDistance, int threads,
                                                 std::stop_token stop) const {
    checkInputs(points, normals, light);
    if (maxDistance.size() != points.size())
        throw std::invalid_argument("GroundTruth::occluderDistance: " + std::to_string(points.size()) + " points but " +
                                    std::to_string(maxDistance.size()) + " distances");
    if (!impl_) throw std::logic_error("GroundTruth::occluderDistance on a moved-from object");
    std::vector<float> out(points.size(), kInf);
    // occluded()'s rays, each ending at its distance, intersected for their hit.
    forEachPacket(RunLayout{points.size()}, threads, stop, [&](const Lanes& lanes) {
        RTCRayHit16 rh;
        alignas(64) std::array<int, kLanes> valid{};
        bool any = false;
        for (int i = 0; i < kLanes; ++i) {
            const float reach = lanes[i] != kNoPoint ? maxDistance[lanes[i]] : 0.f;
            if (!setShadowLane(rh.ray, i, *this, lanes[i], points, normals, light, reach)) continue;
            rh.hit.geomID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
            valid[i] = -1;
            any = true;
        }
        if (!any) return;
        RTCIntersectContext ctx = coherentContext();
        rtcIntersect16(valid.data(), impl_->scene, &ctx, &rh);
        for (int i = 0; i < kLanes; ++i)
            if (valid[i] && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID) out[lanes[i]] = rh.ray.tfar[i];
    });
    impl_->throwIfError("tracing occluder distances");
    return out;
}

std::vector<glm::vec3> GroundTruth::surfaceNormals(const glm::vec3& eye, const std::vector<glm::vec3>& points,
                                                   const std::vector<glm::vec3>& fallback, int threads,
                                                   std::vector<int>* meshes, std::stop_token stop) const {
    if (points.size() != fallback.size())
        throw std::invalid_argument("GroundTruth::surfaceNormals: " + std::to_string(points.size()) + " points but " +
                                    std::to_string(fallback.size()) + " normals");
    if (!finite(eye)) throw std::invalid_argument("GroundTruth::surfaceNormals: the eye is not finite");
    if (!impl_) throw std::logic_error("GroundTruth::surfaceNormals on a moved-from object");
    std::vector<glm::vec3> out = fallback;
    if (meshes) meshes->assign(points.size(), -1);
    forEachPacket(RunLayout{points.size()}, threads, stop, [&](const Lanes& lanes) {
        RTCRayHit16 rh;
        alignas(64) std::array<int, kLanes> valid{};
        std::array<float, kLanes> distance{}, reach{};
        bool any = false;
        for (int i = 0; i < kLanes; ++i) {
            const size_t idx = lanes[i];
            const glm::vec3 p = idx != kNoPoint ? points[idx] : glm::vec3(0.f);
            const float d = glm::length(p - eye);
            if (idx == kNoPoint || !finite(p) || !(d > 0.f) || !std::isfinite(d)) {
                setIdleLane(rh.ray, i);
                continue;
            }
            distance[i] = d;
            reach[i] = std::max(4.f * epsilon(p), 1e-4f * d);
            setLane(rh.ray, i, eye, (p - eye) / d, 0.f, d + reach[i]);
            rh.hit.geomID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
            valid[i] = -1;
            any = true;
        }
        if (!any) return;
        RTCIntersectContext ctx = coherentContext();
        rtcIntersect16(valid.data(), impl_->scene, &ctx, &rh);
        for (int i = 0; i < kLanes; ++i) {
            if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
            const size_t idx = lanes[i];
            if (!(std::abs(rh.ray.tfar[i] - distance[i]) <= reach[i])) continue; // another surface: keep the fallback
            glm::vec3 n = impl_->frames.normal(rh.hit, i);
            const float len = glm::length(n);
            if (!(len > 0.f) || !std::isfinite(len)) continue;
            n /= len;
            const glm::vec3 dir(rh.ray.dir_x[i], rh.ray.dir_y[i], rh.ray.dir_z[i]);
            out[idx] = glm::dot(n, dir) > 0.f ? -n : n; // face the eye
            if (meshes) (*meshes)[idx] = impl_->frames.mesh(rh.hit, i);
        }
    });
    impl_->throwIfError("tracing surface normals");
    return out;
}

namespace {

/// A primary ray: from org along dir (not necessarily unit), hits kept for t in [tnear, tfar].
struct PrimaryRay {
    glm::vec3 org, dir;
    float tnear, tfar;
};

/// Traces one primary ray per cell of a `width` × `rows` grid (rayAt(x, y) gives it) in 4×4 tiles;
/// writes the nearest hit point and its unit geometric normal, facing the ray's origin, per cell.
/// Misses keep the values the caller filled in (NaN point, zero normal).
template <class RayAt>
void tracePrimary(RTCScene scene, const HitFrames& frames, size_t width, size_t rows, int threads,
                  const std::stop_token& stop, const RayAt& rayAt, std::vector<glm::vec3>& points,
                  std::vector<glm::vec3>& normals) {
    forEachPacket(TileLayout{width * rows, width}, threads, stop, [&](const Lanes& lanes) {
        RTCRayHit16 rh;
        alignas(64) std::array<int, kLanes> valid{};
        for (int i = 0; i < kLanes; ++i) {
            if (lanes[i] == kNoPoint) {
                setIdleLane(rh.ray, i);
                continue;
            }
            const PrimaryRay r = rayAt(lanes[i] % width, lanes[i] / width);
            // A camera of extreme depth range can unproject its far plane to infinity: no sample.
            if (!(maxAbs(r.org) < 1e18f) || !(maxAbs(r.dir) < 1e18f)) { // NaN fails too
                setIdleLane(rh.ray, i);
                continue;
            }
            setLane(rh.ray, i, r.org, r.dir, r.tnear, r.tfar);
            rh.hit.geomID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID; // as Embree requires
            valid[i] = -1;
        }
        RTCIntersectContext ctx = coherentContext();
        rtcIntersect16(valid.data(), scene, &ctx, &rh);
        for (int i = 0; i < kLanes; ++i) {
            if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
            const glm::vec3 org(rh.ray.org_x[i], rh.ray.org_y[i], rh.ray.org_z[i]);
            const glm::vec3 dir(rh.ray.dir_x[i], rh.ray.dir_y[i], rh.ray.dir_z[i]);
            glm::vec3 n = frames.normal(rh.hit, i);
            const float len = glm::length(n);
            if (!(len > 0.f) || !std::isfinite(len)) continue; // degenerate triangle: treat as unseen
            n /= len;
            points[lanes[i]] = org + rh.ray.tfar[i] * dir;
            normals[lanes[i]] = glm::dot(n, dir) > 0.f ? -n : n; // face the camera
        }
    });
}

} // namespace

PrimaryHits GroundTruth::primaryHits(const scene::Camera& camera, int width, int height, int threads) const {
    if (width < 1 || height < 1) throw std::invalid_argument("GroundTruth::primaryHits: image size must be positive");
    if (!impl_) throw std::logic_error("GroundTruth::primaryHits on a moved-from object");
    PrimaryHits hits;
    hits.width = width;
    hits.height = height;
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    hits.points.assign(count, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
    hits.normals.assign(count, glm::vec3(0.f));

    // Camera basis from the same view matrix the renderer uses. The direction has a unit
    // forward component, so the ray parameter t is the view depth and [near, far] clips as GL.
    const glm::mat4 toWorld = glm::inverse(camera.view());
    const glm::vec3 right(toWorld[0]), up(toWorld[1]), forward(-glm::vec3(toWorld[2]));
    const glm::vec3 eye(toWorld[3]);
    const float tanHalf = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    tracePrimary(
        impl_->scene, impl_->frames, size_t(width), size_t(height), threads, {},
        [&](size_t px, size_t py) {
            const float x = (static_cast<float>(px) + 0.5f) / static_cast<float>(width) * 2.f - 1.f;
            const float y = 1.f - (static_cast<float>(py) + 0.5f) / static_cast<float>(height) * 2.f;
            const glm::vec3 dir = forward + (x * tanHalf * aspect) * right + (y * tanHalf) * up;
            return PrimaryRay{eye, dir, camera.near, camera.far};
        },
        hits.points, hits.normals);
    impl_->throwIfError("tracing primary rays");
    return hits;
}

std::vector<float> GroundTruth::coverage(const glm::mat4& viewProj, int width, int height, const TruthLight& light,
                                         int samplesPerAxis, int threads, std::stop_token stop) const {
    if (width < 1 || height < 1) throw std::invalid_argument("GroundTruth::coverage: image size must be positive");
    if (samplesPerAxis < 1 || samplesPerAxis > kMaxSamplesPerAxis)
        throw std::invalid_argument("GroundTruth::coverage: samples per axis " + std::to_string(samplesPerAxis) +
                                    " is outside 1.." + std::to_string(kMaxSamplesPerAxis));
    checkLight(light, "GroundTruth::coverage");
    if (!impl_) throw std::logic_error("GroundTruth::coverage on a moved-from object");
    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(viewProj));
    const auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 p = toWorld * glm::dvec4(x, y, z, 1.0);
        return glm::vec3(glm::dvec3(p) / p.w);
    };
    const size_t N = size_t(samplesPerAxis), W = size_t(width) * N, H = size_t(height) * N;
    // Pixel rows per band: ~256 k samples (about 6 MiB of points, normals and verdicts) in memory at a
    // time, whatever the image size. The truth runs beside the model's BVH: at plant scale its peak
    // is the process's (docs/performance.md "Scale").
    const size_t bandRows = std::max<size_t>(1, (size_t(1) << 18) / (W * N));
    std::vector<float> lit(size_t(width) * size_t(height), 0.f), hit(lit.size(), 0.f);
    std::vector<glm::vec3> points, normals;
    for (size_t y0 = 0; y0 < size_t(height); y0 += bandRows) {
        const size_t rows = std::min(bandRows, size_t(height) - y0) * N;
        points.assign(W * rows, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
        normals.assign(W * rows, glm::vec3(0.f));
        // Sample (X, Y) of the N-times finer grid sits at the centre of its cell: N × N stratified
        // samples per pixel. Rays run from the near to the far plane (t ∈ [0, 1]), as GL clips.
        tracePrimary(
            impl_->scene, impl_->frames, W, rows, threads, stop,
            [&](size_t X, size_t Y) {
                const double x = (double(X) + 0.5) / double(W) * 2.0 - 1.0;
                const double y = 1.0 - (double(y0 * N + Y) + 0.5) / double(H) * 2.0;
                const glm::vec3 nearP = unproject(x, y, -1.0), farP = unproject(x, y, 1.0);
                return PrimaryRay{nearP, farP - nearP, 0.f, 1.f};
            },
            points, normals);
        // Samples on a surface facing away from the light are dark without a shadow ray (their normal
        // becomes 0, in place); samples the light does not reach are left out as misses are.
        std::vector<glm::vec3>& facing = normals;
        for (size_t k = 0; k < facing.size(); ++k) {
            if (!light.reaches(points[k])) points[k] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
            if (!(glm::dot(facing[k], light.toLight(points[k])) > 0.f)) facing[k] = glm::vec3(0.f);
        }
        const std::vector<uint8_t> occ =
            traceOccluded(*this, impl_->scene, RunLayout{points.size()}, points, facing, light, threads, stop);
        for (size_t k = 0; k < points.size(); ++k) {
            if (!finite(points[k])) continue;
            const size_t pixel = (y0 + (k / W) / N) * size_t(width) + (k % W) / N;
            hit[pixel] += 1.f;
            if (facing[k] != glm::vec3(0.f) && !occ[k]) lit[pixel] += 1.f;
        }
    }
    impl_->throwIfError("tracing coverage rays");
    for (size_t i = 0; i < lit.size(); ++i)
        lit[i] = hit[i] > 0.f ? lit[i] / hit[i] : std::numeric_limits<float>::quiet_NaN();
    return lit;
}

// ---- [SECTION] The sun's disk ---------------------------------------------------------------

namespace {

/// MurmurHash3's 32-bit finalizer: every input bit flips each output bit with probability ~1/2.
constexpr uint32_t mix32(uint32_t h) noexcept {
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

/// The top 24 bits of h as a float in [0, 1).
float unitFloat(uint32_t h) noexcept { return static_cast<float>(h >> 8) * 0x1p-24f; }

/// A seed from the point's coordinates alone, so the jitter follows the point wherever it lies in
/// the input and whichever thread traces it.
uint32_t pointSeed(const glm::vec3& p) noexcept {
    uint32_t h = mix32(std::bit_cast<uint32_t>(p.x) ^ 0x9e3779b9u);
    h = mix32(h ^ std::bit_cast<uint32_t>(p.y));
    return mix32(h ^ std::bit_cast<uint32_t>(p.z));
}

/// Shirley and Chiu's concentric map from the unit square [0, 1]² onto the unit disk: area
/// preserving and continuous, so a stratified grid stays stratified on the disk.
glm::vec2 concentricDisk(float u, float v) noexcept {
    const float a = 2.f * u - 1.f, b = 2.f * v - 1.f;
    if (a == 0.f && b == 0.f) return glm::vec2(0.f);
    constexpr float kQuarterPi = 0.785398163397448f;
    if (std::abs(a) > std::abs(b)) {
        const float phi = kQuarterPi * (b / a);
        return a * glm::vec2(std::cos(phi), std::sin(phi));
    }
    const float phi = 2.f * kQuarterPi - kQuarterPi * (a / b);
    return b * glm::vec2(std::cos(phi), std::sin(phi));
}

/// Two unit vectors spanning the plane ⊥ d (unit): Duff et al.'s branchless orthonormal basis.
std::array<glm::vec3, 2> perpendicularBasis(const glm::vec3& d) noexcept {
    const float sign = std::copysign(1.f, d.z);
    const float a = -1.f / (sign + d.z), b = d.x * d.y * a;
    return {glm::vec3(1.f + sign * d.x * d.x * a, sign * b, -sign * d.x), glm::vec3(b, sign + d.y * d.y * a, -d.y)};
}

} // namespace

std::vector<float> GroundTruth::sunVisibility(const std::vector<glm::vec3>& points,
                                              const std::vector<glm::vec3>& normals, const TruthLight& light,
                                              float angularDiameterRad, int samplesPerAxis, int threads,
                                              std::stop_token stop) const {
    checkInputs(points, normals, light, "GroundTruth::sunVisibility");
    constexpr float kPi = 3.14159265358979f;
    if (!(angularDiameterRad >= 0.f && angularDiameterRad < kPi))
        throw std::invalid_argument("GroundTruth::sunVisibility: the sun's angular diameter must lie in [0, pi) "
                                    "radians");
    if (samplesPerAxis < 1 || samplesPerAxis > kMaxSamplesPerAxis)
        throw std::invalid_argument("GroundTruth::sunVisibility: samples per axis " + std::to_string(samplesPerAxis) +
                                    " is outside 1.." + std::to_string(kMaxSamplesPerAxis));
    if (!impl_) throw std::logic_error("GroundTruth::sunVisibility on a moved-from object");

    const float sunTanHalf = std::tan(0.5f * angularDiameterRad);
    const int S = samplesPerAxis, samples = S * S;
    // Each task takes whole points, so a point's count is one thread's: ~256 rays a task.
    const size_t pointsPerTask = std::max<size_t>(1, 256 / size_t(samples));
    const size_t tasks = (points.size() + pointsPerTask - 1) / pointsPerTask;
    std::vector<float> visible(points.size(), 0.f);
    parallelFor(tasks, resolveThreads(threads), stop, [&](size_t task) {
        const size_t end = std::min(points.size(), (task + 1) * pointsPerTask);
        for (size_t idx = task * pointsPerTask; idx < end; ++idx) {
            const glm::vec3& p = points[idx];
            const glm::vec3& n = normals[idx];
            const float len = glm::length(n);
            if (!finite(p) || !finite(n) || !(len > 0.f) || !std::isfinite(len)) continue; // 0, untraced
            // As traceOccluded: θ = 0 traces exactly its ray. A positional emitter's disk faces p.
            const glm::vec3 toLight = light.toLight(p);
            const float distance = light.reach(p);
            const float eps = epsilon(p);
            if (toLight == glm::vec3(0.f) || !(distance > eps)) continue; // at the light: 0, untraced
            const std::array<glm::vec3, 2> e = perpendicularBasis(toLight);
            const float tanHalf = light.positional() ? light.radius / distance : sunTanHalf;
            const glm::vec3 side = glm::dot(n, toLight) > 0.f ? n : -n;
            const glm::vec3 origin = p + side * (eps / len);
            const uint32_t seed = pointSeed(p);
            int lit = 0;
            for (int first = 0; first < samples; first += kLanes) {
                RTCRay16 ray;
                alignas(64) std::array<int, kLanes> valid{};
                for (int i = 0; i < kLanes; ++i) {
                    const int k = first + i;
                    if (k >= samples) {
                        setIdleLane(ray, i);
                        continue;
                    }
                    glm::vec3 dir = toLight;
                    float tfar = distance; // +∞ for the sun
                    if (tanHalf > 0.f) {
                        const uint32_t h = mix32(seed ^ (0x9e3779b9u * uint32_t(k + 1)));
                        const float u = (float(k % S) + unitFloat(h)) / float(S);
                        const float v = (float(k / S) + unitFloat(mix32(h ^ 0x68e31da4u))) / float(S);
                        const glm::vec2 d = tanHalf * concentricDisk(u, v);
                        const glm::vec3 offset = toLight + d.x * e[0] + d.y * e[1]; // on the disk at 1 unit
                        dir = glm::normalize(offset);
                        tfar = distance * glm::length(offset); // to the emitter's disk
                    }
                    setLane(ray, i, origin, dir, eps, tfar);
                    valid[i] = -1;
                }
                RTCIntersectContext ctx = coherentContext();
                rtcOccluded16(valid.data(), impl_->scene, &ctx, &ray);
                for (int i = 0; i < kLanes; ++i)
                    if (valid[i] && !(ray.tfar[i] < 0.f)) ++lit; // Embree sets tfar = −inf on a hit
            }
            visible[idx] = static_cast<float>(lit) / static_cast<float>(samples);
        }
    });
    impl_->throwIfError("tracing sun rays");
    return visible;
}

} // namespace geometry::analysis
