// Index
//   [SECTION] Typed values with key paths ... member, element, Reader (describeJsonValue: json_file.h)
//   [SECTION] Placement ..................... rotationXyz, readPlacement, readInstances, reboundChunks,
//                                             place
//   [SECTION] Scene pieces .................. makeGround, framedCamera, meshBounds, endsWithIgnoreCase
//   [SECTION] The scene file ................ budgetParams, plantParams, builtinEntry, readMeshEntry, readViews,
//                                             readPaths, readSceneFile
//   [SECTION] Public functions .............. frameCamera, defaultLight, loadSceneFile, resolveScene

#include "geometry/io/scene_file.h"
#include "geometry/io/json_file.h"
#include "geometry/io/preset.h"

#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/instancing.h"
#include "geometry/scene/mesh_builder.h"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace geometry::io {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const glm::vec3 kGroundColor{0.75f, 0.75f, 0.72f};
// A ground grid rather than one quad keeps the rasterized depth of a huge plane well behaved.
constexpr int kGroundCells = 16;
constexpr float kGroundFootprintFactor = 4.f;

std::runtime_error fileError(const std::string& path, const std::string& problem) {
    return std::runtime_error(path + ": " + problem);
}

// ---- [SECTION] Typed values with key paths --------------------------------------------------

std::string member(const std::string& key, const std::string& name) { return key.empty() ? name : key + "." + name; }
std::string element(const std::string& key, size_t i) { return key + "[" + std::to_string(i) + "]"; }

