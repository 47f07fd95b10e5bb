#include "geometry/io/mesh_limits.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

namespace geometry::io::detail {

namespace {

constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b) noexcept {
    return b != 0 && a > kNoLimit / b ? kNoLimit : a * b;
}

/// MemAvailable in bytes, or kNoLimit where /proc/meminfo does not say.
std::uint64_t memAvailable() noexcept {
    try {
        std::ifstream in("/proc/meminfo");
        std::string key;
        std::uint64_t kib = 0;
        std::string unit;
        while (in >> key >> kib >> unit)
            if (key == "MemAvailable:") return saturatingMul(kib, 1024);
    } catch (...) {}
    return kNoLimit;
}

std::uint64_t rlimitBytes(int resource) noexcept {
    rlimit r{};
    if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return kNoLimit;
    return std::uint64_t(r.rlim_cur);
}

/// "3.2 GiB", "870 MiB", "235 KiB".
std::string bytesText(std::uint64_t bytes) {
    char buf[32];
    const double mib = double(bytes) / double(1 << 20);
    if (mib >= 1024.0) std::snprintf(buf, sizeof buf, "%.1f GiB", mib / 1024.0);
    else if (mib >= 1.0) std::snprintf(buf, sizeof buf, "%.0f MiB", mib);
    else std::snprintf(buf, sizeof buf, "%.0f KiB", double(bytes) / 1024.0);
    return buf;
}

} // namespace

std::uint64_t loadBytesEstimate(std::uint64_t vertices, std::uint64_t triangles) noexcept {
    const std::uint64_t v = saturatingMul(vertices, kLoadBytesPerVertex);
    const std::uint64_t t = saturatingMul(triangles, kLoadBytesPerTriangle);
    return v > kNoLimit - t ? kNoLimit : v + t;
}

std::uint64_t availableMemory() noexcept {
    if (const char* e = std::getenv("SHADOWSCOPE_MEMORY_BYTES")) {
        char* end = nullptr;
        const unsigned long long v = std::strtoull(e, &end, 10);
        if (end != e && *end == '\0') return v;
    }
    return std::min({memAvailable(), rlimitBytes(RLIMIT_AS), rlimitBytes(RLIMIT_DATA)});
}

std::string meshMemoryProblem(std::uint64_t vertices, std::uint64_t triangles, std::uint64_t available) {
    std::ostringstream os;
    if (vertices > kMaxIndexed || triangles > kMaxIndexed) {
        os << vertices << " vertices and " << triangles << " triangles: over the 2^32 - 1 that 32-bit indices reach";
        return os.str();
    }
    const std::uint64_t need = loadBytesEstimate(vertices, triangles);
    if (need <= available) return {};
    os << vertices << " vertices and " << triangles << " triangles need about " << bytesText(need) << " to load, but "
       << bytesText(available) << " is available";
    return os.str();
}

} // namespace geometry::io::detail
