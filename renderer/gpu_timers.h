#pragma once
// GPU time per pass from GL_TIME_ELAPSED queries, read a few frames later so the frame never
// waits on the GPU.
#include "gl/gl_api.h"

#include <array>
#include <cstddef>

namespace renderer {

/// Prepass: the eye's depth pre-pass, and with focus.mode = samples the reduction of its samples.
enum class Pass { Prepass, Shadow, Eye, LightView, Count };

struct PassTimes {
    std::array<double, static_cast<std::size_t>(Pass::Count)> ms{};  // GPU milliseconds per pass
    std::array<bool, static_cast<std::size_t>(Pass::Count)> drawn{}; // the frame ran that pass
    bool valid = false;
    [[nodiscard]] double of(Pass p) const noexcept { return ms[static_cast<std::size_t>(p)]; }
    [[nodiscard]] double total() const noexcept; // every pass, the inspection views included
    /// The shadowing itself: depth pre-pass, shadow maps and eye view, without the inspection views.
    [[nodiscard]] double frame() const noexcept { return of(Pass::Prepass) + of(Pass::Shadow) + of(Pass::Eye); }
};

class GpuTimers {
public:
    GpuTimers();
    ~GpuTimers();
    GpuTimers(const GpuTimers&) = delete;
    GpuTimers& operator=(const GpuTimers&) = delete;

    void begin(Pass p) noexcept;
    void end() noexcept;
    /// Closes the frame; collects any earlier frame whose results are ready.
    void endFrame() noexcept;
    /// The newest frame whose results have arrived (valid == false before the first).
    [[nodiscard]] const PassTimes& latest() const noexcept { return latest_; }
    /// A pass's time in the newest finished frame that ran it (NaN: none yet): a pass skipped since
    /// (shadow maps reused) keeps its last time, whichever frames a poll collects together.
    [[nodiscard]] double lastDrawn(Pass p) const noexcept { return lastDrawn_[static_cast<size_t>(p)]; }
    /// Collects the frames whose results have arrived, without closing one (a window that draws
    /// nothing new still shows them); true while some are still in flight.
    bool poll() noexcept;
    /// Waits for every frame in flight (for one-shot exports, not for the interactive loop).
    const PassTimes& waitForAll() noexcept;

private:
    static constexpr int kFrames = 4;
    static constexpr int kPasses = static_cast<int>(Pass::Count);
    /// A pass may run several times a frame (once per light); its times add up. Beyond this many
    /// runs the rest goes untimed.
    static constexpr int kRuns = 8;
    struct Slot {
        GLuint queries[kPasses][kRuns] = {};
        int used[kPasses] = {}; // runs begun this frame
        bool pending = false;
    };
    void collect(Slot& s, bool wait) noexcept;
    std::array<Slot, kFrames> slots_{};
    int current_ = 0;
    bool open_ = false;
    PassTimes latest_;
    std::array<double, kPasses> lastDrawn_{};
};

} // namespace renderer
