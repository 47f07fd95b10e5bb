#include "geometry/shadow/virtual_plan.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace geometry::shadow {

namespace {
uint64_t mix(uint64_t h, double v) noexcept {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    return h;
}
} // namespace

glm::dmat4 VirtualPlan::pageViewProj(const PageKey& k) const noexcept {
    const ClipLevel& c = levels[size_t(std::clamp(k.level, 0, int(levels.size()) - 1))];
    const double w = c.pageWorld, x0 = double(k.x) * w, y0 = double(k.y) * w;
    const double d = std::max(depthHi - depthLo, 1e-9);
    glm::dmat4 m(0.0); // rows: right, up, l scaled to [−1, 1]; column-major (m[column][row])
    const glm::dvec3 rows[3] = {frame.right * (2.0 / w), frame.up * (2.0 / w), frame.l * (2.0 / d)};
    const double offsets[3] = {-2.0 * x0 / w - 1.0, -2.0 * y0 / w - 1.0, -2.0 * depthLo / d - 1.0};
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) m[col][r] = rows[r][col];
        m[3][r] = offsets[r];
    }
    m[3][3] = 1.0;
    return m;
}

glm::dvec2 VirtualPlan::levelOrigin(int k) const noexcept {
    const ClipLevel& c = levels[size_t(std::clamp(k, 0, int(levels.size()) - 1))];
    return glm::dvec2(double(c.firstPageX), double(c.firstPageY)) * c.pageWorld - frame.project(eye);
}

double VirtualPlan::depthOf(const glm::dvec3& x) const noexcept {
    return (glm::dot(frame.l, x) - depthLo) / std::max(depthHi - depthLo, 1e-9);
}

uint64_t virtualMemoryBytes(const VirtualMapConfig& config) noexcept {
    const uint64_t pps = config.pagesPerSide();
    return uint64_t(config.poolPages) * config.pageSize * config.pageSize * 4u +
           uint64_t(std::max(config.levels, 0)) * pps * pps * 4u;
}

VirtualPlan planVirtual(const VirtualSettings& settings, const scene::Aabb& S, const glm::vec3& eye,
                        const glm::vec3& l) {
    VirtualPlan p;
    p.enabled = true;
    p.frame = lightFrame(l);
    p.eye = glm::dvec3(eye);
    // validate() refuses other sizes; a widget dragged between them is read as the power of two below,
    // with 4 to kMaxVirtualPagesPerSide pages a side, so a plan is always one the renderer can draw.
    p.config.virtualSize = std::bit_floor(uint32_t(std::clamp(settings.size, 64, 1 << 20)));
    p.config.pageSize = std::clamp(std::bit_floor(uint32_t(std::clamp(settings.pageSize, 1, 1 << 16))),
                                   p.config.virtualSize / uint32_t(kMaxVirtualPagesPerSide), p.config.virtualSize / 4);
    p.config.levels = std::clamp(settings.levels, 1, 16);
    p.config.poolPages = uint32_t(std::max(settings.poolPages, 1));
    // S's extent across l (D) and along it.
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    p.depthLo = HUGE_VAL;
    p.depthHi = -HUGE_VAL;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? S.hi.x : S.lo.x, (i & 2) ? S.hi.y : S.lo.y, (i & 4) ? S.hi.z : S.lo.z);
        const glm::dvec2 s = p.frame.project(c);
        lo = glm::min(lo, s);
        hi = glm::max(hi, s);
        p.depthLo = std::min(p.depthLo, glm::dot(p.frame.l, c));
        p.depthHi = std::max(p.depthHi, glm::dot(p.frame.l, c));
    }
    const double D = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3});
    if (!std::isfinite(D) || !std::isfinite(p.depthLo) || !std::isfinite(p.depthHi)) {
        p.depthLo = 0;
        p.depthHi = 1;
    }
    // A sliver of depth beyond S at both ends: casters on S's faces are not clipped.
    const double pad = 1e-4 * std::max(p.depthHi - p.depthLo, 1e-3);
    p.depthLo -= pad;
    p.depthHi += pad;
    // The coarsest square reaches pps/2 − 1 whole pages from the eye's page on every side (clipLevels):
    // D from any eye above S. Level 0 is 2^(levels−1) times narrower.
    const double pps = double(p.config.pagesPerSide());
    const double reach = std::max(pps / 2.0 - 1.0, 1.0) / pps; // of a level's side
    const double coarsest = (std::isfinite(D) ? D : 1.0) / reach;
    p.config.side0 = std::ldexp(coarsest, -(std::max(p.config.levels, 1) - 1));
    p.levels = clipLevels(p.frame, p.eye, p.config);
    uint64_t h = 0x5ADE5C09Eull;
    for (double v :
         {p.frame.l.x, p.frame.l.y, p.frame.l.z, p.depthLo, p.depthHi, p.config.side0, pps, double(p.config.pageSize)})
        h = mix(h, v);
    p.content = h;
    return p;
}

} // namespace geometry::shadow
