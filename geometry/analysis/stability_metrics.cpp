#include "geometry/analysis/stability_metrics.h"

#include "geometry/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace geometry::analysis {

namespace {

void requireSameSize(size_t expected, size_t got, const char* what) {
    if (got != expected)
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(got) + " values, expected " +
                                    std::to_string(expected));
}

/// percentile() of the values, 0 when there are none (no pairs: no seam).
double percentileOrZero(std::vector<double>& v, unsigned pct) {
    return v.empty() ? 0.0 : percentile(std::span(v), pct);
}

} // namespace

FlickerStats flickerStats(std::span<const float> sBefore, std::span<const uint8_t> occludedBefore,
                          std::span<const uint8_t> receiverBefore, std::span<const float> sAfter,
                          std::span<const uint8_t> occludedAfter, std::span<const uint8_t> receiverAfter) {
    const size_t n = sBefore.size();
    requireSameSize(n, occludedBefore.size(), "flickerStats occludedBefore");
    requireSameSize(n, receiverBefore.size(), "flickerStats receiverBefore");
    requireSameSize(n, sAfter.size(), "flickerStats sAfter");
    requireSameSize(n, occludedAfter.size(), "flickerStats occludedAfter");
    requireSameSize(n, receiverAfter.size(), "flickerStats receiverAfter");
    FlickerStats out;
    for (size_t i = 0; i < n; ++i) {
        if (!receiverBefore[i] || !receiverAfter[i]) continue;
        if (!std::isfinite(sBefore[i]) || !std::isfinite(sAfter[i])) continue;
        if ((occludedBefore[i] != 0) != (occludedAfter[i] != 0)) continue; // truth moved: not flicker
        ++out.stable;
        out.flips += (sBefore[i] >= 0.5f) != (sAfter[i] >= 0.5f);
    }
    out.rate = out.stable ? double(out.flips) / double(out.stable) : 0.0;
    return out;
}

SeamStats seamStats(std::span<const float> m, std::span<const glm::vec4> aux, std::span<const uint8_t> receiver,
                    std::span<const glm::vec3> positions, std::span<const glm::vec3> normals, const glm::vec3& eye,
                    int width, int height) {
    if (width < 0 || height < 0) throw std::invalid_argument("seamStats: negative image size");
    const size_t n = size_t(width) * size_t(height);
    requireSameSize(n, m.size(), "seamStats m");
    requireSameSize(n, aux.size(), "seamStats aux");
    requireSameSize(n, receiver.size(), "seamStats receiver");
    requireSameSize(n, positions.size(), "seamStats positions");
    requireSameSize(n, normals.size(), "seamStats normals");
    constexpr float kSameNormal = 0.99f;     // cos 8°
    constexpr float kPlaneTolerance = 0.01f; // of the distance to the eye
    const auto split = [&](size_t i) -> long {
        if (!receiver[i] || !std::isfinite(m[i]) || !(m[i] > 0.f) || !(m[i] < kSingularM) || !std::isfinite(aux[i].z))
            return -1;
        return std::lround(aux[i].z);
    };
    const auto sameSurface = [&](size_t a, size_t b) {
        const glm::vec3 na = normals[a], nb = normals[b];
        const float distance = glm::length(positions[a] - eye);
        return glm::dot(na, nb) >= kSameNormal * glm::length(na) * glm::length(nb) &&
               std::abs(glm::dot(na, positions[b] - positions[a])) <= kPlaneTolerance * distance * glm::length(na);
    };
    std::vector<double> across, raw, inside;
    const auto walk = [&](size_t c, size_t a, size_t b, size_t e) {
        const long sc = split(c), sa = split(a), sb = split(b), se = split(e);
        if (sc < 0 || sa < 0 || sb < 0 || se < 0 || sc != sa || se != sb) return;
        if (!sameSurface(a, c) || !sameSurface(a, b) || !sameSurface(a, e)) return;
        const double lc = std::log(double(m[c])), la = std::log(double(m[a])), lb = std::log(double(m[b])),
                     le = std::log(double(m[e]));
        const double seam = std::exp(std::abs((lb - la) - 0.5 * (la - lc) - 0.5 * (le - lb)));
        if (!std::isfinite(seam)) return;
        if (sa != sb) {
            across.push_back(seam);
            raw.push_back(std::exp(std::abs(lb - la)));
        } else {
            inside.push_back(seam);
        }
    };
    const size_t w = size_t(width);
    for (size_t y = 0; y < size_t(height); ++y)
        for (size_t x = 0; x < w; ++x) {
            const size_t i = y * w + x;
            if (x >= 1 && x + 2 < w) walk(i - 1, i, i + 1, i + 2);
            if (y >= 1 && y + 2 < size_t(height)) walk(i - w, i, i + w, i + 2 * w);
        }
    SeamStats out;
    out.pairs = across.size();
    out.baselinePairs = inside.size();
    out.median = percentileOrZero(across, 50);
    out.p95 = percentileOrZero(across, 95);
    out.rawMedian = percentileOrZero(raw, 50);
    out.baselineMedian = percentileOrZero(inside, 50);
    return out;
}

