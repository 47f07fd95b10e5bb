#include "geometry/analysis/heatmap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

using namespace geometry::analysis;

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

Image filled(int w, int h, uint8_t grey) {
    Image img{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 4, grey)};
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return img;
}

bool inside(const PixelRect& r, int x, int y) {
    return x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
}

/// Counts pixels inside r for which pred(r, g, b) holds.
template <class Pred> int countIn(const Image& img, const PixelRect& r, Pred pred) {
    int n = 0;
    for (int y = std::max(r.y, 0); y < std::min(r.y + r.height, img.height); ++y)
        for (int x = std::max(r.x, 0); x < std::min(r.x + r.width, img.width); ++x) {
            const uint8_t* p = img.at(x, y);
            n += pred(p[0], p[1], p[2]);
        }
    return n;
}

bool light(int r, int g, int b) { return r >= 240 && g >= 240 && b >= 240; }
bool strongRed(int r, int g, int b) { return r > 150 && g < 80 && b < 80; }
bool strongBlue(int r, int g, int b) { return b > 150 && r < 80 && g < 120; }

std::string tempPath(const std::string& name) { return testing::TempDir() + "shadowscope_heatmap_" + name; }

void writeBytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string floatBytes(std::initializer_list<float> v, bool bigEndian = false) {
    std::string s;
    for (float f : v) {
        uint32_t u = std::bit_cast<uint32_t>(f);
        for (int i = 0; i < 4; ++i) s.push_back(char(bigEndian ? (u >> (24 - 8 * i)) & 0xff : (u >> (8 * i)) & 0xff));
    }
    return s;
}
} // namespace

// ---- colour maps ----------------------------------------------------------------------------

TEST(ColourMap, UnitErrorIsWhiteish) {
    const glm::vec3 c = divergingLog2(1.f);
    EXPECT_GT(std::min({c.r, c.g, c.b}), 0.9f);
    EXPECT_LT(std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}), 0.05f);
}

TEST(ColourMap, UndersampledRedOversampledBlue) {
    const glm::vec3 red = divergingLog2(16.f), blue = divergingLog2(1.f / 16);
    EXPECT_GT(red.r, 2 * red.g);
    EXPECT_GT(red.r, 2 * red.b);
    EXPECT_GT(blue.b, 2 * blue.r);
    EXPECT_GT(blue.b, blue.g);
}

TEST(ColourMap, MonotonicAlongTheScale) {
    // Lightness rises from the blue end to white at m = 1 and falls towards the red end; the
    // colour moves steadily away from white on both sides, and the hue side never flips.
    const glm::vec3 white = divergingLog2(1.f);
    float prevLum = -1, prevDist = 1e9f;
    for (int i = -80; i <= 80; ++i) {
        const float e = float(i) / 20.f; // log2 m ∈ [−4, 4]
        const glm::vec3 c = divergingLog2(std::exp2(e));
        const float lum = luminance(c), dist = glm::length(c - white);
        if (i <= 0) {
            EXPECT_GE(lum, prevLum - 1e-6f) << "log2 m = " << e;
            if (i > -80) {
                EXPECT_LE(dist, prevDist + 1e-6f) << "log2 m = " << e;
            }
        } else {
            EXPECT_LE(lum, prevLum + 1e-6f) << "log2 m = " << e;
            EXPECT_GE(dist, prevDist - 1e-6f) << "log2 m = " << e;
        }
        if (i < 0) {
            EXPECT_GT(c.b, c.r) << "log2 m = " << e;
        } else if (i > 0) {
            EXPECT_GT(c.r, c.b) << "log2 m = " << e;
        }
        prevLum = lum;
        prevDist = dist;
    }
}

TEST(ColourMap, ClampsBeyondRangeAndHonoursRange) {
    EXPECT_EQ(divergingLog2(1e6f), divergingLog2(16.f));
    EXPECT_EQ(divergingLog2(1e-6f), divergingLog2(1.f / 16));
    EXPECT_EQ(divergingLog2(4.f, 2.f), divergingLog2(16.f, 4.f)); // both at the red end
}

TEST(ColourMap, InvalidValuesAreMagenta) {
    for (float m : {kNaN, kInf, -kInf, 0.f, -1.f}) EXPECT_EQ(divergingLog2(m), kInvalidColour) << m;
    EXPECT_EQ(divergingLog2(2.f, 0.f), kInvalidColour);
    EXPECT_EQ(falseColourTruth(kNaN, false), kInvalidColour);
}

