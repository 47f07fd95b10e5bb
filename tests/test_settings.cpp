#include "geometry/shadow/setting_relevance.h"
#include "geometry/shadow/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace geometry::shadow;

namespace {
std::string errorOf(const std::string& kv) {
    ShadowSettings s;
    try {
        applyAssignment(s, kv);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(Settings, EveryDeclaredKeyRoundTripsThroughText) {
    ShadowSettings s;
    EXPECT_TRUE(validate(s).empty());
    for (const auto& info : settingsDeclaration()) {
        ShadowSettings t;
        applySetting(t, info.key, info.format(s));
        EXPECT_EQ(info.get(t), info.get(s)) << info.key;
        EXPECT_FALSE(info.help.empty()) << info.key;
    }
}

// Every setter reaches its field: a value other than the default, set through the declaration's
// text, reads back through its getter and changes the settings (a no-op setter fails here).
TEST(Settings, EveryDeclaredSetterChangesItsField) {
    const ShadowSettings defaults;
    for (const auto& info : settingsDeclaration()) {
        const double was = info.get(defaults);
        double other = was;
        switch (info.kind) {
        case SettingInfo::Kind::Bool: other = was != 0 ? 0 : 1; break;
        case SettingInfo::Kind::Choice: other = double((int(was) + 1) % int(info.choices.size())); break;
        case SettingInfo::Kind::Int: other = was != info.max ? info.max : info.min; break;
        case SettingInfo::Kind::Float: other = was != info.max ? info.max : info.min; break;
        }
        ASSERT_NE(other, was) << info.key << ": no other value in its range";
        ShadowSettings t;
        info.set(t, other);
        const std::string text = info.format(t);
        ShadowSettings u;
        applySetting(u, info.key, text);
        EXPECT_EQ(info.get(u), info.get(t)) << info.key << " = " << text;
        EXPECT_NEAR(info.get(u), other, 1e-6 * std::max(1.0, std::abs(other))) << info.key; // float fields
        EXPECT_NE(info.format(u), info.format(defaults)) << info.key;
        EXPECT_FALSE(u == defaults) << info.key << ": the setter changed nothing";
    }
}

TEST(Settings, AssignmentsChangeTheirField) {
    ShadowSettings s;
    applyAssignment(s, "splits.count=4");
    applyAssignment(s, "splits.scheme=adaptive");
    applyAssignment(s, "splits.alpha=2.5");
    applyAssignment(s, "warp.method=glispsm");
    applyAssignment(s, "warp.falloff=eq17");
    applyAssignment(s, "splits.resolution_falloff=true");
    applyAssignment(s, "shadow_map.resolution=1024");
    EXPECT_EQ(s.splits.count, 4);
    EXPECT_EQ(s.splits.scheme, SplitScheme::Adaptive);
    EXPECT_DOUBLE_EQ(s.splits.alpha, 2.5);
    EXPECT_EQ(s.warp.method, WarpMethod::Glispsm);
    EXPECT_EQ(s.warp.falloff, GlispsmFalloff::Eq17);
    EXPECT_TRUE(s.splits.resolutionFalloff);
    EXPECT_EQ(s.resolution, 1024);
}

TEST(Settings, InvalidValuesNameTheKeyAndRange) {
    EXPECT_NE(errorOf("splits.count=0").find("splits.count"), std::string::npos);
    EXPECT_NE(errorOf("splits.count=0").find("1..8"), std::string::npos);
    EXPECT_NE(errorOf("splits.count=9").find("1..8"), std::string::npos);
    EXPECT_NE(errorOf("splits.count=2.5").find("splits.count"), std::string::npos);
    EXPECT_NE(errorOf("splits.alpha=0.5").find("splits.alpha"), std::string::npos);
    EXPECT_NE(errorOf("splits.alpha=nan").find("splits.alpha"), std::string::npos);
    EXPECT_NE(errorOf("splits.lambda=inf").find("splits.lambda"), std::string::npos);
    EXPECT_NE(errorOf("warp.method=foo").find("uniform, psm, lispsm"), std::string::npos);
    EXPECT_NE(errorOf("splits.resolution_falloff=maybe").find("true or false"), std::string::npos);
    EXPECT_NE(errorOf("no.such=1").find("unknown setting"), std::string::npos);
    EXPECT_NE(errorOf("splits.count").find("key=value"), std::string::npos);
    EXPECT_EQ(errorOf("splits.count=8"), "");
}

TEST(Settings, ValidateReportsOutOfRangeStructValues) {
    ShadowSettings s;
    s.splits.count = 0;
    s.splits.alpha = NAN;
    const auto problems = validate(s);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].find("splits.count"), std::string::npos);
    EXPECT_NE(problems[1].find("splits.alpha"), std::string::npos);
    EXPECT_THROW(validateOrThrow(s), std::invalid_argument);
}

// The virtual map's pages tile its levels: sizes must be powers of two, a level at least 4 × 4 pages.
// Under technique = virtual the fitted maps' settings have no effect, and the warnings say so.
TEST(Settings, VirtualSizesArePowersOfTwoAndTheFittedMapsSettingsStepAside) {
    ShadowSettings s;
    s.technique = Technique::Virtual;
    EXPECT_TRUE(validate(s).empty());
    s.virtualMap.size = 12000;
    s.virtualMap.pageSize = 100;
    const auto problems = validate(s);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0], "virtual.size: 12000 is not a power of two");
    EXPECT_EQ(problems[1], "virtual.page_size: 100 is not a power of two");
    s.virtualMap = {};
    s.virtualMap.size = 256;
    s.virtualMap.pageSize = 128;
    EXPECT_NE(validate(s).at(0).find("more than a quarter of virtual.size"), std::string::npos);
    s.virtualMap.size = 65536;
    s.virtualMap.pageSize = 16;
    EXPECT_EQ(validate(s).at(0), "virtual.size: 65536 / virtual.page_size 16 is 4096 pages a side, more than 512");
    s.virtualMap = {};
    s.splits.count = 3;
    EXPECT_FALSE(settingMatters(s, "splits.count"));
    EXPECT_TRUE(settingMatters(s, "virtual.pool_pages"));
    EXPECT_TRUE(settingMatters(s, "filter.kernel") == settingMatters(ShadowSettings{}, "filter.kernel"));
    const auto warnings = inertSettingWarnings(s);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "splits.count = 3 has no effect (technique = virtual)");
    s.technique = Technique::Maps;
    EXPECT_FALSE(settingMatters(s, "virtual.pool_pages"));
    EXPECT_TRUE(settingMatters(s, "splits.count"));
}

