#pragma once
// The dashboard: eye view, the light's warped view and a heatmap side by side, a controls panel
// generated from the settings declaration, a stats panel and a status bar with the pixel under
// the cursor; A/B comparison of two settings sets; pixel inspector with zoom and pan.
//
// It only builds ImGui windows and asks the renderer for frames, so the same code runs in the
// GLFW window (viewer.cpp) and headless into an image (dashboard_headless.cpp): same layout and
// same pixels for the same state and size.
//
// Index
//   DashboardOptions ... what the front end fixes: screenshot folder, pickers, UI scale, clock, budgets
//   FrameInput ......... the keys the window reads for a frame (screenshot, fly)
//   PassCounts ......... how often it drew and inspected (tests, stats, widget map)
//   PixelProbe ......... one pixel's exact values (the inspector)
//   Dashboard .......... public: frame, state, screenshots and exports, images, probes, scheduling,
//                        charts, lights, scene; private: sides, drawing (dashboard_frame.cpp),
//                        panels (dashboard_panels.cpp), controls, stats, charts, dialogs
#include "caster_lod_job.h"
#include "dashboard_state.h"
#include "export_dialog.h"
#include "file_browser.h"
#include "geometry/analysis/heatmap.h"
#include "geometry/analysis/tuner.h"
#include "help_overlay.h"
#include "pass_inputs.h"
#include "progressive.h"
#include "recent_median.h"
#include "recommend_job.h"
#include "renderer/image.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"
#include "renderer/texture.h"
#include "scene_loader.h"
#include "tradeoff_sweep.h"
#include "ui/charts/tradeoff_chart.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace ui {

struct DashboardOptions {
    std::filesystem::path screenshotDir = "screenshots";
    std::vector<std::string> sceneChoices;  // built-in names and scene files for the scene picker
    std::vector<std::string> presetChoices; // preset files for the preset picker
    float uiScale = 1.f;
    std::string view;                       // the canonical view the scene was opened at, if any
    std::optional<geometry::io::UpAxis> up; // --up: model files' up axis, until the Scene group changes it
    /// Draw both passes at full resolution every frame, as the dashboard did before it drew only what
    /// changed: the "before" of the dashboard benchmark (tests/bench_dashboard.cpp), not a user option.
    bool redrawEveryFrame = false;
    /// GPU milliseconds a full-resolution frame may take for the first response to a discrete change;
    /// predicted above it, the change is drawn coarse first (ui::kResponseBudgetMs in the window).
    /// Infinite (headless renders, tests): always at full resolution, whatever the machine's speed.
    double responseBudgetMs = INFINITY;
    /// Seconds on a monotonic clock, for the pause after which a coarse frame is refined; empty:
    /// std::chrono::steady_clock. Tests inject their own and advance it instead of sleeping.
    std::function<double()> clock;
};

/// What the window front end reads from its input system for a frame (the dashboard itself
/// sees the mouse through ImGui).
struct FrameInput {
    bool screenshot = false; // the screenshot key
    glm::vec3 fly{0.f};      // WASD/QE while fly-looking: (right, up, forward), −1..1 each
    float deltaSeconds = 1.f / 60.f;
};

/// How often the dashboard drew and inspected, since it was made (tests, the stats panel, the
/// widget map): hover, zoom and idle frames add nothing.
struct PassCounts {
    uint64_t shadow = 0;      // frames that drew the shadow maps (either side)
    uint64_t eyeFull = 0;     // eye passes at full resolution
    uint64_t eyeCoarse = 0;   // eye passes at reduced resolution during interaction
    uint64_t inspections = 0; // statistics (and truth) computed and shown
    uint64_t cancelled = 0;   // inspections abandoned because the inputs changed
};

/// One pixel's exact values (the pixel inspector).
struct PixelProbe {
    ViewPanel panel = ViewPanel::Eye;
    int side = 0;        // A or B
    glm::ivec2 pixel{0}; // image pixel, x right, y down
    // Eye and heatmap panels:
    bool receiver = false, sky = true;
    float viewDepth = 0, shadow = 1, m = 0, mapDepth = 0;
    int split = -1;
    glm::vec2 texel{0.f};
    std::optional<bool> truthShadowed;
    glm::vec3 position{0.f};
    // Light panel:
    glm::ivec2 mapTexel{0};
    float storedDepth = 0;
};

