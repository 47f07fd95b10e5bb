#include "app/shard.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <map>

namespace app {

std::optional<Shard> parseShard(std::string_view text) noexcept {
    const size_t slash = text.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    const auto number = [](std::string_view s) -> std::optional<size_t> {
        size_t v = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
        return v;
    };
    const std::optional<size_t> i = number(text.substr(0, slash)), n = number(text.substr(slash + 1));
    if (!i || !n || *i < 1 || *i > *n || *n > 1000) return std::nullopt;
    return Shard{*i - 1, *n};
}

void addShardOption(CLI::App& cmd, std::optional<Shard>& shard, const std::string& what) {
    cmd.add_option_function<std::string>(
           "--shard",
           [&shard](const std::string& text) {
               shard = parseShard(text);
               if (!shard)
                   throw CLI::ValidationError("--shard", "expected I/N with 1 <= I <= N <= 1000, got '" + text + "'");
           },
           "Run only share I of N (1-based) of the " + what +
               ", for a CI matrix; `shadowscope merge` joins the shards' output folders")
        ->type_name("I/N");
}

std::vector<size_t> dealShards(const std::vector<size_t>& groupOf, size_t count) {
    std::map<size_t, size_t> shardOfGroup;
    std::vector<size_t> out(groupOf.size());
    for (size_t i = 0; i < groupOf.size(); ++i) {
        const auto [it, isNew] = shardOfGroup.emplace(groupOf[i], shardOfGroup.size() % std::max<size_t>(count, 1));
        out[i] = it->second;
    }
    return out;
}

} // namespace app
