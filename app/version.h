#pragma once
// The version and the revision this binary was built from (`shadowscope --version`).
#include <string_view>

namespace app {

/// "0.1"; the project() version in CMakeLists.txt.
extern const std::string_view kVersion;
/// `git describe --always --dirty` of the source tree at build time, or "unknown" outside git.
extern const std::string_view kRevision;

} // namespace app