/// A float as a person writes it: 1, 0.5, 1e+30 (std::to_string gives 1.000000).
std::string text(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

/// Reads one scene file; every error names the file and the key path.
class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        throw SceneFileError(file_ + ": " + (key.empty() ? "" : key + ": ") + problem);
    }

    /// `v` must be an object whose members are all in `allowed`.
    void checkObject(const json& v, const std::string& key, std::initializer_list<std::string_view> allowed) const {
        if (!v.is_object()) fail(key, "expected an object, got " + describeJsonValue(v));
        for (const auto& [name, value] : v.items()) {
            if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
            std::string known;
            for (auto a : allowed) known += (known.empty() ? "" : ", ") + std::string(a);
            fail(member(key, name), "unknown key (known: " + known + ")");
        }
    }

    float number(const json& v, const std::string& key) const {
        if (!v.is_number()) fail(key, "expected a number, got " + describeJsonValue(v));
        const double d = v.get<double>();
        // Finite doubles beyond float's range would turn into infinities.
        if (!std::isfinite(d) || std::abs(d) > double(std::numeric_limits<float>::max()))
            fail(key, "number out of range: " + describeJsonValue(v));
        return static_cast<float>(d);
    }

    float positive(const json& v, const std::string& key) const {
        const float f = number(v, key);
        if (!(f > 0.f)) fail(key, "expected a positive number, got " + describeJsonValue(v));
        return f;
    }

    uint32_t unsignedInt(const json& v, const std::string& key, uint32_t lo, uint32_t hi) const {
        const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
        if (!v.is_number_integer()) fail(key, "expected an integer in " + range + ", got " + describeJsonValue(v));
        const bool inRange = v.is_number_unsigned()
                                 ? v.get<uint64_t>() >= lo && v.get<uint64_t>() <= hi
                                 : v.get<int64_t>() >= int64_t(lo) && v.get<int64_t>() <= int64_t(hi);
        if (!inRange) fail(key, "expected an integer in " + range + ", got " + describeJsonValue(v));
        return static_cast<uint32_t>(v.get<uint64_t>());
    }

    std::string string(const json& v, const std::string& key) const {
        if (!v.is_string()) fail(key, "expected a string, got " + describeJsonValue(v));
        return v.get<std::string>();
    }

    glm::vec3 vec3(const json& v, const std::string& key) const {
        if (!v.is_array() || v.size() != 3) fail(key, "expected 3 numbers, got " + describeJsonValue(v));
        return {number(v[0], element(key, 0)), number(v[1], element(key, 1)), number(v[2], element(key, 2))};
    }

    glm::vec3 direction(const json& v, const std::string& key) const {
        const glm::vec3 d = vec3(v, key);
        if (!(glm::length(d) > 0.f)) fail(key, "direction must not be zero");
        return d;
    }

    glm::vec3 color(const json& v, const std::string& key) const {
        const glm::vec3 c = vec3(v, key);
        for (int i = 0; i < 3; ++i)
            if (c[i] < 0.f || c[i] > 1.f) fail(element(key, size_t(i)), "colour components must be within 0..1");
        return c;
    }

    /// Members present in `v` replace those of `base`; the result is checked as a whole.
    scene::Camera camera(const json& v, const std::string& key, scene::Camera c) const {
        checkObject(v, key, {"eye", "target", "up", "fov_y", "near", "far"});
        if (v.contains("eye")) c.eye = vec3(v["eye"], member(key, "eye"));
        if (v.contains("target")) c.target = vec3(v["target"], member(key, "target"));
        if (v.contains("up")) c.up = direction(v["up"], member(key, "up"));
        if (v.contains("fov_y")) c.fovYDeg = number(v["fov_y"], member(key, "fov_y"));
        if (v.contains("near")) c.near = positive(v["near"], member(key, "near"));
        if (v.contains("far")) c.far = number(v["far"], member(key, "far"));
        // Blame the member the file gave, so the message points at the line to fix.
        const auto blame = [&](const char* a, const char* b) { return member(key, v.contains(a) ? a : b); };
        if (!(glm::length(c.target - c.eye) > 0.f)) fail(blame("target", "eye"), "eye and target are the same point");
        if (!(c.fovYDeg > 0.f && c.fovYDeg < 180.f))
            fail(member(key, "fov_y"), "expected a field of view in (0, 180) degrees, got " + text(c.fovYDeg));
        if (!(c.far > c.near))
            fail(blame("far", "near"), "far (" + text(c.far) + ") must be greater than near (" + text(c.near) + ")");
        return c;
    }

    /// A light object; members it does not give keep `l`'s (docs/design.md §3.10).
    scene::Light light(const json& v, const std::string& key, scene::Light l) const {
        checkObject(v, key, {"type", "direction", "position", "cone_deg", "range", "radius", "settings"});
        if (v.contains("type")) {
            const std::string type = string(v["type"], member(key, "type"));
            if (type == "directional") l.type = scene::LightType::Directional;
            else if (type == "spot") l.type = scene::LightType::Spot;
            else if (type == "point") l.type = scene::LightType::Point;
            else fail(member(key, "type"), "unknown light type \"" + type + "\" (known: directional, spot, point)");
        }
        if (v.contains("direction")) l.direction = direction(v["direction"], member(key, "direction"));
        if (v.contains("position")) l.position = vec3(v["position"], member(key, "position"));
        if (v.contains("cone_deg")) {
            l.coneDeg = number(v["cone_deg"], member(key, "cone_deg"));
            if (!(l.coneDeg > 0.f && l.coneDeg < 180.f))
                fail(member(key, "cone_deg"), "expected a cone angle in (0, 180) degrees, got " + text(l.coneDeg));
        }
        if (v.contains("range")) l.range = positive(v["range"], member(key, "range"));
        if (v.contains("radius")) {
            l.radius = number(v["radius"], member(key, "radius"));
            if (!(l.radius >= 0.f)) fail(member(key, "radius"), "expected a radius ≥ 0, got " + text(l.radius));
        }
        if (v.contains("settings")) {
            try {
                l.settings = settingAssignments(v["settings"]);
            } catch (const std::invalid_argument& e) {
                fail(member(key, "settings"), e.what());
            }
        }
        return l;
    }

    /// `"lights": [...]`: 1 to kMaxLights light objects, each starting from `base`.
    std::vector<scene::Light> lights(const json& v, const std::string& key, const scene::Light& base) const {
        if (!v.is_array() || v.empty() || v.size() > scene::kMaxLights)
            fail(key, "expected an array of 1 to " + std::to_string(scene::kMaxLights) + " lights, got " +
                          describeJsonValue(v));
        std::vector<scene::Light> out;
        for (size_t i = 0; i < v.size(); ++i) out.push_back(light(v[i], element(key, i), base));
        return out;
    }

private:
    std::string file_;
};

// ---- [SECTION] Placement --------------------------------------------------------------------

