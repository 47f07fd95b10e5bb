// Point labels of the charts (ui/charts/label_placement.h, issue 32): placed without overlap and
// inside the plot, measured with the metrics each renderer uses: DejaVu Sans through ImGui for the
// ImDrawList renderer (the dashboard and the PNG exports), the conservative estimate for the SVG.
#include "svg_labels_util.h"
#include "ui/charts/label_placement.h"
#include "ui/charts/tradeoff_chart.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <random>

namespace {

using ui::charts::LabelBox;

void expectApart(const std::vector<LabelBox>& boxes, const LabelBox& bounds, const std::string& what) {
    for (size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_TRUE(boxes[i].inside(bounds)) << what << " label " << i << " leaves the plot";
        for (size_t j = i + 1; j < boxes.size(); ++j)
            EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << what << " labels " << i << " and " << j << " overlap";
    }
}

/// An ImGui context with the UI font (no GL: only the font atlas is built), for its text metrics.
class ImGuiFont {
public:
    ImGuiFont() {
        context_ = ImGui::CreateContext();
        font_ = ImGui::GetIO().Fonts->AddFontFromFileTTF(SHADOWSCOPE_FONT_PATH, 14.f);
        ImGui::GetIO().Fonts->Build();
    }
    ~ImGuiFont() { ImGui::DestroyContext(context_); }
    ImGuiFont(const ImGuiFont&) = delete;
    ImGuiFont& operator=(const ImGuiFont&) = delete;
    [[nodiscard]] double width(std::string_view s, double size) const {
        return font_->CalcTextSizeA(float(size), FLT_MAX, 0.f, s.data(), s.data() + s.size()).x;
    }

private:
    ImGuiContext* context_ = nullptr;
    ImFont* font_ = nullptr;
};

/// bench's trade-off chart at CI size: the presets and a few kernels, bunched where they cost alike.
ui::charts::Chart crowdedTradeoffChart() {
    std::vector<ui::charts::TradeoffPoint> points;
    const char* names[] = {"ssm",
                           "paper",
                           "cascaded",
                           "lispsm_pcf",
                           "current A",
                           "current B",
                           "paper filter.kernel=3",
                           "paper filter.kernel=5",
                           "paper filter.kernel=7",
                           "ssm shadow_map.resolution=4096",
                           "cascaded splits.count=6"};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    for (size_t i = 0; i < std::size(names); ++i) {
        const std::string n = names[i];
        const std::string preset = n == "ssm" || n == "paper" ? n : "";
        points.push_back({n, preset, 1.0 + 0.5 * jitter(rng), 2.0 + 0.5 * jitter(rng)});
    }
    points.push_back({"outlier", "", 9.0, 40.0}); // spreads the axes so the others bunch up; 12 points: all named
    return ui::charts::tradeoffChart(points, ui::charts::TradeoffX::GpuMs, ui::charts::TradeoffY::P95);
}

TEST(LabelPlacement, AnIsolatedLabelSitsRightAboveItsPoint) {
    const ui::charts::LabelRequest r{100, 100, 4, 60, 14};
    const auto placed = ui::charts::placeLabels(std::span(&r, 1), {0, 0, 400, 300});
    ASSERT_TRUE(placed[0].shown);
    EXPECT_FALSE(placed[0].displaced);
    EXPECT_DOUBLE_EQ(placed[0].box.left, 106);
    EXPECT_DOUBLE_EQ(placed[0].box.bottom, 94);
}

TEST(LabelPlacement, ALabelAtTheEdgeTurnsInward) {
    const ui::charts::LabelRequest r{395, 5, 3, 80, 14}; // the top-right corner: right and above are out
    const auto placed = ui::charts::placeLabels(std::span(&r, 1), {0, 0, 400, 300});
    ASSERT_TRUE(placed[0].shown);
    EXPECT_TRUE(placed[0].box.inside({0, 0, 400, 300}));
    EXPECT_LT(placed[0].box.right, 395.0) << "left of its point";
    EXPECT_GT(placed[0].box.top, 5.0) << "below its point";
}

TEST(LabelPlacement, ACrowdNeverOverlapsAndStaysInside) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> at(150, 250), width(20, 120);
    std::vector<ui::charts::LabelRequest> requests;
    for (int i = 0; i < 40; ++i) requests.push_back({at(rng), at(rng), 3, width(rng), 14});
    const LabelBox bounds{0, 0, 400, 300};
    const auto placed = ui::charts::placeLabels(requests, bounds);
    std::vector<LabelBox> shown;
    int displaced = 0;
    for (const auto& p : placed)
        if (p.shown) shown.push_back(p.box), displaced += p.displaced;
    expectApart(shown, bounds, "crowd");
    EXPECT_GE(shown.size(), 30u) << "most labels find a place";
    EXPECT_GT(displaced, 0) << "a crowd needs leader lines";
    // Displaced labels stay within reach of their point: the last ring's corners, or its column's ends.
    for (size_t i = 0; i < placed.size(); ++i)
        if (placed[i].shown) {
            const ui::charts::ChartPoint e = placed[i].leaderEnd(requests[i].x, requests[i].y);
            EXPECT_LE(std::hypot(e.x - requests[i].x, e.y - requests[i].y),
                      std::hypot(3 + 2 + ui::charts::kLabelRings * 14.0, (ui::charts::kLabelRings + 1) * 14.0) + 1.0);
        }
}

TEST(LabelPlacement, TheSvgEstimateIsNoNarrowerThanTheUiFont) {
    const ImGuiFont font;
    for (const char* s : {"paper filter.kernel=5", "ssm", "WWW MMM", "iiii llll", "γ = 30°", "current A"})
        for (const double size : {11.0, 12.0, 24.0})
            EXPECT_GE(ui::charts::estimatedTextWidth(s, size), font.width(s, size)) << s << " at " << size;
}

TEST(ChartLabels, TheTradeoffChartsLabelsAreApartInTheUiFont) {
    const ImGuiFont font;
    const ui::charts::Chart chart = crowdedTradeoffChart();
    for (const double scale : {1.0, 2.0}) {
        const ui::charts::ChartFrame f = ui::charts::chartFrame(chart, 0, 0, 1000 * scale, 620 * scale, false, scale);
        const auto labels = ui::charts::chartLabels(
            chart, f, [&](std::string_view s, double size) { return font.width(s, size); }, 12 * scale, 14 * scale);
        std::vector<LabelBox> shown;
        for (const auto& l : labels) {
            if (!l.place.shown) continue;
            shown.push_back(l.place.box);
            EXPECT_DOUBLE_EQ(l.place.box.width(), font.width(l.text, 12 * scale)) << "measured in the UI font";
        }
        expectApart(shown, {f.left, f.top, f.right, f.bottom}, "scale " + std::to_string(scale));
        EXPECT_GE(shown.size(), 12u) << "every configuration named at scale " << scale;
    }
}

TEST(ChartLabels, TheExportedSvgsLabelsAreApartAndInsideThePlot) {
    const std::string svg = ui::charts::chartToSvg(crowdedTradeoffChart(), 1000, 620);
    const std::vector<testutil::SvgLabel> labels = testutil::svgPointLabels(svg);
    const LabelBox plot = testutil::svgPlotRect(svg);
    ASSERT_GT(plot.width(), 100.0);
    ASSERT_GE(labels.size(), 12u);
    std::vector<LabelBox> boxes;
    for (const auto& l : labels) boxes.push_back(l.box);
    expectApart(boxes, plot, "svg");
    EXPECT_NE(svg.find("stroke=\"#999999\""), std::string::npos) << "displaced labels have leader lines";
}

} // namespace
