#include "file_browser.h"

#include "modal_footer.h"
#include "widget_map.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <system_error>

namespace ui {

namespace fs = std::filesystem;

namespace {
constexpr const char* kTitle = "Open a scene or model";
}

void FileBrowser::open(const fs::path& start) {
    std::error_code ec;
    fs::path folder = start;
    if (!folder.empty() && !fs::is_directory(folder, ec)) folder = folder.parent_path();
    if (folder.empty() || !fs::is_directory(folder, ec)) folder = fs::current_path(ec);
    enter(folder);
    open_ = popupPending_ = true;
}

void FileBrowser::enter(const fs::path& folder) {
    std::error_code ec;
    fs::path absolute = fs::absolute(folder, ec).lexically_normal();
    if (ec) absolute = folder;
    // "a/b/" normalises to "a/b/": drop the empty last part, so that the parent is "a".
    if (!absolute.has_filename() && absolute.has_parent_path() && absolute != absolute.root_path())
        absolute = absolute.parent_path();
    error_.clear();
    std::vector<FileEntry> entries = listFolder(absolute, &error_);
    if (!error_.empty() && entries.empty() && !folder_.empty()) return; // keep showing the folder we had
    folder_ = absolute;
    entries_ = std::move(entries);
    path_ = folder_.string();
    selected_ = -1;
}

std::optional<std::string> FileBrowser::take(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::path(path).is_absolute() ? fs::path(path) : folder_ / path;
    if (fs::is_directory(p, ec)) {
        enter(p);
        return std::nullopt;
    }
    if (!fs::is_regular_file(p, ec)) {
        error_ = p.string() + ": no such file";
        return std::nullopt;
    }
    if (!isSceneOrModelFile(p.string())) {
        error_ = p.filename().string() + ": not a scene (.json) or model file";
        return std::nullopt;
    }
    open_ = false;
    return p.lexically_normal().string();
}

std::optional<std::string> FileBrowser::frame(float width, float height, const std::vector<std::string>& recent) {
    if (!open_) return std::nullopt;
    if (popupPending_) {
        ImGui::OpenPopup(kTitle);
        popupPending_ = false;
    }
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(width * 0.5f, height * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::max(1.f, std::min(width - 2.f * em, 56.f * em)),
                                    std::max(1.f, std::min(height - 2.f * em, 36.f * em))),
                             ImGuiCond_Always);
    std::optional<std::string> chosen;
    bool keepOpen = true;
    if (!ImGui::BeginPopupModal(kTitle, &keepOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove)) {
        open_ = false; // closed by its own button
        return std::nullopt;
    }
    if (ImGui::Button("Up")) enter(folder_.parent_path());
    widgetMapRecord("browser.up");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The parent folder");
    ImGui::SameLine();
    // The whole width for the path: a path must fit (issue 32's "file field too narrow").
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::InputText("##path", &path_, ImGuiInputTextFlags_EnterReturnsTrue)) chosen = take(path_);
    widgetMapRecord("browser.path");
    if (!recent.empty()) {
        ImGui::SetNextItemWidth(-FLT_MIN);
        if (ImGui::BeginCombo("##recent", "Recent files")) {
            for (const std::string& r : recent) {
                if (ImGui::Selectable(r.c_str())) chosen = take(r);
                widgetMapRecord("browser.recent=" + r);
            }
            ImGui::EndCombo();
        }
        widgetMapRecord("browser.recent");
    }
    const float footer = ImGui::GetFrameHeightWithSpacing() * (error_.empty() ? 1.f : 2.f);
    if (ImGui::BeginChild("entries", ImVec2(0, -footer), true)) {
        for (int i = 0; i < int(entries_.size()); ++i) {
            const FileEntry& e = entries_[size_t(i)];
            const std::string label = e.folder ? e.name + "/" : e.name;
            if (ImGui::Selectable(label.c_str(), i == selected_, ImGuiSelectableFlags_AllowDoubleClick)) {
                selected_ = i;
                path_ = (folder_ / e.name).string();
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
                    chosen = take(path_); // a folder is entered, a file chosen
                    break;                // entries_ may have changed
                }
            }
            widgetMapRecord("browser.entry=" + e.name);
        }
        if (entries_.empty() && error_.empty()) ImGui::TextDisabled("(no folders, scene or model files here)");
    }
    ImGui::EndChild();
    if (!error_.empty()) ImGui::TextColored(ImVec4(1.f, 0.5f, 0.4f, 1.f), "%s", error_.c_str());
    if (ImGui::Button("Open")) chosen = take(path_);
    widgetMapRecord("browser.open");
    ImGui::SameLine();
    ImGui::TextDisabled("scene files (.json) and models (.obj .stl .off .ply .gltf .glb)");
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("Cancel").x -
                    2.f * ImGui::GetStyle().FramePadding.x);
    endModal(open_, keepOpen, "browser");
    return chosen;
}

} // namespace ui