FlickerStats worldFlickerStats(const Inspection& before, const glm::mat4& beforeViewProj, const Inspection& after) {
    const auto check = [](const Inspection& in, const char* which) {
        const size_t n = size_t(std::max(in.width, 0)) * size_t(std::max(in.height, 0));
        if (in.shadow.size() != n || in.receiver.size() != n || in.positions.size() != n ||
            (in.occluded && in.occluded->size() != n))
            throw std::invalid_argument(std::string("worldFlickerStats: the ") + which +
                                        " frame's fields do not match its size");
    };
    check(before, "previous");
    check(after, "current");
    const bool truth = before.occluded && after.occluded;
    const glm::dmat4 vp(beforeViewProj);
    FlickerStats out;
    for (size_t i = 0; i < after.shadow.size(); ++i) {
        if (!after.receiver[i] || !std::isfinite(after.shadow[i])) continue;
        const glm::dvec4 c = vp * glm::dvec4(glm::dvec3(after.positions[i]), 1.0);
        if (!(c.w > 0.0)) continue;
        const double x = (c.x / c.w * 0.5 + 0.5) * before.width, y = (0.5 - c.y / c.w * 0.5) * before.height;
        if (!(x >= 0.0 && y >= 0.0 && x < before.width && y < before.height)) continue;
        const int jx = int(x), jy = int(y);
        const size_t j = size_t(jy) * size_t(before.width) + size_t(jx);
        if (!before.receiver[j] || !std::isfinite(before.shadow[j])) continue;
        // The previous frame saw the same surface there: its view depth agrees (c.w is view depth).
        const double depth = (vp * glm::dvec4(glm::dvec3(before.positions[j]), 1.0)).w;
        if (!(std::abs(depth - c.w) <= 0.02 * c.w)) continue;
        if (truth && (*before.occluded)[j] != (*after.occluded)[i]) continue;
        // The point lay inside a rendered region of the previous frame, not on its edge: the nearest
        // pixel is up to half a pixel from the point, so a state change across a rendered edge that
        // held still would be sampling noise, not shimmer.
        const bool lit = before.shadow[j] >= 0.5f;
        bool inside = true;
        for (int dy = -1; dy <= 1 && inside; ++dy)
            for (int dx = -1; dx <= 1 && inside; ++dx) {
                const int nx = jx + dx, ny = jy + dy;
                if (nx < 0 || ny < 0 || nx >= before.width || ny >= before.height) continue;
                const size_t k = size_t(ny) * size_t(before.width) + size_t(nx);
                if (before.receiver[k] && std::isfinite(before.shadow[k])) inside = (before.shadow[k] >= 0.5f) == lit;
            }
        if (!inside) continue;
        ++out.stable;
        out.flips += lit != (after.shadow[i] >= 0.5f);
    }
    out.rate = out.stable ? double(out.flips) / double(out.stable) : 0.0;
    return out;
}

FramePairFlicker framePairFlicker(const Inspection& before, const glm::mat4& beforeViewProj, const Inspection& after) {
    if (!before.occluded || !after.occluded) throw std::invalid_argument("framePairFlicker: both frames need truth");
    return {
        flickerStats(before.shadow, *before.occluded, before.receiver, after.shadow, *after.occluded, after.receiver),
        worldFlickerStats(before, beforeViewProj, after)};
}

} // namespace geometry::analysis
