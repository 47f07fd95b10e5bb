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

TruthClasses classify(const TruthClassInput& in, std::span<const int> group, int value,
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
    /// Distance from pixel (x, y) to the nearest counted pixel whose truth is `lit`, less half a pixel.
    const auto displacement = [&](int x, int y, bool lit) {
        double best = kSearchRadius;
        for (int dy = -kSearchRadius; dy <= kSearchRadius; ++dy)
            for (int dx = -kSearchRadius; dx <= kSearchRadius; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                const size_t j = size_t(ny) * size_t(w) + size_t(nx);
                if (!counted(j) || truthLit(j) != lit) continue;
                best = std::min(best, std::sqrt(double(dx * dx + dy * dy)) - 0.5);
            }
        return std::max(best, 0.0);
    };

    if (classes) classes->assign(n, TruthClass::NotCounted);
    TruthClasses out;
    size_t interiorShadow = 0, interiorLit = 0, edge = 0, amb = 0, penumbra = 0;
    double absSum = 0;
    std::vector<double> px, texels;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (!group.empty() && group[i] != value) continue;
            if (!counted(i)) continue;
            ++out.count;
            TruthClass c = TruthClass::Agrees;
            if (ambiguous(i)) {
                ++amb;
                c = TruthClass::Ambiguous;
            } else {
                ++penumbra;
                absSum += std::abs(double(in.s[i]) - double(in.coverage[i]));
                const bool rendered = in.s[i] >= 0.5f, truth = truthLit(i);
                if (rendered != truth) {
                    if (nearEdge(x, y)) {
                        ++edge;
                        c = TruthClass::EdgeError;
                        const double d = displacement(x, y, rendered);
                        px.push_back(d);
                        if (!in.texelsPerPixel.empty() && std::isfinite(in.texelsPerPixel[i]))
                            texels.push_back(d * double(in.texelsPerPixel[i]));
                    } else if (truth) {
                        ++interiorShadow;
                        c = TruthClass::InteriorFalseShadow;
                    } else {
                        ++interiorLit;
                        c = TruthClass::InteriorFalseLit;
                    }
                }
            }
            if (classes) (*classes)[i] = c;
        }
    if (out.count == 0) return out;
    const double total = double(out.count);
    out.interiorFalseShadow = double(interiorShadow) / total;
    out.interiorFalseLit = double(interiorLit) / total;
    out.edgeError = double(edge) / total;
    out.ambiguous = double(amb) / total;
    out.penumbraMeanAbs = penumbra ? absSum / double(penumbra) : 0.0;
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

} // namespace

TruthClasses truthClasses(const TruthClassInput& in, std::vector<TruthClass>* classes) {
    return classify(in, {}, 0, classes);
}

TruthClasses truthClassesWhere(const TruthClassInput& in, std::span<const int> group, int value) {
    return classify(in, group, value, nullptr);
}

} // namespace geometry::analysis
