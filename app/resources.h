#pragma once
// Where an installation's resources (scene files, presets) are, found relative to the executable
// so that an installed or bundled binary runs from any working directory.
#include <filesystem>
#include <string>

namespace app {

/// resources/ of this installation, the first that holds presets/: $SHADOWSCOPE_RESOURCES; then,
/// from the executable's folder upwards, share/shadowscope/resources (an install prefix) or
/// resources (a bundle, or the build tree inside the source tree); empty when none exists.
[[nodiscard]] std::filesystem::path resourceDirectory();

/// A path the user gave: itself when it exists (relative to the working directory); else, for
/// "resources/REST", REST inside resourceDirectory() when that exists; else unchanged (so that the
/// caller's error names what the user typed).
[[nodiscard]] std::string findResource(const std::string& path);

} // namespace app
