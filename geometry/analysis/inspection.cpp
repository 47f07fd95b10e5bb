#include "geometry/analysis/inspection.h"

#include "geometry/analysis/ground_truth.h"

#include <nlohmann/json.hpp>

namespace geometry::analysis {

Inspection makeInspection(FrameReadback frame, const glm::vec3& l, const GroundTruth* truth) {
    Inspection in;
    in.shadow = std::move(frame.shadow);
    in.aux = std::move(frame.aux);
    const size_t n = in.aux.size();
    in.m.resize(n);
    in.positions.resize(n);
    in.normals.resize(n);
    in.receiver.resize(n);
    for (size_t i = 0; i < n; ++i) {
        in.positions[i] = glm::vec3(frame.positions[i]);
        in.m[i] = frame.positions[i].w;
        in.normals[i] = glm::vec3(frame.normals[i]);
        in.receiver[i] = in.aux[i].z >= 0.f && frame.normals[i].w > 0.f;
    }
    in.width = frame.width;
    in.height = n && in.width ? int(n / size_t(in.width)) : 0;
    in.aliasing = aliasingStats(in.m, in.receiver);
    for (int s = 0; s < int(frame.resolutions.size()); ++s)
        in.utilization.push_back(texelUtilization(in.aux, in.receiver, s, frame.resolutions[s]));
    if (truth) {
        in.occluded = truthOcclusion(in, frame.eye, l, *truth);
        in.truth = truthStats(in.shadow, *in.occluded, in.receiver);
    }
    return in;
}

std::vector<uint8_t> truthOcclusion(const Inspection& in, const glm::vec3& eye, const glm::vec3& l,
                                    const GroundTruth& truth) {
    std::vector<uint8_t> occluded =
        truth.occluded(in.positions, truth.surfaceNormals(eye, in.positions, in.normals), l);
    for (size_t i = 0; i < occluded.size(); ++i)
        if (!in.receiver[i]) occluded[i] = 0;
    return occluded;
}

void addInspectionMetrics(nlohmann::json& j, const Inspection& in) {
    const auto& a = in.aliasing;
    j["aliasing"] = {
        {"mean", a.mean},         {"p50", a.p50},     {"p95", a.p95}, {"max", a.max}, {"undersampled", a.undersampled},
        {"singular", a.singular}, {"pixels", a.count}};
    if (in.truth)
        j["truth"] = {{"false_shadow", in.truth->falseShadow},
                      {"false_lit", in.truth->falseLit},
                      {"mean_abs", in.truth->meanAbs},
                      {"pixels", in.truth->count}};
    for (size_t s = 0; s < in.utilization.size() && s < j["splits"].size(); ++s)
        j["splits"][s]["utilization"] = in.utilization[s];
}

} // namespace geometry::analysis
