// Legible at 1280×720 and at 4K with content scale 2 (issue 32): the headless dashboard drawn at
// both sizes, every panel and tab with labels in boxes opened, and each text recorded where it is
// drawn (ui/text_fit.h: settings keys and values, stats cells, heatmap legend lines, chart labels)
// compared with the width it was given. Also: the charts' plots keep their minimum height, and the
// trade-off chart exported as SVG (what `bench` writes) has its point labels apart and inside the plot.
#include "app/dashboard_setup.h"
#include "renderer/context.h"
#include "svg_labels_util.h"
#include "ui/charts/chart.h"
#include "ui/charts/tradeoff_chart.h"
#include "ui/dashboard_headless.h"
#include "ui/text_fit.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Screen {
    int width, height;
    float scale;
};

std::string name(const Screen& s) {
    return std::to_string(s.width) + "x" + std::to_string(s.height) + " at scale " + std::to_string(int(s.scale));
}

class DashboardLegibility : public ::testing::TestWithParam<Screen> {
protected:
    void SetUp() override {
        context_ = renderer::createOSMesaContext();
        ui::textFitEnable(true);
    }
    void TearDown() override { ui::textFitEnable(false); }

    std::unique_ptr<ui::HeadlessDashboard> make() {
        app::RenderOptions o;
        o.scene = "plane";
        o.size = {GetParam().width, GetParam().height};
        o.out = ::testing::TempDir() + "legibility_test";
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        ui::DashboardOptions options = app::dashboardOptions(o);
        options.uiScale = GetParam().scale;
        return std::make_unique<ui::HeadlessDashboard>(std::move(scene), state, options, GetParam().width,
                                                       GetParam().height);
    }

    /// Every text the last frame recorded fits its box; returns how many start with `prefix`.
    /// SHADOWSCOPE_TEST_DUMP=1 lists them all.
    static size_t expectAllFit(const std::string& where, const std::string& prefix) {
        size_t matching = 0;
        const char* dump = std::getenv("SHADOWSCOPE_TEST_DUMP");
        for (const ui::TextFit& f : ui::textFits()) {
            if (dump)
                std::printf("%s | %s | %s | %.1f in %.1f\n", where.c_str(), f.id.c_str(), f.text.c_str(), f.width,
                            f.box);
            EXPECT_TRUE(f.fits()) << name(GetParam()) << ", " << where << ": " << f.id << " \"" << f.text << "\" is "
                                  << f.width << " px in " << f.box << " px";
            matching += f.id.rfind(prefix, 0) == 0;
        }
        return matching;
    }
    static bool recorded(const std::string& id) {
        for (const ui::TextFit& f : ui::textFits())
            if (f.id == id) return true;
        return false;
    }

    std::unique_ptr<renderer::GlContext> context_;
};

TEST_P(DashboardLegibility, SettingsStatsAndHeatmapLegendsFitTheirBoxes) {
    auto d = make();
    (void)d->render(2);
    EXPECT_GE(expectAllFit("Stats tab", "stats:"), 40u) << "the table's cells are recorded";
    // The keys reported cut (issue 32) and every other one.
    EXPECT_TRUE(recorded("settings:filter.evsm.positive_exponent"));
    EXPECT_TRUE(recorded("settings:light.angular_diameter_deg"));
    EXPECT_GE(expectAllFit("controls", "settings value:"), 20u);
    // The view panels' header rows (title, split slider or heatmap combo, Fit, 1:1, zoom): at
    // 1280×720 the light view's "1:1" and the heatmap's zoom text were cut at the panel's edge.
    EXPECT_GE(expectAllFit("view headers", "header:"), 9u);
    d->dashboard().state().views.compare = ui::CompareMode::SideBySide; // longer titles: "…, A"
    (void)d->render(2);
    EXPECT_GE(expectAllFit("view headers, A/B", "header:"), 9u);
    d->dashboard().state().views.compare = ui::CompareMode::Off;
    for (const ui::HeatmapKind kind : {ui::HeatmapKind::Aliasing, ui::HeatmapKind::Truth, ui::HeatmapKind::Splits}) {
        d->dashboard().state().views.heatmap = kind;
        (void)d->render(2);
        EXPECT_GE(expectAllFit("heatmap " + std::to_string(int(kind)), "legend:"), 2u)
            << "the legend is drawn in the UI font, line by line";
    }
}

TEST_P(DashboardLegibility, ChartsFitAndKeepTheirPlotHeight) {
    auto d = make();
    (void)d->render(1);
    const auto plotHeights = [&](const std::string& where) {
        size_t n = 0;
        for (const ui::TextFit& f : ui::textFits())
            if (f.id.find(":plot height") != std::string::npos) {
                ++n;
                EXPECT_GE(f.box, ui::charts::kMinPlotHeight * GetParam().scale) << where;
            }
        return n;
    };
    for (int tab = 1; tab <= 3; ++tab) {
        d->dashboard().showTab(tab);
        (void)d->render(2);
        EXPECT_GE(expectAllFit("chart tab " + std::to_string(tab), "chart:"), 4u);
        EXPECT_EQ(plotHeights("chart tab " + std::to_string(tab)), 1u);
    }
    // The Trade-off tab with a sweep's points, each named beside its marker.
    ui::Dashboard& dash = d->dashboard();
    dash.showTab(4);
    dash.startTradeoffSweep();
    for (int i = 0; i < 20 && dash.tradeoffRunning(); ++i) (void)d->render(1);
    (void)d->render(1);
    size_t labels = 0;
    for (const ui::TextFit& f : ui::textFits()) labels += f.id == "chart:tradeoff:point label";
    expectAllFit("Trade-off tab", "chart:");
    EXPECT_GE(labels, 4u) << "the presets are named on the chart";
    EXPECT_EQ(plotHeights("Trade-off tab"), 1u);
    // bench's tradeoff.svg from the same points: labels apart and inside the plot.
    const std::string svg = ui::charts::chartToSvg(
        ui::charts::tradeoffChart(dash.tradeoffResults(), ui::charts::TradeoffX::GpuMs, ui::charts::TradeoffY::P95),
        1000, 620);
    const auto svgLabels = testutil::svgPointLabels(svg);
    const ui::charts::LabelBox plot = testutil::svgPlotRect(svg);
    EXPECT_GE(svgLabels.size(), 4u);
    for (size_t i = 0; i < svgLabels.size(); ++i) {
        EXPECT_TRUE(svgLabels[i].box.inside(plot)) << svgLabels[i].text;
        for (size_t j = i + 1; j < svgLabels.size(); ++j)
            EXPECT_FALSE(svgLabels[i].box.overlaps(svgLabels[j].box))
                << svgLabels[i].text << " / " << svgLabels[j].text;
    }
    // Recommend's controls take a row above the chart (its plot was 70 px tall): the tune chart keeps
    // the minimum too (the panel scrolls instead).
    ASSERT_TRUE(dash.startRecommend("p95=1", 4)) << dash.status();
    for (int i = 0; i < 2; ++i) (void)d->render(1);
    expectAllFit("Recommend", "chart:");
    EXPECT_EQ(plotHeights("Recommend"), 1u);
}

INSTANTIATE_TEST_SUITE_P(Sizes, DashboardLegibility, ::testing::Values(Screen{1280, 720, 1.f}, Screen{3840, 2160, 2.f}),
                         [](const ::testing::TestParamInfo<Screen>& info) {
                             return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

} // namespace
