#include "check_expect.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace app {

KeyPath parseKeyPath(std::string_view text) {
    KeyPath path;
    size_t i = 0;
    const auto fail = [&](const std::string& why) {
        throw std::invalid_argument("bad key path '" + std::string(text) + "': " + why);
    };
    if (text.empty()) fail("empty");
    while (i < text.size()) {
        // A name up to the next '.' or '['.
        const size_t start = i;
        while (i < text.size() && text[i] != '.' && text[i] != '[' && text[i] != ']' && text[i] != '"') ++i;
        if (i < text.size() && (text[i] == ']' || text[i] == '"'))
            fail(std::string("unexpected '") + text[i] + "' at character " + std::to_string(i + 1));
        if (i == start) fail("a name is missing at character " + std::to_string(i + 1));
        path.push_back({std::string(text.substr(start, i - start)), std::nullopt});
        // Then any number of [N] or ["NAME"].
        while (i < text.size() && text[i] == '[') {
            const size_t close = text.find(']', i);
            if (close == std::string_view::npos) fail("'[' at character " + std::to_string(i + 1) + " is not closed");
            const std::string_view inside = text.substr(i + 1, close - i - 1);
            if (inside.size() >= 2 && inside.front() == '"' && inside.back() == '"') {
                if (inside.size() == 2) fail("empty name in [\"\"]");
                path.push_back({std::string(inside.substr(1, inside.size() - 2)), std::nullopt});
            } else {
                if (inside.empty() || inside.size() > 9 || inside.find_first_not_of("0123456789") != inside.npos)
                    fail("expected [N] (an index) or [\"NAME\"], got [" + std::string(inside) + "]");
                path.push_back({"", size_t(std::stoul(std::string(inside)))});
            }
            i = close + 1;
        }
        if (i == text.size()) break;
        if (text[i] != '.') fail(std::string("unexpected '") + text[i] + "' at character " + std::to_string(i + 1));
        if (++i == text.size()) fail("ends with '.'");
    }
    return path;
}

namespace {

std::string stepText(const KeyStep& s) {
    if (s.index) return "[" + std::to_string(*s.index) + "]";
    return s.key.find('.') == std::string::npos ? s.key : "[\"" + s.key + "\"]";
}

std::string pathText(const KeyPath& path, size_t steps) {
    std::string out;
    for (size_t i = 0; i < steps && i < path.size(); ++i)
        out += (i > 0 && !path[i].index && path[i].key.find('.') == std::string::npos ? "." : "") + stepText(path[i]);
    return out.empty() ? "the top level" : out;
}

/// "max, mean, p50, ..." (at most 12 names), for a missing member's message.
std::string memberNames(const nlohmann::json& object) {
    std::string out;
    size_t n = 0;
    for (const auto& [name, value] : object.items()) {
        if (++n > 12) return out + ", ...";
        out += (out.empty() ? "" : ", ") + name;
    }
    return out.empty() ? "nothing" : out;
}

} // namespace

const nlohmann::json* findKey(const nlohmann::json& j, const KeyPath& path, std::string* missing) {
    const nlohmann::json* node = &j;
    for (size_t i = 0; i < path.size(); ++i) {
        const KeyStep& s = path[i];
        const std::string parent = pathText(path, i);
        if (s.index) {
            if (!node->is_array()) {
                if (missing) *missing = parent + " is " + node->type_name() + ", not an array";
                return nullptr;
            }
            if (*s.index >= node->size()) {
                if (missing)
                    *missing = "no element [" + std::to_string(*s.index) + "] in " + parent + " (it has " +
                               std::to_string(node->size()) + ")";
                return nullptr;
            }
            node = &(*node)[*s.index];
            continue;
        }
        if (!node->is_object()) {
            if (missing) *missing = parent + " is " + node->type_name() + ", not an object";
            return nullptr;
        }
        const auto it = node->find(s.key);
        if (it == node->end()) {
            if (missing) *missing = "no '" + s.key + "' in " + parent + " (it has: " + memberNames(*node) + ")";
            return nullptr;
        }
        node = &*it;
    }
    return node;
}

std::optional<double> numericValue(const nlohmann::json& v) {
    if (v.is_number()) return v.get<double>();
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (v.is_string()) {
        const std::string& s = v.get_ref<const std::string&>();
        if (s == "inf") return std::numeric_limits<double>::infinity();
        if (s == "-inf") return -std::numeric_limits<double>::infinity();
        if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    }
    return std::nullopt;
}

bool needsTruth(const KeyPath& path) {
    if (path.empty()) return false;
    if (path[0].key == "truth" || path[0].key == "meshes") return true;
    // splits[i].truth.*
    return path.size() >= 3 && path[0].key == "splits" && path[1].index && path[2].key == "truth";
}

namespace {

std::string withDigits(double v, int digits) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

/// The value and the bound as printed: 6 digits, more when they would print the same but differ,
/// so a failing "6.0000001 > max 6" never reads "6 > max 6".
std::pair<std::string, std::string> printed(double v, double bound) {
    for (int digits = 6;; ++digits) {
        std::string a = withDigits(v, digits), b = withDigits(bound, digits);
        if (a != b || v == bound || digits >= 17) return {std::move(a), std::move(b)};
    }
}

} // namespace

std::string formatFigure(double v) { return withDigits(v, 6); }

std::vector<Verdict> evaluate(const Expectation& e, double value,
                              const std::function<double(const std::string&)>& reference) {
    std::vector<Verdict> out;
    const auto check = [&](bool isMax, double bound, const std::string& ratioTo) {
        double figure = value;
        std::string subject = e.key;
        std::string detail;
        if (!ratioTo.empty()) {
            const double ref = reference(ratioTo);
            figure = value / ref; // 0/0 and x/NaN give NaN, which fails below; x/0 gives ±inf
            subject += " / " + ratioTo;
            detail = " (" + formatFigure(value) + " / " + formatFigure(ref) + ")";
        }
        // Written so that NaN fails: !(NaN <= b) and !(NaN >= b).
        const bool passed = isMax ? figure <= bound : figure >= bound;
        const auto [f, b] = printed(figure, bound);
        const char* op = std::isnan(figure) ? (isMax ? " is not <= " : " is not >= ")
                         : isMax            ? (passed ? " <= " : " > ")
                                            : (passed ? " >= " : " < ");
        out.push_back({e.key, passed, subject + " = " + f + op + (isMax ? "max " : "min ") + b + detail});
    };
    if (e.bound.min) check(false, *e.bound.min, e.bound.minRatioTo);
    if (e.bound.max) check(true, *e.bound.max, e.bound.maxRatioTo);
    return out;
}

} // namespace app
