#include "file_list.h"

#include "geometry/io/model_loader.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace ui {

namespace fs = std::filesystem;

bool isSceneOrModelFile(std::string_view path) noexcept {
    if (geometry::io::isModelFile(path)) return true;
    const size_t dot = path.rfind('.');
    if (dot == std::string_view::npos) return false;
    const std::string_view ext = path.substr(dot);
    return ext.size() == 5 && std::tolower(static_cast<unsigned char>(ext[1])) == 'j' &&
           std::tolower(static_cast<unsigned char>(ext[2])) == 's' &&
           std::tolower(static_cast<unsigned char>(ext[3])) == 'o' &&
           std::tolower(static_cast<unsigned char>(ext[4])) == 'n';
}

namespace {

/// Case-insensitive name order, ties broken case-sensitively (a stable order).
bool lessNoCase(const std::string& a, const std::string& b) {
    const auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    const std::string la = lower(a), lb = lower(b);
    return la != lb ? la < lb : a < b;
}

} // namespace

std::vector<FileEntry> listFolder(const fs::path& folder, std::string* error) {
    std::vector<FileEntry> folders, files;
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        if (error) *error = folder.string() + ": " + ec.message();
        return {};
    }
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) folders.push_back({name, true});
        else if (isSceneOrModelFile(name)) files.push_back({name, false});
    }
    if (ec && error) *error = folder.string() + ": " + ec.message();
    const auto byName = [](const FileEntry& a, const FileEntry& b) { return lessNoCase(a.name, b.name); };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    folders.insert(folders.end(), files.begin(), files.end());
    return folders;
}

std::vector<std::string> withRecentFile(std::vector<std::string> recent, const std::string& path) {
    recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
    recent.insert(recent.begin(), path);
    if (recent.size() > kMaxRecentFiles) recent.resize(kMaxRecentFiles);
    return recent;
}

fs::path createNumberedFolder(const fs::path& parent) {
    fs::create_directories(parent);
    long highest = 0;
    for (const auto& entry : fs::directory_iterator(parent)) {
        const std::string name = entry.path().filename().string();
        if (name.size() < 3 || name.size() > 9 || !std::all_of(name.begin(), name.end(), [](char c) {
                return std::isdigit(static_cast<unsigned char>(c)) != 0;
            }))
            continue;
        highest = std::max(highest, std::stol(name));
    }
    // create_directory is false when the folder exists (another process took the number): the next.
    for (long n = highest + 1;; ++n) {
        std::string name = std::to_string(n);
        if (name.size() < 3) name.insert(0, 3 - name.size(), '0');
        const fs::path folder = parent / name;
        if (fs::create_directory(folder)) return folder;
    }
}

} // namespace ui
