// The Charts tabs: the analytic curves at the current frustum and γ (n'(γ), λ(θ), m_z(z)), and the
// speed/accuracy trade-off of the presets and the current settings (the sweep itself:
// tradeoff_sweep.h), measured in the background of the live dashboard. The same chart descriptions
// as `curves` and `bench`.
#include "dashboard.h"

#include "geometry/io/preset.h"
#include "text_fit.h"
#include "ui/chart_image.h"
#include "ui/charts/analytic_charts.h"
#include "ui/charts/chart_imgui.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace ui {

namespace {

charts::CurveParams curveParams(const geometry::scene::Camera& cam, const geometry::shadow::ShadowPlan& plan,
                                const geometry::shadow::ShadowSettings& s, int screenHeight) {
    charts::CurveParams p;
    p.near = cam.near;
    p.far = cam.far;
    p.fovYDeg = cam.fovYDeg;
    p.gammaStepDeg = 1.0;
    p.gammaDeg = std::clamp(double(plan.gammaDeg), 0.0, 90.0);
    p.screenRes = std::max(screenHeight, 1);
    p.mapRes = plan.splits.empty() ? s.resolution : plan.splits[0].resolution;
    p.settings = s;
    return p;
}

/// The chart area below a row of export buttons, at least tall enough for a plot of
/// charts::kMinPlotHeight (the panel scrolls instead); returns the mouse position when hovered.
Rect chartArea(const char* id, float scale, const float** mouse, float* mouseStorage) {
    const ImVec2 pos = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
    // Compact frames below 360 px × scale (chart_imgui.cpp): the minimum is a compact frame's.
    const float minHeight = float(charts::chartHeightForPlot(charts::kMinPlotHeight * scale, true, scale));
    const Rect area{pos.x, pos.y, std::max(avail.x, 1.f), std::max(avail.y, minHeight)};
    ImGui::InvisibleButton(id, ImVec2(area.w, area.h));
    widgetMapRecord(id);
    *mouse = nullptr;
    if (ImGui::IsItemHovered()) {
        mouseStorage[0] = ImGui::GetIO().MousePos.x;
        mouseStorage[1] = ImGui::GetIO().MousePos.y;
        *mouse = mouseStorage;
    }
    return area;
}

/// Draws the chart and records its texts and plot height for the legibility check (text_fit.h).
void drawRecordedChart(const charts::Chart& chart, const Rect& area, float scale, const float* mouse, const char* id) {
    const charts::DrawnChart drawn =
        charts::drawChart(ImGui::GetWindowDrawList(), chart, {area.x, area.y, area.w, area.h, scale}, mouse);
    if (!textFitEnabled() || !drawn.drawn) return;
    for (const charts::ChartTextFit& t : drawn.texts)
        textFitRecord(std::string("chart:") + id + ":" + t.what, t.text, float(t.width), float(t.box));
    // The plot's height against the minimum, as a "text" so one check covers both.
    textFitRecord(std::string("chart:") + id + ":plot height", "", float(charts::kMinPlotHeight * scale),
                  float(drawn.frame.bottom - drawn.frame.top));
}

} // namespace

void Dashboard::exportChart(const charts::Chart& chart, const std::string& name) {
    try {
        const std::filesystem::path dir = options_.screenshotDir;
        std::filesystem::create_directories(dir);
        charts::writeSvg(dir / (name + ".svg"), chart, 1000, 620);
        geometry::analysis::writePng((dir / (name + ".png")).string(), renderChartImage(chart, 1000, 620));
        status_ = "saved " + (dir / (name + ".svg")).string() + ", " + (dir / (name + ".png")).string();
    } catch (const std::exception& e) {
        status_ = std::string("chart export failed: ") + e.what();
    }
}

