#pragma once
// Loads a scene (built-in name, scene file or model file) on a worker thread so the dashboard
// keeps drawing, with the loader's progress to show; builds the ray-tracing BVH there too. On
// failure the caller keeps its current scene and shows the one-line reason.
#include "geometry/analysis/ground_truth.h"
#include "geometry/io/scene_file.h"

#include <atomic>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <variant>

namespace ui {

struct LoadedScene {
    std::string source; // what was asked for
    geometry::io::SceneFile file;
    std::unique_ptr<geometry::analysis::GroundTruth> truth;
};

/// The outcome of one load: the scene, or the error message.
using SceneLoadResult = std::variant<LoadedScene, std::string>;

class SceneLoader {
public:
    SceneLoader() = default;
    ~SceneLoader();
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;

    /// Starts loading; false (and nothing starts) while another load runs.
    /// `up`: a model file's up axis (empty: its format's default; resolveScene).
    bool start(const std::string& nameOrPath, std::optional<geometry::io::UpAxis> up = std::nullopt);
    [[nodiscard]] bool busy() const noexcept { return future_.valid(); }
    /// Fraction done (0..1) and the current stage, for a progress bar.
    [[nodiscard]] float progress() const noexcept { return progress_.load(); }
    [[nodiscard]] std::string stage() const;
    [[nodiscard]] const std::string& source() const noexcept { return source_; }
    /// The finished load, once; nullopt while running or idle.
    [[nodiscard]] std::optional<SceneLoadResult> poll();

    /// Loads on the calling thread (start-up, headless): same steps, same result.
    [[nodiscard]] static SceneLoadResult loadNow(const std::string& nameOrPath,
                                                 const geometry::io::Progress& progress = {},
                                                 std::optional<geometry::io::UpAxis> up = std::nullopt);

private:
    std::future<SceneLoadResult> future_;
    std::atomic<float> progress_{0.f};
    mutable std::mutex stageMutex_;
    std::string stage_, source_;
};

} // namespace ui
