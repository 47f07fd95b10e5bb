#include "geometry/analysis/truth_classes.h"

#include "geometry/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace geometry::analysis {
namespace {

constexpr int kSearchRadius = 8; // pixels; a displacement beyond it counts as this far

void check(const TruthClassInput& in) {
    const size_t n = in.s.size();
    const auto same = [&](size_t m, size_t want, const char* what, bool optional) {
        if ((optional && m == 0) || m == want) return;
        throw std::invalid_argument(std::string("truthClasses: ") + what + " holds " + std::to_string(m) +
                                    " values, not " + std::to_string(want));
    };
    same(in.coverage.size(), n, "coverage", false);
    same(in.receiver.size(), n, "receiver", false);
    same(in.ambiguity.size(), n, "ambiguity", true);
    same(in.texelsPerPixel.size(), n, "texelsPerPixel", true);
    same(in.singular.size(), n, "singular", true);
    same(in.visibility.size(), n, "visibility", true);
    same(in.contactGap.size(), n, "contactGap", true);
    same(in.edgeCoverage.size(), n, "edgeCoverage", true);
    if (in.samplesPerAxis < 1) throw std::invalid_argument("truthClasses: samplesPerAxis must be at least 1");
    const size_t samples = n * size_t(in.samplesPerAxis) * size_t(in.samplesPerAxis);
    same(in.sampleS.size(), samples, "sampleS", true);
    same(in.sampleTruth.size(), in.sampleS.empty() ? 0 : samples, "sampleTruth", true);
    if (in.width <= 0 || n % size_t(in.width) != 0)
        throw std::invalid_argument("truthClasses: width " + std::to_string(in.width) + " does not divide " +
                                    std::to_string(n) + " pixels");
}

/// How wrong one rendered s is against a truth lit fraction t ∈ [0, 1] (t = 0 or 1 for one sample):
/// the share of t's samples on the other side of 0.5; s exactly 0.5 is half wrong whatever t is.
[[nodiscard]] double wrongShare(float s, double t) noexcept {
    if (s > 0.5f) return 1.0 - t;
    if (s < 0.5f) return t;
    return 0.5;
}

/// One pixel's samples: the mean rendered s, and the shares of its samples wrongly shadowed and
/// wrongly lit (over the samples where both the render and the truth see a receiver; the pixel's own
/// s against its c where there are none).
struct PixelVerdict {
    double s = 0, wrongShadow = 0, wrongLit = 0;
    [[nodiscard]] double wrong() const noexcept { return wrongShadow + wrongLit; }
};

/// Running sums of one group's classes.
struct Tally {
    TruthClasses out;
    double interiorShadow = 0, interiorLit = 0, edge = 0, contactLit = 0;
    size_t amb = 0, singular = 0, penumbra = 0, interiorPixels = 0;
    double absSum = 0, interiorAbsSum = 0, umbraSum = 0, edgeLength = 0, edgeTexels = 0;
    std::vector<double> px, texels, gaps;

    [[nodiscard]] TruthClasses finish() {
        if (out.count == 0) return out;
        const double total = double(out.count);
        out.interiorFalseShadow = interiorShadow / total;
        out.interiorFalseLit = interiorLit / total;
        out.edgeError = edge / total;
        out.ambiguous = double(amb) / total;
        out.singular = double(singular) / total;
        out.contactFalseLit = contactLit / total;
        out.penumbraMeanAbs = penumbra ? absSum / double(penumbra) : 0.0;
        out.interiorMeanAbs = interiorPixels ? interiorAbsSum / double(interiorPixels) : 0.0;
        out.umbraLight = out.umbraPixels ? umbraSum / double(out.umbraPixels) : 0.0;
        out.edgeLengthPx = edgeLength;
        if (edgeLength > 0) {
            out.edgeWidthPx = edge / edgeLength;
            out.edgeWidthTexels = edgeTexels / edgeLength;
        }
        if (!px.empty()) {
            out.edgeDisplacementPxMedian = median(std::span(px));
            out.edgeDisplacementPxP95 = percentile(std::span(px), 95);
        }
        if (!texels.empty()) {
            out.edgeDisplacementTexelsMedian = median(std::span(texels));
            out.edgeDisplacementTexelsP95 = percentile(std::span(texels), 95);
        }
        if (!gaps.empty()) {
            out.contactGapMedian = median(std::span(gaps));
            out.contactGapP95 = percentile(std::span(gaps), 95);
        }
        return out;
    }
};

/// Classifies the pixels of one TruthClassInput (docs/design.md §4 "Truth classes"): each counted
/// pixel's verdict against its truth, whether it lies near a true edge, and how far a misplaced
/// rendered edge lies from the true one.
class Classifier {
public:
    explicit Classifier(const TruthClassInput& in)
        : in_(in), n_(in.s.size()), w_(in.width), h_(int(n_ / size_t(w_))),
          edgeC_(in.edgeCoverage.empty() ? in.coverage : in.edgeCoverage) {
        // Per pixel, the mean rendered s (for the displacement search: a pixel's rendered state). The
        // verdicts themselves are worked out again where a pixel is tallied: kept, at 24 bytes a pixel,
        // they came on top of the truth's peak at plant scale.
        meanS_.assign(n_, std::numeric_limits<float>::quiet_NaN());
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const size_t i = index(x, y);
                if (counted(i)) meanS_[i] = float(verdict(x, y).s);
            }
    }

