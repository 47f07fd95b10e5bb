// The dialogs over the panels (help, file browser, export) and the export's offscreen drawing.
// An exported eye view is drawn as `shadowscope render --views eye` draws one (a fresh renderer,
// every light planned for the export's size, the default view options), so the two PNGs are the
// same; the dashboard view is the headless dashboard at that size (ui/dashboard_headless.h).
//
// Index
//   drawDialogs · openFileBrowser · renderExport (eye, light, heatmap, dashboard) · exportView
#include "dashboard.h"

#include "dashboard_headless.h"
#include "file_list.h"
#include "geometry/analysis/view_images.h"
#include "renderer/inspection.h"
#include "renderer/plan_frame.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <stdexcept>

namespace ui {

namespace {

using geometry::analysis::Image;

/// `img` centred on a width × height canvas of the panels' background (the square light view).
Image letterbox(const Image& img, int width, int height) {
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.resize(size_t(width) * size_t(height) * 4);
    for (size_t i = 0; i < out.rgba.size(); i += 4) {
        out.rgba[i] = 20, out.rgba[i + 1] = 20, out.rgba[i + 2] = 22, out.rgba[i + 3] = 255;
    }
    const int x0 = (width - img.width) / 2, y0 = (height - img.height) / 2;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            std::copy_n(img.at(x, y), 4, out.rgba.data() + (size_t(y0 + y) * size_t(width) + size_t(x0 + x)) * 4);
    return out;
}

/// One side drawn offscreen: its own renderer, so the panels' frames and maps stay as they are.
struct OffscreenFrame {
    std::unique_ptr<renderer::Renderer> renderer;
    geometry::shadow::ShadowPlan plan;
};

} // namespace

void Dashboard::drawDialogs(float width, float height) {
    help_.frame(width, height);
    if (auto path = browser_.frame(width, height, state_.recentFiles)) {
        scenePath_ = *path;
        loadScene(*path);
    }
    const std::array<int, 2> eye{eyeSize_.width, eyeSize_.height};
    const std::array<std::array<int, 2>, size_t(ExportView::Count)> panels{
        eye, eye, std::array<int, 2>{lightViewSize_, lightViewSize_}, eye, std::array<int, 2>{int(width), int(height)}};
    if (auto request = exportDialog_.frame(width, height, panels, comparing())) pendingExport_ = *request;
}

void Dashboard::openFileBrowser(const std::filesystem::path& at) {
    std::error_code ec;
    if (!at.empty()) browser_.open(at);
    else if (!scenePath_.empty() && std::filesystem::exists(scenePath_, ec)) browser_.open(scenePath_);
    else if (!state_.recentFiles.empty()) browser_.open(state_.recentFiles.front());
    else browser_.open({});
}

Image Dashboard::renderExport(const ExportRequest& request) {
    if (const std::string problem = exportSizeProblem(request.view, request.width, request.height); !problem.empty())
        throw std::invalid_argument(problem);
    if (request.view == ExportView::EyeB && !comparing()) throw std::invalid_argument("eye B needs A/B compare on");
    if (request.view == ExportView::Dashboard) {
        LoadedScene copy;
        copy.source = scene_.source;
        copy.file = scene_.file;
        copy.truth = std::make_unique<geometry::analysis::GroundTruth>(
            geometry::analysis::GroundTruth::borrowing(copy.file.scene));
        // Its own ImGui context and frames: the window's context comes back after, and the widget
        // map keeps describing the window.
        ImGuiContext* window = ImGui::GetCurrentContext();
        widgetMapPause(true);
        Image img;
        try {
            HeadlessDashboard offscreen(std::move(copy), state_, options_, request.width, request.height);
            img = offscreen.render();
        } catch (...) {
            widgetMapPause(false);
            ImGui::SetCurrentContext(window);
            throw;
        }
        widgetMapPause(false);
        ImGui::SetCurrentContext(window);
        return img;
    }
    const geometry::scene::Scene& scene = scene_.file.scene;
    const geometry::shadow::Viewport size{request.width, request.height};
    // Every light planned for `eye` as the command line does; the light view `lightSize` square.
    const auto draw = [&](int side, geometry::shadow::Viewport eye, int lightSize) {
        const PassInputs in = passInputs(side);
        OffscreenFrame f;
        f.renderer = std::make_unique<renderer::Renderer>(scene);
        giveCasterLod(*f.renderer);
        std::vector<geometry::shadow::ShadowPlan> plans;
        for (const geometry::scene::Light& light : in.lights)
            plans.push_back(renderer::planFrame(*f.renderer, in.settings, scene.bounds(), in.camera, light, eye));
        if (plans.empty()) throw std::runtime_error("no light to draw");
        const size_t inspected = std::min(in.inspectedLight, plans.size() - 1);
        f.plan = plans[inspected];
        renderer::ViewOptions v;
        v.lightViewSize = lightSize;
        if (request.view == ExportView::Light) {
            v.lightSplit = std::clamp(in.lightSplit, 0, std::max(0, int(f.plan.splits.size()) - 1));
            v.overlays = in.overlays;
        }
        f.renderer->render(plans, eye, v, inspected);
        return f;
    };
    const int cliLightSize = std::clamp(state_.settings[0].resolution, 16, 1024); // as `render` sizes it
    switch (request.view) {
    case ExportView::EyeA:
    case ExportView::EyeB:
        return draw(request.view == ExportView::EyeB ? 1 : 0, size, cliLightSize).renderer->readEye();
    case ExportView::Light: {
        // The map the panel shows (planned for the eye view's size), drawn at the export's size.
        const int side = shownSide();
        const int square = std::min(request.width, request.height);
        const OffscreenFrame f = draw(side, sides_[side].size.width > 0 ? sides_[side].size : size, square);
        return letterbox(state_.views.unwarped ? f.renderer->readUnwarpedLight() : f.renderer->readLight(),
                         request.width, request.height);
    }
    case ExportView::Heatmap: {
        const int side = shownSide();
        const geometry::analysis::GroundTruth* truth = state_.views.truth ? scene_.truth.get() : nullptr;
        const int samples = std::max(1, state_.views.truthSamples);
        OffscreenFrame f = draw(side, size, cliLightSize);
        const geometry::analysis::Inspection in = renderer::inspect(*f.renderer, f.plan, truth, samples);
        const Image eye = f.renderer->readEye();
        const float blend = state_.views.heatmapBlend;
        switch (state_.views.heatmap) {
        case HeatmapKind::Aliasing: return geometry::analysis::aliasingView(in, eye, blend);
        case HeatmapKind::Truth:
            if (!in.occluded) throw std::invalid_argument("the truth heatmap needs ground truth on (Views)");
            return geometry::analysis::truthView(in, eye, blend);
        case HeatmapKind::Splits: return geometry::analysis::splitsView(eye, in, f.plan);
        case HeatmapKind::Texels: return geometry::analysis::texelsView(eye, in, std::max(1, state_.views.texelGrid));
        case HeatmapKind::Soft:
            if (!in.softTruth) throw std::invalid_argument("the soft heatmap needs truth and a sun of some size");
            return geometry::analysis::softView(in, eye, blend);
        case HeatmapKind::Difference: {
            if (!comparing()) throw std::invalid_argument("the difference heatmap needs A/B compare on");
            OffscreenFrame other = draw(1 - side, size, cliLightSize);
            const geometry::analysis::Inspection b = renderer::inspect(*other.renderer, other.plan, nullptr, 1);
            return side == 0 ? geometry::analysis::differenceView(in, b) : geometry::analysis::differenceView(b, in);
        }
        case HeatmapKind::Count: break;
        }
        throw std::invalid_argument("unknown heatmap");
    }
    case ExportView::Dashboard:
    case ExportView::Count: break;
    }
    throw std::invalid_argument("unknown view");
}

std::optional<std::string> Dashboard::exportView(const ExportRequest& request) {
    try {
        Image img = renderExport(request);
        const std::filesystem::path dir = createNumberedFolder(options_.screenshotDir);
        const std::string path = (dir / (std::string(exportViewName(request.view)) + "_" +
                                         std::to_string(request.width) + "x" + std::to_string(request.height) + ".png"))
                                     .string();
        geometry::analysis::writePng(path, img);
        status_ = "exported " + path;
        return path;
    } catch (const std::exception& e) {
        status_ = std::string("export not written: ") + e.what();
        return std::nullopt;
    }
}

} // namespace ui