TEST(ColourMap, TruthFalseColours) {
    EXPECT_EQ(falseColourTruth(0.2f, false), kFalseShadowColour); // truth lit, rendered dark
    EXPECT_EQ(falseColourTruth(0.5f, true), kFalseLitColour);     // truth shadowed, rendered lit
    const glm::vec3 lit = falseColourTruth(1.f, false), shadowed = falseColourTruth(0.f, true);
    EXPECT_EQ(lit.r, lit.g);
    EXPECT_EQ(lit.g, lit.b);
    EXPECT_EQ(shadowed.r, shadowed.b);
    EXPECT_GT(lit.r, shadowed.r + 0.3f);
    EXPECT_GT(kFalseShadowColour.r, 2 * kFalseShadowColour.b);
    EXPECT_GT(kFalseLitColour.b, 2 * kFalseLitColour.r);
}

TEST(ColourMap, EightDistinctSplitColours) {
    for (int i = 0; i < 8; ++i) {
        for (int j = i + 1; j < 8; ++j) EXPECT_GT(glm::length(splitColour(i) - splitColour(j)), 0.15f) << i << " " << j;
        EXPECT_EQ(splitColour(i), splitColour(i + 8));
    }
    EXPECT_EQ(splitColour(-1), splitColour(7));
}

// ---- heatmap images -------------------------------------------------------------------------

TEST(Heatmap, AliasingImageTopRowFirst) {
    // 2×2: (0,0) m = 1, (1,0) non-receiver, (0,1) NaN, (1,1) m = 16.
    const std::vector<float> m{1.f, 1.f, kNaN, 16.f};
    const std::vector<uint8_t> r{1, 0, 1, 1};
    const Image img = aliasingHeatmap(m, r, 2, 2);
    ASSERT_EQ(img.width, 2);
    ASSERT_EQ(img.height, 2);
    ASSERT_EQ(img.rgba.size(), 16u);
    EXPECT_GT(img.at(0, 0)[0], 230);
    EXPECT_GT(img.at(0, 0)[2], 230);
    EXPECT_EQ(img.at(1, 0)[0], 38); // kNonReceiverColour 0.15
    EXPECT_EQ(img.at(1, 0)[1], 38);
    EXPECT_EQ(img.at(0, 1)[0], 255); // magenta
    EXPECT_EQ(img.at(0, 1)[1], 0);
    EXPECT_TRUE(strongRed(img.at(1, 1)[0], img.at(1, 1)[1], img.at(1, 1)[2]));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(img.rgba[4 * size_t(i) + 3], 255);
}

TEST(Heatmap, TruthImage) {
    const std::vector<float> s{0.f, 1.f, 1.f, 0.f, 0.f};
    const std::vector<uint8_t> occ{0, 1, 0, 1, 0};
    const std::vector<uint8_t> r{1, 1, 1, 1, 0};
    const Image img = truthHeatmap(s, occ, r, 5, 1);
    EXPECT_TRUE(strongRed(img.at(0, 0)[0], img.at(0, 0)[1], img.at(0, 0)[2]));
    EXPECT_TRUE(strongBlue(img.at(1, 0)[0], img.at(1, 0)[1], img.at(1, 0)[2]));
    EXPECT_GT(img.at(2, 0)[0], img.at(3, 0)[0]); // lit grey brighter than shadowed grey
    EXPECT_EQ(img.at(4, 0)[0], 38);
}

TEST(Heatmap, SizeMismatchThrows) {
    const std::vector<float> v(6, 1.f);
    const std::vector<uint8_t> r6(6, 1), r5(5, 1);
    EXPECT_THROW((void)aliasingHeatmap(v, r5, 3, 2), std::invalid_argument);
    EXPECT_THROW((void)aliasingHeatmap(v, r6, 2, 2), std::invalid_argument);
    EXPECT_THROW((void)aliasingHeatmap(v, r6, 3, 2, 0.f), std::invalid_argument);
    EXPECT_THROW((void)truthHeatmap(v, r6, r5, 3, 2), std::invalid_argument);
    EXPECT_NO_THROW((void)truthHeatmap(v, r6, r6, 3, 2));
}

// ---- legends --------------------------------------------------------------------------------

