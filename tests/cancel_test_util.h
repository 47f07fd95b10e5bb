#pragma once
// Timing a cancellation: runs `work(token)` once without a stop, then again with a stop requested
// from another thread shortly after it starts, so a test can check that the stop was noticed and
// that it ended the run long before it would have finished.
#include "geometry/analysis/cancelled.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <stop_token>
#include <string>
#include <thread>

namespace testutil {

struct CancelTiming {
    double uncancelledMs = 0; // the whole run
    double cancelledMs = 0;   // from the start to the throw (or the end, when not noticed)
    bool cancelled = false;   // Cancelled was thrown
};

/// The stop comes after 20 ms, or a tenth of the whole run on a machine that needs less than 0.2 s.
template <class Work> CancelTiming timeCancellation(const Work& work) {
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    CancelTiming t;
    auto start = Clock::now();
    work(std::stop_token{});
    t.uncancelledMs = ms(Clock::now() - start);
    const auto delay = std::min<Clock::duration>(
        std::chrono::milliseconds(20),
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::milli>(t.uncancelledMs / 10.0)));
    std::stop_source source;
    start = Clock::now();
    std::jthread stopper([&] {
        std::this_thread::sleep_for(delay);
        source.request_stop();
    });
    try {
        work(source.get_token());
    } catch (const geometry::analysis::Cancelled&) {
        t.cancelled = true;
    }
    t.cancelledMs = ms(Clock::now() - start);
    return t;
}

/// The stop was noticed, and it ended the run in less than half the time of the whole run; both
/// times go into the test's XML report.
inline void expectCancelledEarly(const CancelTiming& t) {
    ::testing::Test::RecordProperty("uncancelled_ms", std::to_string(t.uncancelledMs));
    ::testing::Test::RecordProperty("cancelled_ms", std::to_string(t.cancelledMs));
    EXPECT_TRUE(t.cancelled) << "the run ended in " << t.cancelledMs << " ms without noticing the stop";
    EXPECT_LT(t.cancelledMs, 0.5 * t.uncancelledMs)
        << "cancelled after " << t.cancelledMs << " ms; the whole run takes " << t.uncancelledMs << " ms";
}

} // namespace testutil
