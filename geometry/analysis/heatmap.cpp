// Index
//   [SECTION] Colour helpers ... toByte, setPixel, diverging, requireImageInput, blankImage
//   [SECTION] Legend drawing ... textWidth, Canvas, wrapText, layoutLegend, legendScale, drawBar, drawEntries,
//                                shortNumber
//   [SECTION] PFM helpers ...... headerToken, parseSide, swapFloats
//   [SECTION] Colour maps ...... divergingLog2, falseColourTruth, splitColour
//   [SECTION] Heatmap images ... aliasingHeatmap, truthHeatmap, truthClassHeatmap
//   [SECTION] Legends .......... aliasingLegend, truthLegend, truthClassLegend, splitLegend, legendRect, drawLegend,
//                                withLegend
//   [SECTION] PFM files ........ writePfm, readPfm

#include "geometry/analysis/heatmap.h"

// stb_easy_font is all `static` functions; the ones we don't call would warn.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace geometry::analysis {
namespace {

// ---- [SECTION] Colour helpers ---------------------------------------------------------------

uint8_t toByte(float c) { return uint8_t(std::lround(std::clamp(c, 0.f, 1.f) * 255.f)); }

void setPixel(Image& img, int x, int y, glm::vec3 c) {
    uint8_t* p = &img.rgba[4 * (size_t(y) * size_t(img.width) + size_t(x))];
    p[0] = toByte(c.r);
    p[1] = toByte(c.g);
    p[2] = toByte(c.b);
    p[3] = 255;
}

constexpr glm::vec3 rgb(int hex) {
    return {float((hex >> 16) & 0xff) / 255.f, float((hex >> 8) & 0xff) / 255.f, float(hex & 0xff) / 255.f};
}

// ColorBrewer RdBu (7 classes), blue end first. Chosen over a plain three-colour ramp because its
// lightness falls monotonically away from the white centre on both sides.
constexpr std::array<glm::vec3, 7> kDiverging{rgb(0x2166ac), rgb(0x67a9cf), rgb(0xd1e5f0), rgb(0xf7f7f7),
                                              rgb(0xfddbc7), rgb(0xef8a62), rgb(0xb2182b)};

/// Piecewise-linear lookup in kDiverging, t ∈ [−1, 1] (clamped).
glm::vec3 diverging(float t) {
    const float x = (std::clamp(t, -1.f, 1.f) + 1.f) * 0.5f * float(kDiverging.size() - 1);
    const size_t i = std::min(size_t(x), kDiverging.size() - 2);
    return glm::mix(kDiverging[i], kDiverging[i + 1], x - float(i));
}

void requireImageInput(size_t n, int w, int h, const char* what) {
    if (w < 0 || h < 0 || n != size_t(w) * size_t(h))
        throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(w) + "x" + std::to_string(h) +
                                    " values, got " + std::to_string(n));
}

Image blankImage(int w, int h) { return Image{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 4, 0)}; }

// ---- [SECTION] Legend drawing ---------------------------------------------------------------
// Layout is computed in font units (one stb_easy_font pixel) and scaled by an integer factor
// when drawn, so the legend stays crisp.

constexpr int kPad = 5;   // inside the box
constexpr int kGap = 4;   // between blocks
constexpr int kTextH = 9; // stb_easy_font glyphs span y ∈ [0, 9] with descenders
constexpr int kBarW = 150, kBarH = 10, kTickH = 3;
constexpr int kSwatch = 8, kRowH = 12; // stb_easy_font's own line advance
constexpr int kMargin = 8;             // box to image edge
constexpr glm::vec3 kTextColour{0.97f};
constexpr glm::vec3 kBoxColour{0.04f, 0.04f, 0.05f};
constexpr float kBoxAlpha = 0.7f;
constexpr glm::vec3 kOutlineColour{0.6f};

