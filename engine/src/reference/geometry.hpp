#pragma once
// What the reference path's geometry files share (raster.cpp: triangles and draw();
// lines_points.cpp: rules 6 and 7): the 1/256 px margin of rule 8, the image bounds test, and
// the progress tracker.

#include <algorithm>
#include <cstdint>

#include "reference/shading.hpp"

namespace facet::reference::detail {

// The fast path snaps screen positions to a 1/256 px grid; any decision closer than that to a
// boundary may go either way there (rule 8).
constexpr double kSnap = 1.0 / 256.0;

/// True when pixel (x, y) is inside the image.
inline bool inImage(const Image& img, std::int64_t x, std::int64_t y) {
    return x >= 0 && y >= 0 && x < img.width && y < img.height;
}

// Progress over a draw's pixel work (the primitives' bounding boxes in the image), reported
// every 1/kReports of it. Without a callback it does nothing and costs one test per row.
class Tracker {
  public:
    static constexpr double kReports = 200.0;

    Tracker(const Progress& progress, double total)
        : progress_(progress ? &progress : nullptr),
          total_(std::max(total, 1.0)),
          step_(total_ / kReports),
          next_(step_) {}

    // Counts `work` more done; false once the callback asked to stop.
    bool add(double work) {
        if (!progress_ || stopped_) return !stopped_;
        done_ += work;
        if (done_ < next_) return true;
        next_ = done_ + step_;
        stopped_ = !(*progress_)(std::min(done_ / total_, 1.0));
        return !stopped_;
    }

    // The end, reported as 1 (the estimate is not exact) unless stopped.
    void finish() {
        if (progress_ && !stopped_) stopped_ = !(*progress_)(1.0);
    }

    bool active() const { return progress_ != nullptr; }
    bool stopped() const { return stopped_; }

  private:
    const Progress* progress_;
    double total_;
    double step_;
    double next_;
    double done_ = 0.0;
    bool stopped_ = false;
};

/// Point where the segment inside→outside meets w = near. Always computed from the inside vertex
/// so the fast path, doing the same, gets the same point whichever way the edge is walked.
inline Vertex intersectNear(const Vertex& in, double dIn, const Vertex& out, double dOut) {
    return detail::lerp(in, out, dIn / (dIn - dOut));
}

/// Rule 6 for one segment in clip space (also the normals display, rule 14).
void drawSegment(Image& img, const Pass& pass, Vertex a, Vertex b, double nearPlane);

/// Rule 7: one square around the vertex, every pixel with the vertex's own values.
void drawPoint(Image& img, const Pass& pass, const Vertex& v, double nearPlane);

}  // namespace facet::reference::detail
