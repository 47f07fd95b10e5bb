#pragma once
#include "render_options.h"

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {
struct HeadlessFrame;

/// View names `render --views` accepts.
[[nodiscard]] const std::vector<std::string>& viewNames();

/// What `render` writes besides metrics.json.
struct ExportOptions {
    std::vector<std::string> views{"eye", "light"}; // names from viewNames()
    TruthOptions truth;                             // ground-truth pass (Embree)
    int texelGrid = 1;                              // texels view: a line every N texels
    int lightSplit = 0;                             // light views: which split's map
    glm::vec2 depthRange{-1.f};                     // light view black/white points; x < 0: auto-fit
    bool lightTexels = false;                       // tint the texels visible pixels sample
    float heatmapBlend = 0.f;                       // heatmaps over the eye image: 0 alone … 1 opaque
};

/// Adds --views, --truth, --truth-samples, --texel-grid, --light-split, --depth-range, --light-texels, --heatmap-blend.
void addExportOptions(CLI::App& cmd, ExportOptions& options);

/// `shadowscope render`: writes one PNG per view (plus PFM raw values for aliasing, the shadow
/// factor and truth) and DIR/metrics.json; prints the paths.
int runRender(const RenderOptions& options, const ExportOptions& exports = {});

/// metrics.json content for a rendered frame.
[[nodiscard]] nlohmann::json frameMetrics(const HeadlessFrame& frame, const RenderOptions& options);
} // namespace app
