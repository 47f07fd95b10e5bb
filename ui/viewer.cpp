#include "viewer.h"

#include "orbit_camera.h"
#include "settings_panel.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>

namespace ui {

namespace {

struct ImGuiSession {
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        float sx = 1.f, sy = 1.f;
        glfwGetWindowContentScale(window, &sx, &sy);
        const float scale = std::clamp(std::max(sx, sy), 1.f, 4.f);
        ImFontConfig font;
        font.SizePixels = 13.f * scale;
        ImGui::GetIO().Fonts->AddFontDefault(&font);
        ImGui::StyleColorsDark();
        ImGui::GetStyle().ScaleAllSizes(scale);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 430 core");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
};

ImTextureID textureId(GLuint t) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t)); }

/// Shows a GL texture filling the available region; returns its size in pixels.
ImVec2 showTexture(GLuint texture, float aspect) {
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.x = std::max(avail.x, 1.f);
    avail.y = std::max(avail.y, 1.f);
    ImVec2 size = avail;
    if (aspect > 0.f) size = avail.x / avail.y > aspect ? ImVec2(avail.y * aspect, avail.y) : ImVec2(avail.x, avail.x / aspect);
    ImGui::Image(textureId(texture), size, ImVec2(0, 1), ImVec2(1, 0)); // GL textures are bottom-up
    return size;
}

} // namespace

int runViewer(geometry::Scene scene, const ViewerOptions& options) {
    renderer::GlfwWindowContext window(1600, 900, "shadowscope — " + scene.name);
    ImGuiSession imgui(window.window());
    // Sticky keys: a press and release within one frame still reads as pressed once.
    glfwSetInputMode(window.window(), GLFW_STICKY_KEYS, GLFW_TRUE);
    renderer::Renderer renderer(scene);

    OrbitCamera orbit = OrbitCamera::from(scene.camera);
    SunAngles sun = SunAngles::from(scene.light.direction);
    geometry::ShadowSettings settings = options.settings;
    geometry::Viewport eyeSize{960, 540};
    std::string status;
    double cpuFrameMs = 0;
    bool f12WasDown = false;

    while (!glfwWindowShouldClose(window.window())) {
        glfwPollEvents();
        int fbW = 0, fbH = 0;
        glfwGetFramebufferSize(window.window(), &fbW, &fbH);
        if (fbW <= 0 || fbH <= 0) { // minimised: nothing to draw
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const bool f12Down = glfwGetKey(window.window(), GLFW_KEY_F12) == GLFW_PRESS;
        const bool f12Pressed = f12Down && !f12WasDown;
        f12WasDown = f12Down;
        orbit.applyTo(scene.camera);
        scene.light.direction = sun.direction();
        const geometry::ShadowPlan plan =
            geometry::planShadows(settings, scene.bounds(), scene.camera, scene.light, eyeSize);
        renderer::ViewOptions views;
        views.lightViewSize = std::clamp(settings.resolution, 16, 1024);
        views.unwarped = false; // not shown in this window
        renderer.render(plan, eyeSize, views);

        renderer::beginWindowFrame(fbW, fbH);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImGuiViewport* vp = ImGui::GetMainViewport();
        const float panelW = std::min(340.f * ImGui::GetIO().FontGlobalScale * ImGui::GetFontSize() / 13.f, vp->WorkSize.x * 0.4f);
        const float viewW = (vp->WorkSize.x - panelW) * 0.5f;

        ImGui::SetNextWindowPos(vp->WorkPos, ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(viewW, vp->WorkSize.y), ImGuiCond_Always);
        ImGui::Begin("Eye view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        {
            const ImVec2 avail = ImGui::GetContentRegionAvail();
            eyeSize = {std::max(16, int(avail.x)), std::max(16, int(avail.y))};
            showTexture(renderer.eyeTexture(), 0.f);
            if (ImGui::IsItemHovered()) {
                const ImGuiIO& io = ImGui::GetIO();
                if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) orbit.rotate(io.MouseDelta.x, io.MouseDelta.y);
                if (io.MouseWheel != 0.f) orbit.zoom(io.MouseWheel);
            }
        }
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + viewW, vp->WorkPos.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(viewW, vp->WorkSize.y), ImGuiCond_Always);
        ImGui::Begin("Light view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        showTexture(renderer.lightTexture(), 1.f);
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + 2 * viewW, vp->WorkPos.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(panelW, vp->WorkSize.y), ImGuiCond_Always);
        ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::Text("Scene: %s (%zu triangles)", scene.name.c_str(), scene.triangleCount());
        ImGui::Separator();
        ImGui::TextDisabled("Light");
        ImGui::SliderFloat("Azimuth", &sun.azimuthDeg, -180.f, 180.f, "%.1f deg");
        ImGui::SliderFloat("Elevation", &sun.elevationDeg, 1.f, 90.f, "%.1f deg");
        ImGui::Text("gamma (light vs view): %.1f deg", plan.gammaDeg);
        ImGui::Separator();
        ImGui::TextDisabled("Shadows");
        drawSettingsWidgets(settings);
        for (size_t i = 0; i < plan.splits.size(); ++i) {
            const auto& sp = plan.splits[i];
            ImGui::Text("split %zu: [%.2f, %.2f] n'=%s res %d", i, sp.near, sp.far,
                        sp.warped() ? std::to_string(sp.nPrime).c_str() : "inf", sp.resolution);
        }
        ImGui::Separator();
        ImGui::TextDisabled("Timing");
        const auto& st = renderer.stats();
        ImGui::Text("Frame (CPU): %.2f ms", cpuFrameMs);
        ImGui::Text("GPU shadow %.2f ms, eye %.2f ms", st.gpu.of(renderer::Pass::Shadow), st.gpu.of(renderer::Pass::Eye));
        ImGui::Text("Triangles: shadow %llu, eye %llu", static_cast<unsigned long long>(st.shadowTriangles),
                    static_cast<unsigned long long>(st.eyeTriangles));
        ImGui::Separator();
        ImGui::TextDisabled("Camera");
        ImGui::TextWrapped("Drag in the eye view to orbit, scroll to zoom.");
        if (ImGui::Button("Screenshot (F12)") || f12Pressed) {
            try {
                std::filesystem::create_directories(options.screenshotDir);
                const auto dir = std::filesystem::path(options.screenshotDir);
                renderer::writePng((dir / "eye.png").string(), renderer.readEye());
                renderer::writePng((dir / "light.png").string(), renderer.readLight());
                status = "saved " + (dir / "eye.png").string() + ", " + (dir / "light.png").string();
            } catch (const std::exception& e) {
                status = std::string("screenshot failed: ") + e.what();
            }
        }
        if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
        ImGui::End();

        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window.window());
        cpuFrameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    return 0;
}

} // namespace ui
