#include "dashboard_layout.h"

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
float clampOr(float v, float lo, float hi, float fallback) noexcept {
    return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
}
float whole(float v) noexcept { return std::isfinite(v) ? std::max(0.f, std::floor(v)) : 0.f; }
float scaleOf(float s) noexcept { return std::isfinite(s) && s > 0.f ? std::clamp(s, 0.5f, 4.f) : 1.f; }
} // namespace

LayoutFractions clampFractions(LayoutFractions f) noexcept {
    const LayoutFractions d;
    f.controlsWidth = clampOr(f.controlsWidth, 160.f, 1200.f, d.controlsWidth);
    f.eyeEnd = clampOr(f.eyeEnd, 0.1f, 0.8f, d.eyeEnd);
    f.lightEnd = clampOr(f.lightEnd, f.eyeEnd + 0.1f, 0.95f, std::max(d.lightEnd, f.eyeEnd + 0.1f));
    f.statsHeight = clampOr(f.statsHeight, 0.08f, 0.7f, d.statsHeight);
    return f;
}

DashboardRects layoutDashboard(float width, float height, const LayoutFractions& fractions, float uiScale) noexcept {
    DashboardRects r;
    const float W = whole(width), H = whole(height);
    if (W <= 0.f || H <= 0.f) return r;
    const LayoutFractions f = clampFractions(fractions);
    const float s = scaleOf(uiScale);
    const float gap = whole(kSplitterWidth * s);
    const float statusH = std::min(whole(kStatusBarHeight * s), H);
    const float bodyH = H - statusH;
    r.status = {0.f, bodyH, W, statusH};

    const float controlsW = std::min(whole(f.controlsWidth * s), whole(W * 0.6f));
    r.controls = {0.f, 0.f, controlsW, bodyH};
    r.splitters[int(Splitter::Controls)] = {controlsW, 0.f, std::min(gap, W - controlsW), bodyH};

    const float viewsX = std::min(W, controlsW + gap);
    const float viewsW = W - viewsX;
    const float statsH = whole(bodyH * f.statsHeight);
    const float viewsH = std::max(0.f, bodyH - statsH - gap);
    r.splitters[int(Splitter::Stats)] = {viewsX, viewsH, viewsW, std::min(gap, bodyH - viewsH)};
    r.stats = {viewsX, std::min(bodyH, viewsH + gap), viewsW, std::max(0.f, bodyH - viewsH - gap)};

    // Three views with two handles between them; the handles take their room from the views.
    const float usable = std::max(0.f, viewsW - 2.f * gap);
    const float eyeW = whole(usable * f.eyeEnd);
    const float lightW = std::max(0.f, whole(usable * f.lightEnd) - eyeW);
    const float heatW = std::max(0.f, usable - eyeW - lightW);
    r.eye = {viewsX, 0.f, eyeW, viewsH};
    r.splitters[int(Splitter::EyeLight)] = {viewsX + eyeW, 0.f, gap, viewsH};
    r.light = {viewsX + eyeW + gap, 0.f, lightW, viewsH};
    r.splitters[int(Splitter::LightHeatmap)] = {r.light.right(), 0.f, gap, viewsH};
    r.heatmap = {r.light.right() + gap, 0.f, heatW, viewsH};
    return r;
}

LayoutFractions dragSplitter(LayoutFractions f, Splitter splitter, float dx, float dy, float width, float height,
                             float uiScale) noexcept {
    f = clampFractions(f);
    if (!std::isfinite(dx)) dx = 0.f;
    if (!std::isfinite(dy)) dy = 0.f;
    const float s = scaleOf(uiScale);
    const DashboardRects r = layoutDashboard(width, height, f, s);
    const float usable = std::max(1.f, r.eye.w + r.light.w + r.heatmap.w);
    const float bodyH = std::max(1.f, r.status.y);
    switch (splitter) {
    case Splitter::Controls: f.controlsWidth += dx / s; break;
    case Splitter::EyeLight: f.eyeEnd += dx / usable; break;
    case Splitter::LightHeatmap: f.lightEnd += dx / usable; break;
    case Splitter::Stats: f.statsHeight -= dy / bodyH; break;
    case Splitter::Count: break;
    }
    return clampFractions(f);
}

} // namespace ui
