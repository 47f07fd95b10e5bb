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

/// The config file: --config's, else dashboard.json in the config folder; empty when there is no config folder.
std::filesystem::path configFilePath(const ViewerOptions& options) {
    return !options.configPath.empty() ? options.configPath
           : configDirectory().empty() ? std::filesystem::path()
                                       : configDirectory() / "dashboard.json";
}

/// Reads the config file into `state` and `geometry`; returns the status line when it had to be set aside.
std::string loadStartConfig(const std::filesystem::path& configPath, DashboardState& state, WindowGeometry& geometry) {
    const auto error = loadDashboardConfig(configPath, state, geometry);
    if (!error) return "";
    // Keep the user's broken file next to the fresh one rather than overwriting it.
    std::error_code ec;
    const std::filesystem::path bad = configPath.string() + ".bad";
    std::filesystem::rename(configPath, bad, ec);
    const std::string status = "ignored the config file (kept as " + bad.filename().string() + "): " + *error;
    std::cerr << "shadowscope: " << status << '\n';
    return status;
}

/// The dashboard's options from the viewer's, at the window's UI scale.
DashboardOptions dashboardOptions(const ViewerOptions& options, float uiScale) {
    DashboardOptions dashOptions;
    dashOptions.screenshotDir = options.screenshotDir;
    dashOptions.sceneChoices = options.sceneChoices;
    dashOptions.presetChoices = options.presetChoices;
    dashOptions.uiScale = uiScale;
    dashOptions.view = options.view;
    return dashOptions;
}

/// Writes the dashboard's state and the window size to the config file when they changed.
class ConfigSaver {
public:
    /// An empty path: nothing is saved (the config file is not used, or there is no config folder).
    ConfigSaver(std::filesystem::path path, GLFWwindow* window, WindowGeometry geometry)
        : path_(std::move(path)), window_(window), geometry_(geometry) {}

    /// Whether the state differs from what was last saved.
    [[nodiscard]] bool unsaved(Dashboard& dashboard) const {
        return !path_.empty() && dashboardToJson(dashboard.state(), geometry_).dump() != saved_;
    }

    /// Saves when the state or the window's size changed since the last save, or always when forced.
    void save(Dashboard& dashboard, bool force) {
        if (path_.empty()) return;
        int ww = 0, wh = 0;
        glfwGetWindowSize(window_, &ww, &wh);
        if (ww >= 200 && wh >= 150) geometry_ = {ww, wh};
        const std::string now = dashboardToJson(dashboard.state(), geometry_).dump();
        if (!force && now == saved_) return;
        if (auto error = saveDashboardConfig(path_, dashboard.state(), geometry_)) dashboard.setStatus(*error);
        saved_ = now;
    }

private:
    std::filesystem::path path_;
    GLFWwindow* window_;
    WindowGeometry geometry_;
    std::string saved_; // the config as last saved
};

/// Waits for input, or until a frame is due (at once while settling; no frame due: for as long as it takes).
void waitForInput(std::optional<double> due, bool settling, bool unsaved, bool ticking) {
    std::optional<double> wait = settling ? std::optional<double>(0.0) : due;
    if (unsaved) wait = std::min(wait.value_or(1.0), 1.0); // saved within a second of a change
    if (ticking) wait = std::min(wait.value_or(0.1), 0.1);
    if (!wait) glfwWaitEvents();
    else if (*wait > 0.0) glfwWaitEventsTimeout(*wait);
    else glfwPollEvents();
}

/// This frame's input from the keys: the screenshot key, flying, and Ctrl+Q closing the window.
FrameInput readInput(GLFWwindow* w, float deltaSeconds) {
    FrameInput input;
    input.deltaSeconds = deltaSeconds;
    const bool ctrl =
        glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    if (ctrl && glfwGetKey(w, GLFW_KEY_Q) == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    input.screenshot = f12Presses > 0;
    f12Presses = 0;
    if (!ImGui::GetIO().WantTextInput) input.fly = flyKeys(w);
    return input;
}

/// Draws the dashboard into the window's framebuffer, then saves the screenshots it asked for.
void drawFrame(Dashboard& dashboard, const FrameInput& input, int fbW, int fbH) {
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
}

/// Whether the user is acting (a button held, the wheel turned, typing, flying, a screenshot): ImGui settles after.
bool userActive(const FrameInput& input) {
    const ImGuiIO& io = ImGui::GetIO();
    // (A pointer that only moves needs no extra frame: its hover shows in the frame that took it.)
    return io.MouseWheel != 0.f || io.WantTextInput || ImGui::IsAnyItemActive() || io.MouseDown[0] || io.MouseDown[1] ||
           io.MouseDown[2] || glm::length(input.fly) > 0.f || input.screenshot;
}

} // namespace

int runViewer(LoadedScene scene, const ViewerOptions& options) {
    DashboardState state;
    state.camera = OrbitCamera::from(scene.file.scene.camera);
    // Every light of the scene, --light N inspected, as the headless dashboard starts (a saved list
    // for this scene replaces them below).
    const std::vector<geometry::scene::Light>& lights = scene.file.scene.lights;
    state.lights = lights;
    state.inspectedLight = int(std::min(options.light, lights.size() - 1));
    state.sun = SunAngles::from(lights[size_t(state.inspectedLight)].direction);
    WindowGeometry geometry;
    std::string startStatus;
    const std::filesystem::path configPath = configFilePath(options);
    if (options.persist && !configPath.empty()) startStatus = loadStartConfig(configPath, state, geometry);
    if (options.settings) state.settings[0] = state.settings[1] = *options.settings;

    renderer::GlfwWindowContext window(geometry.width, geometry.height, "shadowscope — " + scene.file.scene.name);
    GLFWwindow* w = window.window();
    glfwSetInputMode(w, GLFW_STICKY_KEYS, GLFW_TRUE); // a press and release within one frame still counts
    ImGuiScope imgui(contentScale(w));
    ImGui_ImplGlfw_InitForOpenGL(w, true);
    previousKeyCallback = glfwSetKeyCallback(w, onKey); // ImGui's, called on from onKey

    Dashboard dashboard(std::move(scene), state, dashboardOptions(options, imgui.scale()));
    dashboard.setStatus(startStatus);
    ConfigSaver config(options.persist ? configPath : std::filesystem::path(), w, geometry);
    auto lastSave = std::chrono::steady_clock::now();

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
        const bool unsaved = config.unsaved(dashboard);
        waitForInput(due, settleFrames > 0, unsaved, ticking);
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
        const FrameInput input = readInput(w, std::chrono::duration<float>(now - last).count());
        last = now;
        drawFrame(dashboard, input, fbW, fbH);
        glfwSwapBuffers(w);
        settleFrames = userActive(input) ? 2 : std::max(0, settleFrames - 1);
        if (now - lastSave > std::chrono::seconds(1)) {
            config.save(dashboard, false);
            lastSave = now;
        }
    }
    config.save(dashboard, true);
    ImGui_ImplGlfw_Shutdown();
    return 0;
}

} // namespace ui
