#pragma once
// The hard caps every mesh reader applies (OBJ, STL, OFF, PLY), far above any real CAD part, so a
// file's header or contents can never make a reader plan for more.
#include <cstdint>

namespace geometry::io::detail {

inline constexpr std::uint64_t kMaxVertices = 50'000'000;
inline constexpr std::uint64_t kMaxFaces = 50'000'000; // faces as written, and triangles after splitting

} // namespace geometry::io::detail
