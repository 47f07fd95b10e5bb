#pragma once
// Cooperative cancellation of the ground truth and the inspection built on it (ground_truth.h,
// inspection.h): the dashboard runs them on a worker thread and abandons a run the user has made
// stale by requesting a stop on its std::stop_token.
#include <stdexcept>
#include <stop_token>

namespace geometry::analysis {

/// Thrown by a call whose std::stop_token was stopped before it finished; its results are gone.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

inline void throwIfStopped(const std::stop_token& stop) {
    if (stop.stop_requested()) throw Cancelled();
}

} // namespace geometry::analysis