TEST(Legend, AliasingTicksArePowersOfTwo) {
    const Legend l = aliasingLegend(4);
    ASSERT_EQ(l.ticks.size(), 5u);
    const char* labels[] = {"1/16", "1/4", "1", "4", "16"};
    for (size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(l.ticks[i].label, labels[i]);
        EXPECT_FLOAT_EQ(l.ticks[i].position, 0.25f * float(i));
    }
    EXPECT_EQ(l.title, "m (pixels per texel)");
    ASSERT_TRUE(bool(l.bar));
    EXPECT_EQ(l.bar(0.75f), divergingLog2(4.f)); // the bar is the heatmap's own scale
    EXPECT_EQ(aliasingLegend(8).ticks.back().label, "256");
}

TEST(Legend, DrawsOnlyInsideItsBoxInTheBottomLeft) {
    Image img = filled(640, 480, 128);
    const Image before = img;
    const Legend legend = aliasingLegend();
    const PixelRect r = legendRect(img.width, img.height, legend);
    ASSERT_GT(r.width, 0);
    ASSERT_GT(r.height, 0);
    EXPECT_LT(r.x, img.width / 4);
    EXPECT_GT(r.y, img.height / 2);
    EXPECT_LE(r.x + r.width, img.width);
    EXPECT_LE(r.y + r.height, img.height);
    drawLegend(img, legend);
    int changedInside = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const bool same = std::memcmp(img.at(x, y), before.at(x, y), 4) == 0;
            if (!inside(r, x, y)) ASSERT_TRUE(same) << "pixel (" << x << ", " << y << ") outside the legend changed";
            else changedInside += !same;
        }
    EXPECT_EQ(changedInside, r.width * r.height); // the translucent box darkens every box pixel
    EXPECT_GT(countIn(img, r, light), 50);        // text (and the bar's white middle)
    EXPECT_GT(countIn(img, r, strongRed), 50);    // the bar's undersampled end (≥ 5 columns)
    EXPECT_GT(countIn(img, r, strongBlue), 50);   // the bar's oversampled end
}

TEST(Legend, TextIsRasterized) {
    Image img = filled(320, 240, 0);
    Legend legend;
    legend.title = "Hello 1/16";
    drawLegend(img, legend);
    const PixelRect r = legendRect(img.width, img.height, legend);
    EXPECT_GT(countIn(img, r, light), 20); // only the title can be light here
    EXPECT_LT(countIn(img, r, light), r.width * r.height / 2);
}

TEST(Legend, CategoricalLegendsShowTheirSwatches) {
    Image img = filled(640, 480, 128);
    drawLegend(img, truthLegend());
    const PixelRect r = legendRect(img.width, img.height, truthLegend());
    EXPECT_GT(countIn(img, r, strongRed), 10);
    EXPECT_GT(countIn(img, r, strongBlue), 10);
    EXPECT_GT(countIn(img, r, light), 50);

    const std::vector<glm::vec2> ranges{{0.5f, 12.345f}, {12.345f, 100.f}, {100.f, 1000.f}};
    const Legend splits = splitLegend(ranges);
    ASSERT_EQ(splits.entries.size(), 3u);
    EXPECT_EQ(splits.entries[0].label, "split 0 [0.5, 12.3]");
    EXPECT_EQ(splits.entries[2].label, "split 2 [100, 1000]");
    EXPECT_EQ(splits.entries[1].colour, splitColour(1));

    // technique = virtual: the levels the pixels sample, each with its texel in scene units.
    const std::vector<glm::dvec2> levels{{3.0, 0.0125}, {4.0, 0.025}};
    const Legend seen = levelLegend(levels);
    ASSERT_EQ(seen.entries.size(), 2u);
    EXPECT_EQ(seen.entries[0].label, "level 3 (texel 0.0125)");
    EXPECT_EQ(seen.entries[1].colour, splitColour(4));
}

TEST(Legend, ScalesWithImageHeight) {
    const Legend l = aliasingLegend();
    const PixelRect small = legendRect(640, 480, l), large = legendRect(1920, 1080, l);
    EXPECT_EQ(large.width, 2 * small.width);
    EXPECT_EQ(large.height, 2 * small.height);
    EXPECT_EQ(large.y + large.height, 1080 - 2 * (480 - small.y - small.height));
}

