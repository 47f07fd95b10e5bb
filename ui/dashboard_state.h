#pragma once
// Everything the dashboard's user chooses, as a plain value: the two settings sets (A and B for
// comparison), the view options, the camera and the lights, the layout. The GUI edits it, the headless
// dashboard takes it as given, and the config file persists part of it.
#include "dashboard_layout.h"
#include "geometry/shadow/settings.h"
#include "image_view.h"
#include "orbit_camera.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace ui {

enum class HeatmapKind { Aliasing, Truth, Splits, Texels, Difference, Soft, Count };
enum class CompareMode { Off, SideBySide, Split, Count };
enum class ViewPanel { Eye, Light, Heatmap, Count };

/// Names used in widgets and in the config file.
[[nodiscard]] std::string_view heatmapName(HeatmapKind k) noexcept;
[[nodiscard]] std::string_view compareName(CompareMode m) noexcept;

/// What the views show (the dashboard's "Views" group).
struct ViewSettings {
    int lightSplit = 0;    // which split's map the light view shows
    bool overlays = true;  // frusta, B, P drawn over the light view
    bool unwarped = false; // the light view without the warp (the same map's texels)
    HeatmapKind heatmap = HeatmapKind::Aliasing;
    float heatmapBlend = 0.f; // eye image under the heatmap: 0 heatmap alone … 1 opaque
    int texelGrid = 4;        // texels heatmap: a line every N texels
    bool truth = true;        // ray-traced ground truth for the statistics and the truth view
    int truthSamples = 1;     // truth rays per pixel per axis (N × N over the footprint)
    CompareMode compare = CompareMode::Off;
    float splitPosition = 0.5f; // split-screen compare: where B starts, 0..1 of the eye view
    bool lightGizmo = true;     // the lights drawn over the eye view
};

struct DashboardState {
    std::array<geometry::shadow::ShadowSettings, 2> settings{}; // A, B
    int editing = 0;                                            // which set the controls edit (0 = A)
    ViewSettings views;
    OrbitCamera camera;
    /// The scene's lights (docs/design.md §3.10), as the Lights group edits them. Empty: the scene's
    /// own, taken when the dashboard opens (and on every scene load).
    std::vector<geometry::scene::Light> lights;
    int inspectedLight = 0; // the light the light view, stats and heatmaps describe (drawn last)
    /// The scene (its source) `lights` belong to: a saved list is used only for that scene; "" any.
    std::string lightsScene;
    SunAngles sun;         // edits the inspected light's direction
    float flySpeed = 10.f; // scene units per second in fly mode
    LayoutFractions layout;
    std::array<ImageView, static_cast<int>(ViewPanel::Count)> imageViews{};
    /// Scene and model files opened (browser, file field, dropped), newest first (file_list.h).
    std::vector<std::string> recentFiles;
};

} // namespace ui