/// T·R·S of a mesh entry, applied after the mesh's own transform.
struct Placement {
    glm::mat4 matrix{1.f};
    glm::mat3 rotation{1.f};
    float maxScale = 1.f;
};

/// Rotations apply about x, then y, then z (R = Rz·Ry·Rx), the usual CAD Euler convention.
glm::mat4 rotationXyz(const glm::vec3& deg) {
    glm::mat4 r(1.f);
    r = glm::rotate(r, glm::radians(deg.z), {0.f, 0.f, 1.f});
    r = glm::rotate(r, glm::radians(deg.y), {0.f, 1.f, 0.f});
    return glm::rotate(r, glm::radians(deg.x), {1.f, 0.f, 0.f});
}

Placement readPlacement(const Reader& r, const json& e, const std::string& key) {
    glm::vec3 t(0.f), rot(0.f), s(1.f);
    if (e.contains("translate")) t = r.vec3(e["translate"], member(key, "translate"));
    if (e.contains("rotate_deg")) rot = r.vec3(e["rotate_deg"], member(key, "rotate_deg"));
    if (e.contains("scale")) {
        const std::string k = member(key, "scale");
        const json& v = e["scale"];
        if (v.is_number()) s = glm::vec3(r.positive(v, k));
        else if (v.is_array() && v.size() == 3)
            s = {r.positive(v[0], element(k, 0)), r.positive(v[1], element(k, 1)), r.positive(v[2], element(k, 2))};
        else r.fail(k, "expected a positive number or 3 positive numbers, got " + describeJsonValue(v));
    }
    const glm::mat4 rm = rotationXyz(rot);
    Placement p;
    p.matrix = glm::translate(glm::mat4(1.f), t) * rm * glm::scale(glm::mat4(1.f), s);
    p.rotation = glm::mat3(rm);
    p.maxScale = std::max({s.x, s.y, s.z});
    return p;
}

/// An entry's placements (docs/design.md §2 "Instances"): `"instances"`, a list of
/// {translate, rotate_deg, scale}, or `"grid"`, {count: [nx, ny, nz], spacing, origin}; each is
/// applied after the entry's own translate/rotate_deg/scale. Empty: the entry is not instanced.
std::vector<glm::mat4> readInstances(const Reader& r, const json& e, const std::string& key) {
    const std::string most = std::to_string(scene::kMaxInstances);
    if (e.contains("instances") && e.contains("grid"))
        r.fail(member(key, "grid"), "expected one of \"instances\" or \"grid\", not both");
    std::vector<glm::mat4> out;
    if (e.contains("instances")) {
        const std::string k = member(key, "instances");
        const json& list = e["instances"];
        if (!list.is_array() || list.empty() || list.size() > scene::kMaxInstances)
            r.fail(k, "expected an array of 1 to " + most + " placements, got " + describeJsonValue(list));
        out.reserve(list.size());
        for (size_t i = 0; i < list.size(); ++i) {
            r.checkObject(list[i], element(k, i), {"translate", "rotate_deg", "scale"});
            out.push_back(readPlacement(r, list[i], element(k, i)).matrix);
        }
    } else if (e.contains("grid")) {
        const std::string k = member(key, "grid");
        const json& g = e["grid"];
        r.checkObject(g, k, {"count", "spacing", "origin"});
        if (!g.contains("count") || !g.contains("spacing")) r.fail(k, "expected \"count\" and \"spacing\"");
        const std::string kc = member(k, "count");
        const json& c = g["count"];
        if (!c.is_array() || c.size() != 3) r.fail(kc, "expected 3 integers [nx, ny, nz], got " + describeJsonValue(c));
        std::array<uint32_t, 3> count{};
        uint64_t total = 1;
        for (size_t i = 0; i < 3; ++i) {
            count[i] = r.unsignedInt(c[i], element(kc, i), 1, uint32_t(scene::kMaxInstances));
            total *= count[i];
        }
        if (total > scene::kMaxInstances)
            r.fail(kc, std::to_string(total) + " placements; at most " + most + " per entry");
        const glm::vec3 origin = g.contains("origin") ? r.vec3(g["origin"], member(k, "origin")) : glm::vec3(0.f);
        out = scene::gridInstances(count, r.vec3(g["spacing"], member(k, "spacing")), origin);
    }
    return out;
}