void Dashboard::drawAnalyticChart(int which) {
    const int side = shownSide();
    const charts::CurveParams p = curveParams(scene_.file.scene.camera, sides_[side].plan, state_.settings[side],
                                              std::max(1, sides_[side].size.height));
    charts::Chart chart;
    const char* name = "chart";
    if (which == 2) {
        chart = charts::errorChart(charts::errorRows(p), p);
        name = "error_curve";
    } else {
        const auto rows = charts::warpRows(p);
        chart = which == 0 ? charts::warpChart(rows, p, p.gammaDeg) : charts::lambdaChart(rows, p, p.gammaDeg);
        name = which == 0 ? "warp_curve" : "lambda_curve";
    }
    bool save = ImGui::SmallButton("Export SVG + PNG");
    widgetMapRecord(std::string("export.") + name);
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.f); // wraps rather than running past the panel's edge
    ImGui::TextDisabled("%s — n %.3g, f %.4g, fov %.0f°, γ %.1f°, %d px / %d texels; hover for values; drag the bar "
                        "above to enlarge",
                        which == 0   ? "n'(γ) per warp"
                        : which == 1 ? "λ(θ) per warp"
                                     : "m_z(z) per warp",
                        p.near, p.far, p.fovYDeg, p.gammaDeg, p.screenRes, p.mapRes);
    ImGui::PopTextWrapPos();
    float storage[2];
    const float* mouse = nullptr;
    const Rect area = chartArea("chart_area", options_.uiScale, &mouse, storage);
    drawRecordedChart(chart, area, options_.uiScale, mouse, name);
    if (save) exportChart(chart, name);
}

void Dashboard::drawTradeoffTab() {
    TradeoffSweep& s = sweep_;
    if (!s.running()) {
        if (ImGui::SmallButton("Run sweep")) startTradeoffSweep();
        widgetMapRecord("tradeoff.run");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Times every preset in resources/presets and the current settings on this view (3 frames "
                              "each, GPU median) and measures aliasing p95; runs between dashboard frames");
    } else {
        ImGui::ProgressBar(s.progress(), ImVec2(ImGui::GetFontSize() * 12, 0));
        ImGui::SameLine();
        if (ImGui::SmallButton("Cancel")) s.cancel();
        widgetMapRecord("tradeoff.cancel");
    }
    ImGui::SameLine();
    // The chart's axes: a cost against an accuracy figure (flicker needs a path: `bench --path`).
    int x = int(s.x), y = int(s.y);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
    if (ImGui::Combo("x", &x, "gpu_ms\0cpu_ms\0memory_mib\0")) s.x = charts::TradeoffX(x);
    widgetMapRecord("tradeoff.x");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
    if (ImGui::Combo("y", &y, "p95\0interior\0edge\0misclassified\0flicker\0soft\0umbra\0")) s.y = charts::TradeoffY(y);
    widgetMapRecord("tradeoff.y");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("interior, edge, misclassified and umbra (light in the truth's umbra) need ground truth "
                          "(Views); soft (mean |s - v| against the sun's disk) also a sun size "
                          "(light.angular_diameter_deg > 0); flicker, a path of the scene file that each "
                          "configuration walks (world-space flicker, 10 frames)");
    if (s.y == charts::TradeoffY::Flicker) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
        if (ImGui::BeginCombo("path", s.path.empty() ? "(none)" : s.path.c_str())) {
            for (const auto& [name, path] : scene_.file.paths)
                if (ImGui::Selectable(name.c_str(), name == s.path)) s.path = name;
            ImGui::EndCombo();
        }
        widgetMapRecord("tradeoff.path");
    }
    ImGui::SameLine();
    const bool tune = recommend_.showChart && recommend_.started();
    const charts::Chart chart = tune ? recommend_.chart() : charts::tradeoffChart(tradeoffResults(), s.x, s.y);
    if (ImGui::SmallButton("Export SVG + PNG")) exportChart(chart, tune ? "tune" : "tradeoff");
    widgetMapRecord("export.tradeoff");
    drawRecommendControls();
    float storage[2];
    const float* mouse = nullptr;
    const Rect area = chartArea("tradeoff_area", options_.uiScale, &mouse, storage);
    drawRecordedChart(chart, area, options_.uiScale, mouse, tune ? "tune" : "tradeoff");
}

std::vector<charts::TradeoffPoint> Dashboard::tradeoffResults() const { return sweep_.points(); }

void Dashboard::startTradeoffSweep() {
    std::vector<TradeoffSweep::Config> configs;
    for (const auto& path : options_.presetChoices) {
        try {
            const std::string stem = std::filesystem::path(path).stem().string();
            configs.push_back({stem, stem, geometry::io::loadPreset(path)});
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    configs.push_back({"current A", "", state_.settings[0]});
    if (comparing()) configs.push_back({"current B", "", state_.settings[1]});
    sweep_.start(std::move(configs));
}

MeasureContext Dashboard::measureContext() {
    return {scene_,
            sceneGeneration_,
            casterLod_.levels(),
            sides_[0].size.width > 0 ? sides_[0].size : geometry::shadow::Viewport{640, 360},
            state_.views.truth,
            state_.views.truthSamples,
            inspectedLight()};
}

} // namespace ui