class Dashboard {
public:
    /// Needs the current GL context (and an ImGui context for frame()).
    Dashboard(LoadedScene scene, DashboardState state, DashboardOptions options);
    ~Dashboard();
    Dashboard(const Dashboard&) = delete;
    Dashboard& operator=(const Dashboard&) = delete;

    /// Renders the views at this frame's panel sizes and builds the ImGui windows for a
    /// width × height window. Call between ImGui::NewFrame() and ImGui::Render().
    void frame(float width, float height, const FrameInput& input = {});

    [[nodiscard]] DashboardState& state() noexcept { return state_; }
    [[nodiscard]] const DashboardRects& rects() const noexcept { return rects_; }
    [[nodiscard]] const std::string& status() const noexcept { return status_; }
    void setStatus(std::string message) { status_ = std::move(message); }
    /// The monitor's content scale changed (fixed sizes in the layout follow it).
    void setUiScale(float scale) noexcept { options_.uiScale = scale; }
    /// DashboardOptions::responseBudgetMs from now on.
    void setResponseBudget(double ms) noexcept { options_.responseBudgetMs = ms; }

    /// The user asked for a screenshot this frame (key or button): the front end calls
    /// saveScreenshots() with the window image after ImGui::Render().
    [[nodiscard]] bool screenshotRequested() const noexcept { return screenshotRequested_; }
    /// Writes eye.png, light.png, heatmap.png (and eye_b.png when comparing) and dashboard.png
    /// into a new numbered folder of the screenshot folder (001, 002, …: never one written before);
    /// returns the paths written and names the folder in the status bar.
    std::vector<std::string> saveScreenshots(const geometry::analysis::Image& dashboard);
    /// `request`'s view drawn offscreen at its size with the current state (dashboard_export.cpp):
    /// the eye views as `shadowscope render --views eye` draws them at that size.
    [[nodiscard]] geometry::analysis::Image renderExport(const ExportRequest& request);
    /// renderExport() written as VIEW_WxH.png into a new numbered folder (as screenshots); the
    /// path, or nullopt with the reason in the status bar.
    std::optional<std::string> exportView(const ExportRequest& request);
    void openExportDialog() noexcept { exportDialog_.open(); }
    [[nodiscard]] bool exportDialogOpen() const noexcept { return exportDialog_.isOpen(); }
    /// The help overlay (F1, "?"): every gesture and key (gesture_table.h).
    [[nodiscard]] bool helpOpen() const noexcept { return help_.open(); }
    /// The file browser ("Browse…"), opened at `at`, or (empty) at the scene file field's folder,
    /// else the last file's, else the current folder.
    void openFileBrowser(const std::filesystem::path& at = {});
    [[nodiscard]] const FileBrowser& fileBrowser() const noexcept { return browser_; }
    /// The eye view's double-click: the camera keeps its direction and frames the scene (fitBounds).
    void fitCamera();

    /// The images the panels show this frame (for screenshots and tests).
    [[nodiscard]] geometry::analysis::Image eyeImage(int side = 0) const;
    [[nodiscard]] geometry::analysis::Image lightImage() const;
    [[nodiscard]] geometry::analysis::Image heatmapImage() const;

