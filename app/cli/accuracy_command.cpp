// `facet accuracy`: how far each of the engine's approximations lands from the ground truth
// (facet/ground_truth.hpp) and what it costs, measured in the same run: per scene and method,
// the engine's median time per frame and its error (RMSE, PSNR, max, share over 2 LSB). Writes
// accuracy.csv and accuracy.png into a new folder unless told which, with progress through each
// phase (ground truth, timing, error) on stderr.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "accuracy/accuracy_methods.hpp"
#include "accuracy/run_output.hpp"
#include "accuracy_command.hpp"
#include "exit_code.hpp"
#include "facet/camera.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "report/accuracy_report.hpp"
#include "report/bench_chart.hpp"
#include "report/machine_info.hpp"

namespace facet::app {
namespace {

/// The supersampled reference image is kept whole in memory; beyond this it is refused.
constexpr double kMaxGroundTruthGigabytes = 8.0;

/// --quick: images at most this wide (the framing kept), a 2×2 truth, one timed frame.
constexpr int kQuickWidth = 128;

struct AccuracyOptions {
    std::vector<std::string> scenes;
    std::string out;      ///< the folder; empty: a new one in the current folder
    std::string texture;  ///< for scenes with uvs but no texture of their own
    std::string gnuplot = "gnuplot";
    bool noChart = false;
    bool quick = false;
    int samples = kDefaultGroundTruthSamples;
    int frames = 15;
    int warmup = 2;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* f, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, f, args...);
    return buf;
}

int runAccuracy(const AccuracyOptions& o) {
    // Every scene loads before anything is measured, so bad input fails at once. A bare
    // .off/.obj mesh opens as `facet render` opens it (spec §3b).
    std::vector<Scene> scenes;
    for (const std::string& path : o.scenes) {
        Result<Scene> scene = openSceneFile(path);
        if (!scene.ok()) {
            std::fprintf(stderr, "%s\n", scene.error().what().c_str());
            return kBadInput;
        }
        if (!o.texture.empty() && !scene.value().texture && !scene.value().mesh->uvs.empty()) {
            if (Status st = loadSceneTexture(scene.value(), o.texture); !st) {
                std::fprintf(stderr, "%s\n", st.error().what().c_str());
                return kBadInput;
            }
        }
        Camera& cam = scene.value().camera;
        if (o.quick && cam.width > kQuickWidth) {
            const int h = std::max(1, cam.height * kQuickWidth / cam.width);
            cam = resizedCamera(cam, kQuickWidth, h);
        }
        // The reference image holds about 33 bytes per sub-sample (colour, depth, a flag).
        const double gigabytes = 33.0 * cam.width * cam.height * o.samples * o.samples / 1e9;
        if (gigabytes > kMaxGroundTruthGigabytes) {
            std::fprintf(stderr,
                         "%s: a ground truth of %dx%d at %dx%d samples needs %.1f GB (at most "
                         "%.0f); lower --samples\n",
                         path.c_str(), cam.width, cam.height, o.samples, o.samples, gigabytes,
                         kMaxGroundTruthGigabytes);
            return kBadInput;
        }
        scenes.push_back(std::move(scene.value()));
    }
    if (!o.noChart) {
        if (Status st = checkGnuplot(o.gnuplot); !st) {
            std::fprintf(stderr, "%s (--no-chart writes the CSV only)\n",
                         st.error().what().c_str());
            return kBadInput;
        }
    }
    const Result<std::string> folder = prepareOutputFolder(o.out, "facet-accuracy");
    if (!folder) {
        std::fprintf(stderr, "%s\n", folder.error().what().c_str());
        return kBadInput;
    }
    const MachineInfo machine = collectMachineInfo();
    if (machineBusy(machine))
        std::fprintf(stderr,
                     "accuracy: warning: load average %s on %d cores: the times will be those of "
                     "a busy machine (the CSV and chart say so); the errors are exact\n",
                     machine.load.c_str(), machine.cores);

    // Only methods coarser than the truth are measured (the viewer's rule too).
    std::vector<std::vector<AccuracyMethod>> methods;
    std::string leftOut;
    std::size_t total = 0;
    for (const Scene& s : scenes) {
        methods.push_back(methodsBelowTruth(accuracyMethods(s), o.samples, &leftOut));
        total += methods.back().size();
    }
    std::fprintf(stderr,
                 "accuracy: %zu scene%s, %zu methods against a %dx%d-sample truth; %d timed "
                 "frame%s each after %d untimed; writing to %s\n",
                 scenes.size(), scenes.size() == 1 ? "" : "s", total, o.samples, o.samples,
                 o.frames, o.frames == 1 ? "" : "s", o.warmup, folder.value().c_str());
    if (!leftOut.empty())
        std::fprintf(stderr,
                     "accuracy: not measured: %s (as many samples per pixel as the %dx%d truth or "
                     "more: nothing finer than the truth can be judged by it)\n",
                     leftOut.c_str(), o.samples, o.samples);

    ProgressLine progress;
    std::vector<AccuracyResult> results;
    Renderer renderer;
    Framebuffer frame;
    std::size_t done = 0;
    const auto runStart = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Scene& scene = scenes[k];
        const std::string name = std::filesystem::path(o.scenes[k]).stem().string();
        const std::string where = format("[scene %zu/%zu] %s", k + 1, scenes.size(), name.c_str());
        const auto start = std::chrono::steady_clock::now();
        int tenth = -1;
        Result<GroundTruth> made =
            renderGroundTruth(scene, baseSettings(scene), o.samples, [&](double f) {
                // Each tenth reaches a log; a terminal sees every step.
                const int t = static_cast<int>(f * 10.0);
                const double s = secondsSince(start);
                std::string line = format("%s: ground truth %dx%d at %dx%d samples: %3d %% (%.0f s",
                                          where.c_str(), scene.camera.width, scene.camera.height,
                                          o.samples, o.samples, static_cast<int>(f * 100.0), s);
                if (f > 0.05) line += format(", about %.0f s left", s * (1.0 - f) / f);
                progress.update(line + ")", t != tenth);
                tenth = t;
                return true;
            });
        if (!made) {
            progress.finish("");
            std::fprintf(stderr, "%s: %s\n", o.scenes[k].c_str(), made.error().message.c_str());
            return kBadInput;
        }
        const GroundTruth truth = std::move(made).value();
        progress.finish(format("%s: ground truth %dx%d at %dx%d samples in %.1f s", where.c_str(),
                               scene.camera.width, scene.camera.height, o.samples, o.samples,
                               secondsSince(start)));
        const std::vector<AccuracyMethod>& ms = methods[k];
        const int rounds = o.warmup + o.frames;
        int round = 0;
        const std::vector<std::vector<double>> times =
            timeMethods(renderer, scene, ms, o.frames, o.warmup, frame, [&](std::size_t j) {
                if (j == 0) ++round;
                const bool warm = round <= o.warmup;
                progress.update(format("%s: timing, %s round %d/%d, method %zu/%zu %s",
                                       where.c_str(), warm ? "untimed" : "timed", round, rounds,
                                       j + 1, ms.size(), ms[j].name.c_str()),
                                j == 0);
            });
        for (std::size_t j = 0; j < ms.size(); ++j) {
            const AccuracyMethod& m = ms[j];
            AccuracyResult r{name, m.axis, m.name, scene.camera.width, scene.camera.height};
            r.times = summarize(times[j]);
            renderer.render(scene, m.settings, frame);  // the image the error is measured on
            r.error = measureError(frame, truth);
            progress.finish(
                format("[%zu/%zu] %s %s %s: %.3f ms (min %.3f, max %.3f), RMSE %.3f, "
                       "PSNR %.2f dB, max %.1f, %.2f %% > 2 LSB",
                       ++done, total, name.c_str(), m.axis.c_str(), m.name.c_str(), r.times.median,
                       r.times.min, r.times.max, r.error.rmse, r.error.psnr, r.error.maxError,
                       100.0 * r.error.over2Lsb));
            results.push_back(r);
        }
    }
    std::fputs(accuracyTable(results).c_str(), stdout);

