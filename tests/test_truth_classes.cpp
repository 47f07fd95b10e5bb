// Truth classes (geometry/analysis/truth_classes.h) on hand-made images with known answers.
#include "geometry/analysis/truth_classes.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

using namespace geometry::analysis;

namespace {

constexpr int W = 20, H = 20;

struct Image {
    std::vector<float> s = std::vector<float>(W * H, 1.f), c = std::vector<float>(W * H, 1.f);
    std::vector<uint8_t> receiver = std::vector<uint8_t>(W * H, 1), ambiguity;
    std::vector<float> texelsPerPixel = std::vector<float>(W * H, 1.f);
    [[nodiscard]] TruthClassInput input() const {
        return {.width = W,
                .s = s,
                .coverage = c,
                .receiver = receiver,
                .ambiguity = ambiguity,
                .texelsPerPixel = texelsPerPixel};
    }
    float& at(std::vector<float>& v, int x, int y) { return v[size_t(y) * W + size_t(x)]; }
};

} // namespace

// Acne in the middle of a lit region: interior false shadow, no edge error.
TEST(TruthClasses, AcneInsideALitRegionIsInteriorFalseShadow) {
    Image img;
    for (int y = 8; y < 12; ++y)
        for (int x = 8; x < 12; ++x) img.at(img.s, x, y) = 0.f;
    std::vector<TruthClass> classes;
    const TruthClasses t = truthClasses(img.input(), &classes);
    EXPECT_EQ(t.count, size_t(W * H));
    EXPECT_DOUBLE_EQ(t.interiorFalseShadow, 16.0 / (W * H));
    EXPECT_EQ(t.interiorFalseLit, 0.0);
    EXPECT_EQ(t.edgeError, 0.0);
    EXPECT_EQ(classes[size_t(9) * W + 9], TruthClass::InteriorFalseShadow);
    EXPECT_EQ(classes[0], TruthClass::Agrees);
}

// A shadow edge drawn one pixel too far: edge error whose displacement is the wrong band's width,
// one pixel (edges lie between pixel centres), in texels through 1/m; nothing interior.
TEST(TruthClasses, AShiftedEdgeIsEdgeErrorWithItsDisplacement) {
    Image img;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            img.at(img.c, x, y) = x < 10 ? 0.f : 1.f;
            img.at(img.s, x, y) = x < 11 ? 0.f : 1.f;
            img.at(img.texelsPerPixel, x, y) = 0.5f;
        }
    const TruthClasses t = truthClasses(img.input());
    EXPECT_DOUBLE_EQ(t.edgeError, double(H) / (W * H));
    EXPECT_EQ(t.interiorFalseShadow, 0.0);
    EXPECT_EQ(t.interiorFalseLit, 0.0);
    EXPECT_DOUBLE_EQ(t.edgeDisplacementPxMedian, 1.0);
    EXPECT_DOUBLE_EQ(t.edgeDisplacementTexelsMedian, 0.5);
    // Three pixels too far: the far ones are no longer within 1 px of the edge.
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) img.at(img.s, x, y) = x < 13 ? 0.f : 1.f;
    const TruthClasses far = truthClasses(img.input());
    EXPECT_DOUBLE_EQ(far.edgeError, double(H) / (W * H));
    EXPECT_DOUBLE_EQ(far.interiorFalseShadow, 2.0 * H / (W * H));
    EXPECT_DOUBLE_EQ(far.edgeDisplacementPxMedian, 3.0) << "every pixel of a 3-px band reports 3 px";
}

// Groups (splits, meshes) are classified in one pass; each group's figures are those of its pixels
// alone, and pixels of no group (−1) or of a group past the count are left out.
TEST(TruthClasses, ByGroupMatchesEachGroupAlone) {
    Image img;
    std::vector<int> group(W * H, 0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            group[size_t(y) * W + size_t(x)] = x < 10 ? 0 : (x < 15 ? 1 : (x < 18 ? -1 : 7));
            if (y == 5) img.at(img.s, x, y) = 0.f; // a false-shadow row across every group
        }
    const auto by = truthClassesByGroup(img.input(), group, 2);
    ASSERT_EQ(by.size(), 2u);
    EXPECT_EQ(by[0].count, size_t(10 * H));
    EXPECT_EQ(by[1].count, size_t(5 * H));
    EXPECT_DOUBLE_EQ(by[0].interiorFalseShadow, 1.0 / H);
    EXPECT_DOUBLE_EQ(by[1].interiorFalseShadow, 1.0 / H);
    EXPECT_THROW((void)truthClassesByGroup(img.input(), std::vector<int>(3, 0), 2), std::invalid_argument);
}

