// The stats panel: the inspected light, timings, triangles, error statistics, γ, utilization per
// split, for A (and B when comparing), and the pinned pixel's values.
//
// Index
//   drawStatsPanel (the tabs) · statRows (the table's rows, as data) · statsOf, gpuTime ·
//   drawStatsTable · drawInspector
#include "dashboard.h"

#include "text_fit.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace ui {

namespace {

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

} // namespace

void Dashboard::drawStatsPanel() {
    const Rect& r = rects_.stats;
    ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
    if (ImGui::BeginChild("stats", ImVec2(std::max(r.w, 1.f), std::max(r.h, 1.f)), true) &&
        ImGui::BeginTabBar("stats_tabs")) {
        const auto flags = [&](int tab) { return requestedTab_ == tab ? ImGuiTabItemFlags_SetSelected : 0; };
        if (ImGui::BeginTabItem("Stats", nullptr, flags(0))) {
            drawStatsTable();
            ImGui::SameLine();
            drawInspector();
            ImGui::EndTabItem();
        }
        widgetMapRecord("tab.stats");
        const char* names[] = {"n'(γ)", "λ(θ)", "m_z(z)"};
        for (int i = 0; i < 3; ++i) {
            if (ImGui::BeginTabItem(names[i], nullptr, flags(1 + i))) {
                drawAnalyticChart(i);
                ImGui::EndTabItem();
            }
            widgetMapRecord(std::string("tab.chart") + std::to_string(i));
        }
        if (ImGui::BeginTabItem("Trade-off", nullptr, flags(4))) {
            drawTradeoffTab();
            ImGui::EndTabItem();
        }
        widgetMapRecord("tab.tradeoff");
        requestedTab_ = -1;
        ImGui::EndTabBar();
    }
    ImGui::EndChild();
}