/// stb_easy_font indexes a table by (char − 32) and takes a mutable char*: keep it to printable
/// ASCII so a stray byte cannot read outside the table.
std::string printable(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (c < 32 || c > 126) c = '?';
    return out;
}

/// Visible width in font units (stb's width includes one column of trailing spacing).
int textWidth(const std::string& s) {
    if (s.empty()) return 0;
    std::string t = printable(s);
    return std::max(0, stb_easy_font_width(t.data()) - 1);
}

/// Draw target: an image, an integer scale and the box origin in pixels; clips to the image.
struct Canvas {
    Image& img;
    int scale;
    int ox, oy;

    void fillPixels(int x0, int y0, int x1, int y1, glm::vec3 c) const {
        x0 = std::max(x0, 0), y0 = std::max(y0, 0);
        x1 = std::min(x1, img.width), y1 = std::min(y1, img.height);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) setPixel(img, x, y, c);
    }
    /// Rectangle in font units relative to the box origin.
    void fill(float x, float y, float w, float h, glm::vec3 c) const {
        auto px = [&](float u) { return int(std::lround(u * float(scale))); };
        fillPixels(ox + px(x), oy + px(y), ox + px(x + w), oy + px(y + h), c);
    }
    void text(float x, float y, const std::string& s, glm::vec3 c) const {
        if (s.empty()) return;
        std::string t = printable(s);
        // stb writes 4 vertices of 16 bytes per quad; no glyph needs more than 24 quads.
        std::vector<char> buf((t.size() + 1) * 24 * 64);
        const int quads = stb_easy_font_print(0, 0, t.data(), nullptr, buf.data(), int(buf.size()));
        for (int q = 0; q < quads; ++q) {
            float v[4][4]; // x, y, z, colour bits per vertex
            std::memcpy(v, &buf[size_t(q) * 64], sizeof v);
            // Quads are axis-aligned segments: vertex 0 is one corner, vertex 2 the opposite.
            fill(x + v[0][0], y + v[0][1], v[2][0] - v[0][0], v[2][1] - v[0][1], c);
        }
    }
};

