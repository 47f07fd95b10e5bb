#pragma once
// The ImGui context shadowscope draws with: style, the embedded DejaVu Sans font rasterized at the
// UI scale (so text stays crisp on high-DPI monitors rather than being scaled up), and the
// OpenGL3 backend on the current GL context. The window and the headless dashboard share it, so
// both produce the same pixels.
struct ImGuiContext;

namespace ui {

class ImGuiScope {
public:
    /// Needs a current GL context.
    explicit ImGuiScope(float uiScale);
    ~ImGuiScope();
    ImGuiScope(const ImGuiScope&) = delete;
    ImGuiScope& operator=(const ImGuiScope&) = delete;
    /// Rebuilds fonts and style for a new scale (the monitor's content scale changed).
    void rescale(float uiScale);
    [[nodiscard]] float scale() const noexcept { return scale_; }
    /// Makes this scope's context ImGui's current one (several headless dashboards may coexist).
    void makeCurrent() const noexcept;

private:
    void applyStyleAndFonts();
    float scale_ = 1.f;
    ::ImGuiContext* context_ = nullptr;
};

/// The monitor content scale clamped to what the layout supports (1 … 4; non-finite → 1).
[[nodiscard]] float clampUiScale(float contentScale) noexcept;

} // namespace ui
