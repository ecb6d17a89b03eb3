// Example: compare two ways of rendering one scene with the evaluation library: each one's
// error against the ground truth (the scene averaged over every pixel's square) and its time.
//
//   compare_settings scene.scene

#include <array>
#include <cstdio>
#include <utility>

#include "facet/camera.hpp"
#include "facet/evaluation/frame_times.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/render.hpp"
#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s SCENE\n", argv[0]);
        return 2;
    }
    facet::Result<facet::Scene> opened = facet::openSceneFile(argv[1]);
    if (!opened) {
        std::fprintf(stderr, "%s\n", opened.error().what().c_str());
        return 2;
    }
    // A small frame keeps the ground truth (16 reference samples per pixel here) quick.
    facet::Scene scene = opened.value();
    scene.camera = facet::resizedCamera(scene.camera, 320, 180);

    facet::RenderSettings base;
    facet::applyOpeningSettings(scene, base);
    facet::RenderSettings affine = base;
    affine.interp = facet::Interp::Affine;
    facet::RenderSettings supersampled = base;
    supersampled.supersample = 2;

    const facet::Result<facet::GroundTruth> made = facet::renderGroundTruth(scene, base, 4);
    if (!made) {
        std::fprintf(stderr, "ground truth: %s\n", made.error().message.c_str());
        return 1;
    }
    const facet::GroundTruth& truth = *made;
    facet::Renderer renderer;
    facet::Framebuffer frame;
    const std::array<std::pair<const char*, facet::RenderSettings>, 3> methods{
        {{"affine", affine}, {"perspective", base}, {"supersample 2x2", supersampled}}};
    for (const auto& method : methods) {
        const char* name = method.first;
        const facet::RenderSettings& settings = method.second;
        bool ok = true;
        const facet::FrameTimes times = facet::timeRepeated(
            5, [&] { ok = ok && renderer.render(scene, settings, frame).ok(); });
        if (!ok) {
            std::fprintf(stderr, "%s: %s\n", name,
                         renderer.render(scene, settings, frame).error().what().c_str());
            return 2;
        }
        const facet::ImageError error = facet::measureError(frame, truth);
        std::printf("%-16s RMSE %6.3f LSB  PSNR %5.1f dB  median %7.3f ms\n", name, error.rmse,
                    error.psnr, times.median);
    }
    return 0;
}
