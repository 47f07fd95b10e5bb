#pragma once
// The export dialog (the "Export…" button): one view — eye A or B, light, heatmap, or the whole
// dashboard — rendered offscreen at a chosen size (1920×1080, 3840×2160, twice the panel, or typed)
// and written as a PNG. The dialog only picks; Dashboard::renderExport draws, with the same
// passes as `shadowscope render` (docs/design.md §2.6 "Documentation screenshots").
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace ui {

enum class ExportView { EyeA, EyeB, Light, Heatmap, Dashboard, Count };

/// "eye_a", "eye_b", "light", "heatmap", "dashboard": the file's name and the widgets' ids.
[[nodiscard]] std::string_view exportViewName(ExportView v) noexcept;

/// The renderer's and the headless dashboard's limits on an exported image's sides.
inline constexpr int kExportMinSide = 16, kExportMaxSide = 8192;

/// Why `view` cannot be drawn at width × height ("" when it can): each side within 16 … 8192, the
/// dashboard within 200×150 … 8192×8192 (ui/dashboard_headless.h).
[[nodiscard]] std::string exportSizeProblem(ExportView view, int width, int height);

struct ExportRequest {
    ExportView view = ExportView::EyeA;
    int width = 1920, height = 1080;
};

class ExportDialog {
public:
    void open() noexcept { open_ = popupPending_ = true; }
    [[nodiscard]] bool isOpen() const noexcept { return open_; }
    /// Draws the dialog while open in a width × height window. `panels`: each view's panel size
    /// now (for "2× panel"); `comparing`: eye B can be chosen. The request once, when Export is
    /// pressed with a size the view can be drawn at (otherwise the dialog says why and stays).
    [[nodiscard]] std::optional<ExportRequest>
    frame(float width, float height, const std::array<std::array<int, 2>, size_t(ExportView::Count)>& panels,
          bool comparing);

private:
    bool open_ = false, popupPending_ = false;
    ExportRequest request_;
    int preset_ = 0; // 1920×1080, 3840×2160, 2× panel, custom
    int custom_[2] = {1920, 1080};
    std::string problem_;
};

} // namespace ui
