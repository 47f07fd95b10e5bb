#pragma once
// The file browser's and the screenshots' file-system part, without ImGui: a folder's listing
// filtered to what the scene loader opens, the recent-files list, and numbered output folders
// (screenshots/001, 002, …) that are never reused. Pure but for the file system; tested alone.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ui {

/// Files the loader opens: scene files (.json) and the model formats of geometry/io/model_loader.h.
[[nodiscard]] bool isSceneOrModelFile(std::string_view path) noexcept;

struct FileEntry {
    std::string name; // the entry's name in its folder
    bool folder = false;
};

/// A folder's sub-folders, then its scene and model files, each group in case-insensitive name
/// order; hidden entries (a leading '.') left out. An unreadable folder gives nothing and `error`
/// (when given) says why in one line.
[[nodiscard]] std::vector<FileEntry> listFolder(const std::filesystem::path& folder, std::string* error = nullptr);

inline constexpr size_t kMaxRecentFiles = 10;

/// `recent` with `path` moved (or added) to the front, newest first, at most kMaxRecentFiles.
[[nodiscard]] std::vector<std::string> withRecentFile(std::vector<std::string> recent, const std::string& path);

/// Creates the next numbered folder under `parent` (created too): one more than the highest
/// three-digit (or longer) number there, "001" first, so that no earlier folder is ever written
/// into again. Throws std::filesystem::filesystem_error when it cannot.
[[nodiscard]] std::filesystem::path createNumberedFolder(const std::filesystem::path& parent);

} // namespace ui
