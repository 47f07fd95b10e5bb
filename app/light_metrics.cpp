#include "light_metrics.h"

#include "renderer/inspection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace app {

nlohmann::json lightDescription(const geometry::scene::Light& light) {
    const auto vec = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    nlohmann::json j = {{"type", geometry::scene::lightTypeName(light.type)}, {"direction", vec(light.l())}};
    if (light.positional()) {
        j["position"] = vec(light.position);
        j["range"] = light.range;
        j["radius"] = light.radius;
        if (light.type == geometry::scene::LightType::Spot) j["cone_deg"] = light.coneDeg;
    }
    if (!light.settings.empty()) j["settings"] = light.settings; // its overrides of the shared settings
    return j;
}

namespace {

nlohmann::json lightBlock(const HeadlessFrame& f, size_t k, const geometry::analysis::Inspection& in) {
    const geometry::shadow::ShadowPlan& plan = f.plans[k];
    const auto& stats = f.renderer->stats();
    nlohmann::json block = lightDescription(f.scene.lights[k]);
    block["inspected"] = k == f.light;
    block["gamma_deg"] = plan.gammaDeg;
    block["light_view_angle_deg"] = plan.lightViewAngleDeg;
    nlohmann::json maps = nlohmann::json::array();
    for (size_t i = 0; i < plan.splits.size(); ++i)
        maps.push_back({{"empty", plan.splits[i].empty()},
                        {"resolution", plan.splits[i].resolution},
                        {"triangles", i < stats.splitTriangles.size() ? stats.splitTriangles[i] : 0}});
    block["maps"] = maps;
    block["warnings"] = plan.warnings;
    geometry::analysis::addInspectionMetrics(block, in);
    return block;
}

} // namespace

void addLightMetrics(nlohmann::json& j, HeadlessFrame& f, const geometry::shadow::Viewport& size,
                     const renderer::ViewOptions& views, const geometry::analysis::Inspection& inspected,
                     const geometry::analysis::GroundTruth* truth, int truthSamples) {
    const size_t count = f.plans.size();
    std::vector<nlohmann::json> blocks(count);
    blocks[f.light] = lightBlock(f, f.light, inspected);
    // Per pixel, the largest m of the lights that pixel receives (docs/design.md §4 "Aliasing error m").
    std::vector<float> worst(inspected.m.size(), 0.f);
    std::vector<uint8_t> receiver(inspected.m.size(), 0);
    // Every (pixel, light) pair a light reaches, for the pooled truth.
    std::vector<float> allS;
    std::vector<uint8_t> allOccluded, allReceiver;
    const auto fold = [&](const geometry::analysis::Inspection& in) {
        for (size_t i = 0; i < worst.size() && i < in.m.size(); ++i)
            if (in.receiver[i] && std::isfinite(in.m[i])) {
                worst[i] = std::max(worst[i], in.m[i]);
                receiver[i] = 1;
            }
        if (!in.occluded) return;
        allS.insert(allS.end(), in.shadow.begin(), in.shadow.end());
        allOccluded.insert(allOccluded.end(), in.occluded->begin(), in.occluded->end());
        allReceiver.insert(allReceiver.end(), in.receiver.begin(), in.receiver.end());
    };
    fold(inspected);
    for (size_t k = 0; k < count; ++k) {
        if (k == f.light) continue;
        f.renderer->render(f.plans, size, views, k);
        const geometry::analysis::Inspection in =
            renderer::inspect(*f.renderer, f.plans[k], inspected.occluded ? truth : nullptr, truthSamples);
        blocks[k] = lightBlock(f, k, in);
        fold(in);
    }
    j["lights"] = blocks;
    if (inspected.occluded && !allS.empty()) {
        const geometry::analysis::TruthStats t = geometry::analysis::truthStats(allS, allOccluded, allReceiver);
        j["truth_all_lights"] = {
            {"false_shadow", t.falseShadow}, {"false_lit", t.falseLit}, {"mean_abs", t.meanAbs}, {"pairs", t.count}};
    }
    const geometry::analysis::AliasingStats a = geometry::analysis::aliasingStats(worst, receiver);
    j["aliasing_worst_light"] = {{"mean", a.mean}, {"p50", a.p50},      {"p95", a.p95},
                                 {"max", a.max},   {"pixels", a.count}, {"undersampled", a.undersampled}};
}

} // namespace app
