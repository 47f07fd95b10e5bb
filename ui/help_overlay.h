#pragma once
// The help overlay (F1, or the "?" button): every gesture and key of the dashboard, drawn from the
// one table in gesture_table.h. ImGui only; it reads F1 through ImGui, so it works headless too.
namespace ui {

class HelpOverlay {
public:
    /// Toggles on F1 (a press seen this frame) and draws the overlay when open, centred in a
    /// width × height window. Call inside the dashboard's frame.
    void frame(float width, float height);
    void toggle() noexcept { open_ = !open_; }
    [[nodiscard]] bool open() const noexcept { return open_; }

private:
    bool open_ = false;
};

} // namespace ui
