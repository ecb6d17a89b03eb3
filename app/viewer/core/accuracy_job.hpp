#pragma once
// The Compare panel's "against the ground truth": for the view on screen, each method's time
// and error against a supersampled ground truth (facet/ground_truth.hpp), measured on a thread
// of its own so the viewer keeps drawing. A request snapshots the scene, the settings and the
// camera; the thread renders the ground truth (seconds: the reference path, single-threaded,
// in double), then times every method with its own Renderer and measures its error. Progress
// and a label can be read at any time, Cancel stops it within a few milliseconds, and the
// result remembers the view it was measured for, so the panel can tell when it went stale.
//
// Plain C++ threads, no GL: the unit tests drive it directly.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "accuracy/accuracy_methods.hpp"
#include "facet/evaluation/frame_times.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// Ground-truth samples per axis the panel offers: 4×4 by default, up to 8×8.
inline constexpr int kDefaultAccuracySamples = 4;
inline constexpr int kMaxAccuracySamples = 8;
/// The supersampled reference image is held whole (about 33 bytes per sub-sample); a request
/// needing more than this is refused with a message.
inline constexpr double kMaxAccuracyGigabytes = 4.0;

/// What a picture shows besides the settings: the scene (by load count and texture), camera and
/// lighting. Equal keys with equal settings render the same pictures.
struct PictureKey {
    std::uint64_t sceneVersion = 0;
    std::shared_ptr<const Texture> texture;  ///< compared by identity: a load makes a new one
    Camera camera;
    LightingParams lighting;

    /// Every field equal.
    bool operator==(const PictureKey&) const = default;
};

/// What a measurement is of: the picture and the settings.
struct AccuracyView {
    PictureKey picture;
    RenderSettings settings;  ///< as the user had them (any draw mode)

    /// Every field equal.
    bool operator==(const AccuracyView&) const = default;
};

/// The view of a scene as the viewer draws it.
AccuracyView accuracyView(const Scene& scene, std::uint64_t sceneVersion,
                          const RenderSettings& settings);

/// Same settings as far as the measured methods go: the ones a Solid render depends on.
bool sameMethod(const RenderSettings& a, const RenderSettings& b);

/// One method measured.
struct AccuracyRow {
    std::string axis;
    std::string method;
    RenderSettings settings;  ///< the method's (Solid)
    FrameTimes times;         ///< the method's frame times (ms)
    ImageError error;
    bool pareto = false;  ///< no other method is both faster and more accurate
};

/// A finished measurement.
struct AccuracyReport {
    AccuracyView view;  ///< what was measured
    int samples = 0;    ///< ground truth per axis
    int width = 0;
    int height = 0;
    int frames = 0;                   ///< timed frames per method
    double groundTruthSeconds = 0.0;  ///< how long the ground truth took
    std::vector<AccuracyRow> rows;
    std::string leftOut;  ///< methods not measured (app::methodsBelowTruth()): as fine as the truth
};

/// Marks the rows on the Pareto front of (median ms, RMSE) by app::onParetoFront(), the rule
/// `facet accuracy` uses too.
void markPareto(std::vector<AccuracyRow>& rows);

/// Whether the report still describes what the viewer shows: the same picture, and settings
/// that are one of the measured methods' (so picking a row keeps it fresh).
bool reportFresh(const AccuracyReport& report, const AccuracyView& now);

/// Copies a row's method (interpolation, subdivision, filter, lighting) into the user's
/// settings, leaving the rest (draw mode, shader, normals...) as the user has it.
void applyMethod(const AccuracyRow& row, RenderSettings& settings);

/// The report as `key value` lines for the viewer's --state file.
std::string accuracyStateText(const AccuracyReport* report);

/// What the job is doing, for the progress bar.
struct AccuracyStatus {
    bool running = false;
    double fraction = 0.0;  ///< of the whole job, 0…1
    std::string label;      ///< "ground truth 37 %", "timing 3/9 subdivided:16"
    std::string message;    ///< why the last request ended without a result (refused, error...)
};

/// Measures on its own thread, one request at a time.
class AccuracyJob {
  public:
    AccuracyJob() = default;
    /// Cancels a measurement in flight and joins its thread.
    ~AccuracyJob();
    AccuracyJob(const AccuracyJob&) = delete;
    AccuracyJob& operator=(const AccuracyJob&) = delete;

    /// Starts measuring the scene as it is now (copied) with methods around `settings`, the
    /// ground truth at samples×samples (clamped to 1…kMaxAccuracySamples), `frames` timed
    /// frames per method after `warmup`. A measurement in flight is cancelled first. Returns
    /// false, with status().message saying why, when the ground truth would not fit in memory.
    bool start(const Scene& scene, std::uint64_t sceneVersion, const RenderSettings& settings,
               int samples = kDefaultAccuracySamples, int frames = 7, int warmup = 1);

    /// Asks the thread to stop; returns at once (the thread ends within milliseconds).
    void cancel();

    /// True from start() until the thread has finished (cancelled or not).
    bool running() const;

    /// Progress, label and message, safe to call any time.
    AccuracyStatus status() const;

    /// The last finished report (null before the first); a new one replaces it when done.
    std::shared_ptr<const AccuracyReport> report() const;

    /// Counts finished reports, so a caller can tell a new one from the one it has seen.
    std::uint64_t reportCount() const;

    /// Blocks until the thread is done and joins it (tests, and the viewer on exit).
    void wait();

  private:
    struct Request {
        Scene scene;
        AccuracyView view;
        int samples = 0;
        int frames = 0;
        int warmup = 0;
    };
    void run(const Request& request);
    bool progress(double fraction, const std::string& label);  // false: cancelled

    mutable std::mutex mutex_;
    AccuracyStatus status_;
    std::shared_ptr<const AccuracyReport> report_;
    std::uint64_t reportCount_ = 0;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> running_{false};
    std::thread thread_;
};

}  // namespace facet::view
