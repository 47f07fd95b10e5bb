#pragma once
// Text for XML, SVG and HTML content and attributes (the charts' SVG, `check`'s report and JUnit file).
#include <string>
#include <string_view>

namespace ui::charts {

/// & < > " ' as entities; control characters XML 1.0 cannot hold (all below 0x20 but tab, newline,
/// carriage return, and DEL) as '?'.
[[nodiscard]] std::string xmlEscape(std::string_view text);

} // namespace ui::charts
