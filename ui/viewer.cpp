// The interactive window: GLFW events queued and fed to ImGui a frame at a time (input_queue.h),
// the dashboard drawn when something changed, the config file read at start and saved on change.
//
// Index
//   [SECTION] Window events ........ the GLFW callbacks: every event onto the input queue
//   [SECTION] Applying input ....... a frame's events to ImGui, the pointer, the viewer's keys, drops
//   [SECTION] Config file .......... configFilePath, loadStartConfig, ConfigSaver
//   [SECTION] The loop ............. waitForInput, readInput, drawFrame, userActive, runViewer
#include "viewer.h"

#include "dashboard_config.h"
#include "imgui_setup.h"
#include "input_queue.h"
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
#include <string>
#include <vector>

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

// The queue's codes are GLFW's.
static_assert(input::kPress == GLFW_PRESS && input::kRelease == GLFW_RELEASE && input::kRepeat == GLFW_REPEAT);
static_assert(input::kFirstModifierKey == GLFW_KEY_LEFT_SHIFT && input::kLastModifierKey == GLFW_KEY_RIGHT_SUPER);

// ---- [SECTION] Window events ---------------------------------------------------------------------
// ImGui's backend is installed without its callbacks: these queue every event instead, and the
// loop applies them a frame at a time (one window per process, hence a file-level queue).

input::InputQueue inputQueue;

extern "C" void onKey(GLFWwindow*, int key, int scancode, int action, int mods) {
    inputQueue.push(input::KeyEvent{key, scancode, action, mods});
}
extern "C" void onChar(GLFWwindow*, unsigned codepoint) { inputQueue.push(input::CharEvent{codepoint}); }
extern "C" void onMouseButton(GLFWwindow*, int button, int action, int mods) {
    inputQueue.push(input::MouseButtonEvent{button, action, mods});
}
extern "C" void onScroll(GLFWwindow*, double dx, double dy) { inputQueue.push(input::ScrollEvent{dx, dy}); }
extern "C" void onCursorPos(GLFWwindow*, double x, double y) { inputQueue.push(input::CursorPosEvent{x, y}); }
extern "C" void onFocus(GLFWwindow*, int focused) { inputQueue.push(input::FocusEvent{focused != 0}); }
extern "C" void onCursorEnter(GLFWwindow*, int entered) { inputQueue.push(input::CursorEnterEvent{entered != 0}); }
/// (GLFW's strings live only during the call: copied.)
extern "C" void onDrop(GLFWwindow*, int count, const char** paths) {
    if (count > 0) inputQueue.push(input::DropEvent{std::vector<std::string>(paths, paths + count)});
}

void installCallbacks(GLFWwindow* w) {
    glfwSetKeyCallback(w, onKey);
    glfwSetCharCallback(w, onChar);
    glfwSetMouseButtonCallback(w, onMouseButton);
    glfwSetScrollCallback(w, onScroll);
    glfwSetCursorPosCallback(w, onCursorPos);
    glfwSetWindowFocusCallback(w, onFocus);
    glfwSetCursorEnterCallback(w, onCursorEnter);
    glfwSetDropCallback(w, onDrop);
}

// ---- [SECTION] Applying input ----------------------------------------------------------------------

/// The pointer as the events applied so far leave it. ImGui 1.86's backend reads the buttons and
/// the position by polling GLFW in NewFrame, which is ahead of the queue (a press already released,
/// a position already left): drawFrame puts these in their place.
struct AppliedPointer {
    std::optional<ImVec2> pos; // the last cursor event's; none before the first (the polled one stands)
    bool down[ImGuiMouseButton_COUNT] = {};
};

/// What a frame's events ask of the viewer itself rather than of ImGui.
struct FrameActions {
    bool screenshot = false; // F12: counted per press, as each press has a frame of its own
    bool quit = false;       // Ctrl+Q
    bool acted = false;      // a key, character, button, wheel, focus or drop event (not a move)
    std::vector<std::string> dropped;
};

/// Hands one event to ImGui through the backend's public callbacks (or the pointer state).
struct ApplyEvent {
    GLFWwindow* window;
    AppliedPointer& pointer;
    FrameActions& actions;

    void operator()(const input::KeyEvent& e) const {
        actions.acted = true;
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
        if (e.action != GLFW_PRESS) return;
        if (e.key == GLFW_KEY_F12) actions.screenshot = true;
        if (e.key == GLFW_KEY_Q && (e.mods & GLFW_MOD_CONTROL)) actions.quit = true;
    }
    void operator()(const input::CharEvent& e) const {
        actions.acted = true;
        ImGui_ImplGlfw_CharCallback(window, e.codepoint);
    }
    /// (1.86's button callback only latches a press for NewFrame's polling, which drawFrame replaces.)
    void operator()(const input::MouseButtonEvent& e) const {
        actions.acted = true;
        if (e.button >= 0 && e.button < ImGuiMouseButton_COUNT) pointer.down[e.button] = e.action == GLFW_PRESS;
    }
    void operator()(const input::ScrollEvent& e) const {
        actions.acted = true;
        ImGui_ImplGlfw_ScrollCallback(window, e.dx, e.dy);
    }
    void operator()(const input::CursorPosEvent& e) const { pointer.pos = ImVec2(float(e.x), float(e.y)); }
    void operator()(const input::FocusEvent& e) const {
        actions.acted = true;
        ImGui_ImplGlfw_WindowFocusCallback(window, e.focused);
    }
    void operator()(const input::CursorEnterEvent& e) const { ImGui_ImplGlfw_CursorEnterCallback(window, e.entered); }
    void operator()(const input::DropEvent& e) const {
        actions.acted = true;
        actions.dropped = e.paths;
    }
};

