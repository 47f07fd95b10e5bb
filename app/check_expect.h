#pragma once
// What `shadowscope check` asks of a case's metrics.json, as pure functions (no GL, no files), so
// the rules are unit-tested on hand-made JSON: key paths into metrics.json, the bounds an
// expectation sets, and the one-line verdicts the command prints and reports.
//
// Comparisons are written so that NaN fails them (docs/design.md §5): a NaN figure, or a ratio to
// a NaN or zero reference, fails every bound.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace app {

/// One step of a key path: a member name, or (index set) an element of an array.
struct KeyStep {
    std::string key;
    std::optional<size_t> index;
    [[nodiscard]] bool operator==(const KeyStep&) const = default;
};
using KeyPath = std::vector<KeyStep>;

/// Parses a dotted key path of metrics.json: names separated by '.', each followed by any number of
/// "[N]" array indices or ["NAME"] members (for names with dots, e.g. meshes["deck.stl"].truth):
/// "aliasing.p95", "splits[0].truth.false_lit", "size[1]". Throws std::invalid_argument with the
/// reason (empty name, unclosed bracket, index not a number, ...).
[[nodiscard]] KeyPath parseKeyPath(std::string_view text);

/// The value at `path` in `j`, or nullptr; then `missing` (when given) says which step is absent
/// and what its parent holds instead, in one line: "no 'p96' in aliasing (it has: max, mean, ...)".
[[nodiscard]] const nlohmann::json* findKey(const nlohmann::json& j, const KeyPath& path,
                                            std::string* missing = nullptr);

/// A metrics.json value as a number: JSON numbers; null as NaN (nlohmann writes a NaN figure as
/// null); the strings "inf", "-inf" and "nan" (metrics.json's n' of an unwarped split). nullopt
/// for anything else (objects, arrays, booleans, other strings).
[[nodiscard]] std::optional<double> numericValue(const nlohmann::json& v);

/// True when metrics.json has the figure at `path` only with ground truth: truth.*, meshes.*,
/// splits[i].truth.*.
[[nodiscard]] bool needsTruth(const KeyPath& path);

/// What an expectation bounds. Without a ratio case, min and max bound the value itself; with
/// min_ratio_to (max_ratio_to), min (max) bounds the value divided by the same key's value in that
/// case, measured in the same run.
struct Bound {
    std::optional<double> min, max;
    std::string minRatioTo, maxRatioTo; // case names; empty: the bound is on the value
};

struct Expectation {
    std::string key; // as written in the check file, e.g. "aliasing.p95"
    KeyPath path;
    Bound bound;
};

/// One rule checked, and how it went.
struct Verdict {
    std::string what; // the key path, or "golden"
    bool passed = false;
    std::string text; // e.g. "aliasing.p95 = 7.31 > max 6"
};

/// The verdicts of one expectation, min first: `value` is the case's figure, `reference(name)` the
/// same figure of case `name` (NaN when unknown). Ratio texts read
/// "timing_ms.frame / deck-ssm = 1.45 > max 1.3 (12.1 / 8.34)".
[[nodiscard]] std::vector<Verdict> evaluate(const Expectation& e, double value,
                                            const std::function<double(const std::string&)>& reference);

/// `v` as a verdict prints it: 6 significant digits ("7.31", "0.002", "1.2e+06"), "nan", "inf".
[[nodiscard]] std::string formatFigure(double v);

} // namespace app
