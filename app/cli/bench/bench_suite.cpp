#include "bench_suite.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <regex>

#include "bench_scenes.hpp"

namespace facet::app {
namespace {

/// A case by name, built only when selected (the 1M-triangle sphere takes a moment).
struct CaseSpec {
    std::string name;
    CaseSeries series;
    std::function<Result<BenchCase>()> build;
};

/// A generated sphere: its own uvs, the checker texture.
BenchCase sphereCase(std::string name, CaseSeries series, int triangles, int width, int height) {
    return BenchCase{std::move(name), "generated UV sphere, checker texture", series,
                     sphereScene(triangles, width, height)};
}

/// The fill-bound case: full-screen quads, back to front.
BenchCase overdrawCase(std::string name, int layers, int width, int height) {
    return BenchCase{std::move(name),
                     "generated: " + std::to_string(layers) +
                         " full-screen quads drawn back to front (every layer shaded), checker "
                         "texture",
                     CaseSeries::Suite, overdrawScene(layers, width, height)};
}

/// A .scene file from the shared data at a size (0: its own), completed for texturing.
CaseSpec fileCase(std::string name, std::string path, int width, int height,
                  std::string fallbackTexture = "") {
    return {name, CaseSeries::Suite, [=]() -> Result<BenchCase> {
                if (!std::filesystem::exists(path))
                    return Error{{path, 0}, "missing (the shared data; see --shared DIR)"};
                Result<Scene> s = fileScene(path, width, height);
                if (!s) return s.error();
                BenchCase c{name, "", CaseSeries::Suite, std::move(s).value()};
                c.notes = completeForTexturing(c.scene, fallbackTexture);
                return c;
            }};
}

std::vector<CaseSpec> suiteSpecs(const std::string& shared, bool quick) {
    if (quick)
        return {
            {"sphere_quick", CaseSeries::Suite,
             [] { return sphereCase("sphere_quick", CaseSeries::Suite, 4096, 160, 90); }},
            {"overdraw_quick", CaseSeries::Suite,
             [] { return overdrawCase("overdraw_quick", 8, 192, 108); }},
        };
    const std::string course = shared + "/data/course/";
    const std::string scenes = shared + "/data/scenes/";
    return {
        fileCase("example0", course + "example0.scene", 0, 0),
        fileCase("example1", course + "example1.scene", 0, 0),
        fileCase("example2", course + "example2.scene", 0, 0),
        // The course's textured facet names no image; docs/cli.md renders it with brick.jpg.
        fileCase("example_textured", course + "example_textured.scene", 0, 0, course + "brick.jpg"),
        fileCase("bunny_720p", scenes + "bunny_1280x720.scene", 1280, 720),
        fileCase("bunny_1080p", scenes + "bunny_1920x1080.scene", 1920, 1080),
        fileCase("spot_720p", scenes + "spot_1280x720.scene", 1280, 720),
        fileCase("spot_1080p", scenes + "spot_1920x1080.scene", 1920, 1080),
        {"sphere1m_1080p", CaseSeries::Suite,
         [] { return sphereCase("sphere1m_1080p", CaseSeries::Suite, 1 << 20, 1920, 1080); }},
        {"overdraw8_2160p", CaseSeries::Suite,
         [] { return overdrawCase("overdraw8_2160p", 8, 3840, 2160); }},
    };
}

/// The --scaling sweeps: a sphere from 1k to 1M triangles at 1080p, and a 64k-triangle sphere
/// (framed by the height, so it covers the same share of every image) at 0.25 … 8 Mpixels, 16:9.
std::vector<CaseSpec> scalingSpecs(bool quick) {
    std::vector<CaseSpec> specs;
    const std::vector<int> tris = quick
                                      ? std::vector<int>{1024, 4096, 16384}
                                      : std::vector<int>{1024, 4096, 16384, 65536, 262144, 1048576};
    const int tw = quick ? 160 : 1920, th = quick ? 90 : 1080;
    for (int t : tris) {
        const std::string name =
            "tri_" + (t >= 1048576 ? std::to_string(t >> 20) + "M" : std::to_string(t >> 10) + "k");
        specs.push_back({name, CaseSeries::Triangles,
                         [=] { return sphereCase(name, CaseSeries::Triangles, t, tw, th); }});
    }
    const std::vector<double> mpix =
        quick ? std::vector<double>{0.01, 0.02, 0.04} : std::vector<double>{0.25, 0.5, 1, 2, 4, 8};
    const int meshTris = quick ? 4096 : 65536;
    for (double m : mpix) {
        const int w = static_cast<int>(std::lround(std::sqrt(m * 1e6 * 16.0 / 9.0)));
        const int h = static_cast<int>(std::lround(w * 9.0 / 16.0));
        char name[32];
        std::snprintf(name, sizeof name, "pix_%gM", m);
        const std::string n = name;
        specs.push_back({n, CaseSeries::Pixels,
                         [=] { return sphereCase(n, CaseSeries::Pixels, meshTris, w, h); }});
    }
    return specs;
}

std::vector<BenchConfig> allConfigs() {
    RenderSettings painter;  // solid, painter, perspective-correct, unlit
    RenderSettings gouraud = painter;
    gouraud.lighting = Lighting::Gouraud;
    RenderSettings phong = painter;
    phong.lighting = Lighting::Phong;
    RenderSettings textured = painter;
    textured.shader = ShaderKind::Texture;  // the texel alone: no lighting, no combine
    textured.filter = TextureFilter::Bilinear;
    // Gouraud multisampled 4×: the engine's MSAA against llvmpipe's in the same run.
    RenderSettings msaa4 = gouraud;
    msaa4.msaa = 4;
    return {{"painter", painter},
            {"gouraud", gouraud},
            {"phong", phong},
            {"textured", textured},
            {"gouraud_msaa4", msaa4}};
}

/// Compiles a filter; an empty pattern matches everything.
Result<std::regex> compileFilter(const std::string& pattern, const char* option) {
    try {
        return std::regex(pattern.empty() ? std::string(".*") : pattern);
    } catch (const std::regex_error& e) {
        return Error{{option, 0}, "'" + pattern + "' is not a valid regular expression"};
    }
}

}  // namespace

Result<BenchSuite> buildSuite(const BenchOptions& o) {
    // The sweeps chart one config; Gouraud is the middle of the road.
    const std::string configPattern = o.configs.empty() && o.scaling ? "^gouraud$" : o.configs;
    Result<std::regex> caseRe = compileFilter(o.cases, "--cases");
    if (!caseRe) return caseRe.error();
    Result<std::regex> configRe = compileFilter(configPattern, "--configs");
    if (!configRe) return configRe.error();

    BenchSuite suite;
    for (BenchConfig& c : allConfigs())
        if (std::regex_search(c.name, *configRe)) suite.configs.push_back(std::move(c));
    const std::vector<CaseSpec> specs =
        o.scaling ? scalingSpecs(o.quick) : suiteSpecs(sharedDir(o), o.quick);
    for (const CaseSpec& spec : specs) {
        if (!std::regex_search(spec.name, *caseRe)) continue;
        Result<BenchCase> c = spec.build();
        if (c)
            suite.cases.push_back(std::move(c).value());
        else
            suite.skipped.push_back({spec.name, c.error().what()});
    }
    return suite;
}

std::size_t triangleCount(const BenchCase& c) {
    return c.scene.mesh->triangleCount();
}

std::size_t pixelCount(const BenchCase& c) {
    return static_cast<std::size_t>(c.scene.camera.width) *
           static_cast<std::size_t>(c.scene.camera.height);
}

}  // namespace facet::app
