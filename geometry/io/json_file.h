#pragma once
// Reading a small JSON file (scene file, preset) from untrusted input: size and nesting bounded
// while reading and parsing, every problem a one-line std::runtime_error "LABEL: problem".
#include <nlohmann/json.hpp>

#include <string>

namespace geometry::io {

/// `label` starts every message (e.g. the path, or "preset PATH").
[[nodiscard]] nlohmann::json readJsonFile(const std::string& path, const std::string& label, std::size_t maxBytes,
                                          int maxDepth);

/// A value for an error message: its type, plus the value itself for scalars (shortened to 40
/// characters): "string \"abc\"", "number 1e+30", "object".
[[nodiscard]] std::string describeJsonValue(const nlohmann::json& v);

} // namespace geometry::io
