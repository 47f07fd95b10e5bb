#pragma once
// The dashboard rendered into an image without a window (`render --views dashboard`, tests):
// the same ImGui frames and the same layout as the GUI at the same size, drawn into an
// off-screen target on the current (OSMesa or EGL) context.
#include "dashboard.h"
#include "imgui_setup.h"
#include "renderer/render_targets.h"

#include <array>
#include <optional>

namespace ui {

/// Pointer state for one headless frame (tests, the dashboard benchmark): the cursor in dashboard
/// pixels (none: outside the window), the buttons held (left, right, middle), wheel steps.
struct PointerInput {
    std::optional<glm::vec2> cursor;
    std::array<bool, 3> buttons{};
    float wheel = 0.f;
};

class HeadlessDashboard {
public:
    /// Needs a current GL context. uiScale 1 matches a window on a normal-DPI monitor.
    HeadlessDashboard(LoadedScene scene, DashboardState state, DashboardOptions options, int width, int height);
    /// Runs `frames` frames (the first lays out and renders the views; later ones settle timings)
    /// and returns the last one's pixels.
    [[nodiscard]] geometry::analysis::Image render(int frames = 3);
    /// One frame with this input, its GL work finished (glFinish), the image not read back.
    void step(const PointerInput& input = {});
    /// The last frame's pixels.
    [[nodiscard]] geometry::analysis::Image image() const;
    [[nodiscard]] Dashboard& dashboard() noexcept { return *dashboard_; }

private:
    void frame(const PointerInput& pointer);
    ImGuiScope imgui_;
    std::unique_ptr<Dashboard> dashboard_;
    renderer::ColorTarget target_;
    int width_, height_;
};

} // namespace ui
