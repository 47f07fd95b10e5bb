#pragma once
// What every mesh reader (OBJ, STL, OFF, PLY, glTF) may plan for: 32-bit indices bound the counts, and
// the memory a load will need, estimated from the counts a header claims (or a text file has reached),
// must fit in what the machine has left. Checked before allocating, so a file's header can never make a
// reader ask for more (docs/design.md §5 "How large a mesh file may be").
#include <cstdint>
#include <string>

namespace geometry::io::detail {

/// Indices are 32-bit: no mesh may hold more vertices or triangles.
inline constexpr std::uint64_t kMaxIndexed = 0xffffffffu;

/// Peak bytes a load costs per vertex and per triangle (the reader's arrays, cleanup's working copies,
/// the scene's resident mesh): measured 143–167 B per triangle of a platform or an STL whose vertices
/// number about half its triangles (docs/design.md §5), so 40 + 120 with v ≈ t/2.
inline constexpr std::uint64_t kLoadBytesPerVertex = 40;
inline constexpr std::uint64_t kLoadBytesPerTriangle = 120;

/// kLoadBytesPerVertex · vertices + kLoadBytesPerTriangle · triangles, saturating (never wraps).
[[nodiscard]] std::uint64_t loadBytesEstimate(std::uint64_t vertices, std::uint64_t triangles) noexcept;

/// Bytes this process can still allocate: the kernel's MemAvailable, lowered to the address-space and
/// data-segment limits (ulimit -v, -d) where those are set. SHADOWSCOPE_MEMORY_BYTES, when set to a
/// number, replaces it (to try a small machine's limit on a large one).
[[nodiscard]] std::uint64_t availableMemory() noexcept;

/// Empty when a mesh of `vertices` and `triangles` fits: counts within kMaxIndexed and its estimate
/// within `available`; else one line naming the counts, the estimate and what is available.
[[nodiscard]] std::string meshMemoryProblem(std::uint64_t vertices, std::uint64_t triangles, std::uint64_t available);

} // namespace geometry::io::detail
