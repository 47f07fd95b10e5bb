#include "geometry/analysis/view_images.h"

#include "geometry/analysis/heatmap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace geometry::analysis {

namespace {
/// Draws `legend` into `img`, or hands it to the caller who asked for it.
void placeLegend(Image& img, Legend legend, Legend* out) {
    if (out) *out = std::move(legend);
    else drawLegend(img, legend);
}

void blend(uint8_t* px, const glm::vec3& c, float t) {
    for (int k = 0; k < 3; ++k) px[k] = uint8_t(std::lround((1.f - t) * float(px[k]) + t * 255.f * c[k]));
}
} // namespace

Image splitsView(const Image& eye, const Inspection& in, const geometry::shadow::ShadowPlan& plan, Legend* out) {
    Image img = eye;
    for (size_t i = 0; i < in.aux.size(); ++i)
        if (in.aux[i].z >= 0.f) blend(&img.rgba[4 * i], splitColour(int(in.aux[i].z)), 0.45f);
    if (plan.virtualMap.enabled) { // aux.z is the level each pixel samples: list those seen
        std::vector<glm::dvec2> seen;
        for (size_t k = 0; k < plan.virtualMap.levels.size(); ++k)
            if (std::any_of(in.aux.begin(), in.aux.end(), [&](const glm::vec4& a) { return int(a.z) == int(k); }))
                seen.emplace_back(double(k), plan.virtualMap.levels[k].texelWorld);
        placeLegend(img, levelLegend(seen), out);
        return img;
    }
    std::vector<glm::vec2> ranges;
    for (const auto& s : plan.splits) ranges.emplace_back(s.near, s.far);
    placeLegend(img, splitLegend(ranges), out);
    return img;
}

Image texelsView(const Image& eye, const Inspection& in, int every) {
    if (every < 1) throw std::invalid_argument("texel grid spacing must be at least 1");
    Image img = eye;
    const int w = in.width, h = in.height;
    const auto cell = [&](int x, int y) {
        const glm::vec4& a = in.aux[size_t(y) * w + x];
        return glm::ivec3(int(std::floor(a.x / float(every))), int(std::floor(a.y / float(every))), int(a.z));
    };
    // A pixel is on a grid line when its right or lower neighbour lies in another texel cell.
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (!in.receiver[i]) continue;
            const glm::ivec3 c = cell(x, y);
            if (c != cell(x + 1, y) || c != cell(x, y + 1)) blend(&img.rgba[4 * i], {0.05f, 0.05f, 0.05f}, 0.8f);
        }
    return img;
}

void tintSampledTexels(Image& light, const Inspection& in, int split, int res) {
    const std::vector<uint8_t> used = geometry::analysis::texelUsageMask(in.aux, in.receiver, split, res);
    if (used.empty()) return;
    // Each light-view pixel covers res/size texels; tint it when any of them is used.
    const int size = light.width;
    std::vector<uint8_t> hit(size_t(size) * size, 0);
    for (int v = 0; v < res; ++v)
        for (int u = 0; u < res; ++u)
            if (used[size_t(v) * res + u]) hit[size_t(size - 1 - v * size / res) * size + size_t(u) * size / res] = 1;
    for (size_t i = 0; i < hit.size(); ++i)
        if (hit[i]) blend(&light.rgba[4 * i], {1.f, 0.2f, 0.8f}, 0.6f);
}

namespace {
/// eye·weight + heat·(1 − weight) per pixel.
Image blendOver(Image heat, const Image& eye, float weight) {
    if (weight <= 0.f) return heat;
    for (size_t i = 0; i + 3 < heat.rgba.size() && i + 3 < eye.rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            heat.rgba[i + k] = uint8_t(std::lround((1.f - weight) * heat.rgba[i + k] + weight * eye.rgba[i + k]));
    return heat;
}
} // namespace

Image aliasingView(const Inspection& in, const Image& eye, float blend, Legend* out) {
    Image img = blendOver(aliasingHeatmap(in.m, in.receiver, in.width, in.height), eye, blend);
    placeLegend(img, aliasingLegend(), out);
    return img;
}

Image differenceView(const Inspection& a, const Inspection& b, Legend* out) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("A and B frames differ in size");
    const size_t n = size_t(a.width) * a.height;
    std::vector<float> ratio(n, 0.f);
    std::vector<uint8_t> both(n, 0);
    for (size_t i = 0; i < n && i < a.m.size() && i < b.m.size(); ++i) {
        both[i] = a.receiver[i] && b.receiver[i];
        if (both[i]) ratio[i] = a.m[i] / b.m[i];
    }
    Image img = aliasingHeatmap(ratio, both, a.width, a.height);
    Legend legend = aliasingLegend();
    legend.title = "m_A / m_B (red: A coarser)";
    placeLegend(img, std::move(legend), out);
    return img;
}

Image softView(const Inspection& in, const Image& eye, float blend, Legend* out) {
    if (!in.softTruth || in.sunVisibility.size() != in.shadow.size())
        throw std::invalid_argument("the soft view needs --truth and light.angular_diameter_deg > 0");
    // s − v on the aliasing scale: d = −0.5 (too dark) ↦ m = 16 (red), +0.5 ↦ 1/16 (blue).
    constexpr float kStops = 8.f; // log2 stops per unit of s − v
    std::vector<float> m(in.shadow.size(), 1.f);
    for (size_t i = 0; i < m.size(); ++i)
        if (in.receiver[i]) m[i] = std::exp2(-kStops * (in.shadow[i] - in.sunVisibility[i]));
    Image img = blendOver(aliasingHeatmap(m, in.receiver, in.width, in.height), eye, blend);
    Legend legend = aliasingLegend();
    legend.title = "s - v (red: too dark, blue: too light)";
    legend.bar = [](float t) { return divergingLog2(std::exp2(kStops * (0.5f - t))); }; // t = 0: s − v = −0.5
    legend.ticks = {{0.f, "-0.5"}, {0.25f, "-0.25"}, {0.5f, "0"}, {0.75f, "+0.25"}, {1.f, "+0.5"}};
    placeLegend(img, std::move(legend), out);
    return img;
}

Image truthView(const Inspection& in, const Image& eye, float blend, Legend* out) {
    if (!in.occluded) throw std::invalid_argument("the truth view needs --truth");
    if (in.classes.size() == in.shadow.size()) { // the truth classes: each its own colour
        Image img = blendOver(truthClassHeatmap(in.classes, in.shadow, in.receiver, in.width, in.height), eye, blend);
        placeLegend(img, truthClassLegend(in.classes, in.shadow, in.receiver), out);
        return img;
    }
    Image img = blendOver(truthHeatmap(in.shadow, *in.occluded, in.receiver, in.width, in.height), eye, blend);
    placeLegend(img, truthLegend(), out);
    return img;
}

} // namespace geometry::analysis
