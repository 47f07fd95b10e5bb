#include "geometry/shadow/virtual_pages.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace geometry::shadow {

std::optional<std::string> VirtualMapConfig::invalid() const {
    if (!std::has_single_bit(virtualSize) || !std::has_single_bit(pageSize))
        return "the virtual size and the page size must be powers of two";
    if (pageSize > virtualSize) return "a page must not be larger than a level";
    if (levels < 1 || levels > 24) return "levels must be 1 to 24";
    if (poolPages == 0) return "the pool must hold at least one page";
    if (!(side0 > 0) || !std::isfinite(side0)) return "level 0's side must be a positive number";
    return std::nullopt;
}

LightFrame lightFrame(const glm::vec3& l) noexcept {
    LightFrame f;
    const glm::dvec3 d(l);
    const double len = glm::length(d);
    f.l = len > 0 && std::isfinite(len) ? d / len : glm::dvec3(0, -1, 0);
    // Any vector across l will do, as long as it depends on l alone: world x unless l is near it.
    const glm::dvec3 helper = std::abs(f.l.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    f.right = glm::normalize(helper - glm::dot(helper, f.l) * f.l);
    f.up = glm::cross(f.l, f.right);
    return f;
}

std::vector<ClipLevel> clipLevels(const LightFrame& frame, const glm::dvec3& eye, const VirtualMapConfig& config) {
    const glm::dvec2 e = frame.project(eye);
    const double pages = config.pagesPerSide();
    std::vector<ClipLevel> levels(size_t(std::max(config.levels, 0)));
    for (size_t k = 0; k < levels.size(); ++k) {
        ClipLevel& c = levels[k];
        c.pageWorld = std::ldexp(config.side0, int(k)) / pages;
        c.texelWorld = c.pageWorld / config.pageSize;
        // The eye's page, half a square back: the square follows the eye a whole page at a time.
        c.firstPageX = int64_t(std::floor(std::clamp(e.x / c.pageWorld, -1e15, 1e15))) - int64_t(pages / 2);
        c.firstPageY = int64_t(std::floor(std::clamp(e.y / c.pageWorld, -1e15, 1e15))) - int64_t(pages / 2);
    }
    return levels;
}

std::optional<PageKey> pageAt(const glm::dvec2& s, int k, const std::vector<ClipLevel>& levels,
                              const VirtualMapConfig& config) noexcept {
    if (k < 0 || size_t(k) >= levels.size()) return std::nullopt;
    const ClipLevel& c = levels[size_t(k)];
    const double x = std::floor(s.x / c.pageWorld), y = std::floor(s.y / c.pageWorld);
    if (!(std::abs(x) < 1e15) || !(std::abs(y) < 1e15)) return std::nullopt; // NaN, infinite or far away
    const int64_t px = int64_t(x), py = int64_t(y), n = int64_t(config.pagesPerSide());
    if (px < c.firstPageX || px >= c.firstPageX + n || py < c.firstPageY || py >= c.firstPageY + n) return std::nullopt;
    return PageKey{k, px, py};
}

int levelFor(double footprint, const std::vector<ClipLevel>& levels) noexcept {
    int k = 0;
    while (size_t(k + 1) < levels.size() && levels[size_t(k + 1)].texelWorld <= footprint) ++k;
    return k;
}

PageRequests requestPages(std::span<const VirtualSample> samples, const LightFrame& frame,
                          const std::vector<ClipLevel>& levels, const VirtualMapConfig& config) {
    PageRequests r;
    for (const VirtualSample& sample : samples) {
        const glm::dvec2 s = frame.project(sample.position);
        bool placed = false;
        for (int k = levelFor(sample.footprint, levels); !placed && size_t(k) < levels.size(); ++k)
            if (const std::optional<PageKey> p = pageAt(s, k, levels, config)) {
                r.pages.push_back(*p);
                placed = true;
            }
        r.uncovered += !placed;
    }
    std::sort(r.pages.begin(), r.pages.end());
    r.pages.erase(std::unique(r.pages.begin(), r.pages.end()), r.pages.end());
    return r;
}

PageKey ancestor(const PageKey& k, int coarser) noexcept {
    const int d = std::clamp(coarser - k.level, 0, 62);
    return {k.level + d, k.x >> d, k.y >> d}; // C++20: >> of a negative value rounds down
}

PagePool::PagePool(uint32_t capacity) : slots_(std::max(capacity, 1u)) {}

uint32_t PagePool::occupied() const noexcept {
    return uint32_t(std::count_if(slots_.begin(), slots_.end(), [](const Slot& s) { return s.used; }));
}

std::optional<PagePool::Entry> PagePool::Frame::resolve(const PageKey& k, int levels) const {
    for (int level = k.level; level < levels; ++level) {
        const PageKey a = ancestor(k, level);
        const auto it = std::lower_bound(table.begin(), table.end(), a,
                                         [](const Entry& e, const PageKey& key) { return e.key < key; });
        if (it != table.end() && it->key == a) return *it;
    }
    return std::nullopt;
}

PagePool::Frame PagePool::update(std::vector<PageKey> requests, uint64_t content, int levels) {
    ++frame_;
    Frame f;
    std::sort(requests.begin(), requests.end());
    requests.erase(std::unique(requests.begin(), requests.end()), requests.end());
    f.requested = requests.size();
    f.finestLevel = requests.empty() ? 0 : requests.front().level;
    for (const PageKey& k : requests) f.finestLevel = std::min(f.finestLevel, k.level);
    // Too many pages: the finest level's pages give way to their parents, one level at a time.
    const int asked = f.finestLevel;
    while (requests.size() > slots_.size() && f.finestLevel + 1 < levels) {
        ++f.finestLevel;
        for (PageKey& k : requests)
            if (k.level < f.finestLevel) k = ancestor(k, f.finestLevel);
        std::sort(requests.begin(), requests.end());
        requests.erase(std::unique(requests.begin(), requests.end()), requests.end());
    }
    size_t leftOut = 0;
    if (requests.size() > slots_.size()) { // even the coarsest level does not fit: keep what fits
        leftOut = requests.size() - slots_.size();
        requests.resize(slots_.size());
    }
    if (f.finestLevel > asked || leftOut > 0)
        f.warning =
            "virtual shadow map: " + std::to_string(f.requested) + " pages asked for, the pool holds " +
            std::to_string(slots_.size()) +
            (f.finestLevel > asked ? "; levels " + std::to_string(asked) + "–" + std::to_string(f.finestLevel - 1) +
                                         " drawn at level " + std::to_string(f.finestLevel)
                                   : std::string()) +
            (leftOut > 0 ? "; " + std::to_string(leftOut) + " pages left unshadowed" : std::string());

    // Pages already held keep their slot (and, when their content is current, their texels).
    std::vector<Entry> held;
    for (uint32_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].used) held.push_back({slots_[i].key, i});
    std::sort(held.begin(), held.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
    std::vector<char> kept(slots_.size(), 0);
    std::vector<PageKey> missing;
    for (const PageKey& k : requests) {
        const auto it = std::lower_bound(held.begin(), held.end(), k,
                                         [](const Entry& e, const PageKey& key) { return e.key < key; });
        if (it == held.end() || !(it->key == k)) {
            missing.push_back(k);
            continue;
        }
        Slot& s = slots_[it->physical];
        kept[it->physical] = 1;
        if (s.content == content) ++f.cached;
        else f.drawn.push_back(it->physical);
        s.content = content;
        s.lastUsed = frame_;
        f.table.push_back({k, it->physical});
    }
    // The others take free slots first, then the least recently used ones not asked for now.
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < slots_.size(); ++i)
        if (!kept[i]) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const Slot &sa = slots_[a], &sb = slots_[b];
        if (sa.used != sb.used) return !sa.used;
        return sa.lastUsed < sb.lastUsed;
    });
    for (size_t i = 0; i < missing.size(); ++i) {
        Slot& s = slots_[order[i]];
        s = {missing[i], true, content, frame_};
        f.drawn.push_back(order[i]);
        f.table.push_back({missing[i], order[i]});
    }
    std::sort(f.table.begin(), f.table.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
    std::sort(f.drawn.begin(), f.drawn.end());
    return f;
}

} // namespace geometry::shadow