/// Chunk bounds are world space: recompute them for the mesh's (new) transform from the chunk's
/// own triangles, which is exact and keeps the triangle order chunkMesh chose.
void reboundChunks(scene::Mesh& mesh) {
    if (mesh.chunks.empty()) scene::chunkMesh(mesh);
    else scene::reboundRuns(mesh);
}

void place(scene::Mesh& mesh, const Placement& p) {
    if (mesh.instanced()) { // a file's repeated part: its chunk boxes stay in the mesh's own space
        for (glm::mat4& m : mesh.instances) m = p.matrix * m;
        return;
    }
    mesh.transform = p.matrix * mesh.transform;
    reboundChunks(mesh);
}

/// Places `mesh` at each of the entry's placements, in front of any it has (a glTF file's
/// instances), at most kMaxInstances in all.
void instance(const Reader& r, const std::string& key, scene::Mesh& mesh, const std::vector<glm::mat4>& placements) {
    if (placements.empty()) return;
    if (!mesh.instanced()) {
        mesh.instances = placements;
        return;
    }
    const uint64_t total = uint64_t(placements.size()) * mesh.instances.size();
    if (total > scene::kMaxInstances)
        r.fail(key, "'" + mesh.name + "' would be placed " + std::to_string(total) + " times; at most " +
                        std::to_string(scene::kMaxInstances));
    std::vector<glm::mat4> out;
    out.reserve(size_t(total));
    for (const glm::mat4& e : placements)
        for (const glm::mat4& g : mesh.instances) out.push_back(e * g);
    mesh.instances = std::move(out);
}

/// Placements compose: two finite translations or scales can reach infinity, and a mesh there has
/// no bounds to frame, cull or trace.
void checkFinitePlacements(const Reader& r, const std::string& key, const scene::Mesh& mesh) {
    if (const size_t i = mesh.firstPlacementBeyondFloat(); i < mesh.placementCount())
        r.fail(key, "'" + mesh.name + "' placement " + std::to_string(i) +
                        " lies beyond the float range (translate, scale or instances too large)");
}

/// A built-in scene's camera follows its meshes, so its view of them stays the same.
scene::Camera place(scene::Camera c, const Placement& p) {
    c.eye = glm::vec3(p.matrix * glm::vec4(c.eye, 1.f));
    c.target = glm::vec3(p.matrix * glm::vec4(c.target, 1.f));
    c.up = p.rotation * c.up;
    c.near *= p.maxScale;
    c.far *= p.maxScale;
    return c;
}

// ---- [SECTION] Scene pieces -----------------------------------------------------------------

scene::Mesh makeGround(const scene::Aabb& meshBounds, std::optional<float> size, std::optional<float> height,
                       glm::vec3 color) {
    const glm::vec3 e = meshBounds.extent();
    const float footprint = std::max(e.x, e.z);
    if (!size) size = footprint > 0.f ? kGroundFootprintFactor * footprint : 100.f;
    if (!height) height = meshBounds.empty() ? 0.f : meshBounds.lo.y;
    const glm::vec3 c = meshBounds.empty() ? glm::vec3(0.f) : meshBounds.center();
    scene::MeshBuilder ground("ground", color);
    ground.addGroundGrid({c.x, *height, c.z}, *size, kGroundCells);
    return ground.build();
}

/// frameCamera() on the meshes, with far pushed out to the whole scene (the ground plane is much
/// wider than the model and would otherwise be cut off in the distance).
scene::Camera framedCamera(const scene::Aabb& meshBounds, const scene::Aabb& sceneBounds) {
    scene::Camera c = frameCamera(meshBounds.empty() ? sceneBounds : meshBounds);
    for (const auto& corner : sceneBounds.corners()) c.far = std::max(c.far, 1.05f * glm::length(corner - c.eye));
    return c;
}

/// Scene::bounds() for a bare mesh list: every placement's chunk bounds (cheap).
scene::Aabb meshBounds(const std::vector<scene::Mesh>& meshes) {
    scene::Aabb b;
    for (const scene::Mesh& m : meshes)
        for (size_t i = 0; i < m.placementCount(); ++i) b.add(m.placementBounds(i));
    return b;
}

bool endsWithIgnoreCase(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - std::ptrdiff_t(suffix.size()), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
    });
}

