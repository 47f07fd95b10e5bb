#pragma once
#include "geometry/analysis/image.h"
#include "render_options.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

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

/// Throws std::invalid_argument when `exports` asks for views it cannot make (truth views without truth).
void validateExports(const ExportOptions& exports);

/// What one `render` wrote into options.out.
struct RenderOutput {
    nlohmann::json metrics;            // the content of metrics.json
    std::vector<std::string> written;  // every file's path, metrics.json last
    geometry::analysis::Image eye;     // the eye view (written as eye.png when exports ask for it)
    std::vector<std::string> warnings; // the plan's and the renderer's, not printed
};

/// The work of runRender on a scene already loaded and viewed (loadScene(options)), printing
/// nothing: renders one frame, writes the exports and metrics.json into options.out (created).
/// Throws std::invalid_argument for options the frame cannot honour (--light-split beyond the
/// plan's splits), std::runtime_error when a file cannot be written or GL reports an error.
[[nodiscard]] RenderOutput renderInto(geometry::scene::Scene scene, const RenderOptions& options,
                                      const ExportOptions& exports);

/// metrics.json content for a rendered frame.
[[nodiscard]] nlohmann::json frameMetrics(const HeadlessFrame& frame, const RenderOptions& options);
} // namespace app
