#include "ui/chart_image.h"

#include "renderer/image.h"
#include "renderer/render_targets.h"
#include "ui/charts/chart_imgui.h"
#include "ui/imgui_setup.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>

namespace ui {

geometry::analysis::Image renderChartImage(const charts::Chart& chart, int width, int height) {
    width = std::clamp(width, 200, 8192);
    height = std::clamp(height, 150, 8192);
    ImGuiContext* previous = ImGui::GetCurrentContext();
    geometry::analysis::Image img;
    {
        ImGuiScope scope(1.f);
        renderer::ColorTarget target;
        target.ensure(width, height);
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(float(width), float(height));
        io.DeltaTime = 1.f / 60.f;
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        charts::drawChart(ImGui::GetBackgroundDrawList(), chart, {0.f, 0.f, float(width), float(height)});
        ImGui::Render();
        target.bindAndClear(1.f, 1.f, 1.f);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        img = renderer::readTexture(target.texture(), width, height);
        renderer::ColorTarget::unbind();
    }
    ImGui::SetCurrentContext(previous);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return img;
}

} // namespace ui
