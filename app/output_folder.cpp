#include "app/output_folder.h"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace app {

void createOutputFolder(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create output folder " + dir.string() + ": " + ec.message());
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
    if (const std::filesystem::path parent = path.parent_path(); !parent.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

} // namespace app
