#include "accuracy_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <sstream>
#include <utility>

#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "frame_stats.hpp"

namespace facet::view {
namespace {

// The ground truth is most of the work (seconds against a few hundred milliseconds of timing on
// the default scene); the bar gives it this share.
constexpr double kGroundTruthShare = 0.8;

// Thrown out of the measurement when Cancel was pressed.
struct Cancelled {};
/// The ground truth refused the frame (its camera, size or memory): the message says why.
struct Refused {
    std::string why;
};

std::string percent(double fraction) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%d %%", static_cast<int>(std::floor(100.0 * fraction)));
    return buf;
}

}  // namespace

AccuracyView accuracyView(const Scene& scene, std::uint64_t sceneVersion,
                          const RenderSettings& settings) {
    // Accuracy is of the shaded image: a debug view on screen changes nothing here.
    RenderSettings shaded = settings;
    shaded.view = DebugView::None;
    return {{sceneVersion, scene.texture, scene.camera, scene.lighting}, shaded};
}

bool sameMethod(const RenderSettings& a, const RenderSettings& b) {
    // What a Solid render does not depend on is set alike, and the subdivision where it is not
    // used; everything else (a field added later too) counts.
    const auto method = [](RenderSettings s) {
        const RenderSettings none;
        s.mode = none.mode;
        s.showNormals = none.showNormals;
        s.normalLength = none.normalLength;
        s.depthLegend = none.depthLegend;
        s.pointSize = none.pointSize;
        s.threads = none.threads;
        if (s.interp != Interp::Subdivided) s.subdivision = none.subdivision;
        return s;
    };
    return method(a) == method(b);
}

void markPareto(std::vector<AccuracyRow>& rows) {
    std::vector<app::ParetoPoint> points;
    for (const AccuracyRow& r : rows) points.push_back({r.times.median, r.error.rmse});
    const std::vector<bool> front = app::onParetoFront(points);
    for (std::size_t k = 0; k < rows.size(); ++k) rows[k].pareto = front[k];
}

bool reportFresh(const AccuracyReport& report, const AccuracyView& now) {
    if (report.view.picture != now.picture) return false;
    return std::any_of(report.rows.begin(), report.rows.end(), [&now](const AccuracyRow& r) {
        return sameMethod(r.settings, now.settings);
    });
}

void applyMethod(const AccuracyRow& row, RenderSettings& settings) {
    settings.interp = row.settings.interp;
    settings.subdivision = row.settings.subdivision;
    settings.filter = row.settings.filter;
    settings.lighting = row.settings.lighting;
}

std::string accuracyStateText(const AccuracyReport* report) {
    if (!report) return "accuracy_rows 0\n";
    std::ostringstream s;
    s << "accuracy_rows " << report->rows.size() << "\n";
    s << "accuracy_samples " << report->samples << "\n";
    s << "accuracy_size " << report->width << " " << report->height << "\n";
    s << "accuracy_left_out " << report->leftOut << "\n";
    for (const AccuracyRow& r : report->rows) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "accuracy_%s_%s %.4f %.4f %.3f %.1f %.5f %d\n",
                      r.axis.c_str(), r.method.c_str(), r.times.median, r.error.rmse, r.error.psnr,
                      r.error.maxError, r.error.over2Lsb, r.pareto ? 1 : 0);
        s << buf;
    }
    return s.str();
}

AccuracyJob::~AccuracyJob() {
    cancel();
    wait();
}

bool AccuracyJob::start(const Scene& scene, std::uint64_t sceneVersion,
                        const RenderSettings& settings, int samples, int frames, int warmup) {
    cancel();
    wait();  // a cancelled job ends within milliseconds
    const int n = std::clamp(samples, 1, kMaxAccuracySamples);
    const Camera& cam = scene.camera;
    // The reference image holds about 33 bytes per sub-sample (colour, depth, a flag).
    const double gigabytes = 33.0 * cam.width * cam.height * n * n / 1e9;
    std::lock_guard lock(mutex_);
    if (gigabytes > kMaxAccuracyGigabytes) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "A ground truth of %dx%d at %dx%d samples needs %.1f GB (at most %.0f): "
                      "lower the samples or the window size.",
                      cam.width, cam.height, n, n, gigabytes, kMaxAccuracyGigabytes);
        status_ = {false, 0.0, "", buf};
        return false;
    }
    try {
        Request request{scene, accuracyView(scene, sceneVersion, settings), n, std::max(frames, 1),
                        std::max(warmup, 0)};
        status_ = {true, 0.0, "ground truth 0 %", ""};
        cancel_ = false;
        running_ = true;
        thread_ = std::thread([this, r = std::move(request)] { run(r); });
    } catch (const std::exception& e) {  // no memory for the copy, or no thread to be had
        status_ = {false, 0.0, "", std::string("Cannot start the measurement: ") + e.what()};
        running_ = false;
        return false;
    }
    return true;
}

