#pragma once
// Everything the inspection views and metrics need from one rendered frame, read back once:
// per-pixel shadow factor, map coordinates, aliasing error, receivers, optional ray-traced truth.
#include "geometry/metrics.h"
#include "geometry/shadow_plan.h"
#include "renderer/image.h"
#include "renderer/renderer.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <vector>

namespace geometry { class GroundTruth; }

namespace renderer {

struct Inspection {
    int width = 0, height = 0;
    std::vector<float> shadow;          // s per pixel
    std::vector<float> m;               // aliasing error per pixel (DESIGN §4)
    std::vector<glm::vec4> aux;         // map texel u, v, split, map depth
    std::vector<glm::vec3> positions;   // world
    std::vector<glm::vec3> normals;     // facing normal
    std::vector<uint8_t> receiver;      // visible and facing the light (N·L > 0)
    std::optional<std::vector<uint8_t>> occluded; // ground truth, 1 = shadowed

    geometry::AliasingStats aliasing;
    std::optional<geometry::TruthStats> truth;
    std::vector<double> utilization;    // per split
};

/// Reads back the last frame and computes the statistics; `truth` adds the ground-truth pass.
[[nodiscard]] Inspection inspect(const Renderer& r, const geometry::ShadowPlan& plan,
                                 const geometry::GroundTruth* truth);

/// metrics.json fields: aliasing{mean,p50,p95,max,undersampled}, truth{false_shadow,false_lit,mean_abs}.
void addInspectionMetrics(nlohmann::json& j, const Inspection& in);

} // namespace renderer