// ---- [SECTION] The scene file ---------------------------------------------------------------

/// What the mesh entries contribute besides meshes: the first built-in scene's camera and light.
struct Defaults {
    std::optional<scene::Camera> camera;
    std::optional<scene::Light> light;
    std::optional<UpAxis> up; // for model files without "up" (--up); else their format's default
};

/// The `params` of a built-in scene that takes a triangle budget and a seed.
template <class Params> Params budgetParams(const Reader& r, const json& e, const std::string& key) {
    Params params;
    if (!e.contains("params")) return params;
    const std::string k = member(key, "params");
    const json& p = e["params"];
    r.checkObject(p, k, {"triangles", "seed"});
    // The upper bound keeps a typo from asking for tens of gigabytes; 64 M covers the 50 M-triangle
    // plant of docs/performance.md "Scale".
    if (p.contains("triangles"))
        params.targetTriangles = r.unsignedInt(p["triangles"], member(k, "triangles"), 1, 64'000'000);
    if (p.contains("seed")) params.seed = r.unsignedInt(p["seed"], member(k, "seed"), 0, UINT32_MAX);
    return params;
}

/// The plant's `params`: triangles placed in the world (instancing holds ≤ 750k of them), seed,
/// and whether to instance at all.
scene::PlantParams plantParams(const Reader& r, const json& e, const std::string& key) {
    scene::PlantParams params;
    if (!e.contains("params")) return params;
    const std::string k = member(key, "params");
    const json& p = e["params"];
    r.checkObject(p, k, {"triangles", "seed", "instanced"});
    if (p.contains("triangles"))
        params.targetTriangles = r.unsignedInt(p["triangles"], member(k, "triangles"), 1, UINT32_MAX);
    if (p.contains("seed")) params.seed = r.unsignedInt(p["seed"], member(k, "seed"), 0, UINT32_MAX - 3);
    if (p.contains("instanced")) {
        if (!p["instanced"].is_boolean())
            r.fail(member(k, "instanced"), "expected true or false, got " + describeJsonValue(p["instanced"]));
        params.instanced = p["instanced"].get<bool>();
        // Un-instanced, every placement's arrays are copies: the piperack's budget cap applies.
        if (!params.instanced && params.targetTriangles > 64'000'000)
            r.fail(member(k, "triangles"), "at most 64000000 triangles without instancing");
    }
    return params;
}

scene::Scene builtinEntry(const Reader& r, const json& e, const std::string& key) {
    const std::string name = r.string(e["builtin"], member(key, "builtin"));
    const auto& names = scene::builtinSceneNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        r.fail(member(key, "builtin"), "unknown built-in scene '" + name + "' (built-in scenes: " + list + ")");
    }
    if (name == "platform") return scene::makePlatformScene(budgetParams<scene::PlatformParams>(r, e, key));
    if (name == "piperack") return scene::makePiperackScene(budgetParams<scene::PiperackParams>(r, e, key));
    if (name == "plant") return scene::makePlantScene(plantParams(r, e, key));
    if (e.contains("params")) r.fail(member(key, "params"), "the " + name + " scene takes no parameters");
    return scene::makeBuiltinScene(name);
}

std::vector<scene::Mesh> fileEntry(const Reader& r, const json& e, const std::string& key, const fs::path& folder,
                                   const Progress& progress, std::optional<UpAxis> up) {
    if (e.contains("up")) {
        const std::string text = r.string(e["up"], member(key, "up"));
        up = parseUpAxis(text);
        if (!up) r.fail(member(key, "up"), "expected one of y, z, -y, -z, x, -x, got '" + text + "'");
    }
    const std::string k = member(key, "file");
    const std::string file = r.string(e["file"], k);
    if (file.empty()) r.fail(k, "expected a file name, got an empty string");
    const fs::path p(file);
    try {
        return loadModel((p.is_absolute() ? p : folder / p).string(), {}, progress, up).meshes;
    } catch (const std::exception& ex) {
        r.fail(k, ex.what()); // loadModel's own "FILE: problem"
    }
}

