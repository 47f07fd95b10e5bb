#pragma once
// What the dashboard's drawing and inspection of one side depend on, as plain comparable values
// (docs/design.md §2.6): a side is drawn again only when its PassInputs
// change, inspected again only when its InspectionInputs change, and the heatmap rebuilt only when
// its HeatmapInputs change. Hover, zoom, pan, tab switches and idle frames change none of them.
#include "dashboard_state.h"
#include "geometry/scene/scene.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/shadow_plan.h"

#include <cstdint>
#include <vector>

namespace ui {

struct PassInputs {
    geometry::shadow::ShadowSettings settings;
    geometry::scene::Camera camera;             // eye, target, up, fov, near, far
    std::vector<geometry::scene::Light> lights; // every light drawn, the sun applied
    size_t inspectedLight = 0;                  // drawn last; its maps are the light view's
    geometry::shadow::Viewport size{0, 0};      // the eye view at full resolution
    int lightViewSize = 0;
    int lightSplit = 0;
    bool overlays = true;
    bool unwarped = false;
    int sceneGeneration = 0;
    bool casterLod = false; // the renderer holds the scene's caster levels
    [[nodiscard]] bool operator==(const PassInputs&) const = default;
};

struct InspectionInputs {
    PassInputs passes;
    int truthSamples = 0; // per axis; 0: no ground truth
    [[nodiscard]] bool operator==(const InspectionInputs&) const = default;
};

struct HeatmapInputs {
    uint64_t inspectionA = 0, inspectionB = 0; // serial numbers of the inspections shown (0: none)
    int side = 0;
    bool comparing = false;
    HeatmapKind kind = HeatmapKind::Aliasing;
    float blend = 0.f;
    int texelGrid = 0;
    [[nodiscard]] bool operator==(const HeatmapInputs&) const = default;
};

} // namespace ui
