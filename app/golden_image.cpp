#include "golden_image.h"

#include "check_expect.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace app {

using geometry::analysis::Image;

namespace {

/// The largest channel difference of pixel i.
int pixelDifference(const Image& a, const Image& b, size_t i) {
    int d = 0;
    for (size_t c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.rgba[4 * i + c]) - int(b.rgba[4 * i + c])));
    return d;
}

bool sameSize(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgba.size() == size_t(a.width) * size_t(a.height) * 4 &&
           b.rgba.size() == a.rgba.size();
}

} // namespace

ImageComparison compareImages(const Image& render, const Image& golden, int channelTolerance) {
    ImageComparison c;
    c.width = render.width;
    c.height = render.height;
    c.goldenWidth = golden.width;
    c.goldenHeight = golden.height;
    c.sameSize = sameSize(render, golden);
    if (!c.sameSize) return c;
    c.pixels = size_t(render.width) * size_t(render.height);
    for (size_t i = 0; i < c.pixels; ++i) {
        const int d = pixelDifference(render, golden, i);
        c.maxChannelDifference = std::max(c.maxChannelDifference, d);
        c.differing += d > channelTolerance;
    }
    return c;
}

Image diffImage(const Image& render, const Image& golden, int channelTolerance) {
    if (!sameSize(render, golden)) throw std::invalid_argument("diffImage: the images differ in size");
    Image out{render.width, render.height, std::vector<uint8_t>(render.rgba.size())};
    for (size_t i = 0; i < out.rgba.size() / 4; ++i) {
        uint8_t* p = &out.rgba[4 * i];
        if (pixelDifference(render, golden, i) > channelTolerance) {
            std::copy(std::begin(kDiffColour), std::end(kDiffColour), p);
            continue;
        }
        // Rec. 601 luma at a third of its brightness (at most 85): the differing pixels stand out,
        // the picture under them stays recognisable.
        const uint8_t* q = &render.rgba[4 * i];
        const int luma = (299 * q[0] + 587 * q[1] + 114 * q[2]) / 1000;
        p[0] = p[1] = p[2] = uint8_t(luma / 3);
        p[3] = 255;
    }
    return out;
}

std::string comparisonText(const std::string& golden, const ImageComparison& c, int channelTolerance,
                           double allowedFraction) {
    const std::string head = "golden " + golden + ": ";
    if (!c.sameSize)
        return head + "the render is " + std::to_string(c.width) + "x" + std::to_string(c.height) + ", the golden " +
               std::to_string(c.goldenWidth) + "x" + std::to_string(c.goldenHeight);
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.3g%%", 100.0 * c.fraction());
    return head + std::to_string(c.differing) + " of " + std::to_string(c.pixels) + " pixels (" + percent +
           ") differ by more than " + std::to_string(channelTolerance) + (c.passes(allowedFraction) ? " <= " : " > ") +
           "fraction " + formatFigure(allowedFraction);
}

} // namespace app