/// The next frame's events from the queue, applied.
FrameActions applyNextFrameInput(GLFWwindow* w, AppliedPointer& pointer) {
    FrameActions actions;
    for (const input::InputEvent& e : inputQueue.takeFrame()) std::visit(ApplyEvent{w, pointer, actions}, e);
    return actions;
}

/// After ImGui_ImplGlfw_NewFrame: the pointer as the applied events leave it, not as polled.
void overridePolledPointer(const AppliedPointer& pointer) {
    ImGuiIO& io = ImGui::GetIO();
    // The backend leaves no position when the pointer is outside an unfocused window: keep that.
    if (pointer.pos && ImGui::IsMousePosValid(&io.MousePos)) io.MousePos = *pointer.pos;
    for (int b = 0; b < ImGuiMouseButton_COUNT; ++b) io.MouseDown[b] = pointer.down[b];
}

/// A dropped file loads as a scene (the first one: one scene at a time).
void loadDropped(Dashboard& dashboard, const std::vector<std::string>& paths) {
    if (paths.empty()) return;
    dashboard.loadScene(paths.front());
    if (paths.size() > 1)
        dashboard.setStatus(dashboard.status() + " (" + std::to_string(paths.size() - 1) +
                            " more dropped files ignored: one scene at a time)");
}

/// WASD/QE as (right, up, forward), from the keys as the applied events leave them.
glm::vec3 flyKeys() {
    const ImGuiIO& io = ImGui::GetIO();
    const auto down = [&](int key) { return io.KeysDown[key] ? 1.f : 0.f; };
    return {down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
            down(GLFW_KEY_W) - down(GLFW_KEY_S)};
}

// ---- [SECTION] Config file -------------------------------------------------------------------------

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
    dashOptions.responseBudgetMs = kResponseBudgetMs; // a person waits: coarse first when a full frame is slow
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

// ---- [SECTION] The loop ----------------------------------------------------------------------------

/// Waits for input, or until a frame is due (at once while settling or while queued input waits for
/// its frames; no frame due: for as long as it takes).
void waitForInput(std::optional<double> due, bool now, bool unsaved, bool ticking) {
    std::optional<double> wait = now ? std::optional<double>(0.0) : due;
    if (unsaved) wait = std::min(wait.value_or(1.0), 1.0); // saved within a second of a change
    if (ticking) wait = std::min(wait.value_or(0.1), 0.1);
    if (!wait) glfwWaitEvents();
    else if (*wait > 0.0) glfwWaitEventsTimeout(*wait);
    else glfwPollEvents();
}

/// This frame's input for the dashboard: the screenshot key and flying (not while typing).
FrameInput readInput(const FrameActions& actions, float deltaSeconds) {
    FrameInput input;
    input.deltaSeconds = deltaSeconds;
    input.screenshot = actions.screenshot;
    if (!ImGui::GetIO().WantTextInput) input.fly = flyKeys();
    return input;
}

/// Draws the dashboard into the window's framebuffer, then saves the screenshots it asked for.
void drawFrame(Dashboard& dashboard, const FrameInput& input, const AppliedPointer& pointer, int fbW, int fbH) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    overridePolledPointer(pointer);
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

/// Whether the user is acting (a key, button or wheel event, a button held, typing, flying, a
/// screenshot): ImGui settles after.
bool userActive(const FrameInput& input, const FrameActions& actions) {
    const ImGuiIO& io = ImGui::GetIO();
    // (A pointer that only moves needs no extra frame: its hover shows in the frame that took it.)
    return actions.acted || io.MouseWheel != 0.f || io.WantTextInput || ImGui::IsAnyItemActive() || io.MouseDown[0] ||
           io.MouseDown[1] || io.MouseDown[2] || glm::length(input.fly) > 0.f || input.screenshot;
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
    ImGuiScope imgui(contentScale(w));
    ImGui_ImplGlfw_InitForOpenGL(w, false); // its callbacks would show ImGui one state per frame
    installCallbacks(w);
    AppliedPointer pointer;

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
        waitForInput(due, settleFrames > 0 || !inputQueue.empty(), unsaved, ticking);
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
        const FrameActions actions = applyNextFrameInput(w, pointer);
        if (actions.quit) glfwSetWindowShouldClose(w, GLFW_TRUE);
        loadDropped(dashboard, actions.dropped);
        const auto now = std::chrono::steady_clock::now();
        const FrameInput input = readInput(actions, std::chrono::duration<float>(now - last).count());
        last = now;
        drawFrame(dashboard, input, pointer, fbW, fbH);
        glfwSwapBuffers(w);
        settleFrames = userActive(input, actions) ? 2 : std::max(0, settleFrames - 1);
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
