#pragma once
// Scene files (resources/scenes/*.json): meshes from model files or built-in scenes, placed by
// a transform each, an optional ground plane, camera, light, named canonical views and camera or
// light paths. Also resolveScene(), which turns whatever --scene names (a built-in scene, a scene
// file, a model file) into a scene.
//
// The format, every key with its type and default: docs/scene-files.md; its JSON Schema:
// resources/scene.schema.json (tests/test_scene_schema.cpp holds the two to the same files).
#include "geometry/io/model_loader.h"
#include "geometry/scene/scene.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace geometry::io {

/// Files above this size are refused before parsing (a scene file is a few hundred lines at most).
inline constexpr std::size_t kMaxSceneFileBytes = 1u << 20;
/// Objects and arrays may nest at most this deep (the deepest legal member uses 6 levels).
inline constexpr int kMaxSceneFileDepth = 16;

/// What is wrong in a scene file's content (a key, a value), "PATH: KEY.PATH: problem": bad input,
/// so the command line exits 2 for it as for a bad argument (a missing or unreadable file stays a
/// plain std::runtime_error).
struct SceneFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A named camera + light pair, for benchmarks and sweeps that must see the same thing every run.
struct CanonicalView {
    scene::Camera camera;
    scene::Light light;
};

/// A sequence of cameras or of light keys (or both), for animated sweeps: `lights` (directions) and
/// `lightPositions` move the scene's light `lightIndex` (docs/design.md §3.10).
struct ScenePath {
    std::vector<scene::Camera> cameras;
    std::vector<glm::vec3> lights;
    std::vector<glm::vec3> lightPositions;
    size_t lightIndex = 0;
};

struct SceneFile {
    scene::Scene scene;
    std::map<std::string, CanonicalView> views;
    std::map<std::string, ScenePath> paths;
};

/// Reads a scene file. Throws std::runtime_error with a one-line message "PATH: KEY.PATH: problem"
/// (or "PATH: problem" for file-level problems): missing or unreadable file, larger than
/// kMaxSceneFileBytes, nested deeper than kMaxSceneFileDepth, not JSON, not an object, unknown
/// keys, wrong types, numbers out of range, a model file that does not load (loadModel's message),
/// no meshes and no ground, eye == target, near <= 0, far <= near, fov_y outside (0, 180), a zero
/// light direction, an occluder_edge that is not two distinct finite points. `progress` sees the
/// model loads, scaled to the whole file.
/// `up`: the up axis of model files whose entry has no "up" (default: their format's).
[[nodiscard]] SceneFile loadSceneFile(const std::string& path, const Progress& progress = {},
                                      std::optional<UpAxis> up = std::nullopt);

/// What --scene names: a built-in scene name (one view, "default"), a scene file (*.json), or a
/// model file (isModelFile): its meshes on a ground plane 4× their footprint at their lowest point,
/// a framed camera, defaultLight(), one view "default". Throws std::runtime_error with a one-line
/// message; for anything else it lists the built-in names and the accepted extensions.
/// `up` is the model's up axis (loadModel), or the default for a scene file's model files.
[[nodiscard]] SceneFile resolveScene(const std::string& nameOrPath, const Progress& progress = {},
                                     std::optional<UpAxis> up = std::nullopt);

/// Another file's "camera", "light" or "lights", and "views" (a check case's) on top of a loaded
/// scene, read by the scene file's rules: the camera and lights start from the scene's, and the views
/// are added (a name the scene has is replaced). Other members of `j` are ignored. Throws
/// SceneFileError "WHERE: KEY.PATH: problem".
void applyViewKeys(SceneFile& f, const nlohmann::json& j, const std::string& where);

/// A 3/4 view from above looking at the centre of `bounds`, far enough that the bounds' sphere
/// fits the vertical field of view; near = diagonal / 1000, far = diagonal · 3.
[[nodiscard]] scene::Camera frameCamera(const scene::Aabb& bounds, float fovYDeg = 60.f);

/// A sun at ~55° elevation shining across frameCamera()'s view (γ ≈ 75°), so shadows are seen.
[[nodiscard]] scene::Light defaultLight();

} // namespace geometry::io
