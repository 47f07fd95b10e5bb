#pragma once
// Preconditions, checked where a caller's mistake would otherwise be clamped or wrapped into
// something else downstream (as Filament's ASSERT_PRECONDITION). In the checked build
// (SHADOWSCOPE_CHECKED: the clang ASan/UBSan build of scripts/build-checked, which runs the whole
// test suite) a broken one prints the condition, the file and the line, and aborts; in release
// builds the condition is compiled but not evaluated. Only for what a correct caller guarantees —
// user input is validated with a message instead (geometry/shadow/settings.h).
#include <cstdio>
#include <cstdlib>

namespace geometry {

[[noreturn]] inline void preconditionFailed(const char* condition, const char* file, int line) noexcept {
    std::fprintf(stderr, "shadowscope: precondition failed: %s (%s:%d)\n", condition, file, line);
    std::abort();
}

} // namespace geometry

#if defined(SHADOWSCOPE_CHECKED)
#define SHADOWSCOPE_EXPECTS(condition)                                                                                 \
    ((condition) ? void(0) : ::geometry::preconditionFailed(#condition, __FILE__, __LINE__))
#else
#define SHADOWSCOPE_EXPECTS(condition) void(sizeof(bool(condition)))
#endif