void AccuracyJob::cancel() {
    cancel_ = true;
}

bool AccuracyJob::running() const {
    return running_;
}

AccuracyStatus AccuracyJob::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

std::shared_ptr<const AccuracyReport> AccuracyJob::report() const {
    std::lock_guard lock(mutex_);
    return report_;
}

std::uint64_t AccuracyJob::reportCount() const {
    std::lock_guard lock(mutex_);
    return reportCount_;
}

void AccuracyJob::wait() {
    if (thread_.joinable()) thread_.join();
}

bool AccuracyJob::progress(double fraction, const std::string& label) {
    std::lock_guard lock(mutex_);
    status_.fraction = fraction;
    status_.label = label;
    return !cancel_;
}

void AccuracyJob::run(const Request& request) {
    std::string message;
    try {
        const Scene& scene = request.scene;
        const auto report = std::make_shared<AccuracyReport>();
        report->view = request.view;
        report->samples = request.samples;
        report->width = scene.camera.width;
        report->height = scene.camera.height;
        report->frames = request.frames;
        const std::vector<app::AccuracyMethod> methods = app::methodsBelowTruth(
            app::accuracyMethods(scene, request.view.settings), request.samples, &report->leftOut);

        const auto t0 = Clock::now();
        Result<GroundTruth> made =
            renderGroundTruth(scene, request.view.settings, request.samples, [this](double f) {
                return progress(kGroundTruthShare * f, "ground truth " + percent(f));
            });
        if (!made) throw Refused{made.error().message};
        const GroundTruth truth = std::move(made).value();
        report->groundTruthSeconds = ms(t0, Clock::now()) / 1000.0;
        if (truth.cancelled || cancel_) throw Cancelled{};

        // The same settings on several axes (the user's own method is on each of them) are
        // measured once, so those rows agree instead of differing by the timing's noise.
        std::vector<app::AccuracyMethod> measured;            // each distinct method once
        std::vector<std::size_t> measuredAs(methods.size());  // index into `measured`
        for (std::size_t k = 0; k < methods.size(); ++k) {
            const auto same = [&](const app::AccuracyMethod& m) {
                return m.settings == methods[k].settings;
            };
            measuredAs[k] = static_cast<std::size_t>(
                std::find_if(measured.begin(), measured.end(), same) - measured.begin());
            if (measuredAs[k] == measured.size()) measured.push_back(methods[k]);
        }

        // Round-robin like `facet accuracy`: a stretch when the viewer (or anything else) holds
        // the cores slows every method alike, not the one measured then. Then one more frame
        // each for the error.
        Renderer renderer;
        Framebuffer frame;
        const std::size_t count = measured.size();
        const std::size_t rounds = static_cast<std::size_t>(request.warmup + request.frames);
        const double steps = static_cast<double>((rounds + 1) * count);
        std::vector<ImageError> errors(count);
        std::size_t step = 0;
        auto next = [&](const char* what, std::size_t d) {
            const double f = static_cast<double>(step++) / steps;
            const std::string label = std::string(what) + " " + std::to_string(d + 1) + "/" +
                                      std::to_string(count) + " " + measured[d].name;
            if (!progress(kGroundTruthShare + (1.0 - kGroundTruthShare) * f, label))
                throw Cancelled{};
        };
        const std::vector<std::vector<double>> times =
            app::timeMethods(renderer, scene, measured, request.frames, request.warmup, frame,
                             [&](std::size_t d) { next("timing", d); });
        for (std::size_t d = 0; d < count; ++d) {
            next("error", d);
            renderer.render(scene, measured[d].settings, frame);
            errors[d] = measureError(frame, truth);
        }
        for (std::size_t k = 0; k < methods.size(); ++k) {
            const app::AccuracyMethod& m = methods[k];
            report->rows.push_back({m.axis, m.name, m.settings, summarize(times[measuredAs[k]]),
                                    errors[measuredAs[k]], false});
        }
        markPareto(report->rows);
        std::lock_guard lock(mutex_);
        report_ = report;
        ++reportCount_;
        status_ = {false, 1.0, "done", ""};
        running_ = false;
        return;
    } catch (const Cancelled&) {
        message = "Cancelled.";
    } catch (const Refused& r) {
        message = "No ground truth: " + r.why;
    } catch (const std::bad_alloc&) {
        message = "Out of memory: lower the samples or the window size.";
    } catch (const std::exception& e) {
        message = std::string("The measurement failed: ") + e.what();
    } catch (...) {
        message = "The measurement failed.";
    }
    std::lock_guard lock(mutex_);
    status_ = {false, 0.0, "", message};
    running_ = false;
}

}  // namespace facet::view