std::vector<Dashboard::StatRow> Dashboard::statRows(int sides) const {
    std::vector<StatRow> rows;
    const auto row = [&rows](const char* name, std::function<std::string(int)> value, const char* tip = nullptr) {
        rows.push_back({name, std::move(value), tip});
    };
    row(
        "light",
        [this](int i) {
            const geometry::scene::Light& l = sides_[i].plan.light;
            std::string out = std::to_string(inspectedLight()) + " of " + std::to_string(lights().size()) + ": " +
                              geometry::scene::lightTypeName(l.type);
            if (l.type == geometry::scene::LightType::Spot) out += fmt(", cone %.3g°", l.coneDeg);
            if (l.positional()) out += fmt(", range %.4g", l.range);
            return out;
        },
        "The inspected light (Lights): every figure below, the light view and the heatmaps describe it; the "
        "other lights are drawn into the eye view too");
    row("γ / light–view angle", [this](int i) {
        return fmt("%.2f°", sides_[i].plan.gammaDeg) + " / " + fmt("%.1f°", sides_[i].plan.lightViewAngleDeg);
    });
    row("GPU depth pre-pass", gpuTime(renderer::Pass::Prepass),
        "GPU time of the eye's depth pre-pass (and, with focus.mode = samples, the sample reduction)");
    row(
        "focus",
        [this](int i) {
            const auto& p = sides_[i].plan;
            if (!p.fittedToSamples) return std::string("geometry");
            std::string skipped;
            for (size_t k = 0; k < p.splits.size(); ++k)
                if (p.splits[k].skipped) skipped += (skipped.empty() ? "" : ",") + std::to_string(k);
            return "samples " + fmt("%.3g", p.sampleDepthRange.x) + "–" + fmt("%.3g", p.sampleDepthRange.y) +
                   (skipped.empty() ? std::string() : ", skipped " + skipped);
        },
        "focus.mode = samples: the visible samples' view-depth range, from this frame's depth pre-pass "
        "(reduced on the GPU before the shadow maps are drawn), and the splits skipped for having none");
    row(
        "caster LOD", [this](int i) { return casterLodStatus(i); },
        "casters.lod = auto: simplified caster levels, built once per scene in the background; the "
        "shadow passes draw every triangle until they are in");
    row(
        "GPU shadow pass",
        [this](int i) {
            const auto* s = statsOf(i);
            if (!s || !std::isfinite(sides_[i].shadowGpuMs)) return std::string("–");
            return fmt("%.2f ms", sides_[i].shadowGpuMs) + (s->shadowMapsReused ? " (maps reused)" : "");
        },
        "GPU time of the shadow maps (all splits) when last drawn; the maps are reused while only "
        "eye-side values change (filter, receiver offsets, heatmap)");
    row("GPU eye pass", gpuTime(renderer::Pass::Eye), "GPU time of the eye view with filtering and blur");
    row("GPU light views", gpuTime(renderer::Pass::LightView),
        "GPU time of the inspection views (not part of the shadowing)");
    row(
        "plan (CPU)",
        [this](int i) {
            const RecentMedian& m = sides_[i].planMicroseconds;
            return m.count() ? fmt("%.1f µs", m.median()) + " (median of " + std::to_string(m.count()) + ")"
                             : std::string("–");
        },
        "geometry::planShadows, the median over the last plans (the pre-pass of focus.mode = samples "
        "not included)");
    row("dashboard frame (CPU)", [this](int) { return fmt("%.1f ms", cpuFrameMs_); });
    row(
        "passes drawn",
        [this](int) {
            return std::to_string(counts_.shadow) + " shadow, " + std::to_string(counts_.eyeFull) + " eye + " +
                   std::to_string(counts_.eyeCoarse) + " coarse, " + std::to_string(counts_.inspections) + " inspected";
        },
        "Since the dashboard started (both sides): shadow-map passes, eye passes at full and reduced "
        "resolution, statistics computed. Hover, zoom and idle frames draw nothing.");
    row(
        "statistics",
        [this](int i) {
            const Side& s = sides_[i];
            if (s.coarseDivisor > 1) return std::string("coarse view: from the last full frame");
            if (s.job) return std::string("recomputing (shown: stale)");
            return s.inspection ? std::string("current") : std::string("–");
        },
        "Statistics and ground truth are computed on a worker thread for the last full-resolution "
        "frame; the values shown stay until the new ones are ready");
    row(
        "triangles shadow / eye",
        [this](int i) {
            const auto* s = statsOf(i);
            return s ? std::to_string(s->shadowTriangles) + " / " + std::to_string(s->eyeTriangles) : std::string("–");
        },
        "Triangles submitted per pass after culling (shadow: all splits)");
    row("shadow map", [this](int i) {
        const auto* s = statsOf(i);
        if (s && s->virtualPages.active)
            return "virtual " + std::to_string(s->shadowResolution) + "² × " +
                   std::to_string(sides_[i].plan.virtualMap.config.levels) + " levels";
        return s ? std::to_string(s->shadowResolution) + "² × " + std::to_string(sides_[i].plan.splits.size())
                 : std::string("–");
    });
    row(
        "virtual pages",
        [this](int i) {
            const auto* s = statsOf(i);
            if (!s || !s->virtualPages.active) return std::string("–");
            const auto& v = s->virtualPages;
            return std::to_string(v.allocated) + " (" + std::to_string(v.drawn) + " drawn), pool " +
                   fmt("%.0f %%", v.poolPages ? 100.0 * v.occupied / v.poolPages : 0.0) + " of " +
                   fmt("%.0f MiB", double(v.memoryBytes) / (1 << 20));
        },
        "technique = virtual (docs/design.md §3.11): the pages the visible pixels read this frame, how many "
        "were drawn (the others were kept from earlier frames), and how full the physical pool is");
    row(
        "m mean / p50",
        [this](int i) {
            const auto* in = inspection(i);
            return in ? fmt("%.3g", in->aliasing.mean) + " / " + fmt("%.3g", in->aliasing.p50) : std::string("–");
        },
        "Aliasing error m (screen pixels per shadow texel, docs/design.md §4) over receiver pixels");
    row("m p95 / max", [this](int i) {
        const auto* in = inspection(i);
        return in ? fmt("%.3g", in->aliasing.p95) + " / " + fmt("%.3g", in->aliasing.max) : std::string("–");
    });
    row("undersampled (m > 1)", [this](int i) {
        const auto* in = inspection(i);
        return in ? fmt("%.1f %%", 100.0 * in->aliasing.undersampled) : std::string("–");
    });
    row(
        "singular J",
        [this](int i) {
            const auto* in = inspection(i);
            return in ? fmt("%.2f %%", 100.0 * in->aliasing.singular) : std::string("–");
        },
        "Receiver pixels whose texel Jacobian is singular (surfaces edge-on to the light): m is not "
        "measured there and they are left out of the figures above");
    row(
        "false shadow / false lit",
        [this](int i) {
            const auto* in = inspection(i);
            if (!in || !in->truth) return std::string(state_.views.truth ? "–" : "truth off");
            return fmt("%.2f %%", 100.0 * in->truth->falseShadow) + " / " + fmt("%.2f %%", 100.0 * in->truth->falseLit);
        },
        "Against ray-traced ground truth: lit pixels shadowed (acne) / shadowed pixels lit (leaks)");
    row(
        "interior fs / fl / edge",
        [this](int i) {
            const auto* in = inspection(i);
            if (!in || !in->truthClasses) return std::string(state_.views.truth ? "–" : "truth off");
            const auto& t = *in->truthClasses;
            return fmt("%.2f", 100.0 * t.interiorFalseShadow) + " / " + fmt("%.2f", 100.0 * t.interiorFalseLit) +
                   " / " + fmt("%.2f %%", 100.0 * t.edgeError);
        },
        "The same split by cause (docs/design.md §4 \"Truth classes\"): false shadow and false lit at least "
        "1 px from a true shadow edge (acne, leaks), and misclassified pixels within 1 px of one (an edge "
        "drawn slightly off)");
    row(
        "edge offset / ambiguous",
        [this](int i) {
            const auto* in = inspection(i);
            if (!in || !in->truthClasses) return std::string(state_.views.truth ? "–" : "truth off");
            const auto& t = *in->truthClasses;
            return fmt("%.2f texels", t.edgeDisplacementTexelsMedian) + " / " + fmt("%.2f %%", 100.0 * t.ambiguous);
        },
        "Median distance from a misplaced shadow edge to the true one, in texels; receivers no map can be "
        "judged on (terminator, shading and geometric normals disagree, an occluder within a pixel's "
        "footprint), left out of the classes");
    row(
        "peter-panning / interior |s − c|",
        [this](int i) {
            const auto* in = inspection(i);
            if (!in || !in->truthClasses) return std::string(state_.views.truth ? "–" : "truth off");
            const auto& t = *in->truthClasses;
            return fmt("%.2f %%", 100.0 * t.contactFalseLit) + fmt(" (gap p95 %.3g)", t.contactGapP95) + " / " +
                   fmt("%.4f", t.interiorMeanAbs);
        },
        "contact_false_lit: shadow lost near a contact (occluder within 32 pixel footprints), with the "
        "occluder's distance; interior_mean_abs: mean |s - c| inside fully lit or shadowed regions (a wide "
        "kernel's darkening, light in the umbra)");
    bool soft = false; // the soft truth's row only where a side has one (light.angular_diameter_deg > 0)
    for (int i = 0; i < sides; ++i) soft = soft || (inspection(i) && inspection(i)->softTruth);
    if (soft)
        row(
            "soft truth |s − v|",
            [this](int i) {
                const auto* in = inspection(i);
                if (!in || !in->softTruth) return std::string("–");
                return fmt("%.4f", in->softTruth->meanAbs) + fmt(" (sun %.2f°)", in->softTruth->angularDiameterDeg);
            },
            "soft_mean_abs (docs/design.md §4 \"Soft truth\"): mean |s − v| over the receivers, v the "
            "fraction of the sun's disk each one sees, traced with 64 rays");
    row(
        "texel utilization",
        [this](int i) {
            const auto* in = inspection(i);
            if (!in) return std::string("–");
            std::string out;
            for (double u : in->utilization) out += (out.empty() ? "" : " ") + fmt("%.1f%%", 100.0 * u);
            return out;
        },
        "Per split: the share of the map's texels that some visible receiver samples");
    row("splits [n, f] n'", [this](int i) {
        std::string out;
        for (const auto& sp : sides_[i].plan.splits)
            out += (out.empty() ? "" : "  ") + fmt("[%.3g", sp.near) + fmt(", %.3g]", sp.far) +
                   (sp.warped() ? fmt(" %.3g", sp.nPrime) : std::string(" ∞"));
        return out;
    });
    row("warnings", [this](int i) {
        const auto* s = statsOf(i);
        std::string out;
        for (const auto& w : sides_[i].plan.warnings) out += (out.empty() ? "" : "; ") + w;
        if (s)
            for (const auto& w : s->warnings) out += (out.empty() ? "" : "; ") + w;
        return out.empty() ? std::string("none") : out;
    });
    return rows;
}

