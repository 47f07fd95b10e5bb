#include "geometry/analysis/caster_coverage.h"

#include "geometry/shadow/focus.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geometry::analysis {

namespace {

constexpr double kTolerance = 1e-3; // NDC units: fitUnitCube's margin is 1e-5 of the extent

bool insideMap(const glm::dmat4& viewProj, const glm::vec3& p) noexcept {
    const glm::dvec4 c = viewProj * glm::dvec4(glm::dvec3(p), 1.0);
    if (!(c.w > 0.0)) return false;
    const double lim = (1.0 + kTolerance) * c.w;
    return std::abs(c.x) <= lim && std::abs(c.y) <= lim && c.z >= -lim;
}

} // namespace

CasterCoverage casterCoverage(const shadow::ShadowPlan& plan, std::span<const glm::vec3> positions,
                              std::span<const glm::vec4> aux, std::span<const uint8_t> receiver,
                              std::span<const uint8_t> occluded, std::span<const float> shadow) {
    const size_t n = positions.size();
    if (aux.size() != n || receiver.size() != n || occluded.size() != shadow.size() ||
        (!occluded.empty() && occluded.size() != n))
        throw std::invalid_argument("casterCoverage: " + std::to_string(n) + " positions but " +
                                    std::to_string(aux.size()) + " aux, " + std::to_string(receiver.size()) +
                                    " receiver, " + std::to_string(occluded.size()) + " truth and " +
                                    std::to_string(shadow.size()) + " shadow values");
    CasterCoverage out;
    std::vector<glm::dmat4> viewProj;
    for (const auto& s : plan.splits) viewProj.emplace_back(s.lightViewProj);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 p = positions[i];
        if (!receiver[i] || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            !std::isfinite(aux[i].z))
            continue;
        const long split = std::lround(aux[i].z);
        if (split < 0 || split >= long(plan.splits.size())) continue;
        ++out.count;
        const glm::vec3 end = shadow::exitTowardLight(p, plan.l, plan.sceneBounds);
        const bool inside = plan.splits[size_t(split)].empty()
                                ? end == p
                                : insideMap(viewProj[size_t(split)], p) && insideMap(viewProj[size_t(split)], end);
        if (inside) continue;
        ++out.clippedCount;
        if (!occluded.empty() && occluded[i] && shadow[i] >= 0.5f) ++out.falseLitClippedCount;
    }
    if (out.count) {
        out.clipped = double(out.clippedCount) / double(out.count);
        out.falseLitClipped = double(out.falseLitClippedCount) / double(out.count);
    }
    return out;
}

} // namespace geometry::analysis
