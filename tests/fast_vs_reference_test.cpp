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
};

std::string caseName(const Case& c) {
    std::string name = std::filesystem::path(c.scene).filename().string();
    // Appends one piece at a time: GCC 12 warns falsely (-Wrestrict) on "_" + std::string.
    for (const std::string_view part :
         {facet::toString(c.mode), facet::toString(c.shader), facet::toString(c.interp)}) {
        name += '_';
        name += part;
    }
    if (c.cull) name += "_cull";
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

int channelDiff(std::uint32_t a, std::uint32_t b) {
    int worst = 0;
    for (int shift = 0; shift < 24; shift += 8) {
        const int ca = static_cast<int>((a >> shift) & 0xFF);
        const int cb = static_cast<int>((b >> shift) & 0xFF);
        worst = std::max(worst, std::abs(ca - cb));
    }
    return worst;
}

std::string hex(std::uint32_t rgba) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", rgba & 0xFF, (rgba >> 8) & 0xFF,
                  (rgba >> 16) & 0xFF);
    return buf;
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
    facet::Scene dollied;
    const facet::Scene* scene = loaded;
    if (c.dolly != 1.0) {
        dollied = *loaded;
        facet::Camera& cam = dollied.camera;
        cam.eye = cam.look + c.dolly * (cam.eye - cam.look);
        scene = &dollied;
    }

    facet::RenderSettings settings;
    settings.mode = c.mode;
    settings.shader = c.shader;
    settings.interp = c.interp;
    settings.cullBackFaces = c.cull;

    const facet::reference::Image ref = facet::reference::render(*scene, settings);
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    facet::Renderer renderer;
    facet::Framebuffer fast;
    const facet::RenderStats stats = renderer.render(*scene, settings, fast);
    ASSERT_EQ(fast.width, ref.width);
    ASSERT_EQ(fast.height, ref.height);
    ASSERT_EQ(fast.color.size(), refRgba.size());

    // Simple never writes depth, so there coverage can only be told by colour.
    const std::uint32_t background = facet::rgbaFromHex(settings.background);
    const bool byColour = c.shader == ShaderKind::Simple;
    std::size_t compared = 0, ambiguous = 0, differing = 0, offByOne = 0, covered = 0;
    int maxDiff = 0;
    std::ostringstream examples;
    int shown = 0;
    for (std::size_t i = 0; i < refRgba.size(); ++i) {
        if (ref.ambiguous[i]) {
            ++ambiguous;
            continue;
        }
        ++compared;
        const bool refCovered = byColour ? refRgba[i] != background : std::isfinite(ref.depth[i]);
        const bool fastCovered =
            byColour ? fast.color[i] != background : std::isfinite(fast.depth[i]);
        const int diff = channelDiff(refRgba[i], fast.color[i]);
        covered += refCovered ? 1 : 0;
        if (refCovered != fastCovered) {
            ++differing;
        } else {
            maxDiff = std::max(maxDiff, diff);
            offByOne += diff == 1 ? 1 : 0;
        }
        if ((refCovered != fastCovered || diff > 1) && shown < 8) {
            ++shown;
            const int x = static_cast<int>(i % static_cast<std::size_t>(ref.width));
            const int y = static_cast<int>(i / static_cast<std::size_t>(ref.width));
            examples << "\n  pixel (" << x << "," << y << "): ref " << hex(refRgba[i]) << " depth "
                     << ref.depth[i] << ", fast " << hex(fast.color[i]) << " depth "
                     << fast.depth[i];
        }
    }

    const std::string name = caseName(c);
    std::printf(
        "[fast-vs-ref] %-44s compared=%zu covered=%zu ambiguous=%zu differing=%zu "
        "maxdiff=%d offby1=%zu clipped=%zu\n",
        name.c_str(), compared, covered, ambiguous, differing, maxDiff, offByOne,
        stats.trianglesClipped);
    RecordProperty("compared", static_cast<int>(compared));
    RecordProperty("ambiguous", static_cast<int>(ambiguous));
    RecordProperty("differing", static_cast<int>(differing));
    RecordProperty("maxdiff", maxDiff);
    EXPECT_EQ(differing, 0u) << name << examples.str();
    EXPECT_LE(maxDiff, 1) << name << examples.str();
}

std::string paramName(const testing::TestParamInfo<Case>& param) {
    return caseName(param.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FastVsReference, testing::ValuesIn(allCases()), paramName);

}  // namespace
