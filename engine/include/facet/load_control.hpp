#pragma once
// Progress and cancellation for a load that runs on a worker thread (the viewer's LoadJob): the
// loaders report the fraction done every few hundred kilobytes or thousands of lines, never per
// vertex, and stop with a "cancelled" Error (Error::cancelled) soon after the flag is set.

#include <atomic>
#include <functional>

namespace facet {

/// What a loader reports to and reads from its caller while it works; both parts are optional.
struct LoadControl {
    /// Called on the loading thread with the fraction done, in [0, 1] and never decreasing; a
    /// load that succeeds ends with 1.
    std::function<void(float)> progress;
    /// Set (from any thread) to stop the load; it then returns an Error with `cancelled` set and
    /// no partial product.
    const std::atomic<bool>* cancel = nullptr;
};

}  // namespace facet
