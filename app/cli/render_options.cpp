#include "render_options.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "exit_code.hpp"
#include "facet/camera.hpp"
#include "facet/evaluation/frame_times.hpp"
#include "facet/image_io.hpp"
#include "facet/limits.hpp"
#include "facet/render.hpp"
#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"

namespace facet::app {
namespace {

/// Parses RRGGBB (an optional leading # or 0x is accepted).
bool parseHexColor(std::string text, std::uint32_t& rgb) {
    if (text.rfind("#", 0) == 0) text.erase(0, 1);
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0) text.erase(0, 2);
    if (text.size() != 6) return false;
    auto r = std::from_chars(text.data(), text.data() + 6, rgb, 16);
    return r.ec == std::errc{} && r.ptr == text.data() + 6;
}

/// Parses "X,Y,Z" (three finite numbers).
bool parseVec3(const std::string& text, glm::dvec3& v) {
    const char* p = text.data();
    const char* end = p + text.size();
    for (int i = 0; i < 3; ++i) {
        auto r = std::from_chars(p, end, v[i]);
        if (r.ec != std::errc{} || !std::isfinite(v[i])) return false;
        p = r.ptr;
        if (i < 2) {
            if (p == end || *p != ',') return false;
            ++p;
        }
    }
    return p == end;
}

}  // namespace

void addRenderOptions(CLI::App& cmd, RenderOptions& o, const std::string& interpHelp,
                      RenderCommand command) {
    const bool engine = command == RenderCommand::engine;
    const bool gl = command == RenderCommand::openGl;
    const bool inspect = command == RenderCommand::inspect;
    // An option the command does not use stays out of its --help; given anyway, prepareRender
    // refuses it with `why` rather than drawing what was not asked for.
    auto usedIf = [&o](CLI::Option* option, bool used, const char* why) {
        if (!used) {
            option->group("");
            o.unused.emplace_back(option, why);
        }
        return option;
    };
    // The options the viewer shares come from the one table; here the scene is required,
    // --interp is worded for the command, and --normals and --view are hidden where unused.
    const RegisteredOptions shared = addRenderOptionTable(cmd, o);
    shared.at("scene")->required();
    shared.at("--interp")->description(interpHelp);
    CLI::Option* output = cmd.add_option(
        "-o,--output", o.output, "Output image: a .png file, or - for the PNG on standard output");
    if (inspect)
        usedIf(output, false, "inspect writes no image: it prints the pixel's history");
    else
        output->required();
    constexpr const char* kOverlay =
        "inspect lists the triangles' fragments; overlays drawn after them are not part of a "
        "pixel's history (see them with facet render)";
    usedIf(shared.at("--normals"), !inspect, kOverlay);
    usedIf(cmd.add_flag("--legend", o.legend,
                        "Depth shader: draw a legend bar with the near and far depth it maps"),
           !inspect, kOverlay);
    usedIf(cmd.add_option("--normal-length", o.normalLength,
                          "Length of the normal segments in world units (implies --normals; "
                          "default: bounding-box diagonal / 100)")
               ->check(CLI::PositiveNumber),
           !inspect, kOverlay);
    cmd.add_option("--eye", o.eye, "Camera position X,Y,Z, replacing the scene's");
    cmd.add_option("--look", o.look, "Look-at point X,Y,Z, replacing the scene's");
    usedIf(cmd.add_option("--write-scene", o.writeScene,
                          "Also save the scene (mesh, camera, size, light, material, texture) as "
                          "a .scene file that renders the same image with the same options"),
           !inspect, "inspect writes no files (save the scene with facet render --write-scene)");
    cmd.add_option("--background", o.background, "Background colour, hex RRGGBB")
        ->capture_default_str();
    cmd.add_option("--near", o.nearPlane, "Near plane distance (default: 1/1000 of the mesh size)")
        ->check(CLI::NonNegativeNumber);
    usedIf(cmd.add_option("--point-size", o.pointSize, "Side of the vertex squares in pixels")
               ->check(CLI::Range(1, 64))
               ->capture_default_str(),
           !inspect, "inspect follows triangles (solid mode), not points");
    usedIf(cmd.add_option("--frames", o.frames, "Render N frames and print the median time")
               ->check(CLI::Range(1, 100000)),
           !inspect, "inspect follows one pixel once and times nothing");
    usedIf(cmd.add_option("--threads", o.threads, "Worker threads (0: all cores)")
               ->check(CLI::Range(0, 256))
               ->capture_default_str(),
           engine,
           gl ? "the OpenGL twin runs on the driver's threads (llvmpipe: set LP_NUM_THREADS)"
              : "inspect follows one pixel on one thread");
    usedIf(cmd.add_option("--subpixel-bits", o.subPixelBits,
                          "Fractional bits of the sub-pixel grid vertices snap to for coverage")
               ->check(CLI::Range(kMinSubPixelBits, kMaxSubPixelBits))
               ->capture_default_str(),
           !gl, "the OpenGL driver snaps vertices to its own sub-pixel grid (facet render has it)");
    usedIf(cmd.add_option("--supersample", o.supersample,
                          "Samples per pixel axis: render N×N times the pixels and average them "
                          "(anti-aliasing; solid mode)")
               ->check(CLI::Range(1, 4))
               ->capture_default_str(),
           !gl,
           "the OpenGL twin draws one sample per pixel (it multisamples with --msaa; facet "
           "render supersamples)");
    usedIf(shared.at("--view"), engine,
           gl ? "debug views are drawn by the CPU engine only (facet render --view)"
              : "inspect follows the shaded image (a debug view is facet render --view)");
    cmd.add_option("--msaa", o.msaa,
                   "Multisampling: coverage and depth at N standard sample positions per pixel, "
                   "shaded once per pixel, averaged (edges anti-aliased, not textures or "
                   "highlights; solid mode)")
        ->check(CLI::IsMember({1, 2, 4, 8}))
        ->capture_default_str();
    usedIf(cmd.add_flag("--stats", o.stats, "Print mesh and draw statistics"), !inspect,
           "inspect prints the pixel's history, not frame statistics");
}