    /// Every pixel whose group[i] lies in [0, groups) (every pixel into group 0 when `group` is
    /// empty), one pass over the image whatever the number of groups.
    std::vector<TruthClasses> run(std::span<const int> group, int groups, std::vector<TruthClass>* classes) const {
        if (classes) classes->assign(n_, TruthClass::NotCounted);
        std::vector<Tally> tallies(size_t(std::max(groups, 0)));
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const size_t i = index(x, y);
                const int g = group.empty() ? 0 : group[i];
                if (g < 0 || g >= groups || !counted(i)) continue;
                Tally& t = tallies[size_t(g)];
                ++t.out.count;
                TruthClass c = TruthClass::Agrees;
                if (!in_.ambiguity.empty() && in_.ambiguity[i] != 0) {
                    ++t.amb;
                    c = TruthClass::Ambiguous;
                } else if (!in_.singular.empty() && in_.singular[i] != 0) {
                    ++t.singular;
                    c = TruthClass::Singular;
                } else {
                    c = tallyDecidable(t, x, y);
                }
                if (classes) (*classes)[i] = c;
            }
        std::vector<TruthClasses> out;
        out.reserve(tallies.size());
        for (Tally& t : tallies) out.push_back(t.finish());
        return out;
    }

private:
    [[nodiscard]] size_t index(int x, int y) const noexcept { return size_t(y) * size_t(w_) + size_t(x); }
    [[nodiscard]] bool counted(size_t i) const noexcept {
        return in_.receiver[i] && std::isfinite(in_.s[i]) && std::isfinite(in_.coverage[i]) && in_.coverage[i] >= 0.f &&
               in_.coverage[i] <= 1.f;
    }
    [[nodiscard]] bool fractional(size_t i) const noexcept { return in_.coverage[i] > 0.f && in_.coverage[i] < 1.f; }
    [[nodiscard]] bool undecidable(size_t i) const noexcept {
        return (!in_.ambiguity.empty() && in_.ambiguity[i] != 0) || (!in_.singular.empty() && in_.singular[i] != 0);
    }
    [[nodiscard]] float fine(size_t i) const noexcept { return std::isfinite(edgeC_[i]) ? edgeC_[i] : in_.coverage[i]; }
    [[nodiscard]] bool truthLit(size_t j) const noexcept { return in_.coverage[j] > 0.5f; }
    [[nodiscard]] bool renderedLit(size_t j) const noexcept { return meanS_[j] > 0.5f; }

    [[nodiscard]] PixelVerdict verdict(int x, int y) const {
        const size_t i = index(x, y);
        const int N = in_.samplesPerAxis;
        PixelVerdict v;
        size_t k = 0;
        double sSum = 0;
        if (!in_.sampleS.empty())
            for (int sy = 0; sy < N; ++sy)
                for (int sx = 0; sx < N; ++sx) {
                    const size_t j = (size_t(y) * size_t(N) + size_t(sy)) * size_t(w_) * size_t(N) +
                                     size_t(x) * size_t(N) + size_t(sx);
                    const float sj = in_.sampleS[j], tj = in_.sampleTruth[j];
                    if (!std::isfinite(sj) || !std::isfinite(tj)) continue;
                    ++k;
                    sSum += sj;
                    const double wrong = wrongShare(sj, tj > 0.5f ? 1.0 : 0.0);
                    (tj > 0.5f ? v.wrongShadow : v.wrongLit) += wrong;
                }
        if (k > 0) {
            v.s = sSum / double(k);
            v.wrongShadow /= double(k);
            v.wrongLit /= double(k);
            return v;
        }
        const double c = in_.coverage[i];
        v.s = in_.s[i];
        // Against c: its lit samples wrongly shadowed, its shadowed samples wrongly lit.
        if (in_.s[i] == 0.5f) {
            v.wrongShadow = 0.5 * c;
            v.wrongLit = 0.5 * (1.0 - c);
        } else if (in_.s[i] < 0.5f) {
            v.wrongShadow = c;
        } else {
            v.wrongLit = 1.0 - c;
        }
        return v;
    }

    [[nodiscard]] bool nearEdge(int x, int y) const {
        const size_t i = index(x, y);
        if (fractional(i) || (fine(i) > 0.f && fine(i) < 1.f)) return true;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w_ || ny >= h_) continue;
                const size_t j = index(nx, ny);
                if (counted(j) && (in_.coverage[j] != in_.coverage[i] || fine(j) != fine(i))) return true;
            }
        return false;
    }

    /// Distance from pixel (x, y) to the nearest counted pixel where `wanted(j)` holds, less half a
    /// pixel (an edge lies between pixel centres); kSearchRadius when none is that close.
    template <class Wanted> [[nodiscard]] double distanceTo(int x, int y, const Wanted& wanted) const {
        double best = kSearchRadius;
        for (int dy = -kSearchRadius; dy <= kSearchRadius; ++dy)
            for (int dx = -kSearchRadius; dx <= kSearchRadius; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= w_ || ny >= h_) continue;
                const size_t j = index(nx, ny);
                if (!counted(j) || !wanted(j)) continue;
                best = std::min(best, std::sqrt(double(dx * dx + dy * dy)) - 0.5);
            }
        return std::max(best, 0.0);
    }

    /// The truth edge's length at (x, y): a fractional pixel, or a step to the right or down.
    [[nodiscard]] double edgeLengthAt(int x, int y) const {
        const size_t i = index(x, y);
        double length = fractional(i) ? 1.0 : 0.0;
        for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
            if (x + dx >= w_ || y + dy >= h_) continue;
            const size_t j = index(x + dx, y + dy);
            if (counted(j) && !undecidable(j) && !fractional(i) && !fractional(j) && in_.coverage[j] != in_.coverage[i])
                length += 1.0;
        }
        return length;
    }

    /// Adds a decidable pixel to `t`: near an edge or interior, umbra, contact; returns its class.
    TruthClass tallyDecidable(Tally& t, int x, int y) const {
        const size_t i = index(x, y);
        const PixelVerdict v = verdict(x, y);
        const double cov = in_.coverage[i];
        ++t.penumbra;
        t.absSum += std::abs(v.s - cov);
        const bool edge = nearEdge(x, y);
        const bool umbra = in_.visibility.empty() ? cov == 0.0 : in_.visibility[i] == 0.f;
        if (umbra && !edge) {
            ++t.out.umbraPixels;
            t.umbraSum += v.s;
        }
        t.edgeLength += edgeLengthAt(x, y);
        if (!in_.contactGap.empty() && std::isfinite(in_.contactGap[i]) && v.wrongLit > 0) {
            t.contactLit += v.wrongLit;
            t.gaps.push_back(in_.contactGap[i]);
        }
        const double tpp =
            in_.texelsPerPixel.empty() ? std::numeric_limits<double>::quiet_NaN() : double(in_.texelsPerPixel[i]);
        if (!edge) {
            ++t.interiorPixels;
            t.interiorAbsSum += std::abs(v.s - cov);
            t.interiorShadow += v.wrongShadow;
            t.interiorLit += v.wrongLit;
            if (v.wrong() > 0) return cov > 0.5 ? TruthClass::InteriorFalseShadow : TruthClass::InteriorFalseLit;
            return TruthClass::Agrees;
        }
        t.edge += v.wrong();
        if (std::isfinite(tpp)) t.edgeTexels += v.wrong() * tpp;
        // Where the pixel's mean truth and mean render fall on different sides of 0.5 (a tie at 0.5
        // on either side measures nothing).
        const bool truth = truthLit(i), rendered = renderedLit(i);
        if (cov != 0.5 && v.s != 0.5 && rendered != truth) {
            // The width of the wrong band this pixel lies in, across the edge: from the true edge (the
            // nearest pixel whose truth is what was rendered here) to the rendered one (the nearest
            // pixel rendered the other way). Every pixel of a band W pixels wide reports W: how far
            // the rendered edge lies from the true one.
            const double d = distanceTo(x, y, [&](size_t j) { return truthLit(j) == rendered; }) +
                             distanceTo(x, y, [&](size_t j) { return renderedLit(j) != rendered; });
            t.px.push_back(d);
            if (std::isfinite(tpp)) t.texels.push_back(d * tpp);
        }
        return v.wrong() > 0 ? TruthClass::EdgeError : TruthClass::Agrees;
    }

    const TruthClassInput& in_;
    size_t n_;
    int w_, h_;
    std::span<const float> edgeC_;
    std::vector<float> meanS_;
};

std::vector<TruthClasses> classify(const TruthClassInput& in, std::span<const int> group, int groups,
                                   std::vector<TruthClass>* classes) {
    check(in);
    if (!group.empty() && group.size() != in.s.size())
        throw std::invalid_argument("truthClasses: the groups do not match the pixels");
    return Classifier(in).run(group, groups, classes);
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
