#pragma once
// What the dashboard's background measurements (the trade-off sweep, Recommend) read at each step:
// the scene as shown with its truth and caster levels, the view size and the truth's samples; and
// the renderer of their own each keeps, made again when the scene changes.
#include "scene_loader.h"

#include "geometry/lod/caster_lod.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/renderer.h"

#include <memory>

namespace ui {

struct MeasureContext {
    LoadedScene& scene;
    int sceneGeneration = 0;                      // changes with every scene loaded
    const geometry::lod::SceneLod* lod = nullptr; // the caster levels, once built
    geometry::shadow::Viewport size{640, 360};    // the eye view's
    bool truth = false;                           // ground truth on (Views)
    int truthSamples = 1;                         // per pixel a side
    size_t light = 0;                             // the inspected light; the scene's others are drawn too
};

/// A renderer for background measurements, kept across steps while the scene stays.
class MeasureRenderer {
public:
    /// The renderer for `c`'s scene (made again after a scene change), with its caster levels.
    renderer::Renderer& get(const MeasureContext& c) {
        if (!renderer_ || generation_ != c.sceneGeneration) {
            renderer_ = std::make_unique<renderer::Renderer>(c.scene.file.scene);
            generation_ = c.sceneGeneration;
        }
        if (c.lod && !renderer_->hasCasterLod()) renderer_->setCasterLod(*c.lod);
        return *renderer_;
    }

private:
    std::unique_ptr<renderer::Renderer> renderer_;
    int generation_ = -1;
};

} // namespace ui