    /// The last statistics of side A or B (nullptr before the first inspection).
    [[nodiscard]] const geometry::analysis::Inspection* inspection(int side) const noexcept;
    [[nodiscard]] const geometry::shadow::ShadowPlan& plan(int side) const noexcept { return sides_[side].plan; }
    [[nodiscard]] const LoadedScene& scene() const noexcept { return scene_; }
    [[nodiscard]] bool loading() const noexcept { return loader_.busy(); }
    [[nodiscard]] const PassCounts& passCounts() const noexcept { return counts_; }
    /// Side 0's or 1's renderer statistics (GPU times, triangles), or nullptr before it draws.
    [[nodiscard]] const renderer::FrameStats* frameStats(int side) const noexcept { return statsOf(side); }
    /// GPU milliseconds of side A's or B's shadow maps when last drawn (NaN: not timed yet).
    [[nodiscard]] double shadowGpuMs(int side) const noexcept { return sides_[size_t(side)].shadowGpuMs; }
    /// The pinned pixel, as the inspector shows it.
    [[nodiscard]] const std::optional<PixelProbe>& pinnedPixel() const noexcept { return pinned_; }
    /// The values at an image pixel of the eye or heatmap panel, from the last inspection.
    [[nodiscard]] PixelProbe probeEye(int side, glm::ivec2 pixel, ViewPanel panel) const;
    /// When the front end should run the next frame without waiting for input: 0 now (something
    /// changed that is not drawn yet), t > 0 seconds (a coarse view to refine, background work to
    /// poll), nullopt: nothing pending, sleep until input.
    [[nodiscard]] std::optional<double> nextFrameIn() const;
    /// Blocks until the background inspections have finished and takes their results (headless,
    /// tests); true when there were any (the next frame shows them).
    bool finishBackgroundWork();
    /// The eye view shown is coarse (drawn at reduced resolution while the user drags).
    [[nodiscard]] bool coarse() const noexcept { return sides_[0].coarseDivisor > 1 || sides_[1].coarseDivisor > 1; }
    /// Selects a tab of the stats panel: 0 Stats, 1 n'(γ), 2 λ(θ), 3 m_z(z), 4 Trade-off.
    void showTab(int tab) noexcept { requestedTab_ = tab; }
    /// The trade-off sweep's results so far, on the tab's chosen axes (Charts panel).
    [[nodiscard]] std::vector<charts::TradeoffPoint> tradeoffResults() const;
    /// The path of the scene file the trade-off sweep walks for the flicker axis ("" none).
    void setTradeoffPath(std::string name) { sweep_.path = std::move(name); }
    /// The trade-off chart's axes (the tab's x and y choices).
    void setTradeoffAxes(charts::TradeoffX x, charts::TradeoffY y) noexcept {
        sweep_.x = x;
        sweep_.y = y;
    }
    [[nodiscard]] bool tradeoffRunning() const noexcept { return sweep_.running(); }
    /// Starts the trade-off sweep (the "Run sweep" button).
    void startTradeoffSweep();
    /// Starts the Trade-off tab's "Recommend" (geometry/analysis/tuner.h) on the current view from the
    /// settings being edited; false, with the reason in the status bar, for a bad target or no truth.
    bool startRecommend(const std::string& target, int budgetEvals = 40);
    [[nodiscard]] bool recommendRunning() const noexcept { return recommend_.running(); }
    /// The recommended settings, once a search has found them.
    [[nodiscard]] const std::optional<geometry::shadow::ShadowSettings>& recommendation() const noexcept {
        return recommend_.result();
    }
    /// Loads the recommendation into side A (0) or B (1; A/B compare turns on).
    void applyRecommendation(int side);
    /// The camera's n and f (the "near, far" field); refused with a status line unless 0 < n < f.
    bool setNearFar(float n, float f);
    /// Back to the scene's camera, or to the canonical view last chosen, lens included.
    void resetCamera();
    /// Starts loading a scene in the background; the current one stays until it succeeds.
    void loadScene(const std::string& nameOrPath);

    // The light list (the Lights group; dashboard_lights.cpp). An edit that would leave an invalid
    // light or list is refused: the lights stay as they were and the status line says why.
    /// Adds a spot light above the scene looking down (defaultSpotLight) and inspects it.
    bool addLight();
    /// Removes light `index`; refused for the last light.
    bool removeLight(size_t index);
    /// Replaces light `index`; refused for a light lightProblem() rejects.
    bool setLight(size_t index, const geometry::scene::Light& light);
    /// Makes light `index` the inspected one: drawn last, its maps in the light view, its statistics.
    bool inspectLight(size_t index);
    /// Back to the lights the scene was loaded with (a saved list may have replaced them).
    void resetLights();
    /// The lights as the next frame draws them (the sun angles applied to the inspected one).
    [[nodiscard]] std::vector<geometry::scene::Light> lights() const;
    [[nodiscard]] size_t inspectedLight() const noexcept;
    /// The maps the light view's selector offers: the inspected light's splits, 1 for a spot light,
    /// 6 cube faces for a point light.
    [[nodiscard]] int lightViewMaps() const noexcept;

private:
    /// A side's statistics being computed on a worker thread for the frame last drawn at full size.
    struct InspectionJob {
        InspectionInputs inputs;
        std::stop_source stop;
        std::future<geometry::analysis::Inspection> result;
        geometry::analysis::Image eye;
        geometry::shadow::ShadowPlan plan;
    };
    struct Side {
        std::unique_ptr<renderer::Renderer> renderer;
        geometry::shadow::ShadowPlan plan;
        RecentMedian planMicroseconds;
        std::optional<PassInputs> drawn;       // what the images shown were drawn from
        int coarseDivisor = 1;                 // > 1: the eye image shown is that much smaller a side
        geometry::shadow::Viewport size{0, 0}; // the eye view at full resolution
        double shadowGpuMs = NAN;              // the last time the maps were drawn
        std::optional<geometry::analysis::Inspection> inspection;
        std::optional<InspectionInputs> inspected; // what `inspection` describes
        uint64_t inspectionSerial = 0;             // changes with every inspection shown
        geometry::analysis::Image eye;             // the eye image of that frame (heatmap blend)
        std::optional<InspectionJob> job;
    };