void readMeshEntry(const Reader& r, const json& e, const std::string& key, const fs::path& folder,
                   const Progress& progress, scene::Scene& scene, Defaults& defaults) {
    r.checkObject(
        e, key, {"file", "builtin", "params", "up", "translate", "rotate_deg", "scale", "color", "instances", "grid"});
    if (e.contains("builtin") && e.contains("up")) r.fail(member(key, "up"), "only model files take an up axis");
    if (e.contains("file") == e.contains("builtin")) r.fail(key, "expected exactly one of \"file\" or \"builtin\"");
    if (e.contains("file") && e.contains("params"))
        r.fail(member(key, "params"), "only built-in scenes take parameters");
    // Check the cheap members before loading anything.
    const Placement placement = readPlacement(r, e, key);
    const std::vector<glm::mat4> instances = readInstances(r, e, key);
    std::optional<glm::vec3> color;
    if (e.contains("color")) color = r.color(e["color"], member(key, "color"));

    std::vector<scene::Mesh> meshes;
    if (e.contains("builtin")) {
        if (progress) progress(0.f, "building");
        scene::Scene builtin = builtinEntry(r, e, key);
        if (progress) progress(1.f, "building");
        if (!defaults.camera) defaults.camera = place(builtin.camera, placement);
        if (!defaults.light) defaults.light = scene::Light{placement.rotation * builtin.lights[0].direction};
        meshes = std::move(builtin.meshes);
    } else {
        meshes = fileEntry(r, e, key, folder, progress, defaults.up);
    }
    for (scene::Mesh& m : meshes) {
        place(m, placement);
        instance(r, key, m, instances);
        checkFinitePlacements(r, key, m);
        if (color) m.color = *color;
        scene.meshes.push_back(std::move(m));
    }
}

/// Scales each entry's progress into its share of the whole file.
Progress entryProgress(const Progress& progress, size_t index, size_t count) {
    if (!progress) return {};
    return [progress, index, count](float f, std::string_view stage) {
        progress((static_cast<float>(index) + std::clamp(f, 0.f, 1.f)) / static_cast<float>(count), stage);
    };
}

void readMeshes(const Reader& r, const json& j, const fs::path& folder, const Progress& progress, scene::Scene& scene,
                Defaults& defaults) {
    if (!j.contains("meshes")) return;
    const json& list = j["meshes"];
    if (!list.is_array()) r.fail("meshes", "expected an array, got " + describeJsonValue(list));
    for (size_t i = 0; i < list.size(); ++i)
        readMeshEntry(r, list[i], element("meshes", i), folder, entryProgress(progress, i, list.size()), scene,
                      defaults);
}

void readGround(const Reader& r, const json& j, scene::Scene& scene) {
    if (!j.contains("ground")) return;
    const json& g = j["ground"];
    r.checkObject(g, "ground", {"size", "height", "color"});
    std::optional<float> size, height;
    if (g.contains("size")) size = r.positive(g["size"], "ground.size");
    if (g.contains("height")) height = r.number(g["height"], "ground.height");
    const glm::vec3 color = g.contains("color") ? r.color(g["color"], "ground.color") : kGroundColor;
    scene.meshes.push_back(makeGround(scene.bounds(), size, height, color));
}

/// "occluder_edge": [[x,y,z], [x,y,z]], two distinct finite points in world space.
void readOccluderEdge(const Reader& r, const json& j, scene::Scene& scene) {
    if (!j.contains("occluder_edge")) return;
    const json& v = j["occluder_edge"];
    if (!v.is_array() || v.size() != 2)
        r.fail("occluder_edge", "expected 2 points [[x,y,z], [x,y,z]], got " + describeJsonValue(v));
    const std::array<glm::vec3, 2> edge{r.vec3(v[0], element("occluder_edge", 0)),
                                        r.vec3(v[1], element("occluder_edge", 1))};
    if (!(glm::length(edge[1] - edge[0]) > 0.f)) r.fail("occluder_edge", "the two points are the same");
    scene.occluderEdge = edge;
}

void readViews(const Reader& r, const json& j, SceneFile& f) {
    if (!j.contains("views")) return;
    const json& views = j["views"];
    if (!views.is_object()) r.fail("views", "expected an object of named views, got " + describeJsonValue(views));
    for (const auto& [name, v] : views.items()) {
        const std::string key = "views." + name;
        if (name.empty()) r.fail("views", "a view needs a non-empty name");
        r.checkObject(v, key, {"camera", "light"});
        CanonicalView view{f.scene.camera, f.scene.lights[0]};
        if (v.contains("camera")) view.camera = r.camera(v["camera"], member(key, "camera"), f.scene.camera);
        if (v.contains("light")) view.light = r.light(v["light"], member(key, "light"), f.scene.lights[0]);
        f.views[name] = view;
    }
}

