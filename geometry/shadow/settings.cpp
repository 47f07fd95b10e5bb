#include "geometry/shadow/settings.h"

#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geometry::shadow {

namespace {

using Kind = SettingInfo::Kind;

std::string formatNumber(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

} // namespace

std::string SettingInfo::glslName() const {
    std::string name(key);
    for (char& c : name)
        if (c == '.') c = '_';
    return name;
}

std::string SettingInfo::format(const ShadowSettings& s) const {
    const double v = get(s);
    switch (kind) {
    case Kind::Choice: {
        const int i = static_cast<int>(v);
        return i >= 0 && i < int(choices.size()) ? std::string(choices[i]) : "?";
    }
    case Kind::Bool: return v != 0.0 ? "true" : "false";
    case Kind::Int: return std::to_string(static_cast<long long>(v));
    case Kind::Float: return formatNumber(v);
    }
    return "?";
}

std::string SettingInfo::rangeText() const {
    switch (kind) {
    case Kind::Choice: {
        std::string out;
        for (auto c : choices) out += (out.empty() ? "" : ", ") + std::string(c);
        return "one of " + out;
    }
    case Kind::Bool: return "true or false";
    default: return (odd ? "odd " : "") + formatNumber(min) + ".." + formatNumber(max);
    }
}

const SettingInfo* findSetting(std::string_view key) noexcept {
    for (const auto& info : settingsDeclaration())
        if (info.key == key) return &info;
    return nullptr;
}

static std::string knownKeys() {
    std::string out;
    for (const auto& info : settingsDeclaration()) out += (out.empty() ? "" : ", ") + std::string(info.key);
    return out;
}

void applySetting(ShadowSettings& s, std::string_view key, std::string_view value) {
    const SettingInfo* info = findSetting(key);
    if (!info) throw std::invalid_argument("unknown setting '" + std::string(key) + "' (known: " + knownKeys() + ")");
    const std::string text(value);
    const auto bad = [&] {
        return std::invalid_argument(std::string(key) + ": '" + text + "' is not valid (" + info->rangeText() + ")");
    };
    double v = 0;
    switch (info->kind) {
    case Kind::Choice: {
        size_t i = 0;
        while (i < info->choices.size() && info->choices[i] != value) ++i;
        if (i == info->choices.size()) throw bad();
        v = double(i);
        break;
    }
    case Kind::Bool:
        if (value == "true" || value == "1" || value == "on") v = 1;
        else if (value == "false" || value == "0" || value == "off") v = 0;
        else throw bad();
        break;
    case Kind::Int:
    case Kind::Float: {
        size_t used = 0;
        try {
            v = std::stod(text, &used);
        } catch (const std::exception&) {
            throw bad();
        }
        if (used != text.size() || !std::isfinite(v)) throw bad();
        if (info->kind == Kind::Int && v != std::floor(v)) throw bad();
        if (!(v >= info->min && v <= info->max)) throw bad();
        if (info->odd && std::fmod(v, 2.0) == 0.0) throw bad();
        break;
    }
    }
    info->set(s, v);
}

void applyAssignment(ShadowSettings& s, std::string_view kv) {
    const auto eq = kv.find('=');
    if (eq == std::string_view::npos)
        throw std::invalid_argument("--set expects key=value, got '" + std::string(kv) + "'");
    applySetting(s, kv.substr(0, eq), kv.substr(eq + 1));
}

std::vector<std::string> validate(const ShadowSettings& s) {
    std::vector<std::string> problems;
    for (const auto& info : settingsDeclaration()) {
        const double v = info.get(s);
        if (!(std::isfinite(v) && v >= info.min && v <= info.max) || (info.odd && std::fmod(v, 2.0) == 0.0))
            problems.push_back(std::string(info.key) + ": " + formatNumber(v) + " is outside " + info.rangeText());
    }
    // The virtual map's pages tile its levels: both sides powers of two, at least 4 × 4 pages a level.
    const auto& v = s.virtualMap;
    for (const auto& [key, value] : {std::pair{"virtual.size", v.size}, std::pair{"virtual.page_size", v.pageSize}})
        if (value > 0 && !std::has_single_bit(unsigned(value)))
            problems.push_back(std::string(key) + ": " + std::to_string(value) + " is not a power of two");
    if (v.pageSize > 0 && v.size > 0 && v.pageSize * 4 > v.size)
        problems.push_back("virtual.page_size: " + std::to_string(v.pageSize) +
                           " is more than a quarter of virtual.size (" + std::to_string(v.size) + ")");
    // The page table holds (size / page_size)² entries a level: 512² × 16 levels is 16 MiB.
    if (v.pageSize > 0 && v.size / v.pageSize > kMaxVirtualPagesPerSide)
        problems.push_back("virtual.size: " + std::to_string(v.size) + " / virtual.page_size " +
                           std::to_string(v.pageSize) + " is " + std::to_string(v.size / v.pageSize) +
                           " pages a side, more than " + std::to_string(kMaxVirtualPagesPerSide));
    return problems;
}

void validateOrThrow(const ShadowSettings& s) {
    const auto problems = validate(s);
    if (!problems.empty()) throw std::invalid_argument(problems.front());
}

void validateFrustum(double n, double f, double fovYDeg) {
    if (!(std::isfinite(n) && n > 0)) throw std::invalid_argument("near: " + formatNumber(n) + " must be > 0");
    if (!(std::isfinite(f) && f > n))
        throw std::invalid_argument("far: " + formatNumber(f) + " must be finite and > near (" + formatNumber(n) + ")");
    if (!(std::isfinite(fovYDeg) && fovYDeg > 0 && fovYDeg < 180))
        throw std::invalid_argument("fov-y: " + formatNumber(fovYDeg) + " must be within 0..180 (exclusive)");
}

} // namespace geometry::shadow
