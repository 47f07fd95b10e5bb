#pragma once
// The folder a command writes its files into (render, sweep, curves, bench, tune, check), and
// the text files it writes there.
#include <filesystem>
#include <string>

namespace app {

/// Creates `dir` and its parents when missing; throws std::runtime_error "cannot create output
/// folder DIR: REASON" (one line, the commands' error) when it cannot.
void createOutputFolder(const std::filesystem::path& dir);

/// Writes `text` to `path` (its folder created when missing); throws std::runtime_error "cannot
/// write PATH" when it cannot.
void writeTextFile(const std::filesystem::path& path, const std::string& text);

} // namespace app
