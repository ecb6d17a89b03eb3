// The fast path against the reference path on every shared scene, draw mode, shader and
// interpolation. Outside the reference's ambiguity mask the two must agree on coverage exactly
// and on colour within one 8-bit step. Each case prints one summary line:
//   [fast-vs-ref] <case> compared=<n> covered=<n> ambiguous=<n> differing=<n> maxdiff=<lsb>
//                 offby1=<n> clipped=<n>
// compared: unambiguous pixels; covered: those the reference drew; differing: coverage
// mismatches among them; maxdiff: largest channel difference in 8-bit steps where coverage
// agrees; offby1: pixels exactly one step apart; clipped: triangles the fast path clipped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "image_compare.hpp"

namespace {

using facet::DrawMode;
using facet::Interp;
using facet::ShaderKind;

struct Case {
    std::string scene;  ///< path relative to FACET_SHARED_DIR/data, without ".scene"
    DrawMode mode;
    ShaderKind shader;
    Interp interp;
    bool cull;
    double dolly = 1.0;  ///< eye moved to look + dolly·(eye - look): < 1 moves in, clips
    facet::Lighting lighting = facet::Lighting::Off;
    facet::TextureFilter filter = facet::TextureFilter::Bilinear;
    bool combine = false;
    bool normals = false;
    int subdivision = 8;
};

/// The course's textured facet names no texture; the course pairs it with the brick image.
std::string textureFor(const std::string& scene) {
    return scene == "course/example_textured" ? "course/brick.jpg" : "";
}

std::string caseName(const Case& c) {
    std::string name = std::filesystem::path(c.scene).filename().string();
    // Appends one piece at a time: GCC 12 warns falsely (-Wrestrict) on "_" + std::string.
    for (const std::string_view part :
         {facet::toString(c.mode), facet::toString(c.shader), facet::toString(c.interp)}) {
        name += '_';
        name += part;
    }
    if (c.interp == Interp::Subdivided) name += std::to_string(c.subdivision);
    if (c.cull) name += "_cull";
    if (c.lighting != facet::Lighting::Off) {
        name += '_';
        name += facet::toString(c.lighting);
    }
    if (c.shader == ShaderKind::Texture) {
        name += '_';
        name += facet::toString(c.filter);
        if (c.combine) name += "_combine";
    }
    if (c.normals) name += "_normals";
    if (c.dolly != 1.0) name += "_dolly" + std::to_string(static_cast<int>(c.dolly * 1000));
    return name;
}

// Every combination on every scene: in a Release build the whole file takes seconds.
std::vector<Case> allCases() {
    const std::vector<std::string> scenes{"course/example0",       "course/example1",
                                          "course/example2",       "course/example_textured",
                                          "scenes/bunny_1280x720", "scenes/bunny_1920x1080",
                                          "scenes/spot_1280x720",  "scenes/spot_1920x1080"};
    std::vector<Case> cases;
    for (const std::string& scene : scenes) {
        for (const DrawMode mode : {DrawMode::Vertices, DrawMode::Wireframe, DrawMode::Solid}) {
            for (const ShaderKind shader :
                 {ShaderKind::Simple, ShaderKind::Painter, ShaderKind::Depth}) {
                for (const Interp interp : {Interp::Affine, Interp::Perspective}) {
                    cases.push_back({scene, mode, shader, interp, false});
                    if (mode == DrawMode::Solid)
                        cases.push_back({scene, mode, shader, interp, true});
                }
            }
        }
    }
    // Gouraud lighting: lit vertex colours through every mode.
    for (const std::string& scene : scenes)
        for (const DrawMode mode : {DrawMode::Vertices, DrawMode::Wireframe, DrawMode::Solid})
            for (const Interp interp : {Interp::Affine, Interp::Perspective})
                cases.push_back({scene, mode, ShaderKind::Painter, interp, false, 1.0,
                                 facet::Lighting::Gouraud});
    // Phong: per-pixel lighting through every mode; subdivided colour interpolation.
    for (const std::string& scene : scenes) {
        for (const DrawMode mode : {DrawMode::Vertices, DrawMode::Wireframe, DrawMode::Solid})
            cases.push_back({scene, mode, ShaderKind::Painter, Interp::Perspective, false, 1.0,
                             facet::Lighting::Phong});
        cases.push_back({scene, DrawMode::Solid, ShaderKind::Painter, Interp::Affine, false, 1.0,
                         facet::Lighting::Phong});
        cases.push_back({scene, DrawMode::Solid, ShaderKind::Painter, Interp::Subdivided, false});
        cases.push_back({scene, DrawMode::Solid, ShaderKind::Painter, Interp::Subdivided, false,
                         1.0, facet::Lighting::Gouraud, facet::TextureFilter::Bilinear, false,
                         false, 32});
    }
    // Textures on the textured scenes: every filter × interpolation, then combined with each
    // lighting, lines and points.
    using facet::Lighting;
    using facet::TextureFilter;
    for (const std::string scene :
         {"course/example_textured", "scenes/spot_1280x720", "scenes/spot_1920x1080"}) {
        for (const TextureFilter filter :
             {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear})
            for (const Interp interp : {Interp::Affine, Interp::Subdivided, Interp::Perspective})
                cases.push_back({scene, DrawMode::Solid, ShaderKind::Texture, interp, false, 1.0,
                                 Lighting::Off, filter});
        for (const Lighting lighting : {Lighting::Off, Lighting::Gouraud, Lighting::Phong})
            cases.push_back({scene, DrawMode::Solid, ShaderKind::Texture, Interp::Perspective,
                             false, 1.0, lighting, TextureFilter::Trilinear, true});
        for (const DrawMode mode : {DrawMode::Vertices, DrawMode::Wireframe})
            cases.push_back({scene, mode, ShaderKind::Texture, Interp::Perspective, false, 1.0,
                             Lighting::Phong, TextureFilter::Bilinear, true});
    }
    // The normals display over each shader.
    for (const char* scene : {"course/example2", "scenes/bunny_1280x720"})
        for (const ShaderKind shader : {ShaderKind::Simple, ShaderKind::Painter, ShaderKind::Depth})
            cases.push_back({scene, DrawMode::Solid, shader, Interp::Perspective, false, 1.0,
                             Lighting::Off, TextureFilter::Bilinear, false, true});
    // Close-ups of the lit, textured cow: clipped triangles with every varying.
    for (const double dolly : {0.3, 0.1})
        for (const Interp interp : {Interp::Affine, Interp::Subdivided, Interp::Perspective})
            cases.push_back({"scenes/spot_1280x720", DrawMode::Solid, ShaderKind::Texture, interp,
                             false, dolly, Lighting::Phong, TextureFilter::Trilinear, true});
    // Close-ups with the eye near or inside the mesh: geometry crosses the near plane and runs
    // far beyond the image (near clipping, guard band, very long lines).
    for (const char* scene : {"course/example2", "scenes/bunny_1280x720", "scenes/spot_1280x720"}) {
        for (const double dolly : {0.3, 0.1, 0.02}) {
            for (const Interp interp : {Interp::Affine, Interp::Perspective}) {
                for (const DrawMode mode : {DrawMode::Wireframe, DrawMode::Solid}) {
                    for (const ShaderKind shader : {ShaderKind::Painter, ShaderKind::Depth}) {
                        cases.push_back({scene, mode, shader, interp, false, dolly});
                    }
                }
            }
        }
    }
    return cases;
}

std::string scenePath(const std::string& name) {
    return std::string(FACET_SHARED_DIR) + "/data/" + name + ".scene";
}

// Scenes are loaded once and shared by all their cases (the bunny OBJ is the slow part).
const facet::Scene* loadCached(const std::string& path, std::string& error) {
    static std::map<std::string, std::unique_ptr<facet::Scene>> cache;
    auto it = cache.find(path);
    if (it == cache.end()) {
        facet::Result<facet::Scene> loaded = facet::loadScene(path);
        if (!loaded.ok()) {
            error = loaded.error().what();
            return nullptr;
        }
        it = cache.emplace(path, std::make_unique<facet::Scene>(std::move(loaded).value())).first;
    }
    return it->second.get();
}

// Names the case in gtest's messages instead of dumping its bytes.
void PrintTo(const Case& c, std::ostream* os) {
    *os << caseName(c);
}

class FastVsReference : public testing::TestWithParam<Case> {};

TEST_P(FastVsReference, AgreesOutsideTheAmbiguityMask) {
    const Case& c = GetParam();
    const std::string path = scenePath(c.scene);
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data not found: " << path;
    std::string error;
    const facet::Scene* loaded = loadCached(path, error);
    ASSERT_NE(loaded, nullptr) << error;
    facet::Scene changed;
    const facet::Scene* scene = loaded;
    if (c.dolly != 1.0 || (c.shader == ShaderKind::Texture && !textureFor(c.scene).empty())) {
        changed = *loaded;
        facet::Camera& cam = changed.camera;
        cam.eye = cam.look + c.dolly * (cam.eye - cam.look);
        if (c.shader == ShaderKind::Texture && !textureFor(c.scene).empty()) {
            const std::string image =
                std::string(FACET_SHARED_DIR) + "/data/" + textureFor(c.scene);
            const facet::Status st = facet::loadSceneTexture(changed, image);
            ASSERT_FALSE(st.has_value()) << st->what();
        }
        scene = &changed;
    }

    facet::RenderSettings settings;
    settings.mode = c.mode;
    settings.shader = c.shader;
    settings.interp = c.interp;
    settings.cullBackFaces = c.cull;
    settings.lighting = c.lighting;
    settings.filter = c.filter;
    settings.combine = c.combine;
    settings.showNormals = c.normals;
    settings.subdivision = c.subdivision;

    const facet::reference::Image ref = facet::reference::render(*scene, settings);
    facet::Renderer renderer;
    facet::Framebuffer fast;
    const facet::RenderStats stats = renderer.render(*scene, settings, fast);
    ASSERT_EQ(fast.width, ref.width);
    ASSERT_EQ(fast.height, ref.height);

    const facet::test::Comparison r =
        facet::test::compare(fast, ref, c.shader, settings.background);
    const std::string name = caseName(c);
    std::printf(
        "[fast-vs-ref] %-44s compared=%zu covered=%zu ambiguous=%zu differing=%zu "
        "maxdiff=%d offby1=%zu clipped=%zu\n",
        name.c_str(), r.compared, r.covered, r.ambiguous, r.coverageDiffers, r.maxColorDiff,
        r.offByOne, stats.trianglesClipped);
    RecordProperty("compared", static_cast<int>(r.compared));
    RecordProperty("ambiguous", static_cast<int>(r.ambiguous));
    RecordProperty("differing", static_cast<int>(r.coverageDiffers));
    RecordProperty("maxdiff", r.maxColorDiff);
    EXPECT_EQ(r.coverageDiffers, 0u) << name << r.examples;
    EXPECT_LE(r.maxColorDiff, 1) << name << r.examples;
}

std::string paramName(const testing::TestParamInfo<Case>& param) {
    return caseName(param.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FastVsReference, testing::ValuesIn(allCases()), paramName);

}  // namespace
