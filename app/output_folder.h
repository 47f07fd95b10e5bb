#pragma once
// The folder a command writes its files into (render, sweep, curves, bench, tune, check).
#include <filesystem>

namespace app {

/// Creates `dir` and its parents when missing; throws std::runtime_error "cannot create output
/// folder DIR: REASON" (one line, the commands' error) when it cannot.
void createOutputFolder(const std::filesystem::path& dir);

} // namespace app