// Ambiguous pixels are counted apart; a leak in a shadow is interior false lit; fractional
// coverage marks an edge, where a pixel adds the share of its samples on the wrong side; |s − c| is
// the penumbra error.
TEST(TruthClasses, AmbiguousLeaksAndPenumbra) {
    Image img;
    img.c.assign(W * H, 0.f);
    img.s.assign(W * H, 0.f);
    img.ambiguity.assign(W * H, 0);
    img.at(img.s, 5, 5) = 1.f;              // a leak
    img.ambiguity[size_t(15) * W + 15] = 1; // terminator
    img.at(img.s, 15, 15) = 1.f;            // misclassified, but ambiguous
    img.at(img.c, 10, 3) = 0.5f;            // a penumbra pixel…
    img.at(img.s, 10, 3) = 0.75f;           // …rendered lit: its shadowed half is wrong (a tie decides nothing)
    img.at(img.s, 10, 4) = 1.f;             // lit beside the penumbra: an edge error
    img.receiver[size_t(19) * W + 19] = 0;  // not a receiver
    const TruthClasses t = truthClasses(img.input());
    EXPECT_EQ(t.count, size_t(W * H - 1));
    EXPECT_DOUBLE_EQ(t.interiorFalseLit, 1.0 / double(t.count));
    EXPECT_DOUBLE_EQ(t.ambiguous, 1.0 / double(t.count));
    EXPECT_DOUBLE_EQ(t.edgeError, 1.5 / double(t.count));
    EXPECT_NEAR(t.penumbraMeanAbs, (1.0 + 0.25 + 1.0) / double(t.count - 1), 1e-12);
    // The umbra: all but the ambiguous pixel and the 3×3 block about the penumbra pixel; its only
    // light is the leak.
    EXPECT_EQ(t.umbraPixels, t.count - 1 - 9);
    EXPECT_DOUBLE_EQ(t.umbraLight, 1.0 / double(t.count - 10));
}

TEST(TruthClasses, BadInputsThrow) {
    Image img;
    img.c.pop_back();
    EXPECT_THROW((void)truthClasses(img.input()), std::invalid_argument);
    Image odd;
    EXPECT_THROW((void)truthClasses({.width = 7, .s = odd.s, .coverage = odd.c, .receiver = odd.receiver}),
                 std::invalid_argument);
}

// Like for like: with the render sampled where the truth is, an edge through the middle of pixels
// drawn exactly is no error at all, however fractional its pixels; drawn one sample too far, it
// is a band 1/N pixel wide: the edge width says so in pixels and, through 1/m, in texels.
TEST(TruthClasses, SamplesComparedWithSamplesHaveNoFloor) {
    constexpr int N = 4;
    Image img;
    std::vector<float> sampleS(W * H * N * N), sampleT(sampleS.size());
    const auto fill = [&](int renderedEdge) {
        for (int y = 0; y < H * N; ++y)
            for (int x = 0; x < W * N; ++x) {
                sampleT[size_t(y) * W * N + size_t(x)] = x < 10 * N + 1 ? 0.f : 1.f; // a quarter into column 10
                sampleS[size_t(y) * W * N + size_t(x)] = x < renderedEdge ? 0.f : 1.f;
            }
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                img.at(img.c, x, y) = x < 10 ? 0.f : x == 10 ? 0.75f : 1.f;
                img.at(img.s, x, y) = x < 10 ? 0.f : 1.f; // one sample per pixel would be wrong by a quarter
                img.at(img.texelsPerPixel, x, y) = 0.5f;
            }
    };
    fill(10 * N + 1);
    TruthClassInput in = img.input();
    const TruthClasses pixelOnly = truthClasses(in);
    EXPECT_NEAR(pixelOnly.edgeError, 0.25 * H / (W * H), 1e-12) << "the centre sample against the area";
    in.samplesPerAxis = N;
    in.sampleS = sampleS;
    in.sampleTruth = sampleT;
    const TruthClasses exact = truthClasses(in);
    EXPECT_EQ(exact.edgeError, 0.0);
    EXPECT_EQ(exact.edgeWidthPx, 0.0);
    EXPECT_DOUBLE_EQ(exact.edgeLengthPx, double(H)) << "one fractional pixel per row";
    fill(10 * N + 2); // one sample too far: a quarter of a pixel per row
    const TruthClasses off = truthClasses(in);
    EXPECT_NEAR(off.edgeError, 0.25 * H / (W * H), 1e-12);
    EXPECT_NEAR(off.edgeWidthPx, 0.25, 1e-12);
    EXPECT_NEAR(off.edgeWidthTexels, 0.125, 1e-12);
    EXPECT_EQ(off.interiorFalseShadow + off.interiorFalseLit, 0.0);
}

