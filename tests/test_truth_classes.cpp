// Truth classes (geometry/analysis/truth_classes.h) on hand-made images with known answers.
#include "geometry/analysis/truth_classes.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using namespace geometry::analysis;

namespace {

constexpr int W = 20, H = 20;

struct Image {
    std::vector<float> s = std::vector<float>(W * H, 1.f), c = std::vector<float>(W * H, 1.f);
    std::vector<uint8_t> receiver = std::vector<uint8_t>(W * H, 1), ambiguity;
    std::vector<float> texelsPerPixel = std::vector<float>(W * H, 1.f);
    [[nodiscard]] TruthClassInput input() const { return {W, s, c, receiver, ambiguity, texelsPerPixel}; }
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
// coverage marks an edge; |s − c| is the penumbra error.
TEST(TruthClasses, AmbiguousLeaksAndPenumbra) {
    Image img;
    img.c.assign(W * H, 0.f);
    img.s.assign(W * H, 0.f);
    img.ambiguity.assign(W * H, 0);
    img.at(img.s, 5, 5) = 1.f;              // a leak
    img.ambiguity[size_t(15) * W + 15] = 1; // terminator
    img.at(img.s, 15, 15) = 1.f;            // misclassified, but ambiguous
    img.at(img.c, 10, 3) = 0.5f;            // a penumbra pixel…
    img.at(img.s, 10, 3) = 0.75f;           // …rendered lit (c ≥ 0.5: agrees)
    img.at(img.s, 10, 4) = 1.f;             // lit beside the penumbra: an edge error
    img.receiver[size_t(19) * W + 19] = 0;  // not a receiver
    const TruthClasses t = truthClasses(img.input());
    EXPECT_EQ(t.count, size_t(W * H - 1));
    EXPECT_DOUBLE_EQ(t.interiorFalseLit, 1.0 / double(t.count));
    EXPECT_DOUBLE_EQ(t.ambiguous, 1.0 / double(t.count));
    EXPECT_DOUBLE_EQ(t.edgeError, 1.0 / double(t.count));
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
    EXPECT_THROW((void)truthClasses({7, odd.s, odd.c, odd.receiver, {}, {}}), std::invalid_argument);
}