    void pollSceneLoad();
    void adoptScene(LoadedScene loaded);
    // Caster LOD (dashboard_lod.cpp; built by casterLod_, caster_lod_job.h) when a side asks.
    void stepCasterLod();
    void giveCasterLod(renderer::Renderer& r) const;
    [[nodiscard]] std::string casterLodStatus(int side) const;
    // Drawing only what changed (dashboard_frame.cpp).
    void renderViews();
    [[nodiscard]] PassInputs passInputs(int side) const;
    [[nodiscard]] InspectionInputs inspectionInputs(int side) const;
    /// Draws a side at 1/divisor of each side of the view, its shadow maps at 1/mapDivisor.
    void drawSide(int side, const PassInputs& in, int divisor, int mapDivisor);
    void updateInspection();
    void startInspection(int side, const InspectionInputs& in);
    void pollInspections();
    void abandonInspection(Side& side);
    void cancelInspections();
    void updateHeatmap();
    [[nodiscard]] bool backgroundBusy() const noexcept;
    [[nodiscard]] bool comparing() const noexcept { return state_.views.compare != CompareMode::Off; }
    [[nodiscard]] int shownSide() const noexcept { return comparing() ? state_.editing : 0; }

    // Panels (dashboard_panels.cpp, dashboard_controls.cpp, dashboard_stats.cpp).
    void drawSplitters(float width, float height);
    void drawEyePanel();
    void drawLightPanel();
    void drawHeatmapPanel();
    void drawStatsPanel();
    /// One row of the statistics table: its name, its value for side 0 or 1, and a tooltip.
    struct StatRow {
        const char* name;
        std::function<std::string(int)> value;
        const char* tip = nullptr;
    };
    /// The statistics table's rows, as data (the soft truth's only where a side has one).
    [[nodiscard]] std::vector<StatRow> statRows(int sides) const;
    [[nodiscard]] const renderer::FrameStats* statsOf(int side) const noexcept;
    [[nodiscard]] std::function<std::string(int)> gpuTime(renderer::Pass pass) const;
    void drawStatsTable();
    void drawInspector();
    void drawAnalyticChart(int which); // 0 n'(γ), 1 λ(θ), 2 m_z(z)
    void drawTradeoffTab();
    // Recommend (dashboard_recommend.cpp).
    void drawRecommendControls();
    /// What the background measurements (trade-off sweep, Recommend) read this frame.
    [[nodiscard]] MeasureContext measureContext();
    void exportChart(const charts::Chart& chart, const std::string& name);
    void drawStatusBar();
    /// The help overlay, file browser and export dialog over the panels (dashboard_export.cpp).
    void drawDialogs(float width, float height);
    void drawControlsPanel();
    void drawSceneGroup();
    void drawCameraLightGroup();
    void drawLightsGroup();
    /// The lights over an eye image placed in `area` (width × height image pixels).
    void drawLightGizmo(const Rect& area, int width, int height);
    /// Takes the scene's lights, or the state's where they are valid and meant for this scene.
    void initLights();
    /// Writes the sun angles into the inspected light's direction when they changed.
    void commitSun();
    /// Refuses an edit: the status line says why.
    bool refuseLight(const std::string& why);
    void drawSettingsGroups();
    void drawViewsGroup();
    void drawPresetsGroup();
    /// An image filling `area` with zoom/pan/hover handling; returns the hovered image pixel.
    std::optional<glm::ivec2> imageArea(ViewPanel panel, GLuint texture, int width, int height, const Rect& area,
                                        bool cameraControls, const char* id);
    /// The values at an image pixel of the light view (its stored depth).
    [[nodiscard]] PixelProbe probeLight(glm::ivec2 pixel);
    /// Reads the pinned pixel again, so that it never shows values of an earlier camera, setting or scene.
    void refreshPin();