// The tie rule: a rendered s of exactly 0.5 is half wrong whatever the truth; c = 0.5 counts its
// shadowed half wrong when rendered lit and its lit half when rendered shadowed.
TEST(TruthClasses, ATieIsHalfWrongEitherWay) {
    Image img;
    img.at(img.s, 5, 5) = 0.5f; // in a lit interior
    Image tie;
    tie.at(tie.c, 5, 5) = 0.5f;
    const TruthClasses t = truthClasses(img.input());
    EXPECT_DOUBLE_EQ(t.interiorFalseShadow, 0.5 / (W * H));
    EXPECT_DOUBLE_EQ(truthClasses(tie.input()).edgeError, 0.5 / (W * H)) << "rendered lit: the shadowed half";
    tie.at(tie.s, 5, 5) = 0.f;
    EXPECT_DOUBLE_EQ(truthClasses(tie.input()).edgeError, 0.5 / (W * H)) << "rendered shadowed: the lit half";
}

// Singular pixels are their own class, as in the aliasing figures; a soft sun's umbra is where its
// disk is hidden; peter-panning is the light within the contact reach, with its gap; the interior's
// mean |s − c| counts a darkened lit region that no threshold calls wrong.
TEST(TruthClasses, SingularUmbraContactAndInteriorDarkening) {
    Image img;
    std::vector<uint8_t> singular(W * H, 0);
    singular[size_t(2) * W + 2] = 1;
    img.at(img.s, 2, 2) = 0.f; // wrong, but singular
    for (float& s : img.s) s = s == 1.f ? 0.9f : s;
    TruthClassInput in = img.input();
    in.singular = singular;
    const TruthClasses t = truthClasses(in);
    EXPECT_DOUBLE_EQ(t.singular, 1.0 / (W * H));
    EXPECT_EQ(t.interiorFalseShadow, 0.0);
    EXPECT_NEAR(t.interiorMeanAbs, 0.1, 1e-6) << "lit ground at s = 0.9";
    EXPECT_EQ(t.interiorFalseShadow + t.interiorFalseLit + t.edgeError, 0.0);

    Image dark;
    dark.c.assign(W * H, 0.f);
    dark.s.assign(W * H, 0.f);
    dark.at(dark.s, 5, 5) = 1.f; // a leak 0.3 from its occluder
    dark.at(dark.s, 15, 15) = 0.8f;
    std::vector<float> gap(W * H, std::numeric_limits<float>::infinity()), v(W * H, 0.f);
    gap[size_t(5) * W + 5] = 0.3f;
    v[size_t(15) * W + 15] = 0.5f; // the sun's disk half seen: not umbra
    TruthClassInput soft = dark.input();
    soft.contactGap = gap;
    soft.visibility = v;
    const TruthClasses u = truthClasses(soft);
    EXPECT_DOUBLE_EQ(u.contactFalseLit, 1.0 / (W * H));
    EXPECT_FLOAT_EQ(float(u.contactGapMedian), 0.3f);
    EXPECT_EQ(u.umbraPixels, size_t(W * H - 1));
    EXPECT_DOUBLE_EQ(u.umbraLight, 1.0 / double(W * H - 1));
    EXPECT_DOUBLE_EQ(u.interiorFalseLit, 2.0 / (W * H));
}