ScenePath readPath(const Reader& r, const json& v, const std::string& key, const scene::Scene& scene) {
    r.checkObject(v, key, {"camera", "light", "light_position", "light_index"});
    if (!v.contains("camera") && !v.contains("light") && !v.contains("light_position"))
        r.fail(key, "expected \"camera\", \"light\" or \"light_position\"");
    ScenePath path;
    if (v.contains("camera")) {
        const std::string k = member(key, "camera");
        const json& list = v["camera"];
        if (!list.is_array() || list.empty())
            r.fail(k, "expected a non-empty array of cameras, got " + describeJsonValue(list));
        for (size_t i = 0; i < list.size(); ++i) path.cameras.push_back(r.camera(list[i], element(k, i), scene.camera));
    }
    if (v.contains("light")) {
        const std::string k = member(key, "light");
        const json& list = v["light"];
        if (!list.is_array() || list.empty())
            r.fail(k, "expected a non-empty array of light directions, got " + describeJsonValue(list));
        for (size_t i = 0; i < list.size(); ++i) path.lights.push_back(r.direction(list[i], element(k, i)));
    }
    if (v.contains("light_index")) {
        const uint32_t last = uint32_t(scene.lights.size() - 1);
        path.lightIndex = r.unsignedInt(v["light_index"], member(key, "light_index"), 0, last);
    }
    if (v.contains("light_position")) {
        const std::string k = member(key, "light_position");
        const json& list = v["light_position"];
        if (!list.is_array() || list.empty())
            r.fail(k, "expected a non-empty array of light positions, got " + describeJsonValue(list));
        if (!scene.lights[path.lightIndex].positional())
            r.fail(k, "light " + std::to_string(path.lightIndex) + " is directional: it has no position to move");
        for (size_t i = 0; i < list.size(); ++i) path.lightPositions.push_back(r.vec3(list[i], element(k, i)));
    }
    return path;
}

void readPaths(const Reader& r, const json& j, SceneFile& f) {
    if (!j.contains("paths")) return;
    const json& paths = j["paths"];
    if (!paths.is_object()) r.fail("paths", "expected an object of named paths, got " + describeJsonValue(paths));
    for (const auto& [name, v] : paths.items()) {
        if (name.empty()) r.fail("paths", "a path needs a non-empty name");
        f.paths[name] = readPath(r, v, "paths." + name, f.scene);
    }
}

/// "camera", then "light" or "lights" (not both): a scene file's top level, or a check case.
void readCameraAndLights(const Reader& r, const json& j, scene::Scene& scene, const scene::Camera& camera,
                         const scene::Light& light) {
    scene.camera = j.contains("camera") ? r.camera(j["camera"], "camera", camera) : camera;
    if (j.contains("light") && j.contains("lights")) r.fail("lights", "give \"light\" or \"lights\", not both");
    if (j.contains("lights")) scene.lights = r.lights(j["lights"], "lights", light);
    else if (j.contains("light")) scene.lights = {r.light(j["light"], "light", light)};
}

SceneFile readSceneFile(const std::string& path, const json& j, const Progress& progress, std::optional<UpAxis> up) {
    const Reader r(path);
    r.checkObject(
        j, "",
        {"name", "description", "meshes", "ground", "camera", "light", "lights", "occluder_edge", "views", "paths"});
    SceneFile f;
    f.scene.name = j.contains("name") ? r.string(j["name"], "name") : fs::path(path).stem().string();
    if (j.contains("description")) (void)r.string(j["description"], "description");

    Defaults defaults;
    defaults.up = up;
    readMeshes(r, j, fs::path(path).parent_path(), progress, f.scene, defaults);
    const scene::Aabb models = f.scene.bounds();
    readGround(r, j, f.scene);
    if (f.scene.meshes.empty()) r.fail("", "empty scene: no meshes and no ground");

    const scene::Camera base = defaults.camera ? *defaults.camera : framedCamera(models, f.scene.bounds());
    const scene::Light light = defaults.light ? *defaults.light : defaultLight();
    f.scene.lights = {light};
    readCameraAndLights(r, j, f.scene, base, light);
    readOccluderEdge(r, j, f.scene);
    readViews(r, j, f);
    readPaths(r, j, f);
    return f;
}