    LoadedScene scene_;
    DashboardState state_;
    DashboardOptions options_;
    SceneLoader loader_;
    std::array<Side, 2> sides_;
    renderer::Texture2D heatmap_;
    geometry::analysis::Image heatmapImage_;
    geometry::analysis::Legend heatmapLegend_; // drawn over the panel in the UI font (heatmap_legend.h)
    std::optional<HeatmapInputs> heatmapShown_;
    PassCounts counts_;
    geometry::shadow::Viewport eyeSize_{0, 0}; // this frame's full-resolution eye view size
    bool continuousInput_ = false;             // the last frame's input was a drag, the wheel or fly keys
    bool drewThisFrame_ = false;
    bool gpuTimesInFlight_ = false;     // a drawn frame's GPU times have not arrived: poll them next frame
    double lastChange_ = 0;             // seconds on now()'s clock
    double refinePause_ = kRefinePause; // the pause before refining the last change's coarse frame
    [[nodiscard]] double now() const;
    uint64_t nextInspectionSerial_ = 1;
    std::vector<std::future<geometry::analysis::Inspection>> retiring_; // cancelled jobs winding down
    geometry::scene::Camera homeCamera_; // Reset camera: the scene's, or the canonical view last chosen
    DashboardRects rects_;
    Rect eyeArea_, lightArea_, heatmapArea_;
    int lightViewSize_ = 256;
    std::string status_;
    std::optional<PixelProbe> hovered_, pinned_;
    bool screenshotRequested_ = false;
    double cpuFrameMs_ = 0;
    int sceneGeneration_ = 0;
    CasterLodJob casterLod_;
    std::string scenePath_;                      // the picker's text field
    std::optional<geometry::io::UpAxis> upAxis_; // model files' up axis; empty: their format's default
    std::string presetPath_;                     // the preset field
    std::string viewChoice_;                     // the canonical view last applied
    float targetGammaDeg_ = 30.f;                // the "set γ" control
    /// The sun angles last written into the inspected light; empty: write them on the next frame
    /// (the sun leads, as with one light). Only a change of the sun moves the light, so a light's own
    /// direction (edited in the Lights group) is not rounded through the angles.
    std::optional<SunAngles> sunApplied_;
    std::vector<geometry::scene::Light> sceneLights_; // as the scene was loaded (Reset)
    int requestedTab_ = -1;
    bool flyLooking_ = false; // right mouse held on the eye view: WASD/QE fly
    // The eye view's camera controls, recorded by imageArea() and applied at the start of the next
    // frame, before it draws: a drag step shows in the frame that takes it.
    bool cameraHovered_ = false, cameraDragging_ = false;
    float cameraAreaHeight_ = 1.f;
    bool flying_ = false; // this frame moved the camera with the fly keys
    void applyCameraInput(const FrameInput& input);

    HelpOverlay help_;
    FileBrowser browser_;
    ExportDialog exportDialog_;
    std::optional<ExportRequest> pendingExport_; // drawn at the start of the next frame, before its widgets

    TradeoffSweep sweep_;    // the Charts panel's trade-off sweep (tradeoff_sweep.h)
    RecommendJob recommend_; // the Trade-off tab's Recommend (recommend_job.h)
};

/// One line with a probe's values (status bar, inspector).
[[nodiscard]] std::string describeProbe(const PixelProbe& p);

/// Groups of the controls panel, in order, and the group a settings key belongs to.
[[nodiscard]] const std::vector<std::string>& controlGroups();
[[nodiscard]] std::string settingGroup(std::string_view key);

} // namespace ui
