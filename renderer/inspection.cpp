#include "inspection.h"

#include "geometry/ground_truth.h"

#include <nlohmann/json.hpp>

namespace renderer {

Inspection inspect(const Renderer& r, const geometry::ShadowPlan& plan, const geometry::GroundTruth* truth) {
    Inspection in;
    const auto aux = r.readAux();
    const auto positions = r.readPositions();
    const auto normals = r.readNormals();
    in.shadow = r.readShadowMask();
    in.aux = aux;
    const size_t n = aux.size();
    in.m.resize(n);
    in.positions.resize(n);
    in.normals.resize(n);
    in.receiver.resize(n);
    for (size_t i = 0; i < n; ++i) {
        in.positions[i] = glm::vec3(positions[i]);
        in.m[i] = positions[i].w;
        in.normals[i] = glm::vec3(normals[i]);
        in.receiver[i] = aux[i].z >= 0.f && normals[i].w > 0.f;
    }
    in.width = int(r.stats().eyeWidth);
    in.height = n && in.width ? int(n / size_t(in.width)) : 0;
    in.aliasing = geometry::aliasingStats(in.m, in.receiver);
    for (int s = 0; s < int(plan.splits.size()); ++s)
        in.utilization.push_back(
            geometry::texelUtilization(in.aux, in.receiver, s, std::min(plan.splits[s].resolution, r.stats().shadowResolution)));
    if (truth) {
        in.occluded = truth->occluded(in.positions, in.normals, plan.l);
        for (size_t i = 0; i < n; ++i)
            if (!in.receiver[i]) (*in.occluded)[i] = 0;
        in.truth = geometry::truthStats(in.shadow, *in.occluded, in.receiver);
    }
    return in;
}

void addInspectionMetrics(nlohmann::json& j, const Inspection& in) {
    const auto& a = in.aliasing;
    j["aliasing"] = {{"mean", a.mean}, {"p50", a.p50}, {"p95", a.p95}, {"max", a.max},
                     {"undersampled", a.undersampled}, {"pixels", a.count}};
    if (in.truth)
        j["truth"] = {{"false_shadow", in.truth->falseShadow}, {"false_lit", in.truth->falseLit},
                      {"mean_abs", in.truth->meanAbs}, {"pixels", in.truth->count}};
    for (size_t s = 0; s < in.utilization.size() && s < j["splits"].size(); ++s)
        j["splits"][s]["utilization"] = in.utilization[s];
}

} // namespace renderer
