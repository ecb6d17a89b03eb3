// `facet inspect SCENE X Y [render options]`: the pixel inspector's history of one pixel
// (facet/inspect.hpp) printed as text, with the ground truth beside the final colour.

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "exit_code.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/framebuffer.hpp"
#include "facet/inspect.hpp"
#include "inspect_command.hpp"
#include "render_options.hpp"

namespace facet::app {
namespace {

/// A packed RGBA pixel as #RRGGBB.
std::string vec(const glm::vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4f, %.4f, %.4f)", v.x, v.y, v.z);
    return buf;
}

std::string depthText(double d) {
    if (std::isinf(d)) return "none (+inf)";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", d);
    return buf;
}

void printFragment(const InspectedFragment& f, std::size_t number, int samples) {
    const bool covered = f.coverage == CoverageResult::Covered;
    std::printf("\n#%zu triangle %zu", number, f.triangle);
    if (samples > 1) std::printf(" sample (%d, %d)", f.sample % samples, f.sample / samples);
    if (f.clipped) std::printf(" piece %d (clipped)", f.piece);
    std::printf(" %s-facing: %s\n", f.backFacing ? "back" : "front",
                covered    ? "COVERED"
                : f.onEdge ? "EXCLUDED by the top-left rule (centre on an edge that is not top or "
                             "left)"
                           : "EXCLUDED (centre outside an edge)");
    std::printf("  %-3s %8s  %-34s %-44s %-22s %s\n", "", "index", "world", "clip (x, y, z, w)",
                "screen px", "fixed (1/256 px)");
    for (int j = 0; j < 3; ++j) {
        const InspectedVertex& v = f.vertices[j];
        char world[64], clip[80], screen[48];
        std::snprintf(world, sizeof world, "(%.4f, %.4f, %.4f)", v.world.x, v.world.y, v.world.z);
        std::snprintf(clip, sizeof clip, "(%.2f, %.2f, %.4f, %.4f)", v.clip.x, v.clip.y, v.clip.z,
                      v.clip.w);
        std::snprintf(screen, sizeof screen, "(%.4f, %.4f)", v.screen.x, v.screen.y);
        std::printf("  %-3s %8u  %-34s %-44s %-22s (%lld, %lld)\n", vertexName(j), v.index, world,
                    clip, screen, static_cast<long long>(v.fixedX),
                    static_cast<long long>(v.fixedY));
    }
    std::printf("  edges at the centre (1/65536 px^2):");
    for (const InspectedEdge& e : f.edges)
        std::printf("  E(%s->%s) = %lld%s %s", vertexName(e.from), vertexName(e.to),
                    static_cast<long long>(e.value), e.topLeft ? " top-left" : "",
                    e.inside ? "in" : "OUT");
    std::printf("\n");
    if (!covered) return;
    if (f.depthTested)
        std::printf("  depth %s %s stored %s: %s\n", depthText(f.depth).c_str(),
                    f.passed ? "<" : ">=", depthText(f.storedDepth).c_str(),
                    f.passed ? "PASS (written)" : "FAIL (discarded)");
    else
        std::printf("  depth %s, not tested (Simple shader): written\n",
                    depthText(f.depth).c_str());
    std::printf("  weights: screen-linear %s  perspective %s  used %s\n",
                vec(f.screenWeights).c_str(), vec(f.perspectiveWeights).c_str(),
                vec(f.weights).c_str());
    if (f.hasColor) std::printf("  colour %s\n", vec(f.color).c_str());
    if (f.hasUv) std::printf("  uv (%.5f, %.5f)\n", f.uv.x, f.uv.y);
    if (f.hasNormal)
        std::printf("  normal %s  position %s\n", vec(f.normal).c_str(), vec(f.position).c_str());
    if (f.lit) {
        const InspectedLighting& l = f.lighting;
        std::printf(
            "  lighting: n.l %.4f  n.h %.4f  ambient %.4f + diffuse %.4f + specular %.4f "
            "= I %.4f\n",
            l.nDotL, l.nDotH, l.ambient, l.diffuse, l.specular, l.intensity);
    }
    if (f.textured) {
        std::printf("  texture: lod %.3f, %zu texel%s:", f.lod, f.texels.size(),
                    f.texels.size() == 1 ? "" : "s");
        for (const InspectedTexel& t : f.texels)
            std::printf("  L%d (%d, %d) %s x %.3f", t.level, t.x, t.y, vec(t.color).c_str(),
                        t.weight);
        std::printf("\n");
    }
    std::printf("  colour out %s = %s\n", vec(f.shaded).c_str(), hexFromRgba(f.rgba).c_str());
}

int runInspect(const RenderOptions& o, int x, int y, int truthSamples) {
    Scene scene;
    RenderSettings settings;
    if (const int code = prepareRender(o, "facet inspect", scene, settings); code != kOk)
        return code;
    if (x < 0 || y < 0 || x >= scene.camera.width || y >= scene.camera.height) {
        std::fprintf(stderr, "facet inspect: pixel (%d, %d) is outside the %dx%d image\n", x, y,
                     scene.camera.width, scene.camera.height);
        return kBadInput;
    }
    const PixelHistory h = inspectPixel(scene, settings, x, y);
    std::printf("pixel (%d, %d) of %s, %dx%d, %s %s %s, lighting %s\n", x, y, o.scene.c_str(),
                scene.camera.width, scene.camera.height, o.mode.c_str(),
                std::string(toString(settings.shader)).c_str(), o.interp.c_str(),
                std::string(toString(settings.lighting)).c_str());
    std::printf("final colour  %s  depth %s\n", hexFromRgba(h.finalColor).c_str(),
                depthText(h.finalDepth).c_str());
    if (settings.shader == ShaderKind::Depth)
        std::printf("  (depth shader: viridis over the frame's range %g .. %g)\n", h.depthNear,
                    h.depthFar);
    if (h.hasReference) {
        const glm::vec3 c(h.referenceColor);
        std::printf("reference     %s  %s  depth %s%s\n", hexFromRgba(h.referenceRgba).c_str(),
                    vec(c).c_str(), depthText(h.referenceDepth).c_str(),
                    h.referenceAmbiguous ? "  (ambiguous: rounding may decide it, rule 8)" : "");
    }
    if (truthSamples > 0) {
        const GroundTruth t = renderGroundTruthPixel(scene, settings, x, y, truthSamples);
        if (t.width == 1)
            std::printf("ground truth  %s  (%dx%d samples of the pixel, %.0f%% covered)\n",
                        vec(t.color[0]).c_str(), t.samples, t.samples, 100.0 * t.coverage[0]);
    }
    for (const std::string& note : h.notes) std::printf("note: %s\n", note.c_str());
    std::size_t covered = 0;
    for (const InspectedFragment& f : h.fragments)
        covered += f.coverage == CoverageResult::Covered ? 1 : 0;
    std::printf("%zu triangle%s with the pixel in its box: %zu fragment%s, %zu excluded\n",
                h.fragments.size(), h.fragments.size() == 1 ? "" : "s", covered,
                covered == 1 ? "" : "s", h.fragments.size() - covered);
    for (std::size_t i = 0; i < h.fragments.size(); ++i)
        printFragment(h.fragments[i], i + 1, h.samples);
    return kOk;
}

}  // namespace

void addInspectCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<RenderOptions>();
    auto x = std::make_shared<int>(0);
    auto y = std::make_shared<int>(0);
    auto samples = std::make_shared<int>(kDefaultGroundTruthSamples);
    CLI::App* cmd = app.add_subcommand(
        "inspect",
        "Why pixel X Y has its colour: every fragment that reached it, in draw order (coverage and "
        "the top-left rule, depth test, weights, interpolated values, lighting, texels), with the "
        "reference path's value and the ground truth");
    addRenderOptions(*cmd, *opts, "Interpolation: affine, perspective, subdivided[:N]",
                     RenderCommand::inspect);
    cmd->add_option("x", *x, "Pixel column (0 at the left)")->required();
    cmd->add_option("y", *y, "Pixel row (0 at the top)")->required();
    cmd->add_option("--truth-samples", *samples,
                    "Ground truth samples per pixel axis (0: no ground truth)")
        ->check(CLI::Range(0, kMaxGroundTruthSamples))
        ->capture_default_str();
    cmd->callback(
        [opts, x, y, samples, &exitCode] { exitCode = runInspect(*opts, *x, *y, *samples); });
}

}  // namespace facet::app