int prepareRender(const RenderOptions& o, const char* command, Scene& scene,
                  RenderSettings& settings, DelayedProgress* progress) {
    auto bad = [command](const std::string& message) {
        std::fprintf(stderr, "%s: %s\n", command, message.c_str());
        return kBadInput;
    };
    for (const auto& [option, why] : o.unused)
        if (option->count() > 0)
            return bad("--" + option->get_lnames().front() + " has no use here: " + why);
    // Only PNG is written: another extension would get PNG bytes under a wrong name.
    if (!o.output.empty() && o.output != "-") {
        std::string ext = std::filesystem::path(o.output).extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".png")
            return bad("-o " + o.output +
                       ": only PNG is written; name the file .png, or give - for standard output");
    }
    // CLI11 has already checked the names against the option table's choices; the table's
    // check covers --interp and --size. The rest applies once the scene is loaded, over what it
    // opens with.
    if (Status st = checkRenderOptions(o); !st) return bad(st.error().what());
    settings.normalLength = o.normalLength;
    settings.depthLegend = o.legend;
    settings.nearPlane = o.nearPlane;
    settings.pointSize = o.pointSize;
    settings.threads = o.threads;
    settings.subPixelBits = o.subPixelBits;
    settings.supersample = o.supersample;
    settings.msaa = o.msaa;
    if (!parseHexColor(o.background, settings.background))
        return bad("--background wants a hex colour RRGGBB, got '" + o.background + "'");

    int w = 0, h = 0;
    if (!o.size.empty()) parseSize(o.size, w, h);  // checked above
    const bool bareMesh = fileKind(o.scene) == FileKind::mesh;
    if (!o.up.empty() && !bareMesh)
        return bad("--up frames a bare .off/.obj mesh; " + o.scene +
                   " is not one (a .scene has its own camera: use --eye and --look)");
    glm::dvec3 eye{0.0}, look{0.0};
    if (!o.eye.empty() && !parseVec3(o.eye, eye))
        return bad("--eye wants X,Y,Z (three numbers), got '" + o.eye + "'");
    if (!o.look.empty() && !parseVec3(o.look, look))
        return bad("--look wants X,Y,Z (three numbers), got '" + o.look + "'");
    OpenOptions open;
    open.width = w > 0 ? w : kBareMeshWidth;
    open.height = w > 0 ? h : kBareMeshHeight;
    if (!o.up.empty()) open.up = *parseUpAxis(o.up);
    if (progress) progress->phase("loading " + o.scene);
    Result<Scene> loaded = openSceneFile(o.scene, open, progress ? progress->control() : nullptr);
    if (!loaded) return bad(loaded.error().what());
    scene = std::move(loaded).value();
    if (!o.texture.empty()) {
        if (progress) progress->phase("loading " + o.texture);
        if (Status st =
                loadSceneTexture(scene, o.texture, progress ? progress->control() : nullptr);
            !st)
            return bad(st.error().what());
    }
    // One rule for what a scene opens with, whichever route opened it (spec §9): the
    // viewer's, so a bare mesh and the scene written from it render alike; options override it.
    applyOpeningSettings(scene, settings);
    if (Status st = applyRenderOptions(o, settings); !st) return bad(st.error().what());
    settings.showNormals = o.normals || o.normalLength > 0.0;
    if (settings.shader == ShaderKind::Texture && !scene.texture)
        return bad(o.scene +
                   ": the texture shader needs a texture: the scene names none (line 10 "
                   "or an OBJ map_Kd); give one with --texture IMAGE");
    if (settings.shader == ShaderKind::Texture && !scene.mesh->hasUvs())
        std::fprintf(stderr,
                     "%s: warning: %s has no texture coordinates; every pixel samples "
                     "uv = (0, 0)\n",
                     command, scene.meshPath.c_str());
    // Options the others leave without effect: one line each, naming what they need.
    auto warn = [command](const char* message) {
        std::fprintf(stderr, "%s: warning: %s\n", command, message);
    };
    if (settings.shader != ShaderKind::Texture) {
        if (o.combine || o.noCombine)
            warn("--combine and --no-combine apply to the texture shader (--shader texture)");
        if (!o.filter.empty()) warn("--filter applies to the texture shader (--shader texture)");
    }
    if (o.legend && settings.shader != ShaderKind::Depth)
        warn("--legend is the depth shader's legend (--shader depth)");
    if (settings.mode != DrawMode::Solid && (o.supersample > 1 || o.msaa > 1))
        warn("--supersample and --msaa apply to triangles (--mode solid)");
    if (!bareMesh && w > 0)
        scene.camera = resizedCamera(scene.camera, w, h);  // the horizontal field of view stays
    if (!o.eye.empty()) scene.camera.eye = eye;
    if (!o.look.empty()) scene.camera.look = look;
    // Refused before --write-scene and before the renderer allocates anything: the engine's
    // own check (Renderer::render makes the same), so the messages are the library's.
    if (Status st = checkFrame(scene.camera, settings); !st) return bad(st.error().what());
    if (!o.writeScene.empty()) {
        if (Status st = writeScene(scene, o.writeScene); !st) {
            std::fprintf(stderr, "%s: %s\n", command, st.error().what().c_str());
            return kFailed;
        }
    }
    return kOk;
}

Status writeOutput(const Framebuffer& frame, const std::string& output,
                   const LoadControl* control) {
    if (output != "-") return writePng(frame, output, control);
    Result<std::string> bytes = encodePng(frame, control);
    if (!bytes) return bytes.error();
    if (std::fwrite(bytes.value().data(), 1, bytes.value().size(), stdout) !=
            bytes.value().size() ||
        std::fflush(stdout) != 0)
        return Error{{"standard output", 0}, "cannot write the PNG"};
    return {};
}

std::FILE* reportStream(const std::string& output) {
    return output == "-" ? stderr : stdout;
}

void printFrameTimes(std::vector<double> ms, std::FILE* out) {
    if (ms.size() < 2) return;
    const FrameTimes t = summarize(std::move(ms));
    std::fprintf(out, "median %.3f ms (min %.3f, max %.3f) over %d frames\n", t.median, t.min,
                 t.max, t.frames);
}

}  // namespace facet::app
