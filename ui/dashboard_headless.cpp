#include "dashboard_headless.h"

#include "renderer/context.h"
#include "renderer/texture.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <stdexcept>

namespace ui {

HeadlessDashboard::HeadlessDashboard(LoadedScene scene, DashboardState state, DashboardOptions options, int width,
                                     int height)
    : imgui_(options.uiScale), width_(width), height_(height) {
    if (width < 200 || height < 150 || width > 8192 || height > 8192)
        throw std::invalid_argument("dashboard size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " outside 200x150 … 8192x8192");
    dashboard_ = std::make_unique<Dashboard>(std::move(scene), std::move(state), std::move(options));
    target_.ensure(width, height);
}

void HeadlessDashboard::frame(const PointerInput& pointer) {
    imgui_.makeCurrent();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width_), float(height_));
    io.DisplayFramebufferScale = ImVec2(1.f, 1.f);
    io.DeltaTime = 1.f / 60.f;
    io.MousePos = pointer.cursor ? ImVec2(pointer.cursor->x, pointer.cursor->y) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = pointer.buttons[size_t(b)];
    io.MouseWheel = pointer.wheel;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    dashboard_->frame(float(width_), float(height_));
    ImGui::Render();
    target_.bindAndClear(0.f, 0.f, 0.f);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void HeadlessDashboard::step(const PointerInput& input) {
    frame(input);
    glFinish();
    renderer::ColorTarget::unbind();
}

geometry::analysis::Image HeadlessDashboard::render(int frames) {
    for (int i = 0; i < std::max(frames, 1); ++i) frame({});
    // The statistics run on worker threads: wait for them, then one frame that shows them.
    if (dashboard_->finishBackgroundWork()) frame({});
    renderer::ColorTarget::unbind();
    return image();
}

geometry::analysis::Image HeadlessDashboard::image() const {
    geometry::analysis::Image img = renderer::readTexture(target_.texture(), width_, height_);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return img;
}

} // namespace ui