const renderer::FrameStats* Dashboard::statsOf(int side) const noexcept {
    return sides_[side].renderer ? &sides_[side].renderer->stats() : nullptr;
}

std::function<std::string(int)> Dashboard::gpuTime(renderer::Pass pass) const {
    return [this, pass](int i) {
        const auto* s = statsOf(i);
        return s && s->gpu.valid ? fmt("%.2f ms", s->gpu.of(pass)) : std::string("–");
    };
}

void Dashboard::drawStatsTable() {
    const int sides = comparing() ? 2 : 1;
    const float inspectorW = std::min(ImGui::GetContentRegionAvail().x * 0.38f, 30.f * ImGui::GetFontSize());
    ImGui::BeginChild("stats_table", ImVec2(ImGui::GetContentRegionAvail().x - inspectorW, 0), false);
    // Column widths from the text (issue 32: cells were cut, "[97.9", "14 ins"): the names' column as
    // wide as its widest name (at most 45 % of the table), the value columns share the rest in
    // proportion to their widest values; a value still too wide wraps in its cell instead of being cut.
    const std::vector<StatRow> rows = statRows(sides);
    std::vector<std::array<std::string, 2>> values(rows.size());
    float widestName = ImGui::CalcTextSize("value").x;
    std::array<float, 2> widestValue{ImGui::GetFontSize(), ImGui::GetFontSize()};
    for (size_t k = 0; k < rows.size(); ++k) {
        widestName = std::max(widestName, ImGui::CalcTextSize(rows[k].name).x);
        for (int i = 0; i < sides; ++i) {
            values[k][size_t(i)] = rows[k].value(i);
            widestValue[size_t(i)] =
                std::max(widestValue[size_t(i)], ImGui::CalcTextSize(values[k][size_t(i)].c_str()).x);
        }
    }
    const float avail = ImGui::GetContentRegionAvail().x;
    const float cellPad = 2.f * ImGui::GetStyle().CellPadding.x + 1.f;
    const float nameW = std::min(widestName, 0.45f * avail - cellPad);
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("stats_table", 1 + sides, flags)) {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, std::max(nameW, 1.f));
        ImGui::TableSetupColumn(sides == 2 ? "A" : "value", ImGuiTableColumnFlags_WidthStretch, widestValue[0]);
        if (sides == 2) ImGui::TableSetupColumn("B", ImGuiTableColumnFlags_WidthStretch, widestValue[1]);
        ImGui::TableHeadersRow();
        // Wrapped at the cell's right edge; the record compares the widest wrapped line with the cell.
        const auto cell = [](const std::string& id, const char* text) {
            const float box = ImGui::GetContentRegionAvail().x;
            ImGui::PushTextWrapPos(0.f);
            ImGui::TextUnformatted(text);
            ImGui::PopTextWrapPos();
            if (textFitEnabled())
                textFitRecord(id, text, ImGui::CalcTextSize(text, nullptr, false, std::max(box, 1.f)).x, box);
        };
        for (size_t k = 0; k < rows.size(); ++k) {
            const StatRow& r = rows[k];
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            cell(std::string("stats:") + r.name, r.name);
            if (r.tip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.tip);
            for (int i = 0; i < sides; ++i) {
                ImGui::TableSetColumnIndex(1 + i);
                cell(std::string("stats:") + r.name + (i == 0 ? "/A" : "/B"), values[k][size_t(i)].c_str());
            }
        }
        ImGui::EndTable();
    }
    ImGui::EndChild();
}

void Dashboard::drawInspector() {
    {
        ImGui::BeginChild("inspector", ImVec2(0, 0), false);
        ImGui::TextUnformatted("Pixel inspector");
        widgetMapRecord("inspector");
        const std::optional<PixelProbe>& p = pinned_ ? pinned_ : hovered_;
        if (!p) {
            ImGui::TextDisabled("hover a view; Shift+click to pin a pixel");
        } else {
            ImGui::TextDisabled(pinned_ ? "pinned" : "under the cursor");
            ImGui::PushTextWrapPos(0.f);
            ImGui::TextUnformatted(describeProbe(*p).c_str());
            ImGui::PopTextWrapPos();
            if (p->panel != ViewPanel::Light && !p->sky)
                ImGui::Text("world (%.4g, %.4g, %.4g)", p->position.x, p->position.y, p->position.z);
            if (pinned_ && ImGui::SmallButton("unpin")) pinned_.reset();
        }
        ImGui::EndChild();
    }
}

} // namespace ui
