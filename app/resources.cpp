#include "app/resources.h"

#include <cstdlib>
#include <system_error>

namespace app {

namespace fs = std::filesystem;

fs::path resourceDirectory() {
    std::error_code ec;
    const auto usable = [&](const fs::path& p) { return !p.empty() && fs::is_directory(p / "presets", ec); };
    if (const char* env = std::getenv("SHADOWSCOPE_RESOURCES"); env && *env && usable(env)) return env;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
        for (const fs::path& candidate : {dir / "share" / "shadowscope" / "resources", dir / "resources"})
            if (usable(candidate)) return candidate;
        if (dir == dir.root_path()) break;
    }
    return {};
}

std::string findResource(const std::string& path) {
    std::error_code ec;
    if (path.empty() || fs::exists(path, ec)) return path;
    const fs::path p(path);
    if (p.is_relative() && !p.empty() && *p.begin() == "resources") {
        const fs::path root = resourceDirectory();
        if (!root.empty()) {
            const fs::path found = root / p.lexically_relative("resources");
            if (fs::exists(found, ec)) return found.string();
        }
    }
    return path;
}

} // namespace app
