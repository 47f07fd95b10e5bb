#pragma once
// The point labels of an SVG chart written by ui/charts (class="point-label" <text> elements) as
// boxes, measured with the writer's own width estimate, and the plot's clip rectangle.
#include "ui/charts/label_placement.h"

#include <regex>
#include <string>
#include <vector>

namespace testutil {

struct SvgLabel {
    std::string text;
    ui::charts::LabelBox box;
};

inline std::string xmlUnescape(std::string s) {
    const std::pair<const char*, const char*> entities[] = {
        {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities)
        for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1))
            s.replace(at, std::string(from).size(), to);
    return s;
}

inline std::vector<SvgLabel> svgPointLabels(const std::string& svg) {
    static const std::regex text(
        R"re(<text x="([-0-9.]+)" y="([-0-9.]+)"[^>]*font-size="([0-9.]+)"[^>]*class="point-label">([^<]*)</text>)re");
    std::vector<SvgLabel> out;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it) {
        const double x = std::stod((*it)[1]), y = std::stod((*it)[2]), size = std::stod((*it)[3]);
        SvgLabel l{xmlUnescape((*it)[4]), {}};
        const double top = y - ui::charts::kLabelBaseline * size;
        l.box = {x, top, x + ui::charts::estimatedTextWidth(l.text, size), top + ui::charts::kLabelLineHeight * size};
        out.push_back(l);
    }
    return out;
}

/// The first panel's plot rectangle (its clipPath).
inline ui::charts::LabelBox svgPlotRect(const std::string& svg) {
    static const std::regex clip(
        R"re(<clipPath id="plot-0"><rect x="([-0-9.]+)" y="([-0-9.]+)" width="([0-9.]+)" height="([0-9.]+)"/>)re");
    std::smatch m;
    if (!std::regex_search(svg, m, clip)) return {};
    const double x = std::stod(m[1]), y = std::stod(m[2]);
    return {x, y, x + std::stod(m[3]), y + std::stod(m[4])};
}

} // namespace testutil
