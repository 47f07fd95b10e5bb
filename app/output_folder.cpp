#include "app/output_folder.h"

#include <stdexcept>
#include <system_error>

namespace app {

void createOutputFolder(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create output folder " + dir.string() + ": " + ec.message());
}

} // namespace app