// Issue 32: the truth classes' longest label was cut at the edge of a 480-pixel-wide heatmap.png.
// The legend picks the smaller text and wraps its labels so that the box fits the image.
TEST(Legend, ALongLegendWrapsToFitTheImageWidth) {
    using C = TruthClass;
    const std::vector<C> classes{
        C::InteriorFalseShadow, C::InteriorFalseLit, C::EdgeError, C::Ambiguous, C::Agrees, C::Agrees, C::NotCounted};
    const Legend legend = truthClassLegend(classes, std::vector<float>{0.f, 1.f, 1.f, 1.f, 1.f, 0.f, 1.f},
                                           std::vector<uint8_t>{1, 1, 1, 1, 1, 1, 0});
    ASSERT_NE(std::find_if(legend.entries.begin(), legend.entries.end(),
                           [](const LegendEntry& e) { return e.label.find("singular J") != std::string::npos; }),
              legend.entries.end());
    for (const auto& [w, h] : {std::pair{480, 595}, std::pair{480, 700}, std::pair{300, 400}, std::pair{1920, 1080}}) {
        const PixelRect r = legendRect(w, h, legend);
        EXPECT_GE(r.x, 0) << w << "x" << h;
        EXPECT_LE(r.x + r.width, w) << w << "x" << h << ": the legend is cut at the right edge";
        EXPECT_GE(r.y, 0) << w << "x" << h;
    }
    // Wrapping adds lines: narrower images give taller boxes at the same text size.
    EXPECT_GT(legendRect(300, 400, legend).height, legendRect(640, 400, legend).height);
    // Every label's text is drawn: light pixels reach the box's right part when the labels wrap.
    Image img = filled(300, 400, 0);
    drawLegend(img, legend);
    const PixelRect r = legendRect(img.width, img.height, legend);
    EXPECT_GT(countIn(img, {r.x + r.width / 2, r.y, r.width / 2, r.height}, light), 20);
}

TEST(Legend, ClipsOnTinyImages) {
    Image img = filled(24, 12, 128);
    drawLegend(img, aliasingLegend());
    EXPECT_EQ(img.rgba.size(), 24u * 12u * 4u);
    Image empty;
    drawLegend(empty, truthLegend()); // nothing to draw into; must not crash
}

// ---- PFM ------------------------------------------------------------------------------------

TEST(Pfm, RoundTripIsBitExactIncludingNonFinite) {
    const float denormal = std::numeric_limits<float>::denorm_min();
    const std::vector<float> v{1.f, -0.f, kNaN, kInf, -kInf, denormal, 3.25f, -1e30f, 0.1f, 42.f, 7.f, -2.5f};
    const std::string path = tempPath("roundtrip.pfm");
    writePfm(path, v, 4, 3);
    int w = 0, h = 0;
    const auto back = readPfm(path, w, h);
    EXPECT_EQ(w, 4);
    EXPECT_EQ(h, 3);
    ASSERT_EQ(back.size(), v.size());
    for (size_t i = 0; i < v.size(); ++i)
        EXPECT_EQ(std::bit_cast<uint32_t>(back[i]), std::bit_cast<uint32_t>(v[i])) << "value " << i;
}

TEST(Pfm, FileIsGreyscaleLittleEndianBottomRowFirst) {
    const std::vector<float> v{1.f, 2.f, 3.f, 4.f, 5.f, 6.f}; // 3×2, top row 1 2 3
    const std::string path = tempPath("layout.pfm");
    writePfm(path, v, 3, 2);
    EXPECT_EQ(readBytes(path), "Pf\n3 2\n-1.0\n" + floatBytes({4.f, 5.f, 6.f, 1.f, 2.f, 3.f}));
}

TEST(Pfm, ReadsBigEndianFromOtherTools) {
    const std::string path = tempPath("big.pfm");
    writeBytes(path, "Pf\n2 1\n1.0\n" + floatBytes({0.5f, -8.f}, true));
    int w = 0, h = 0;
    EXPECT_EQ(readPfm(path, w, h), (std::vector<float>{0.5f, -8.f}));
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 1);
}

