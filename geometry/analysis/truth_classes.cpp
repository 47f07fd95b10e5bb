#include "geometry/analysis/truth_classes.h"

#include "geometry/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace geometry::analysis {
namespace {

constexpr int kSearchRadius = 8; // pixels; a displacement beyond it counts as this far

void check(const TruthClassInput& in) {
    const size_t n = in.s.size();
    const auto same = [&](size_t m, const char* what, bool optional) {
        if ((optional && m == 0) || m == n) return;
        throw std::invalid_argument(std::string("truthClasses: ") + what + " holds " + std::to_string(m) +
                                    " values, s holds " + std::to_string(n));
    };
    same(in.coverage.size(), "coverage", false);
    same(in.receiver.size(), "receiver", false);
    same(in.ambiguity.size(), "ambiguity", true);
    same(in.texelsPerPixel.size(), "texelsPerPixel", true);
    if (in.width <= 0 || n % size_t(in.width) != 0)
        throw std::invalid_argument("truthClasses: width " + std::to_string(in.width) + " does not divide " +
                                    std::to_string(n) + " pixels");
}

/// Running sums of one group's classes.
struct Tally {
    TruthClasses out;
    size_t interiorShadow = 0, interiorLit = 0, edge = 0, amb = 0, penumbra = 0;
    double absSum = 0, umbraSum = 0;
    std::vector<double> px, texels;

    [[nodiscard]] TruthClasses finish() {
        if (out.count == 0) return out;
        const double total = double(out.count);
        out.interiorFalseShadow = double(interiorShadow) / total;
        out.interiorFalseLit = double(interiorLit) / total;
        out.edgeError = double(edge) / total;
        out.ambiguous = double(amb) / total;
        out.penumbraMeanAbs = penumbra ? absSum / double(penumbra) : 0.0;
        out.umbraLight = out.umbraPixels ? umbraSum / double(out.umbraPixels) : 0.0;
        if (!px.empty()) {
            out.edgeDisplacementPxMedian = median(std::span(px));
            out.edgeDisplacementPxP95 = percentile(std::span(px), 95);
        }
        if (!texels.empty()) {
            out.edgeDisplacementTexelsMedian = median(std::span(texels));
            out.edgeDisplacementTexelsP95 = percentile(std::span(texels), 95);
        }
        return out;
    }
};

/// Classifies every pixel whose group[i] lies in [0, groups) (every pixel into group 0 when `group`
/// is empty), one pass over the image whatever the number of groups.
std::vector<TruthClasses> classify(const TruthClassInput& in, std::span<const int> group, int groups,
                                   std::vector<TruthClass>* classes) {
    check(in);
    if (!group.empty() && group.size() != in.s.size())
        throw std::invalid_argument("truthClasses: the groups do not match the pixels");
    const size_t n = in.s.size();
    const int w = in.width, h = int(n / size_t(w));
    const auto counted = [&](size_t i) {
        return in.receiver[i] && std::isfinite(in.s[i]) && std::isfinite(in.coverage[i]) && in.coverage[i] >= 0.f &&
               in.coverage[i] <= 1.f;
    };
    const auto truthLit = [&](size_t i) { return in.coverage[i] >= 0.5f; };
    const auto renderedLit = [&](size_t i) { return in.s[i] >= 0.5f; };
    const auto ambiguous = [&](size_t i) { return !in.ambiguity.empty() && in.ambiguity[i] != 0; };
    const auto nearEdge = [&](int x, int y) {
        const size_t i = size_t(y) * size_t(w) + size_t(x);
        if (in.coverage[i] > 0.f && in.coverage[i] < 1.f) return true;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                const size_t j = size_t(ny) * size_t(w) + size_t(nx);
                if (counted(j) && (truthLit(j) != truthLit(i) || (in.coverage[j] > 0.f && in.coverage[j] < 1.f)))
                    return true;
            }
        return false;
    };
    /// Distance from pixel (x, y) to the nearest counted pixel where `wanted(j)` holds, less half a
    /// pixel (an edge lies between pixel centres); kSearchRadius when none is that close.
    const auto distanceTo = [&](int x, int y, const auto& wanted) {
        double best = kSearchRadius;
        for (int dy = -kSearchRadius; dy <= kSearchRadius; ++dy)
            for (int dx = -kSearchRadius; dx <= kSearchRadius; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                const size_t j = size_t(ny) * size_t(w) + size_t(nx);
                if (!counted(j) || !wanted(j)) continue;
                best = std::min(best, std::sqrt(double(dx * dx + dy * dy)) - 0.5);
            }
        return std::max(best, 0.0);
    };

    if (classes) classes->assign(n, TruthClass::NotCounted);
    std::vector<Tally> tallies(size_t(std::max(groups, 0)));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const int g = group.empty() ? 0 : group[i];
            if (g < 0 || g >= groups || !counted(i)) continue;
            Tally& t = tallies[size_t(g)];
            ++t.out.count;
            TruthClass c = TruthClass::Agrees;
            if (ambiguous(i)) {
                ++t.amb;
                c = TruthClass::Ambiguous;
            } else {
                ++t.penumbra;
                t.absSum += std::abs(double(in.s[i]) - double(in.coverage[i]));
                const bool rendered = renderedLit(i), truth = truthLit(i);
                if (in.coverage[i] == 0.f && !nearEdge(x, y)) {
                    ++t.out.umbraPixels;
                    t.umbraSum += double(in.s[i]);
                }
                if (rendered != truth) {
                    if (nearEdge(x, y)) {
                        ++t.edge;
                        c = TruthClass::EdgeError;
                        // The width of the wrong band this pixel lies in, across the edge: from the
                        // true edge (the nearest pixel whose truth is what was rendered here) to the
                        // rendered one (the nearest pixel rendered the other way). Every pixel of a
                        // band W pixels wide reports W: how far the rendered edge lies from the true one.
                        const double d = distanceTo(x, y, [&](size_t j) { return truthLit(j) == rendered; }) +
                                         distanceTo(x, y, [&](size_t j) { return renderedLit(j) != rendered; });
                        t.px.push_back(d);
                        if (!in.texelsPerPixel.empty() && std::isfinite(in.texelsPerPixel[i]))
                            t.texels.push_back(d * double(in.texelsPerPixel[i]));
                    } else if (truth) {
                        ++t.interiorShadow;
                        c = TruthClass::InteriorFalseShadow;
                    } else {
                        ++t.interiorLit;
                        c = TruthClass::InteriorFalseLit;
                    }
                }
            }
            if (classes) (*classes)[i] = c;
        }
    std::vector<TruthClasses> out;
    out.reserve(tallies.size());
    for (Tally& t : tallies) out.push_back(t.finish());
    return out;
}

} // namespace

TruthClasses truthClasses(const TruthClassInput& in, std::vector<TruthClass>* classes) {
    return classify(in, {}, 1, classes).front();
}

std::vector<TruthClasses> truthClassesByGroup(const TruthClassInput& in, std::span<const int> group, int groups) {
    if (group.empty()) throw std::invalid_argument("truthClassesByGroup: no groups given");
    return classify(in, group, groups, nullptr);
}

} // namespace geometry::analysis
