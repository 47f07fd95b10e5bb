// `shadowscope check`'s golden comparison and reports, without rendering (app/golden_image.h,
// app/check_report.h): the channel and fraction tolerances at their edges, the diff picture, and
// escaped, well-counted JUnit XML.
#include "app/check_report.h"
#include "app/golden_image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

using geometry::analysis::Image;

namespace {

Image solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
    Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        img.rgba[i] = r;
        img.rgba[i + 1] = g;
        img.rgba[i + 2] = b;
        img.rgba[i + 3] = 255;
    }
    return img;
}

size_t magenta(const Image& img) {
    size_t n = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4)
        n += std::equal(img.rgba.begin() + long(i), img.rgba.begin() + long(i) + 4, std::begin(app::kDiffColour));
    return n;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

} // namespace

TEST(GoldenImage, AChannelDiffersWhenBeyondTheTolerance) {
    const Image golden = solid(10, 10, 100, 100, 100);
    Image render = golden;
    render.rgba[4 * 5 + 1] = 108; // pixel 5, green +8
    render.rgba[4 * 7 + 2] = 91;  // pixel 7, blue −9
    auto c = app::compareImages(render, golden, 8);
    EXPECT_TRUE(c.sameSize);
    EXPECT_EQ(c.pixels, 100u);
    EXPECT_EQ(c.differing, 1u);
    EXPECT_EQ(c.maxChannelDifference, 9);
    EXPECT_DOUBLE_EQ(c.fraction(), 0.01);
    EXPECT_TRUE(c.passes(0.01)); // "more than fraction" fails, exactly fraction passes
    EXPECT_FALSE(c.passes(0.009));
    EXPECT_FALSE(c.passes(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_EQ(app::compareImages(render, golden, 0).differing, 2u); // the default tolerance is exact
    EXPECT_EQ(app::compareImages(golden, golden, 0).differing, 0u);
    EXPECT_TRUE(app::compareImages(golden, golden, 0).passes(0));
    EXPECT_EQ(app::comparisonText("g.png", c, 8, 0.001),
              "golden g.png: 1 of 100 pixels (1%) differ by more than 8 > fraction 0.001");
}

TEST(GoldenImage, DifferentSizesFail) {
    const auto c = app::compareImages(solid(16, 9, 0, 0, 0), solid(9, 16, 0, 0, 0), 255);
    EXPECT_FALSE(c.sameSize);
    EXPECT_FALSE(c.passes(1.0));
    EXPECT_EQ(app::comparisonText("g.png", c, 0, 0), "golden g.png: the render is 16x9, the golden 9x16");
    EXPECT_THROW((void)app::diffImage(solid(16, 9, 0, 0, 0), solid(9, 16, 0, 0, 0), 0), std::invalid_argument);
}

TEST(GoldenImage, TheDiffMarksExactlyTheDifferingPixelsOverADimmedGreyRender) {
    const Image golden = solid(8, 4, 200, 40, 40);
    Image render = golden;
    for (int i : {0, 9, 31}) render.rgba[4 * size_t(i)] = 0;
    const Image diff = app::diffImage(render, golden, 8);
    EXPECT_EQ(diff.width, 8);
    EXPECT_EQ(diff.height, 4);
    EXPECT_EQ(magenta(diff), 3u);
    EXPECT_EQ(magenta(diff), app::compareImages(render, golden, 8).differing);
    const uint8_t* p = diff.at(1, 0); // unchanged: grey, darker than the render
    EXPECT_EQ(p[0], p[1]);
    EXPECT_EQ(p[1], p[2]);
    EXPECT_LE(p[0], 85);
    EXPECT_GT(p[0], 0);
    EXPECT_EQ(p[3], 255);
    EXPECT_EQ(magenta(app::diffImage(golden, golden, 0)), 0u);
}

TEST(CheckReport, XmlEscapesMarkupQuotesAndControlCharacters) {
    EXPECT_EQ(app::xmlEscape("a < b && c > \"d\" 'e'"), "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;");
    EXPECT_EQ(app::xmlEscape(std::string("x\x01y\tz\n", 6)), "x?y\tz\n");
}

TEST(CheckReport, JUnitCountsCasesFailuresAndErrors) {
    std::vector<app::CaseReport> cases(3);
    cases[0].name = "good";
    cases[0].verdicts = {{"aliasing.p95", true, "aliasing.p95 = 2 <= max 6"}};
    cases[1].name = "bad<1>";
    cases[1].verdicts = {{"aliasing.p95", false, "aliasing.p95 = 7 > max 6"},
                         {"golden", false, "golden g.png: 9 of 10 pixels (90%) differ by more than 0 > fraction 0"}};
    cases[1].seconds = 1.5;
    cases[2].name = "broken";
    cases[2].error = "GL error: GL_OUT_OF_MEMORY & more";
    const std::string xml = app::junitXml("suite&co", cases);
    EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0), 0u) << xml;
    EXPECT_NE(xml.find("<testsuite name=\"suite&amp;co\" tests=\"3\" failures=\"1\" errors=\"1\""), std::string::npos)
        << xml;
    EXPECT_EQ(count(xml, "<testcase "), 3u);
    EXPECT_EQ(count(xml, "</testcase>"), 3u);
    EXPECT_EQ(count(xml, "<failure "), 1u);
    EXPECT_EQ(count(xml, "<error "), 1u);
    EXPECT_NE(xml.find("name=\"bad&lt;1&gt;\""), std::string::npos);
    EXPECT_NE(xml.find("time=\"1.500\""), std::string::npos);
    EXPECT_NE(xml.find("message=\"aliasing.p95 = 7 &gt; max 6; golden g.png"), std::string::npos) << xml;
    EXPECT_NE(xml.find("GL_OUT_OF_MEMORY &amp; more"), std::string::npos);
    EXPECT_EQ(xml.find(" > max"), std::string::npos) << "every '>' in text is escaped";

    const std::string table = app::summaryTable(cases);
    EXPECT_NE(table.find("case    verdict  failed  time\n"), std::string::npos) << table;
    EXPECT_NE(table.find("bad<1>  FAIL     2       1.50 s\n"), std::string::npos) << table;
    EXPECT_NE(table.find("3 case(s): 1 passed, 2 failed"), std::string::npos) << table;

    cases[0].render = "good/eye.png";
    const std::string html = app::htmlReport("check <x>", cases);
    EXPECT_NE(html.find("<title>check &lt;x&gt;</title>"), std::string::npos);
    EXPECT_NE(html.find("<img src=\"good/eye.png\""), std::string::npos);
    EXPECT_NE(html.find("aliasing.p95 = 7 &gt; max 6"), std::string::npos);
    EXPECT_EQ(html.find("bad<1>"), std::string::npos);
}