/// Lines of at most `maxWidth` font units, broken at spaces (a word wider than that stands alone;
/// drawing clips it). maxWidth ≤ 0: one line.
std::vector<std::string> wrapText(const std::string& s, int maxWidth) {
    if (maxWidth <= 0 || textWidth(s) <= maxWidth) return {s};
    std::vector<std::string> lines;
    std::string line;
    size_t i = 0;
    while (i < s.size()) {
        const size_t end = std::min(s.find(' ', i), s.size());
        const std::string word = s.substr(i, end - i);
        const std::string joined = line.empty() ? word : line + " " + word;
        if (!line.empty() && textWidth(joined) > maxWidth) {
            lines.push_back(line);
            line = word;
        } else {
            line = joined;
        }
        i = end + 1;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

/// Space the tick labels need beyond the bar's left and right ends.
std::pair<int, int> tickOverhang(const Legend& legend) {
    int left = 0, right = 0;
    for (const auto& t : legend.ticks) {
        const float centre = std::clamp(t.position, 0.f, 1.f) * float(kBarW);
        const float half = 0.5f * float(textWidth(t.label));
        left = std::max(left, int(std::ceil(half - centre)));
        right = std::max(right, int(std::ceil(centre + half - float(kBarW))));
    }
    return {left, right};
}

/// Block positions in font units, shared by legendRect() and drawLegend(); the title and the
/// swatches' labels wrapped to the room the image leaves.
struct LegendLayout {
    int width = 0, height = 0;
    int barX = 0, barY = 0;
    int entriesY = 0;
    std::vector<std::string> title;
    std::vector<std::vector<std::string>> entries;
};

/// `maxWidth`: the widest box the image has room for, in font units (≤ 0: no limit).
LegendLayout layoutLegend(const Legend& legend, int maxWidth) {
    LegendLayout l;
    const int content = maxWidth > 0 ? maxWidth - 2 * kPad : 0;
    int y = kPad, contentW = 0;
    auto block = [&](int h) { // stacks a block, with a gap before every block but the first
        if (y > kPad) y += kGap;
        const int top = y;
        y += h;
        return top;
    };
    if (!legend.title.empty()) {
        l.title = wrapText(legend.title, content);
        block(int(l.title.size()) * kRowH - (kRowH - kTextH));
        for (const auto& line : l.title) contentW = std::max(contentW, textWidth(line));
    }
    if (legend.bar) {
        const auto [left, right] = tickOverhang(legend);
        l.barX = kPad + left;
        l.barY = block(kBarH + (legend.ticks.empty() ? 0 : kTickH + 2 + kTextH));
        contentW = std::max(contentW, left + kBarW + right);
    }
    if (!legend.entries.empty()) {
        int rows = 0;
        for (const auto& e : legend.entries) {
            l.entries.push_back(wrapText(e.label, content > 0 ? content - kSwatch - kPad : 0));
            rows += int(l.entries.back().size());
            for (const auto& line : l.entries.back()) contentW = std::max(contentW, kSwatch + kPad + textWidth(line));
        }
        l.entriesY = block(rows * kRowH - (kRowH - kTextH));
    }
    l.width = contentW + 2 * kPad;
    l.height = y + kPad;
    return l;
}

/// The text scale (font pixels per font unit): 2 on images at least 600 pixels tall where the
/// legend fits the width at that size, else 1.
int legendScale(int imageWidth, int imageHeight, const Legend& legend) {
    if (imageHeight < 600) return 1;
    return layoutLegend(legend, 0).width + 2 * kMargin <= imageWidth / 2 ? 2 : 1;
}

/// The layout at scale k in an image `imageWidth` pixels wide: wrapped to fit beside the margins.
LegendLayout fittedLayout(const Legend& legend, int imageWidth, int k) {
    return layoutLegend(legend, std::max(imageWidth / k - 2 * kMargin, 1));
}

void drawBar(const Canvas& cv, const Legend& legend, const LegendLayout& l) {
    for (int i = 0; i < kBarW * cv.scale; ++i) { // one colour per output pixel column
        const float t = (float(i) + 0.5f) / float(kBarW * cv.scale);
        const int x = cv.ox + l.barX * cv.scale + i;
        cv.fillPixels(x, cv.oy + l.barY * cv.scale, x + 1, cv.oy + (l.barY + kBarH) * cv.scale, legend.bar(t));
    }
    const int tickY = l.barY + kBarH;
    const int barPx = kBarW * cv.scale;
    for (const auto& t : legend.ticks) {
        const float pos = std::clamp(t.position, 0.f, 1.f);
        // The tick covers the bar column(s) holding its position, so ends stay under the bar.
        const int tickX = cv.ox + l.barX * cv.scale + std::min(int(pos * float(barPx)), barPx - cv.scale);
        cv.fillPixels(tickX, cv.oy + tickY * cv.scale, tickX + cv.scale, cv.oy + (tickY + kTickH) * cv.scale,
                      kTextColour);
        const float centre = float(l.barX) + pos * float(kBarW);
        cv.text(std::round(centre - 0.5f * float(textWidth(t.label))), float(tickY + kTickH + 2), t.label, kTextColour);
    }
}

void drawEntries(const Canvas& cv, const Legend& legend, const LegendLayout& l) {
    int y = l.entriesY;
    for (size_t i = 0; i < legend.entries.size() && i < l.entries.size(); ++i) {
        // An outline keeps dark swatches (non-receivers) visible on the dark box.
        cv.fill(kPad, float(y), kSwatch, kSwatch, kOutlineColour);
        cv.fill(kPad + 1, float(y + 1), kSwatch - 2, kSwatch - 2, legend.entries[i].colour);
        for (const auto& line : l.entries[i]) {
            cv.text(kPad + kSwatch + kPad, float(y), line, kTextColour);
            y += kRowH;
        }
    }
}

std::string powerOfTwoLabel(int e) {
    if (std::abs(e) > 30) return "2^" + std::to_string(e);
    const std::string p = std::to_string(1L << std::abs(e));
    return e >= 0 ? p : "1/" + p;
}

/// Three significant digits, but whole numbers up to a million in full ("1000", not "1e+03").
std::string shortNumber(float x) {
    char buf[32];
    const double d = x;
    std::snprintf(buf, sizeof buf, std::abs(d) >= 100 && std::abs(d) < 1e6 ? "%.0f" : "%.3g", d);
    return buf;
}

// ---- [SECTION] PFM helpers ------------------------------------------------------------------

constexpr int kPfmMaxSide = 65536;
constexpr size_t kPfmMaxPixels = size_t(1) << 28;

[[noreturn]] void pfmError(const std::string& path, const std::string& why) {
    throw std::runtime_error("PFM " + path + ": " + why);
}

bool isPfmSpace(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// Reads one whitespace-delimited header token, skipping leading whitespace; consumes exactly one
/// whitespace character after it (the PFM header ends with a single one before the data).
std::string headerToken(std::istream& in, const std::string& path, const char* what) {
    int c = in.get();
    while (isPfmSpace(c)) c = in.get();
    std::string tok;
    while (c != EOF && !isPfmSpace(c)) {
        if (tok.size() >= 32) pfmError(path, std::string("malformed header: ") + what + " too long");
        tok.push_back(char(c));
        c = in.get();
    }
    if (tok.empty()) pfmError(path, std::string("malformed header: missing ") + what);
    if (c == EOF) pfmError(path, std::string("malformed header: file ends after ") + what);
    return tok;
}

int parseSide(const std::string& tok, const std::string& path, const char* what) {
    int v = 0;
    const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || end != tok.data() + tok.size())
        pfmError(path, std::string("malformed header: ") + what + " '" + tok + "' is not an integer");
    if (v < 1 || v > kPfmMaxSide)
        pfmError(path, std::string("absurd ") + what + " " + tok + " (allowed 1.." + std::to_string(kPfmMaxSide) + ")");
    return v;
}

uint32_t byteSwap(uint32_t x) { return (x >> 24) | ((x >> 8) & 0xff00u) | ((x << 8) & 0xff0000u) | (x << 24); }

/// Floats travel as raw bits so NaN payloads and infinities survive exactly.
void swapFloats(std::span<float> v) {
    for (float& f : v) f = std::bit_cast<float>(byteSwap(std::bit_cast<uint32_t>(f)));
}

} // namespace

// ---- [SECTION] Colour maps ------------------------------------------------------------------

glm::vec3 divergingLog2(float m, float range) {
    if (!std::isfinite(m) || !(m > 0.f) || !(range > 0.f) || !std::isfinite(range)) return kInvalidColour;
    return diverging(std::log2(m) / range);
}

glm::vec3 falseColourTruth(float s, bool occluded) {
    if (!std::isfinite(s)) return kInvalidColour;
    const bool lit = s >= 0.5f; // docs/design.md §4 threshold, as in geometry::truthStats
    if (!occluded && !lit) return kFalseShadowColour;
    if (occluded && lit) return kFalseLitColour;
    return glm::vec3(0.3f + 0.6f * std::clamp(s, 0.f, 1.f));
}

glm::vec3 splitColour(int i) {
    static constexpr std::array<glm::vec3, 8> kSplits{rgb(0x4e79a7), rgb(0xf28e2b), rgb(0xe15759), rgb(0x76b7b2),
                                                      rgb(0x59a14f), rgb(0xedc948), rgb(0xb07aa1), rgb(0xff9da7)};
    return kSplits[size_t(((i % 8) + 8) % 8)];
}

// ---- [SECTION] Heatmap images ---------------------------------------------------------------

Image aliasingHeatmap(std::span<const float> m, std::span<const uint8_t> receiver, int width, int height, float range) {
    requireImageInput(m.size(), width, height, "aliasingHeatmap");
    requireImageInput(receiver.size(), width, height, "aliasingHeatmap");
    if (!(range > 0.f) || !std::isfinite(range))
        throw std::invalid_argument("aliasingHeatmap: range must be positive and finite");
    Image img = blankImage(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            setPixel(img, x, y, receiver[i] ? divergingLog2(m[i], range) : kNonReceiverColour);
        }
    return img;
}

Image truthHeatmap(std::span<const float> s, std::span<const uint8_t> occluded, std::span<const uint8_t> receiver,
                   int w, int h) {
    requireImageInput(s.size(), w, h, "truthHeatmap");
    requireImageInput(occluded.size(), w, h, "truthHeatmap");
    requireImageInput(receiver.size(), w, h, "truthHeatmap");
    Image img = blankImage(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            setPixel(img, x, y, receiver[i] ? falseColourTruth(s[i], occluded[i] != 0) : kNonReceiverColour);
        }
    return img;
}

namespace {
bool invalidAt(std::span<const TruthClass> classes, std::span<const float> s, std::span<const uint8_t> receiver,
               size_t i) {
    return classes[i] == TruthClass::NotCounted && receiver[i] && !std::isfinite(s[i]);
}
glm::vec3 classColour(TruthClass c, float s) {
    switch (c) {
    case TruthClass::InteriorFalseShadow: return kFalseShadowColour;
    case TruthClass::InteriorFalseLit: return kFalseLitColour;
    case TruthClass::EdgeError: return kEdgeErrorColour;
    case TruthClass::Ambiguous:
    case TruthClass::Singular: return kAmbiguousColour;
    case TruthClass::Agrees: return glm::vec3(0.3f + 0.6f * std::clamp(s, 0.f, 1.f));
    case TruthClass::NotCounted: break;
    }
    return kNonReceiverColour;
}
} // namespace

Image truthClassHeatmap(std::span<const TruthClass> classes, std::span<const float> s,
                        std::span<const uint8_t> receiver, int w, int h) {
    requireImageInput(classes.size(), w, h, "truthClassHeatmap");
    requireImageInput(s.size(), w, h, "truthClassHeatmap");
    requireImageInput(receiver.size(), w, h, "truthClassHeatmap");
    Image img = blankImage(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            setPixel(img, x, y, invalidAt(classes, s, receiver, i) ? kInvalidColour : classColour(classes[i], s[i]));
        }
    return img;
}

// ---- [SECTION] Legends ----------------------------------------------------------------------

Legend aliasingLegend(float range) {
    if (!(range > 0.f) || !std::isfinite(range)) range = 4;
    Legend l;
    l.title = "m (pixels per texel)";
    l.bar = [](float t) { return diverging(2.f * t - 1.f); }; // = divergingLog2(2^((2t−1)·range))
    // Ticks at powers of two, at most five of them: every 2nd power for range 4, every 4th for 8.
    const int whole = int(std::min(std::floor(range), 60.f)); // 2^±60 is already absurd for m
    const int step = std::max(1, (whole + 1) / 2);
    for (int e = -(whole / step) * step; e <= whole; e += step)
        l.ticks.push_back({0.5f + 0.5f * float(e) / range, powerOfTwoLabel(e)});
    l.entries = {{kNonReceiverColour, "not a receiver"}, {kInvalidColour, "invalid (NaN/Inf)"}};
    return l;
}

Legend truthLegend() {
    Legend l;
    l.title = "shadow vs ground truth";
    l.entries = {{kFalseShadowColour, "false shadow"},
                 {kFalseLitColour, "false lit"},
                 {falseColourTruth(1.f, false), "agrees, lit"},
                 {falseColourTruth(0.f, true), "agrees, shadowed"},
                 {kNonReceiverColour, "not a receiver"}};
    return l;
}

Legend truthClassLegend(std::span<const TruthClass> classes, std::span<const float> s,
                        std::span<const uint8_t> receiver) {
    if (classes.size() != s.size() || classes.size() != receiver.size())
        throw std::invalid_argument("truthClassLegend: per-pixel inputs differ in size");
    std::array<bool, size_t(TruthClass::Singular) + 1> shown{};
    bool invalid = false, agreesLit = false, agreesShadowed = false;
    for (size_t i = 0; i < classes.size(); ++i) {
        if (invalidAt(classes, s, receiver, i)) {
            invalid = true;
            continue;
        }
        shown[int(classes[i])] = true;
        if (classes[i] == TruthClass::Agrees) (s[i] >= 0.5f ? agreesLit : agreesShadowed) = true;
    }
    Legend l;
    l.title = "shadow vs ground truth";
    const auto add = [&](bool on, glm::vec3 colour, const char* label) {
        if (on) l.entries.push_back({colour, label});
    };
    add(shown[int(TruthClass::InteriorFalseShadow)], kFalseShadowColour, "false shadow (interior)");
    add(shown[int(TruthClass::InteriorFalseLit)], kFalseLitColour, "false lit (interior)");
    add(shown[int(TruthClass::EdgeError)], kEdgeErrorColour, "edge misplaced (within 1 px)");
    add(shown[int(TruthClass::Ambiguous)] || shown[int(TruthClass::Singular)], kAmbiguousColour,
        "undecidable (terminator, normals, contact, singular J)");
    add(agreesLit, classColour(TruthClass::Agrees, 1.f), "agrees, lit (grey = s)");
    add(agreesShadowed, classColour(TruthClass::Agrees, 0.f), "agrees, shadowed");
    add(shown[int(TruthClass::NotCounted)], kNonReceiverColour, "not a receiver");
    add(invalid, kInvalidColour, "invalid (NaN/Inf)");
    return l;
}

Legend splitLegend(std::span<const glm::vec2> depthRanges) {
    Legend l;
    l.title = "splits";
    for (size_t i = 0; i < depthRanges.size(); ++i)
        l.entries.push_back({splitColour(int(i)), "split " + std::to_string(i) + " [" + shortNumber(depthRanges[i].x) +
                                                      ", " + shortNumber(depthRanges[i].y) + "]"});
    return l;
}

Legend levelLegend(std::span<const glm::dvec2> levels) {
    Legend l;
    l.title = "virtual map levels";
    for (const glm::dvec2& k : levels)
        l.entries.push_back(
            {splitColour(int(k.x)), "level " + std::to_string(int(k.x)) + " (texel " + shortNumber(float(k.y)) + ")"});
    return l;
}

PixelRect legendRect(int width, int height, const Legend& legend) {
    const int k = legendScale(width, height, legend);
    const LegendLayout l = fittedLayout(legend, width, k);
    return {kMargin * k, height - kMargin * k - l.height * k, l.width * k, l.height * k};
}

void drawLegend(Image& img, const Legend& legend) {
    const PixelRect r = legendRect(img.width, img.height, legend);
    const int k = legendScale(img.width, img.height, legend);
    const LegendLayout l = fittedLayout(legend, img.width, k);
    // Translucent box: the heatmap stays faintly visible behind the legend.
    for (int y = std::max(r.y, 0); y < std::min(r.y + r.height, img.height); ++y)
        for (int x = std::max(r.x, 0); x < std::min(r.x + r.width, img.width); ++x) {
            uint8_t* p = &img.rgba[4 * (size_t(y) * size_t(img.width) + size_t(x))];
            for (int c = 0; c < 3; ++c) p[c] = toByte(glm::mix(float(p[c]) / 255.f, kBoxColour[c], kBoxAlpha));
            p[3] = 255;
        }
    const Canvas cv{img, k, r.x, r.y};
    for (size_t i = 0; i < l.title.size(); ++i) cv.text(kPad, float(kPad + int(i) * kRowH), l.title[i], kTextColour);
    if (legend.bar) drawBar(cv, legend, l);
    drawEntries(cv, legend, l);
}

bool Legend::empty() const noexcept { return title.empty() && !bar && entries.empty(); }

Image withLegend(Image img, const Legend& legend) {
    if (!legend.empty()) drawLegend(img, legend);
    return img;
}

// ---- [SECTION] PFM files --------------------------------------------------------------------

void writePfm(const std::string& path, std::span<const float> values, int width, int height) {
    requireImageInput(values.size(), width, height, "writePfm");
    std::ofstream out(path, std::ios::binary);
    if (!out) pfmError(path, "cannot open for writing");
    out << "Pf\n" << width << ' ' << height << "\n-1.0\n"; // negative scale: little-endian
    std::vector<float> row(static_cast<size_t>(width));
    for (int y = height - 1; y >= 0; --y) { // PFM stores the bottom row first
        std::memcpy(row.data(), &values[size_t(y) * size_t(width)], row.size() * sizeof(float));
        if constexpr (std::endian::native == std::endian::big) swapFloats(row);
        out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    out.close();
    if (!out) pfmError(path, "write failed");
}

std::vector<float> readPfm(const std::string& path, int& w, int& h) {
    std::ifstream in(path, std::ios::binary);
    if (!in) pfmError(path, "cannot open");
    char magic[2] = {};
    in.read(magic, 2);
    if (in.gcount() != 2 || magic[0] != 'P' || (magic[1] != 'f' && magic[1] != 'F'))
        pfmError(path, "not a PFM file (bad magic)");
    if (magic[1] == 'F') pfmError(path, "colour PFM (PF) is not supported, only greyscale (Pf)");
    if (!isPfmSpace(in.peek())) pfmError(path, "malformed header: no whitespace after magic");
    const int width = parseSide(headerToken(in, path, "width"), path, "width");
    const int height = parseSide(headerToken(in, path, "height"), path, "height");
    const size_t pixels = size_t(width) * size_t(height);
    if (pixels > kPfmMaxPixels) pfmError(path, "absurd size " + std::to_string(width) + "x" + std::to_string(height));
    const std::string scaleTok = headerToken(in, path, "scale");
    double scale = 0;
    const auto [end, ec] = std::from_chars(scaleTok.data(), scaleTok.data() + scaleTok.size(), scale);
    if (ec != std::errc() || end != scaleTok.data() + scaleTok.size() || !std::isfinite(scale) || scale == 0)
        pfmError(path, "malformed header: scale '" + scaleTok + "' is not a non-zero number");

    // Check the length before allocating: a short file may claim a gigabyte.
    const auto dataStart = in.tellg();
    in.seekg(0, std::ios::end);
    const auto available = size_t(in.tellg() - dataStart);
    in.seekg(dataStart);
    if (available < pixels * sizeof(float))
        pfmError(path, "file too short: " + std::to_string(available) + " of " +
                           std::to_string(pixels * sizeof(float)) + " data bytes");
    std::vector<float> data(pixels);
    in.read(reinterpret_cast<char*>(data.data()), std::streamsize(pixels * sizeof(float)));
    if (size_t(in.gcount()) != pixels * sizeof(float))
        pfmError(path, "read failed after " + std::to_string(in.gcount()) + " data bytes");
    const bool fileLittle = scale < 0;
    if (fileLittle != (std::endian::native == std::endian::little)) swapFloats(data);

    std::vector<float> out(pixels); // flip to top row first
    for (int y = 0; y < height; ++y)
        std::memcpy(&out[size_t(y) * size_t(width)], &data[size_t(height - 1 - y) * size_t(width)],
                    size_t(width) * sizeof(float));
    w = width;
    h = height;
    return out;
}

} // namespace geometry::analysis
