#pragma once
// How a view panel's header row (title, an optional widget, the zoom buttons and the zoom text)
// fits the panel's width (issue 32: at 1280×720 the light view's "1:1" and the heatmap's zoom
// text were cut at the panel's edge). Pure arithmetic on text extents measured by the caller.
namespace ui {

/// The header's pieces, in pixels at the current font; `spacing` goes between two pieces.
struct HeaderItems {
    float title = 0, shortTitle = 0;          // the title, and the shorter one it falls back to
    float widgetPreferred = 0, widgetMin = 0; // the split slider or heatmap combo; 0: none
    float zoomButtons = 0, zoomText = 0;      // "Fit" and "1:1" together; the "100%" text after them
    float spacing = 0;
};

/// What the row draws: the short title or not, the widget's width, the zoom text or not.
struct HeaderFit {
    bool shortTitle = false;
    float widget = 0;
    bool zoomText = true;
    bool fits = true; // false: even the most compact row is wider than the panel
};

/// Fits the row into `avail` pixels: the widget shrinks towards its minimum first, then the zoom
/// text goes, then the title shortens; the buttons always stay.
[[nodiscard]] constexpr HeaderFit fitHeader(const HeaderItems& h, float avail) noexcept {
    const bool hasWidget = h.widgetPreferred > 0.f;
    const auto attempt = [&](bool shortTitle, bool zoomText) {
        HeaderFit f{shortTitle, 0.f, zoomText, false};
        const float fixed = (shortTitle ? h.shortTitle : h.title) + h.spacing + h.zoomButtons +
                            (zoomText ? h.spacing + h.zoomText : 0.f) + (hasWidget ? h.spacing : 0.f);
        const float room = avail - fixed;
        // NaN-safe: an unknown width gives the widget its minimum and does not fit.
        f.widget = !hasWidget                 ? 0.f
                   : room > h.widgetPreferred ? h.widgetPreferred
                   : room > h.widgetMin       ? room
                                              : h.widgetMin;
        f.fits = room >= f.widget;
        return f;
    };
    // Most to least complete: all of it; without the zoom text; with the short title too.
    if (const HeaderFit f = attempt(false, true); f.fits) return f;
    if (const HeaderFit f = attempt(false, false); f.fits) return f;
    return attempt(true, false);
}

} // namespace ui
