#include "ui/charts/xml_text.h"

namespace ui::charts {

std::string xmlEscape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        switch (ch) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        case '\t':
        case '\n':
        case '\r': out += ch; break;
        default: out += (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ? '?' : ch;
        }
    }
    return out;
}

} // namespace ui::charts
