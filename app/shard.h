#pragma once
// `--shard I/N` (check, bench): one CI job's share of a run spread over N jobs (a GitHub Actions
// matrix, a GitLab `parallel:` job); `shadowscope merge` puts the shards' outputs back together.
// Shares are dealt from the run's own order, never from timings or the machine, so every job
// computes the same split.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct Shard {
    size_t index = 0; // 0-based; "I/N" on the command line counts from 1
    size_t count = 1;
    [[nodiscard]] std::string text() const { return std::to_string(index + 1) + "/" + std::to_string(count); }
};

/// "I/N" with 1 ≤ I ≤ N ≤ 1000; nullopt for anything else.
[[nodiscard]] std::optional<Shard> parseShard(std::string_view text) noexcept;

/// Adds --shard I/N to a command; `shard` stays empty without it.
void addShardOption(CLI::App& cmd, std::optional<Shard>& shard, const std::string& what);

/// Which shard each item goes to: items with the same group (`groupOf[i]`, any labels) stay
/// together; groups, in the order of their first item, are dealt round robin.
[[nodiscard]] std::vector<size_t> dealShards(const std::vector<size_t>& groupOf, size_t count);

} // namespace app
