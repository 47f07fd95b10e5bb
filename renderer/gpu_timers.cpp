#include "gpu_timers.h"

#include <limits>

namespace renderer {

double PassTimes::total() const noexcept {
    double t = 0;
    for (double v : ms) t += v;
    return t;
}

GpuTimers::GpuTimers() {
    lastDrawn_.fill(std::numeric_limits<double>::quiet_NaN());
    for (auto& s : slots_) glGenQueries(kPasses * kRuns, &s.queries[0][0]);
}

GpuTimers::~GpuTimers() {
    for (auto& s : slots_) glDeleteQueries(kPasses * kRuns, &s.queries[0][0]);
}

void GpuTimers::begin(Pass p) noexcept {
    Slot& s = slots_[current_];
    if (open_) end();
    const int i = static_cast<int>(p);
    if (s.used[i] >= kRuns) return;
    glBeginQuery(GL_TIME_ELAPSED, s.queries[i][s.used[i]++]);
    open_ = true;
}

void GpuTimers::end() noexcept {
    if (!open_) return;
    glEndQuery(GL_TIME_ELAPSED);
    open_ = false;
}

void GpuTimers::collect(Slot& s, bool wait) noexcept {
    if (!s.pending) return;
    PassTimes t;
    for (int i = 0; i < kPasses; ++i)
        for (int r = 0; r < s.used[i]; ++r) {
            GLint available = GL_FALSE;
            glGetQueryObjectiv(s.queries[i][r], GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available && !wait) return;
        }
    for (int i = 0; i < kPasses; ++i) {
        for (int r = 0; r < s.used[i]; ++r) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(s.queries[i][r], GL_QUERY_RESULT, &ns);
            t.ms[i] += static_cast<double>(ns) * 1e-6;
            t.drawn[i] = true;
        }
        s.used[i] = 0;
    }
    t.valid = true;
    s.pending = false;
    latest_ = t;
    for (int i = 0; i < kPasses; ++i)
        if (t.drawn[i]) lastDrawn_[size_t(i)] = t.ms[i];
}

void GpuTimers::endFrame() noexcept {
    end();
    slots_[current_].pending = true;
    current_ = (current_ + 1) % kFrames;
    // Oldest first, so `latest_` ends on the newest finished frame.
    for (int k = 0; k < kFrames; ++k) collect(slots_[(current_ + k) % kFrames], false);
    // A slot about to be reused must be drained even if it means waiting.
    collect(slots_[current_], true);
}

bool GpuTimers::poll() noexcept {
    bool inFlight = false;
    for (int k = 0; k < kFrames; ++k) { // oldest first, as endFrame
        Slot& s = slots_[(current_ + k) % kFrames];
        collect(s, false);
        inFlight = inFlight || s.pending;
    }
    return inFlight;
}

const PassTimes& GpuTimers::waitForAll() noexcept {
    end();
    for (int k = 0; k < kFrames; ++k) collect(slots_[(current_ + k) % kFrames], true);
    return latest_;
}

} // namespace renderer
