// `facet accuracy`: how far each of the engine's approximations lands from the ground truth
// (facet/ground_truth.hpp) and what it costs, measured in the same run: per scene and method,
// the engine's median time per frame and its error (RMSE, PSNR, max, share over 2 LSB).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "accuracy/accuracy_methods.hpp"
#include "commands.hpp"
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

struct AccuracyOptions {
    std::vector<std::string> scenes;
    std::string csv;
    std::string chart;
    std::string texture;  ///< for scenes with uvs but no texture of their own
    std::string gnuplot = "gnuplot";
    int samples = kDefaultGroundTruthSamples;
    int frames = 15;
    int warmup = 2;
};

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

int runAccuracy(const AccuracyOptions& o) {
    // Every scene loads before anything is measured, so bad input fails at once.
    std::vector<Scene> scenes;
    for (const std::string& path : o.scenes) {
        Result<Scene> scene = loadScene(path);
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
        // The reference image holds about 33 bytes per sub-sample (colour, depth, a flag).
        const Camera& cam = scene.value().camera;
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
    if (!o.chart.empty()) {
        if (Status st = checkGnuplot(o.gnuplot); !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            return kBadInput;
        }
    }
    const MachineInfo machine = collectMachineInfo();
    std::size_t total = 0;
    for (const Scene& s : scenes) total += accuracyMethods(s).size();

    std::vector<AccuracyResult> results;
    Renderer renderer;
    Framebuffer frame;
    std::size_t done = 0;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Scene& scene = scenes[k];
        const std::string name = std::filesystem::path(o.scenes[k]).stem().string();
        std::fprintf(stderr, "%s: ground truth %dx%d at %dx%d samples ... ", name.c_str(),
                     scene.camera.width, scene.camera.height, o.samples, o.samples);
        std::fflush(stderr);
        const auto start = std::chrono::steady_clock::now();
        const GroundTruth truth = renderGroundTruth(scene, baseSettings(scene), o.samples);
        std::fprintf(stderr, "%.1f s; timing %d frames per method, round-robin\n",
                     msSince(start) / 1000.0, o.frames);
        const std::vector<AccuracyMethod> methods = accuracyMethods(scene);
        const std::vector<std::vector<double>> times =
            timeMethods(renderer, scene, methods, o.frames, o.warmup, frame);
        for (std::size_t j = 0; j < methods.size(); ++j) {
            const AccuracyMethod& m = methods[j];
            AccuracyResult r{name, m.axis, m.name, scene.camera.width, scene.camera.height};
            r.times = summarize(times[j]);
            renderer.render(scene, m.settings, frame);  // the image the error is measured on
            r.error = measureError(frame, truth);
            std::fprintf(stderr,
                         "[%zu/%zu] %s %s %s: %.3f ms (min %.3f, max %.3f), RMSE %.3f, PSNR %.2f "
                         "dB, max %.1f, %.2f %% > 2 LSB\n",
                         ++done, total, name.c_str(), m.axis.c_str(), m.name.c_str(),
                         r.times.median, r.times.min, r.times.max, r.error.rmse, r.error.psnr,
                         r.error.maxError, 100.0 * r.error.over2Lsb);
            results.push_back(r);
        }
    }
    std::fputs(accuracyTable(results).c_str(), stdout);

    int code = kOk;
    if (!o.csv.empty()) {
        if (Status st = writeAccuracyCsv(o.csv, machine, o.samples, results); !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            code = kFailed;
        }
    }
    if (!o.chart.empty()) {
        const std::string title = "facet accuracy: " + machine.cpu + ", " +
                                  std::to_string(machine.cores) + " cores; ground truth " +
                                  std::to_string(o.samples) + "x" + std::to_string(o.samples) +
                                  " samples; " + machine.date;
        if (Status st = writeAccuracyChart(o.chart, o.gnuplot, title, results); !st) {
            std::fprintf(stderr, "%s\n", st.error().what().c_str());
            code = kFailed;
        }
    }
    return code;
}

}  // namespace

void addAccuracyCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<AccuracyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "accuracy",
        "Time each interpolation, filter and lighting method and measure its error "
        "against a supersampled ground truth");
    cmd->add_option("scenes", o->scenes, "Scene files")->required();
    cmd->add_option("--csv", o->csv, "Write every measurement to this CSV file");
    cmd->add_option("--chart", o->chart, "Draw a PNG chart (time against RMSE) with gnuplot");
    cmd->add_option("--samples", o->samples, "Ground-truth samples per pixel axis (N×N)")
        ->check(CLI::Range(1, kMaxGroundTruthSamples))
        ->capture_default_str();
    cmd->add_option("--frames", o->frames,
                    "Timed frames per method (median), taken round-robin over the methods")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_option("--warmup", o->warmup, "Untimed frames per method first")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    cmd->add_option("--texture", o->texture,
                    "Texture for the scenes that have uvs but no texture of their own");
    cmd->add_option("--gnuplot", o->gnuplot, "The gnuplot executable")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runAccuracy(*o); });
}

}  // namespace facet::app