SceneFile withDefaultView(scene::Scene scene) {
    SceneFile f;
    f.views["default"] = CanonicalView{scene.camera, scene.lights[0]};
    f.scene = std::move(scene);
    return f;
}

SceneFile modelScene(const std::string& path, const Progress& progress, std::optional<UpAxis> up) {
    scene::Scene scene;
    scene.name = fs::path(path).stem().string();
    scene.meshes = loadModel(path, {}, progress, up).meshes;
    const scene::Aabb models = meshBounds(scene.meshes);
    scene.meshes.push_back(makeGround(models, std::nullopt, std::nullopt, kGroundColor));
    scene.camera = framedCamera(models, scene.bounds());
    scene.lights[0] = defaultLight();
    return withDefaultView(std::move(scene));
}

} // namespace

// ---- [SECTION] Public functions -------------------------------------------------------------

scene::Camera frameCamera(const scene::Aabb& bounds, float fovYDeg) {
    scene::Camera c;
    if (bounds.empty()) return c;
    fovYDeg = std::clamp(fovYDeg, 1.f, 179.f);
    const float diag = std::max(glm::length(bounds.extent()), 1e-3f); // a single point still gets a camera
    // The bounds' sphere (radius diag/2) fits a cone of half-angle fovY/2 at this distance, so a
    // viewport at least as wide as it is tall sees the whole box.
    const float distance = 0.5f * diag / std::sin(glm::radians(0.5f * fovYDeg));
    // 3/4 view: 40° round from +z towards +x, 30° above the horizon.
    const float azimuth = glm::radians(40.f), elevation = glm::radians(30.f);
    const glm::vec3 toEye{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                          std::cos(elevation) * std::cos(azimuth)};
    c.target = bounds.center();
    c.eye = c.target + distance * toEye;
    c.up = {0.f, 1.f, 0.f};
    c.fovYDeg = fovYDeg;
    c.near = diag / 1000.f;
    c.far = 3.f * diag;
    return c;
}

scene::Light defaultLight() {
    // From the left of frameCamera()'s view: shadows fall to the right, visible from the eye.
    return scene::Light{{0.6f, -1.f, -0.2f}};
}

void applyViewKeys(SceneFile& f, const json& j, const std::string& where) {
    const Reader r(where);
    if (!j.is_object()) r.fail("", std::string("expected an object, got ") + j.type_name());
    const scene::Camera camera = f.scene.camera;
    const scene::Light light = f.scene.lights.empty() ? defaultLight() : f.scene.lights[0];
    readCameraAndLights(r, j, f.scene, camera, light);
    readViews(r, j, f);
}

SceneFile loadSceneFile(const std::string& path, const Progress& progress, std::optional<UpAxis> up) {
    const json j = readJsonFile(path, path, kMaxSceneFileBytes, kMaxSceneFileDepth);
    if (!j.is_object())
        throw fileError(path, std::string("expected a JSON object at the top level, got ") + j.type_name());
    return readSceneFile(path, j, progress, up);
}

SceneFile resolveScene(const std::string& nameOrPath, const Progress& progress, std::optional<UpAxis> up) {
    const auto& names = scene::builtinSceneNames();
    if (std::find(names.begin(), names.end(), nameOrPath) != names.end()) {
        if (progress) progress(0.f, "building");
        SceneFile f = withDefaultView(scene::makeBuiltinScene(nameOrPath));
        if (progress) progress(1.f, "building");
        return f;
    }
    if (endsWithIgnoreCase(nameOrPath, ".json")) return loadSceneFile(nameOrPath, progress, up);
    if (isModelFile(nameOrPath)) return modelScene(nameOrPath, progress, up);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    // The extensions are those model_loader.h documents for loadModel().
    throw std::runtime_error("unknown scene '" + nameOrPath + "': expected a built-in scene (" + list +
                             "), a scene file (.json) or a model file (.obj, .stl, .off, .ply, .gltf, .glb)");
}

} // namespace geometry::io
