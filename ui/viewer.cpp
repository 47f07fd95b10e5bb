#include "viewer.h"

#include "dashboard_config.h"
#include "imgui_setup.h"
#include "renderer/context.h"
#include "renderer/texture.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>

namespace ui {

namespace {

/// SIGINT/SIGTERM ask the window to close, so the config is saved as on a normal close.
volatile std::sig_atomic_t quitRequested = 0;
extern "C" void onQuitSignal(int) { quitRequested = 1; }

float contentScale(GLFWwindow* window) {
    float sx = 1.f, sy = 1.f;
    glfwGetWindowContentScale(window, &sx, &sy);
    return clampUiScale(std::max(sx, sy));
}

/// F12 presses counted by a key callback, not by polling the key: a press and release that arrive
/// while the loop sleeps or skips a frame still count once each.
int f12Presses = 0;
GLFWkeyfun previousKeyCallback = nullptr;
extern "C" void onKey(GLFWwindow* w, int key, int scancode, int action, int mods) {
    if (key == GLFW_KEY_F12 && action == GLFW_PRESS) ++f12Presses;
    if (previousKeyCallback) previousKeyCallback(w, key, scancode, action, mods);
}

/// WASD/QE as (right, up, forward).
glm::vec3 flyKeys(GLFWwindow* w) {
    const auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.f : 0.f; };
    return {down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
            down(GLFW_KEY_W) - down(GLFW_KEY_S)};
}

} // namespace

int runViewer(LoadedScene scene, const ViewerOptions& options) {
    DashboardState state;
    state.camera = OrbitCamera::from(scene.file.scene.camera);
    state.sun = SunAngles::from(scene.file.scene.light.direction);
    WindowGeometry geometry;
    std::string startStatus;
    const std::filesystem::path configPath = !options.configPath.empty() ? options.configPath
                                             : configDirectory().empty() ? std::filesystem::path()
                                                                         : configDirectory() / "dashboard.json";
    if (options.persist && !configPath.empty()) {
        if (auto error = loadDashboardConfig(configPath, state, geometry)) {
            // Keep the user's broken file next to the fresh one rather than overwriting it.
            std::error_code ec;
            const std::filesystem::path bad = configPath.string() + ".bad";
            std::filesystem::rename(configPath, bad, ec);
            startStatus = "ignored the config file (kept as " + bad.filename().string() + "): " + *error;
            std::cerr << "shadowscope: " << startStatus << '\n';
        }
    }
    if (options.settings) state.settings[0] = state.settings[1] = *options.settings;

    renderer::GlfwWindowContext window(geometry.width, geometry.height, "shadowscope — " + scene.file.scene.name);
    GLFWwindow* w = window.window();
    glfwSetInputMode(w, GLFW_STICKY_KEYS, GLFW_TRUE); // a press and release within one frame still counts
    ImGuiScope imgui(contentScale(w));
    ImGui_ImplGlfw_InitForOpenGL(w, true);
    previousKeyCallback = glfwSetKeyCallback(w, onKey); // ImGui's, called on from onKey

    DashboardOptions dashOptions;
    dashOptions.screenshotDir = options.screenshotDir;
    dashOptions.sceneChoices = options.sceneChoices;
    dashOptions.presetChoices = options.presetChoices;
    dashOptions.uiScale = imgui.scale();
    dashOptions.view = options.view;
    Dashboard dashboard(std::move(scene), state, dashOptions);
    dashboard.setStatus(startStatus);

    std::string savedConfig;
    auto lastSave = std::chrono::steady_clock::now();
    const auto saveConfig = [&](bool force) {
        if (!options.persist || configPath.empty()) return;
        int ww = 0, wh = 0;
        glfwGetWindowSize(w, &ww, &wh);
        if (ww >= 200 && wh >= 150) geometry = {ww, wh};
        const std::string now = dashboardToJson(dashboard.state(), geometry).dump();
        if (!force && now == savedConfig) return;
        if (auto error = saveDashboardConfig(configPath, dashboard.state(), geometry)) dashboard.setStatus(*error);
        savedConfig = now;
    };

    auto last = std::chrono::steady_clock::now();
    std::signal(SIGINT, onQuitSignal);
    std::signal(SIGTERM, onQuitSignal);
    // Tests (the widget-map hook) wait on the frame counter: tick at 10 Hz instead of sleeping.
    const bool ticking = std::getenv("SHADOWSCOPE_WIDGET_MAP") != nullptr;
    int settleFrames = 2; // ImGui needs a frame or two after input to settle hover and active states
    while (!glfwWindowShouldClose(w) && !quitRequested) {
        // Draw only when something can have changed: input arrived, the dashboard has an undrawn
        // change, a coarse view to refine or background work to poll. Otherwise sleep until input.
        const std::optional<double> due = dashboard.nextFrameIn();
        const bool unsaved = options.persist && !configPath.empty() &&
                             dashboardToJson(dashboard.state(), geometry).dump() != savedConfig;
        std::optional<double> wait = settleFrames > 0 ? std::optional<double>(0.0) : due;
        if (unsaved) wait = std::min(wait.value_or(1.0), 1.0); // saved within a second of a change
        if (ticking) wait = std::min(wait.value_or(0.1), 0.1);
        if (!wait) glfwWaitEvents();
        else if (*wait > 0.0) glfwWaitEventsTimeout(*wait);
        else glfwPollEvents();
        int fbW = 0, fbH = 0;
        glfwGetFramebufferSize(w, &fbW, &fbH);
        if (fbW <= 0 || fbH <= 0 || glfwGetWindowAttrib(w, GLFW_ICONIFIED)) { // minimised or zero-sized
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        const float scale = contentScale(w);
        if (scale != imgui.scale()) {
            imgui.rescale(scale);
            dashboard.setUiScale(imgui.scale());
        }
        const auto now = std::chrono::steady_clock::now();
        FrameInput input;
        input.deltaSeconds = std::chrono::duration<float>(now - last).count();
        last = now;
        const bool ctrl =
            glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
        if (ctrl && glfwGetKey(w, GLFW_KEY_Q) == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
        input.screenshot = f12Presses > 0;
        f12Presses = 0;
        if (!ImGui::GetIO().WantTextInput) input.fly = flyKeys(w);

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        dashboard.frame(display.x, display.y, input);
        ImGui::Render();
        renderer::beginWindowFrame(fbW, fbH);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        if (dashboard.screenshotRequested()) {
            const auto paths = dashboard.saveScreenshots(renderer::readFramebuffer(0, fbW, fbH));
            for (const auto& p : paths) std::cout << p << '\n';
            std::cout.flush();
        }
        glfwSwapBuffers(w);
        const ImGuiIO& io = ImGui::GetIO();
        // (A pointer that only moves needs no extra frame: its hover shows in the frame that took it.)
        const bool active = io.MouseWheel != 0.f || io.WantTextInput || ImGui::IsAnyItemActive() || io.MouseDown[0] ||
                            io.MouseDown[1] || io.MouseDown[2] || glm::length(input.fly) > 0.f || input.screenshot;
        settleFrames = active ? 2 : std::max(0, settleFrames - 1);
        if (now - lastSave > std::chrono::seconds(1)) {
            saveConfig(false);
            lastSave = now;
        }
    }
    saveConfig(true);
    ImGui_ImplGlfw_Shutdown();
    return 0;
}

} // namespace ui
