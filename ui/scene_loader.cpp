#include "scene_loader.h"

#include <chrono>

namespace ui {

SceneLoader::~SceneLoader() {
    if (future_.valid()) future_.wait(); // the worker uses this object's progress fields
}

SceneLoadResult SceneLoader::loadNow(const std::string& nameOrPath, const geometry::io::Progress& progress,
                                     std::optional<geometry::io::UpAxis> up) {
    try {
        LoadedScene loaded;
        loaded.source = nameOrPath;
        loaded.file = geometry::io::resolveScene(
            nameOrPath,
            [&](float f, std::string_view stage) {
                if (progress) progress(0.9f * f, stage);
            },
            up);
        if (progress) progress(0.9f, "building the ray-tracing BVH");
        loaded.truth = std::make_unique<geometry::analysis::GroundTruth>(
            geometry::analysis::GroundTruth::borrowing(loaded.file.scene));
        if (progress) progress(1.f, "done");
        return loaded;
    } catch (const std::exception& e) {
        return std::string(e.what());
    } catch (...) {
        return std::string(nameOrPath + ": unknown error while loading");
    }
}

bool SceneLoader::start(const std::string& nameOrPath, std::optional<geometry::io::UpAxis> up) {
    if (busy()) return false;
    source_ = nameOrPath;
    progress_ = 0.f;
    {
        std::lock_guard lock(stageMutex_);
        stage_ = "starting";
    }
    future_ = std::async(std::launch::async, [this, nameOrPath, up] {
        return loadNow(
            nameOrPath,
            [this](float f, std::string_view stage) {
                progress_ = f;
                std::lock_guard lock(stageMutex_);
                stage_ = std::string(stage);
            },
            up);
    });
    return true;
}

std::string SceneLoader::stage() const {
    std::lock_guard lock(stageMutex_);
    return stage_;
}

std::optional<SceneLoadResult> SceneLoader::poll() {
    if (!future_.valid() || future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    return future_.get();
}

} // namespace ui