TEST(Pfm, MalformedFilesAreRejectedWithOneLineMessages) {
    const std::string four = floatBytes({1.f, 2.f, 3.f, 4.f});
    const std::pair<const char*, std::string> cases[] = {
        {"empty", ""},
        {"ppm", "P6\n2 2\n255\n" + four},
        {"colour", "PF\n2 2\n-1.0\n" + four + four + four},
        {"nowhitespace", "Pf2 2\n-1.0\n" + four},
        {"letters", "Pf\nx 2\n-1.0\n" + four},
        {"trailingjunk", "Pf\n2x 2\n-1.0\n" + four},
        {"zero", "Pf\n0 2\n-1.0\n"},
        {"negative", "Pf\n2 -2\n-1.0\n" + four},
        {"tooWide", "Pf\n100000 1\n-1.0\n"},
        {"tooMany", "Pf\n20000 20000\n-1.0\n"},
        {"overflow", "Pf\n99999999999999999999 1\n-1.0\n"},
        {"scaleZero", "Pf\n2 2\n0\n" + four},
        {"scaleWord", "Pf\n2 2\nbig\n" + four},
        {"scaleNaN", "Pf\n2 2\nnan\n" + four},
        {"headerCut", "Pf\n2 2\n-1.0"},
        {"short", "Pf\n2 2\n-1.0\n" + four.substr(0, 15)},
        {"hugeShort", "Pf\n16384 16384\n-1.0\n" + four},
    };
    for (const auto& [name, bytes] : cases) {
        const std::string path = tempPath(std::string("bad_") + name + ".pfm");
        writeBytes(path, bytes);
        int w = -1, h = -1;
        try {
            (void)readPfm(path, w, h);
            ADD_FAILURE() << name << ": accepted";
        } catch (const std::runtime_error& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.find('\n'), std::string::npos) << name << ": " << msg;
            EXPECT_NE(msg.find(path), std::string::npos) << name << ": " << msg;
        }
        EXPECT_EQ(w, -1) << name; // outputs untouched on failure
    }
    int w = 0, h = 0;
    EXPECT_THROW((void)readPfm(tempPath("does_not_exist.pfm"), w, h), std::runtime_error);
}

TEST(Pfm, WriteChecksSizeAndPath) {
    const std::vector<float> v(5, 0.f);
    EXPECT_THROW(writePfm(tempPath("mismatch.pfm"), v, 2, 2), std::invalid_argument);
    EXPECT_THROW(writePfm("/nonexistent_dir_shadowscope/x.pfm", v, 5, 1), std::runtime_error);
}

// The truth-class heatmap: every class its own colour, and a legend that lists exactly the colours
// the image shows (invalid pixels included).
TEST(Heatmap, TruthClassesHaveTheirOwnColoursAndTheLegendListsEveryColourShown) {
    using C = TruthClass;
    const std::vector<C> classes{C::InteriorFalseShadow, C::InteriorFalseLit, C::EdgeError, C::Ambiguous, C::Agrees,
                                 C::NotCounted,          C::NotCounted};
    const std::vector<float> s{0.f, 1.f, 0.f, 1.f, 1.f, 1.f, NAN};
    const std::vector<uint8_t> receiver{1, 1, 1, 1, 1, 0, 1};
    const Image img = truthClassHeatmap(classes, s, receiver, 7, 1);
    const auto colourAt = [&](int x) {
        const uint8_t* p = img.at(x, 0);
        return glm::ivec3(p[0], p[1], p[2]);
    };
    const auto bytes = [](glm::vec3 c) { return glm::ivec3(glm::round(glm::clamp(c, 0.f, 1.f) * 255.f)); };
    EXPECT_EQ(colourAt(0), bytes(kFalseShadowColour));
    EXPECT_EQ(colourAt(1), bytes(kFalseLitColour));
    EXPECT_EQ(colourAt(2), bytes(kEdgeErrorColour));
    EXPECT_EQ(colourAt(3), bytes(kAmbiguousColour));
    EXPECT_EQ(colourAt(5), bytes(kNonReceiverColour));
    EXPECT_EQ(colourAt(6), bytes(kInvalidColour));
    const Legend legend = truthClassLegend(classes, s, receiver);
    std::vector<glm::ivec3> listed;
    for (const auto& e : legend.entries) listed.push_back(bytes(e.colour));
    for (int x = 0; x < 7; ++x)
        EXPECT_NE(std::find(listed.begin(), listed.end(), colourAt(x)), listed.end()) << "pixel " << x;
    EXPECT_EQ(legend.entries.size(), 7u); // six classes shown (agrees only lit) + invalid
    // Without invalid pixels or edge errors, the legend does not list them.
    const std::vector<C> fewer{C::Agrees, C::InteriorFalseShadow};
    const Legend small = truthClassLegend(fewer, std::vector<float>{1.f, 0.f}, std::vector<uint8_t>{1, 1});
    for (const auto& e : small.entries) {
        EXPECT_NE(bytes(e.colour), bytes(kInvalidColour));
        EXPECT_NE(bytes(e.colour), bytes(kEdgeErrorColour));
    }
    EXPECT_EQ(small.entries.size(), 2u);
}
