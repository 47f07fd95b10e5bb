#pragma once
// The in-tree file browser ("Browse…" beside the scene file field): an ImGui modal with the path
// field, the parent folder, the recent files and the folder's sub-folders and scene/model files
// (file_list.h does the listing, filtering and sorting). Choosing a file hands back its path; the
// dashboard loads it.
#include "file_list.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ui {

class FileBrowser {
public:
    /// Opens at `start`: a folder, a file's folder, or (empty or missing) the current folder.
    void open(const std::filesystem::path& start);
    [[nodiscard]] bool isOpen() const noexcept { return open_; }
    /// Draws the browser while open, in a width × height window; the chosen file's path once, the
    /// frame it is chosen (double-click, Open, or Return in the path field).
    [[nodiscard]] std::optional<std::string> frame(float width, float height, const std::vector<std::string>& recent);
    /// The folder shown and its entries (tests).
    [[nodiscard]] const std::filesystem::path& folder() const noexcept { return folder_; }
    [[nodiscard]] const std::vector<FileEntry>& entries() const noexcept { return entries_; }

private:
    void enter(const std::filesystem::path& folder);
    /// A typed or chosen path: a folder is entered, a file chosen; anything else is an error line.
    std::optional<std::string> take(const std::string& path);

    bool open_ = false, popupPending_ = false;
    std::filesystem::path folder_;
    std::vector<FileEntry> entries_;
    std::string path_;  // the path field
    std::string error_; // the folder could not be read, or the typed path does not exist
    int selected_ = -1;
};

} // namespace ui