TEST(Settings, FrustumValidationNamesTheKey) {
    EXPECT_NO_THROW(validateFrustum(1, 100, 60));
    const auto message = [](double n, double f, double fov) {
        try {
            validateFrustum(n, f, fov);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message(0, 100, 60).rfind("near", 0), 0u);
    EXPECT_EQ(message(-1, 100, 60).rfind("near", 0), 0u);
    EXPECT_EQ(message(NAN, 100, 60).rfind("near", 0), 0u);
    EXPECT_EQ(message(1, 1, 60).rfind("far", 0), 0u);
    EXPECT_EQ(message(1, INFINITY, 60).rfind("far", 0), 0u);
    EXPECT_EQ(message(1, 100, 180).rfind("fov-y", 0), 0u);
}

// The enum tables are checked at compile time (named_enum.h): a table out of order, short of a
// value or with a repeated name is caught by the same check every declared enum passes.
namespace geometry::shadow {
enum class MisorderedEnum { A, B };
template <> struct EnumDeclaration<MisorderedEnum> {
    static constexpr std::string_view glslPrefix = "X_";
    static constexpr std::array entries{EnumEntry<MisorderedEnum>{MisorderedEnum::B, "b", ""},
                                        EnumEntry<MisorderedEnum>{MisorderedEnum::A, "a", ""}};
};
enum class RepeatedNameEnum { A, B };
template <> struct EnumDeclaration<RepeatedNameEnum> {
    static constexpr std::string_view glslPrefix = "Y_";
    static constexpr std::array entries{EnumEntry<RepeatedNameEnum>{RepeatedNameEnum::A, "a", ""},
                                        EnumEntry<RepeatedNameEnum>{RepeatedNameEnum::B, "a", ""}};
};
static_assert(!enumTableConsistent<MisorderedEnum>());
static_assert(!enumTableConsistent<RepeatedNameEnum>());
static_assert(kEnumCount<FilterType> == 10 && enumName(FilterType::Msm) == "msm");
static_assert(enumName(BiasType::ReceiverPlane) == "receiver_plane" && enumName(BiasType(99)) == "?");
} // namespace geometry::shadow

// Every choice row lists its enum's names in order, and its help names each of them.
TEST(Settings, ChoicesAreTheirEnumsNames) {
    const auto names = [](auto entries) {
        std::vector<std::string_view> out;
        for (const auto& e : entries) out.push_back(e.name);
        return out;
    };
    EXPECT_EQ(findSetting("bias.type")->choices, names(kEnumEntries<BiasType>));
    EXPECT_EQ(findSetting("filter.type")->choices, names(kEnumEntries<FilterType>));
    EXPECT_EQ(findSetting("warp.method")->choices, names(kEnumEntries<WarpMethod>));
    EXPECT_EQ(findSetting("splits.scheme")->choices, names(kEnumEntries<SplitScheme>));
    for (const auto& info : settingsDeclaration())
        for (const auto name : info.choices)
            EXPECT_NE(info.help.find(std::string(name)), std::string::npos) << info.key << ": " << name;
}

// A row's `when` names a declared setting (the "has no effect" warning and the tooltip quote it).
TEST(Settings, EveryConditionNamesADeclaredSetting) {
    for (const auto& info : settingsDeclaration()) {
        if (!info.appliesWhen) {
            EXPECT_TRUE(info.governedBy.empty()) << info.key;
            continue;
        }
        EXPECT_NE(findSetting(info.governedBy), nullptr) << info.key << " names " << info.governedBy;
    }
}