    int code = kOk;
    const std::filesystem::path dir(folder.value());
    const std::string csv = (dir / "accuracy.csv").string();
    const AccuracyRun run{o.samples, o.frames, o.warmup, o.quick, leftOut};
    if (Status st = writeAccuracyCsv(csv, machine, run, results); !st) {
        std::fprintf(stderr, "%s\n", st.error().what().c_str());
        code = kFailed;
    } else {
        std::printf("%s\n", csv.c_str());
    }
    if (!o.noChart) {
        const std::string png = (dir / "accuracy.png").string();
        std::string title = "facet accuracy: " + machine.cpu + ", " +
                            std::to_string(machine.cores) + " cores, load average " + machine.load +
                            " at start" +
                            (machineBusy(machine) ? " (BUSY: times indicative only)" : "") +
                            "; ground truth " + std::to_string(o.samples) + "x" +
                            std::to_string(o.samples) + " samples; " + machine.date;
        if (o.quick) title += "; --quick";
        if (Status st = writeAccuracyChart(png, o.gnuplot, title, results); !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            code = kFailed;
        } else {
            std::printf("%s\n", png.c_str());
        }
    }
    std::fprintf(stderr, "accuracy: done in %.0f s\n", secondsSince(runStart));
    return code;
}

}  // namespace

void addAccuracyCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<AccuracyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "accuracy",
        "Time each interpolation, filter, lighting and sampling method and measure its error "
        "against a supersampled ground truth: accuracy.csv and accuracy.png in a new folder");
    cmd->add_option("scenes", o->scenes, "Scene files or bare .off/.obj meshes")->required();
    cmd->add_option("-o,--out", o->out,
                    "Folder for accuracy.csv and accuracy.png (made if missing; files of those "
                    "names in it are replaced). Default: a new facet-accuracy-DATE-TIME folder "
                    "here");
    cmd->add_flag("--no-chart", o->noChart, "Write the CSV only (no gnuplot needed)");
    auto* quick = cmd->add_flag(
        "--quick", o->quick,
        "A smoke run of seconds: images at most 128 px wide, a 2x2 truth, 1 timed frame and no "
        "warm-up (unless given)");
    auto* samples =
        cmd->add_option("--samples", o->samples,
                        "Ground-truth samples per pixel axis (N×N); only methods with fewer "
                        "samples per pixel are measured")
            ->check(CLI::Range(1, kMaxGroundTruthSamples))
            ->capture_default_str();
    auto* frames = cmd->add_option("--frames", o->frames,
                                   "Timed frames per method (median), taken round-robin over the "
                                   "methods")
                       ->check(CLI::Range(1, 100000))
                       ->capture_default_str();
    auto* warmup = cmd->add_option("--warmup", o->warmup, "Untimed frames per method first")
                       ->check(CLI::Range(0, 1000))
                       ->capture_default_str();
    cmd->add_option("--texture", o->texture,
                    "Texture for the scenes that have uvs but no texture of their own");
    cmd->add_option("--gnuplot", o->gnuplot, "The gnuplot executable")->capture_default_str();
    cmd->callback([o, &exitCode, quick, samples, frames, warmup] {
        AccuracyOptions run = *o;
        if (quick->count() > 0) {
            if (samples->count() == 0) run.samples = 2;
            if (frames->count() == 0) run.frames = 1;
            if (warmup->count() == 0) run.warmup = 0;
        }
        exitCode = runAccuracy(run);
    });
}

}  // namespace facet::app
