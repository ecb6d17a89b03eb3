// The viewer's document and its mappings, without a window: the first frame equals the engine's
// own render, a control change (Ks, light, background) shows in the very next frame, a
// malformed scene or texture keeps what was loaded, resizing keeps the framing, and the
// command line, layout, file lists, state file and frame timing behave.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <unistd.h>

#include "facet/camera.hpp"
#include "facet/limits.hpp"
#include "facet/render.hpp"
#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "file_list.hpp"
#include "frame_stats.hpp"
#include "layout.hpp"
#include "load_job.hpp"
#include "options.hpp"
#include "renderer_choice.hpp"
#include "resources.hpp"
#include "scene_defaults.hpp"
#include "settings_map.hpp"
#include "shared_data.hpp"
#include "state_file.hpp"
#include "test_files.hpp"
#include "viewer_model.hpp"

namespace {

using facet::test::sharedData;
using facet::test::testData;

namespace fs = std::filesystem;
using namespace facet;
using namespace facet::view;

const std::string kDefaultScene = std::string(FACET_ASSETS_DIR) + "/default.scene";

/// A model with the default scene loaded and one frame of the scene's size rendered.
ViewerModel loadedModel() {
    ViewerModel m;
    const Status error = m.load(kDefaultScene);
    EXPECT_TRUE(error) << error.error().what();
    m.prepareFrame(m.sceneCamera.width, m.sceneCamera.height);
    m.render();
    return m;
}

// ---------------------------------------------------------------------------------------------
// The document

TEST(ViewerModel, FirstFrameEqualsTheEngineRenderOfTheScene) {
    ViewerModel m = loadedModel();
    Result<Scene> scene = loadScene(kDefaultScene);
    ASSERT_TRUE(scene.ok());
    Renderer renderer;
    Framebuffer expected;
    renderer.render(*scene, RenderSettings{}, expected);
    ASSERT_EQ(m.frame.width, expected.width);
    ASSERT_EQ(m.frame.height, expected.height);
    EXPECT_TRUE(m.frame.color == expected.color);
}

TEST(ViewerModel, MaterialLightAndBackgroundChangesShowInTheNextFrame) {
    ViewerModel m = loadedModel();
    m.settings.lighting = Lighting::Gouraud;
    m.render();
    const std::vector<std::uint32_t> lit = m.frame.color;

    m.scene.lighting.material.ks = 0.0;  // what the Ks slider does
    m.render();
    EXPECT_FALSE(m.frame.color == lit) << "Ks = 0 left the frame unchanged";
    m.scene.lighting.material.ks = 0.4;
    m.render();
    EXPECT_TRUE(m.frame.color == lit) << "Ks back to 0.4 should restore the frame";

    m.scene.lighting.light.position.w = 0.0;  // point → directional
    m.render();
    EXPECT_FALSE(m.frame.color == lit);
    m.scene.lighting.light.position.w = 1.0;

    m.scene.lighting.ambient = 0.0;
    m.render();
    EXPECT_FALSE(m.frame.color == lit);
    m.scene.lighting.ambient = 0.6;

    m.settings.background = 0x102030;
    m.render();
    EXPECT_EQ(m.frame.color[0], rgbaFromHex(0x102030));
}

TEST(ViewerModel, MalformedScenesKeepTheOldOne) {
    ViewerModel m = loadedModel();
    const std::vector<std::uint32_t> before = m.frame.color;
    const std::string path = m.scene.path;
    const std::size_t triangles = m.scene.mesh->triangleCount();
    for (const char* bad :
         {"scene_nan.scene", "scene_inf.scene", "scene_light_3_numbers.scene",
          "scene_missing_mesh.scene", "scene_bad_mesh.scene", "scene_truncated.scene",
          "scene_corrupt_texture.scene", "no_such_file.scene"}) {
        const Status error = m.load(testData(bad));
        ASSERT_FALSE(error) << bad << " loaded";
        // The popup shows "file:line: message" (or "file: message") naming the file at fault,
        // the scene or the mesh it names.
        EXPECT_NE(error.error().what().find("tests/data/"), std::string::npos)
            << error.error().what();
        EXPECT_EQ(m.scene.path, path) << bad;
        EXPECT_EQ(m.scene.mesh->triangleCount(), triangles) << bad;
        m.prepareFrame(m.sceneCamera.width, m.sceneCamera.height);
        m.render();
        EXPECT_TRUE(m.frame.color == before) << bad << " changed the picture";
    }
    EXPECT_EQ(m.recent.size(), 1u);  // failures never join the recent list
    EXPECT_TRUE(m.load(testData("scene_valid.scene")));
    EXPECT_EQ(m.recent.size(), 2u);
    EXPECT_EQ(m.scene.camera.width, 320);
}

TEST(ViewerModel, ABadTextureKeepsTheOldOne) {
    ViewerModel m;
    ASSERT_TRUE(m.load(testData("scene_texture.scene")));
    ASSERT_TRUE(m.scene.texture);
    const Texture* before = m.scene.texture.get();
    EXPECT_FALSE(m.loadTexture(testData("tex_not_an_image.png")));
    EXPECT_FALSE(m.loadTexture(testData("no_such_texture.png")));
    EXPECT_EQ(m.scene.texture.get(), before);
    EXPECT_TRUE(m.loadTexture(testData("tex_4x4.png")));
    EXPECT_NE(m.scene.texture.get(), before);
    EXPECT_EQ(m.scene.texture->width(), 4);
}

// The files of an open scene replaced on disk (a broken texture, a truncated mesh, a pipe, an
// empty file): the loaded scene lives in memory, so frames stay the same, and reopening it fails
// with the file's name and keeps the last good scene.
TEST(ViewerModel, FilesReplacedOnDiskKeepTheLastGoodScene) {
    const fs::path dir = fs::temp_directory_path() /
                         ("facet-viewer-replaced-" +
                          std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(dir);
    for (const char* name : {"scene_texture.scene", "mesh_square.off", "texture_checker.png"})
        fs::copy_file(testData(name), dir / name, fs::copy_options::overwrite_existing);
    const std::string scenePath = (dir / "scene_texture.scene").string();
    ViewerModel m;
    ASSERT_TRUE(m.load(scenePath));
    m.prepareFrame(m.sceneCamera.width, m.sceneCamera.height);
    const std::vector<std::uint32_t> before = m.render().color;
    const std::size_t triangles = m.scene.mesh->triangleCount();
    const Texture* texture = m.scene.texture.get();

    auto replace = [&](const char* name, const std::string& text) {
        fs::remove(dir / name);
        std::ofstream(dir / name, std::ios::binary) << text;
    };
    auto expectKept = [&](const std::string& what, const std::string& fileAtFault) {
        m.prepareFrame(m.sceneCamera.width, m.sceneCamera.height);
        EXPECT_TRUE(m.render().color == before) << what << " changed the picture";
        const Status error = m.load(scenePath);
        ASSERT_FALSE(error) << what << ": reopening succeeded";
        EXPECT_NE(error.error().what().find(fileAtFault), std::string::npos)
            << error.error().what();
        EXPECT_EQ(m.scene.texture.get(), texture) << what;
        EXPECT_EQ(m.scene.mesh->triangleCount(), triangles) << what;
        m.prepareFrame(m.sceneCamera.width, m.sceneCamera.height);
        EXPECT_TRUE(m.render().color == before) << what << " changed the picture";
    };
    const std::string png = (dir / "texture_checker.png").string();
    const std::string off = (dir / "mesh_square.off").string();
    replace("texture_checker.png", "not an image any more");
    expectKept("a texture replaced by text", png);
    replace("texture_checker.png", "");
    expectKept("an emptied texture", png);
    fs::remove(png);
    ASSERT_EQ(::mkfifo(png.c_str(), 0600), 0);
    // Not a regular file: the scene's line 10 is reported as naming no file it can read.
    expectKept("a texture replaced by a pipe", "'texture_checker.png' not found");
    fs::remove(png);
    fs::copy_file(testData("texture_checker.png"), png);
    std::string mesh;
    {
        std::ifstream in(testData("mesh_square.off"), std::ios::binary);
        mesh.resize(static_cast<std::size_t>(fs::file_size(testData("mesh_square.off"))));
        in.read(mesh.data(), static_cast<std::streamsize>(mesh.size()));
    }
    replace("mesh_square.off", mesh.substr(0, mesh.size() / 2));
    expectKept("a truncated mesh", off);
    // Put back, the scene opens again.
    replace("mesh_square.off", mesh);
    EXPECT_TRUE(m.load(scenePath));
    std::error_code ec;
    fs::remove_all(dir, ec);
}

TEST(ViewerModel, MouseMovesTheViewAndResetRestoresIt) {
    ViewerModel m = loadedModel();
    const std::vector<std::uint32_t> start = m.frame.color;
    m.rotate(80.0, 30.0);
    m.prepareFrame(1280, 720);
    m.render();
    EXPECT_TRUE(m.orbitMoved);
    EXPECT_FALSE(m.frame.color == start);
    m.pan(20.0, 5.0);
    m.zoom(2.0);
    m.focal = 500.0;
    m.resetCamera();
    m.prepareFrame(1280, 720);
    m.render();
    EXPECT_FALSE(m.orbitMoved);
    EXPECT_EQ(m.focal, m.sceneCamera.focal);
    EXPECT_TRUE(m.frame.color == start);
}

TEST(ViewerModel, FollowingTheWindowKeepsTheFraming) {
    ViewerModel m = loadedModel();
    // The look-at point stays centred and a world point keeps its place relative to the height.
    const glm::dvec3 probe(0.5, 0.3, -0.2);
    const Camera big = m.prepareFrame(1280, 720);
    const glm::dvec3 a = projectToPixel(big, probe);
    const Camera small = m.prepareFrame(640, 360);
    EXPECT_EQ(small.width, 640);
    EXPECT_EQ(small.height, 360);
    EXPECT_DOUBLE_EQ(small.focal, 550.0);
    const glm::dvec3 b = projectToPixel(small, probe);
    EXPECT_NEAR((b.x - 320.0) * 2.0, a.x - 640.0, 1e-9);
    EXPECT_NEAR((b.y - 180.0) * 2.0, a.y - 360.0, 1e-9);
    // A wider window shows more at the sides, the same height.
    const Camera wide = m.prepareFrame(1920, 720);
    EXPECT_DOUBLE_EQ(wide.focal, 1100.0);
    m.sizePolicy = SizePolicy::SceneSize;
    const Camera kept = m.prepareFrame(300, 200);
    EXPECT_EQ(kept.width, 1280);
    EXPECT_EQ(kept.height, 720);
    EXPECT_DOUBLE_EQ(kept.focal, 1100.0);
}

// ---------------------------------------------------------------------------------------------
// Settings mapping

TEST(ViewerSettings, ComboIndicesFollowTheEngineNameLists) {
    for (DrawMode v : {DrawMode::Vertices, DrawMode::Wireframe, DrawMode::Solid}) {
        const auto names = drawModeNames();
        EXPECT_EQ(parseDrawMode(names[static_cast<std::size_t>(nameIndex(names, toString(v)))]), v);
    }
    for (ShaderKind v :
         {ShaderKind::Simple, ShaderKind::Painter, ShaderKind::Depth, ShaderKind::Texture}) {
        const auto names = shaderNames();
        EXPECT_EQ(parseShader(names[static_cast<std::size_t>(nameIndex(names, toString(v)))]), v);
    }
    for (Interp v : {Interp::Affine, Interp::Subdivided, Interp::Perspective}) {
        const auto names = interpNames();
        EXPECT_EQ(parseInterp(names[static_cast<std::size_t>(nameIndex(names, toString(v)))]), v);
    }
    for (Lighting v : {Lighting::Off, Lighting::Gouraud, Lighting::Phong}) {
        const auto names = lightingNames();
        EXPECT_EQ(parseLighting(names[static_cast<std::size_t>(nameIndex(names, toString(v)))]), v);
    }
    for (TextureFilter v :
         {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear}) {
        const auto names = filterNames();
        EXPECT_EQ(parseFilter(names[static_cast<std::size_t>(nameIndex(names, toString(v)))]), v);
    }
    EXPECT_EQ(nameIndex(drawModeNames(), "sketch"), 0);
}

TEST(ViewerSettings, BackgroundColourRoundTripsAndClamps) {
    for (std::uint32_t hex : {0x000000u, 0xFFFFFFu, 0x5C5C5Cu, 0x123456u, 0xFE01A0u}) {
        float rgb[3];
        rgbFromHex(hex, rgb);
        EXPECT_EQ(hexFromRgb(rgb), hex);
    }
    const float odd[3] = {-1.0f, 2.0f, NAN};
    EXPECT_EQ(hexFromRgb(odd), 0x00FF00u);
}

TEST(ViewerSettings, InterpolationChoiceWithItsN) {
    RenderSettings s;
    applyInterp(s, {Interp::Subdivided, 8});
    EXPECT_EQ(s.interp, Interp::Subdivided);
    EXPECT_EQ(s.subdivision, 8);
    applyInterp(s, {Interp::Subdivided, 100000});
    EXPECT_EQ(s.subdivision, kMaxSubdivision);
    applyInterp(s, {Interp::Subdivided, 0});
    EXPECT_EQ(s.subdivision, kMinSubdivision);
    EXPECT_EQ(interpOf(s).interp, Interp::Subdivided);
    EXPECT_EQ(interpLabel({Interp::Subdivided, 16}), "subdivided 16");
    EXPECT_EQ(interpLabel({Interp::Affine, 16}), "affine");
}

TEST(ViewerSettings, FrameCameraScalesFocalByTheHeight) {
    Camera scene;
    scene.focal = 1000.0;
    scene.width = 1000;
    scene.height = 500;
    const Camera c = frameCamera(scene, SizePolicy::FollowWindow, 400, 250);
    EXPECT_EQ(c.width, 400);
    EXPECT_EQ(c.height, 250);
    EXPECT_DOUBLE_EQ(c.focal, 500.0);
    const Camera z = frameCamera(scene, SizePolicy::FollowWindow, 0, -5);
    EXPECT_EQ(z.width, 1);
    EXPECT_EQ(z.height, 1);
    const Camera k = frameCamera(scene, SizePolicy::SceneSize, 400, 250);
    EXPECT_EQ(k.width, 1000);
    EXPECT_DOUBLE_EQ(k.focal, 1000.0);
}

// ---------------------------------------------------------------------------------------------
// Command line

ParsedOptions parse(const std::vector<const char*>& args) {
    std::vector<const char*> argv{"facet-view"};
    argv.insert(argv.end(), args.begin(), args.end());
    return parseOptions(static_cast<int>(argv.size()), argv.data());
}

TEST(ViewerOptions, ParsesTheTestAndBenchmarkOptions) {
    const ParsedOptions p = parse({"my.scene",
                                   "--frames",
                                   "7",
                                   "--size",
                                   "800x600",
                                   "--no-vsync",
                                   "--fps-report",
                                   "--screenshot",
                                   "a.png",
                                   "--window-shot",
                                   "b.png",
                                   "--state",
                                   "s.txt",
                                   "--shader",
                                   "texture",
                                   "--interp",
                                   "subdivided:8",
                                   "--lighting",
                                   "phong",
                                   "--compare",
                                   "--texture",
                                   "t.png",
                                   "--keep-scene-size",
                                   "--cull",
                                   "--combine",
                                   "--normals",
                                   "--view",
                                   "depth-test"});
    ASSERT_FALSE(p.exit) << p.text;
    const ViewerOptions& o = p.options;
    EXPECT_EQ(o.scene, "my.scene");
    EXPECT_EQ(o.frames, 7);
    EXPECT_EQ(o.width, 800);
    EXPECT_EQ(o.height, 600);
    EXPECT_TRUE(o.noVsync && o.fpsReport && o.compare && o.keepSceneSize);
    EXPECT_EQ(o.screenshot, "a.png");
    EXPECT_EQ(o.windowShot, "b.png");
    EXPECT_EQ(o.statePath, "s.txt");
    EXPECT_EQ(o.texture, "t.png");
    RenderSettings s;
    ASSERT_TRUE(facet::app::applyRenderOptions(o, s));
    EXPECT_EQ(s.shader, ShaderKind::Texture);
    EXPECT_EQ(s.interp, Interp::Subdivided);
    EXPECT_EQ(s.subdivision, 8);
    EXPECT_EQ(s.lighting, Lighting::Phong);
    EXPECT_TRUE(s.cullBackFaces && s.combine && s.showNormals);
    EXPECT_EQ(s.view, facet::DebugView::DepthTest);
    EXPECT_TRUE(parse({"--view", "heat"}).exit);
}

TEST(ViewerOptions, TheRendererChoiceAndHowItGoesWithCompare) {
    EXPECT_EQ(parse({}).options.renderer, "cpu");
    for (const char* name : {"cpu", "gl", "split"}) {
        const ParsedOptions p = parse({"--renderer", name});
        ASSERT_FALSE(p.exit) << p.text;
        EXPECT_EQ(p.options.renderer, name);
        EXPECT_TRUE(parseRenderer(p.options.renderer).has_value());
    }
    // --difference alone is the interpolation Compare's heat map; with the twin beside the
    // engine it is theirs, and Compare stays off.
    const ParsedOptions cpuHeat = parse({"--difference"});
    EXPECT_TRUE(cpuHeat.options.compare && cpuHeat.options.difference);
    const ParsedOptions splitHeat = parse({"--renderer", "split", "--difference"});
    ASSERT_FALSE(splitHeat.exit) << splitHeat.text;
    EXPECT_FALSE(splitHeat.options.compare);
    EXPECT_TRUE(splitHeat.options.difference);
    for (std::vector<const char*> args : {std::vector<const char*>{"--renderer", "vulkan"},
                                          {"--renderer", "gl", "--compare"},
                                          {"--renderer", "split", "--compare"}}) {
        const ParsedOptions p = parse(args);
        EXPECT_TRUE(p.exit) << args[1];
        EXPECT_EQ(p.exitCode, 2) << args[1];
        EXPECT_EQ(p.text.find('\n'), std::string::npos) << p.text;
    }
    EXPECT_NE(parse({"--help"}).text.find("--renderer"), std::string::npos);
}

TEST(ViewerOptions, BadInputIsExitCode2WithOneLine) {
    for (std::vector<const char*> args : {std::vector<const char*>{"--size", "0x10"},
                                          {"--size", "big"},
                                          {"--frames", "-1"},
                                          {"--mode", "sketch"},
                                          {"--interp", "subdivided:1"},
                                          {"--frobnicate"},
                                          {"a", "b"}}) {
        const ParsedOptions p = parse(args);
        EXPECT_TRUE(p.exit) << args[0];
        EXPECT_EQ(p.exitCode, 2) << args[0];
        EXPECT_EQ(p.text.find('\n'), std::string::npos) << p.text;
    }
    const ParsedOptions help = parse({"--help"});
    EXPECT_TRUE(help.exit);
    EXPECT_EQ(help.exitCode, 0);
    for (const char* opt : {"--frames", "--screenshot", "--window-shot", "--size", "--no-vsync",
                            "--fps-report", "--state", "--compare", "--texture"})
        EXPECT_NE(help.text.find(opt), std::string::npos) << opt;
}

// ---------------------------------------------------------------------------------------------
// Layout, files, state, timing

TEST(ViewerLayout, LetterboxKeepsTheAspectAndCentres) {
    const Rect same = letterbox(1280, 720, 1280, 720);
    EXPECT_EQ(same.x, 0);
    EXPECT_EQ(same.y, 0);
    EXPECT_EQ(same.w, 1280);
    EXPECT_EQ(same.h, 720);
    const Rect wide = letterbox(1280, 720, 640, 480);  // bars above and below
    EXPECT_EQ(wide.w, 640);
    EXPECT_EQ(wide.h, 360);
    EXPECT_EQ(wide.y, 60);
    const Rect tall = letterbox(512, 512, 1280, 720);  // bars left and right
    EXPECT_EQ(tall.w, 720);
    EXPECT_EQ(tall.h, 720);
    EXPECT_EQ(tall.x, 280);
    const Rect tiny = letterbox(kMaxImageSide, 1, 100, 100);
    EXPECT_GE(tiny.h, 1);
    EXPECT_EQ(letterbox(10, 10, 0, 5).w, 0);
    const glm::dvec2 p = windowToFrame(wide, 1280, 720, {320.0, 240.0});
    EXPECT_DOUBLE_EQ(p.x, 640.0);
    EXPECT_DOUBLE_EQ(p.y, 360.0);
    EXPECT_DOUBLE_EQ(frameScale(wide, 1280), 2.0);
}

TEST(ViewerFiles, ListsScenesRecentAndFreeNames) {
    std::string error;
    const auto files = listSceneFiles(FACET_TEST_DATA, &error);
    EXPECT_TRUE(error.empty()) << error;
    EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
    EXPECT_NE(std::find(files.begin(), files.end(), testData("scene_valid.scene")), files.end());
    for (const auto& f : files) EXPECT_EQ(fs::path(f).extension(), ".scene") << f;
    EXPECT_TRUE(listSceneFiles("/no/such/folder", &error).empty());
    EXPECT_FALSE(error.empty());

    std::vector<std::string> recent;
    pushRecent(recent, "/a.scene", 3);
    pushRecent(recent, "/b.scene", 3);
    pushRecent(recent, "/a.scene", 3);
    pushRecent(recent, "/c.scene", 3);
    pushRecent(recent, "/d.scene", 3);
    EXPECT_EQ(recent, (std::vector<std::string>{"/d.scene", "/c.scene", "/a.scene"}));

    // The process id keeps two builds' runs on one machine apart.
    const fs::path dir =
        fs::temp_directory_path() / ("facet_viewer_model_test_shots_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string first = nextFreePath(dir.string(), "shot");
    EXPECT_EQ(fs::path(first).filename(), "shot-0001.png");
    std::ofstream(first) << "x";
    EXPECT_EQ(fs::path(nextFreePath(dir.string(), "shot")).filename(), "shot-0002.png");
    fs::remove_all(dir);
}

TEST(ViewerState, TextHoldsTheViewLightAndMaterial) {
    ViewerModel m = loadedModel();
    m.rotate(10.0, 0.0);
    m.scene.lighting.material.ks = 0.25;
    m.prepareFrame(640, 360);
    const auto state = parseState(stateText(m, 42));
    EXPECT_EQ(state.at("frames"), "42");
    EXPECT_EQ(state.at("moved"), "1");
    EXPECT_NEAR(std::stod(state.at("yaw")), -3.0, 1e-12);
    EXPECT_NEAR(std::stod(state.at("distance")), m.orbit.distance, 1e-12);
    EXPECT_EQ(state.at("size"), "640 360");
    EXPECT_EQ(state.at("material").substr(0, 12), "0.5 0.699999");
    EXPECT_NE(state.at("material").find(" 0.25 "), std::string::npos) << state.at("material");
    EXPECT_EQ(state.at("scene"), m.scene.path);
    EXPECT_EQ(state.at("renderer"), "cpu");
    EXPECT_EQ(state.at("view"), "none");
    m.settings.view = facet::DebugView::BinLoad;
    EXPECT_EQ(parseState(stateText(m, 1)).at("view"), "bin-load");
    m.rendererChoice = RendererChoice::Split;
    EXPECT_EQ(parseState(stateText(m, 1)).at("renderer"), "split");
    EXPECT_FALSE(writeTextFile("/no/such/folder/state.txt", "x"));
}

TEST(ViewerState, TheRendererLogStaysOneLinePerKey) {
    RendererLog log;
    EXPECT_EQ(parseState(rendererLogText(log)).at("twin_error"), "");
    log.engineFrames = 7;
    log.twinFrames = 3;
    log.switches = 2;
    log.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
    log.error = "/s/twin.frag: 0:3(1): error: syntax error\nvariant:\n#define PHONG 1\n";
    const auto state = parseState(rendererLogText(log));
    EXPECT_EQ(state.at("engine_frames"), "7");
    EXPECT_EQ(state.at("twin_frames"), "3");
    EXPECT_EQ(state.at("renderer_switches"), "2");
    EXPECT_EQ(state.at("twin_device"), log.device);
    EXPECT_EQ(state.at("twin_error"),
              "/s/twin.frag: 0:3(1): error: syntax error | variant: | #define PHONG 1 | ");
    EXPECT_EQ(state.size(), 5u);
}

TEST(ViewerStats, MediansAndTheHistoryWindow) {
    FrameHistory h;
    h.window = 4;
    for (int i = 1; i <= 9; ++i) {
        StageTimes t;
        t.render = i;
        t.total = 10.0 * i;
        h.push(t);
    }
    EXPECT_EQ(h.plot.size(), 4u);
    EXPECT_FLOAT_EQ(h.plot.front(), 60.0f);
    EXPECT_FLOAT_EQ(h.plot.back(), 90.0f);
    EXPECT_DOUBLE_EQ(h.median().render, 5.0);
    EXPECT_DOUBLE_EQ(h.median(5).render, 7.5);  // frames 6..9
    EXPECT_DOUBLE_EQ(h.recentMedian(3).total, 80.0);
    const std::string line = fpsReport(h, 0);
    EXPECT_NE(line.find("median 20.0 fps"), std::string::npos) << line;  // 50 ms
    EXPECT_NE(line.find("over 9 frames"), std::string::npos) << line;
    h.capacity = 4;
    for (int i = 0; i < 10; ++i) h.push(StageTimes{});
    EXPECT_LE(h.frames.size(), 4u);
    EXPECT_EQ(h.dropped + h.frames.size(), 19u);
}

TEST(ViewerStats, EachRenderersMedianCountsOnlyTheFramesItRan) {
    // Three CPU frames, then the twin alone for four, then both for two.
    FrameHistory h;
    for (int i = 0; i < 3; ++i) h.push(StageTimes{.render = 10.0, .total = 20.0});
    for (int i = 0; i < 4; ++i)
        h.push(StageTimes{.twin = 6.0, .twinUpload = 1.0, .twinDraw = 4.0, .twinReadback = 1.0});
    for (int i = 0; i < 2; ++i) h.push(StageTimes{.render = 12.0, .twin = 8.0, .compare = 2.0});
    const StageTimes m = h.median();
    EXPECT_DOUBLE_EQ(m.render, 10.0);  // the 5 frames it ran: 10 10 10 12 12
    EXPECT_DOUBLE_EQ(m.twin, 6.0);     // 6 6 6 6 8 8
    EXPECT_DOUBLE_EQ(m.twinDraw, 4.0);
    EXPECT_DOUBLE_EQ(m.compare, 0.0);  // every frame counts for the rest
    EXPECT_DOUBLE_EQ(h.recentMedian(2).render, 12.0);
    EXPECT_DOUBLE_EQ(FrameHistory{}.median().twin, 0.0);
    EXPECT_NE(fpsReport(h, 0).find("twin 6.00"), std::string::npos) << fpsReport(h, 0);
}

TEST(ViewerStats, TheReportSplitsTheUiIntoBuildingAndDrawing) {
    // llvmpipe draws the panels on the CPU: the report shows how much of the UI's time that is.
    FrameHistory h;
    for (int i = 1; i <= 3; ++i)
        h.push(StageTimes{.ui = 4.0 * i, .uiDraw = 3.0 * i, .total = 20.0});
    EXPECT_DOUBLE_EQ(h.median().uiDraw, 6.0);
    const std::string line = fpsReport(h, 0);
    EXPECT_NE(line.find("ui 8.00 (drawing 6.00)"), std::string::npos) << line;
}

TEST(ViewerResources, FindsTheDefaultScene) {
    const std::string scene = defaultScenePath();
    ASSERT_FALSE(scene.empty());
    EXPECT_TRUE(fs::exists(scene));
    EXPECT_EQ(findResource("no/such/file.txt", "/nowhere"), "");
}

// ---------------------------------------------------------------------------------------------
// Models as users bring them (issue 14): bare meshes, saving, defaults, the browser, drops,
// recent files across runs, loading on a worker thread.

const std::string kModels = sharedData("models");
const std::string kSpotScene = sharedData("scenes/spot_1280x720.scene");

/// A fresh folder per test, removed when the test passed.
fs::path scratchFolder() {
    const fs::path dir =
        fs::temp_directory_path() /
        ("facet_viewer_models_" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(ViewerModels, ABareMeshOpensLitAndATexturedSceneWithItsTexture) {
    REQUIRE_SHARED_DATA(kSpotScene);
    ViewerModel m;
    ASSERT_TRUE(m.load(kModels + "/teapot.obj"));
    EXPECT_TRUE(m.bareMesh);
    EXPECT_EQ(m.sceneCamera.width, kBareMeshWidth);
    EXPECT_EQ(m.settings.lighting, Lighting::Gouraud);
    EXPECT_EQ(m.settings.shader, ShaderKind::Painter);

    ASSERT_TRUE(m.load(kSpotScene));
    EXPECT_FALSE(m.bareMesh);
    EXPECT_EQ(m.settings.shader, ShaderKind::Texture);
    EXPECT_TRUE(m.settings.combine);
    EXPECT_EQ(m.settings.lighting, Lighting::Gouraud);
    EXPECT_EQ(noEffectNote(m.scene, m.settings), "");

    ASSERT_TRUE(m.load(kDefaultScene));  // no texture: the course's unlit painter
    EXPECT_EQ(m.settings.shader, ShaderKind::Painter);
    EXPECT_EQ(m.settings.lighting, Lighting::Off);
}

TEST(ViewerModels, LightingUnderTheTextureShaderTurnsCombineOnOrSaysWhy) {
    REQUIRE_SHARED_DATA(kSpotScene);
    ViewerModel m;
    ASSERT_TRUE(m.load(kSpotScene));
    RenderSettings& s = m.settings;
    s.combine = false;
    s.lighting = Lighting::Off;
    EXPECT_EQ(noEffectNote(m.scene, s), "");
    s.lighting = Lighting::Phong;
    EXPECT_NE(noEffectNote(m.scene, s).find("combine"), std::string::npos);
    lightingChosen(s);
    EXPECT_TRUE(s.combine);
    EXPECT_EQ(noEffectNote(m.scene, s), "");
    // The note is true: without combine the lit and unlit frames are the same picture.
    s.combine = false;
    m.prepareFrame(320, 180);
    const std::vector<std::uint32_t> lit = m.render().color;
    s.lighting = Lighting::Off;
    EXPECT_EQ(m.render().color, lit);

    ASSERT_TRUE(m.load(kModels + "/cow.obj"));
    s.shader = ShaderKind::Texture;
    EXPECT_NE(noEffectNote(m.scene, s).find("no texture"), std::string::npos);
}

TEST(ViewerModels, SavedAfterOrbitingTheFrameRendersByteForByte) {
    const fs::path dir = scratchFolder();
    for (const std::string& file : {kModels + "/cow.obj", kSpotScene}) {
        REQUIRE_SHARED_DATA(file);
        ViewerModel m;
        ASSERT_TRUE(m.load(file));
        m.rotate(37.0, -12.0);
        m.zoom(1.5);
        m.pan(5.0, 3.0);
        m.prepareFrame(800, 500);  // the window's size, not the scene's
        const Framebuffer shown = m.render();
        const std::string saved = (dir / (fs::path(file).stem().string() + ".scene")).string();
        ASSERT_TRUE(m.saveScene(saved, /*windowSize=*/true));
        EXPECT_EQ(m.recent.front(), fs::absolute(saved).lexically_normal().string());

        Result<Scene> back = loadScene(saved);
        ASSERT_TRUE(back) << back.error().what();
        EXPECT_EQ(back->camera.width, 800);
        Renderer renderer;
        Framebuffer again;
        renderer.render(*back, m.settings, again);
        EXPECT_EQ(again.color, shown.color) << file;

        // By default the scene keeps its own image size, with the view shown: it renders what
        // the viewer draws at that size (--keep-scene-size).
        ASSERT_TRUE(m.saveScene(saved));
        back = loadScene(saved);
        ASSERT_TRUE(back) << back.error().what();
        EXPECT_EQ(back->camera.width, m.sceneCamera.width);
        EXPECT_EQ(back->camera.height, m.sceneCamera.height);
        m.sizePolicy = SizePolicy::SceneSize;
        m.prepareFrame(800, 500);
        const Framebuffer atSceneSize = m.render();
        renderer.render(*back, m.settings, again);
        EXPECT_EQ(again.color, atSceneSize.color) << file;
    }
    fs::remove_all(dir);
}

TEST(ViewerModels, TheBrowserListsFoldersScenesMeshesAndImages) {
    const fs::path dir = scratchFolder();
    fs::create_directories(dir / "sub");
    fs::create_directories(dir / ".hidden");
    for (const char* f : {"b.scene", "a.OBJ", "c.off", "t.png", "notes.txt", ".x.obj"})
        std::ofstream(dir / f) << "x";
    const std::vector<FolderEntry> list = listFolder(dir.string());
    std::vector<std::string> names;
    for (const FolderEntry& e : list) names.push_back(e.name);
    EXPECT_EQ(names,
              (std::vector<std::string>{"..", "sub/", "a.OBJ", "b.scene", "c.off", "t.png"}));
    EXPECT_EQ(list[0].kind, EntryKind::parent);
    EXPECT_EQ(fs::path(list[0].path), dir.parent_path());
    EXPECT_EQ(list[1].kind, EntryKind::folder);
    EXPECT_EQ(list[2].kind, EntryKind::mesh);
    EXPECT_EQ(list[5].kind, EntryKind::image);
    // Going up from the parent entry lists the folder above.
    const std::vector<FolderEntry> up = listFolder(list[0].path);
    EXPECT_NE(
        std::find_if(up.begin(), up.end(),
                     [&](const FolderEntry& e) { return e.name == dir.filename().string() + "/"; }),
        up.end());
    std::string error;
    EXPECT_EQ(listFolder("/no/such/folder", &error).size(), 1u);  // just ".."
    EXPECT_NE(error.find("/no/such/folder"), std::string::npos);
    fs::remove_all(dir);
}

TEST(ViewerModels, ADropOpensMeshesAndScenesTexturesImagesAndRefusesTheRest) {
    REQUIRE_SHARED_DATA(kModels + "/spot_texture.png");
    REQUIRE_SHARED_DATA(kModels + "/spot_triangulated.obj");
    const fs::path dir = scratchFolder();
    std::ofstream(dir / "notes.txt") << "hello\n";
    std::ofstream(dir / "mesh.dat") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const DropPlan plan = planDrop({(dir / "notes.txt").string(), kModels + "/spot_texture.png",
                                    (dir / "mesh.dat").string(), dir.string()});
    EXPECT_EQ(plan.open, (dir / "mesh.dat").string());
    EXPECT_EQ(plan.texture, kModels + "/spot_texture.png");
    EXPECT_EQ(plan.folder, dir.string());
    ASSERT_EQ(plan.refused.size(), 1u);
    EXPECT_NE(plan.refused[0].find("notes.txt"), std::string::npos);

    // What the viewer then does with it: the mesh opens, the image textures Spot.
    ViewerModel m;
    ASSERT_TRUE(m.load(plan.open));
    EXPECT_TRUE(m.bareMesh);
    ASSERT_TRUE(m.load(kModels + "/spot_triangulated.obj"));
    ASSERT_TRUE(m.loadTexture(plan.texture));
    EXPECT_TRUE(m.scene.texture);
    fs::remove_all(dir);
}

TEST(ViewerModels, RecentFilesAndTheConfigFolderSurviveARestart) {
    REQUIRE_SHARED_DATA(kModels + "/cow.obj");
    const fs::path dir = scratchFolder();
    const char* oldXdg = std::getenv("XDG_CONFIG_HOME");
    const std::string keep = oldXdg ? oldXdg : "";
    setenv("XDG_CONFIG_HOME", (dir / "cfg").c_str(), 1);
    EXPECT_EQ(configFolder(), (dir / "cfg" / "facet").string());
    unsetenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (home) {
        EXPECT_EQ(configFolder(), (fs::path(home) / ".config" / "facet").string());
    }
    if (oldXdg) setenv("XDG_CONFIG_HOME", keep.c_str(), 1);

    const std::string file = (dir / "cfg" / "facet" / "recent.txt").string();
    {
        ViewerModel m;
        m.recentFile = file;
        ASSERT_TRUE(m.load(kDefaultScene));
        ASSERT_TRUE(m.load(kModels + "/cow.obj"));
    }
    ViewerModel next;  // a new run
    next.recent = readRecent(file, kMaxRecent);
    ASSERT_EQ(next.recent.size(), 2u);
    EXPECT_EQ(fs::path(next.recent[0]).filename(), "cow.obj");
    EXPECT_EQ(fs::path(next.recent[1]).filename(), "default.scene");
    EXPECT_TRUE(readRecent((dir / "none.txt").string(), kMaxRecent).empty());
    fs::remove_all(dir);
}

TEST(ViewerModels, LoadingRunsOnAWorkerAndCancelOrFailureKeepsTheOldScene) {
    const std::string nefertiti = kModels + "/nefertiti.obj";
    REQUIRE_SHARED_DATA(nefertiti);
    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    const std::size_t before = m.scene.mesh->triangleCount();

    LoadJob job;
    job.start(nefertiti, OpenOptions{640, 360});
    EXPECT_TRUE(job.running());
    // start() returns before the 100k-triangle file is read: the caller's frames go on.
    EXPECT_FALSE(job.take().has_value());
    // The bar moves while it reads; Cancel then drops the load, mid-read, and the scene stays.
    float seen = job.progress();
    for (int i = 0; i < 20000 && seen <= 0.0f; ++i) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        seen = job.progress();
    }
    EXPECT_GT(seen, 0.0f);
    EXPECT_LT(seen, 1.0f);
    job.cancel();
    EXPECT_FALSE(job.running());
    EXPECT_EQ(job.progress(), 0.0f);
    EXPECT_FALSE(job.take().has_value());
    EXPECT_EQ(m.scene.mesh->triangleCount(), before);

    job.start(nefertiti, OpenOptions{640, 360});
    std::optional<Result<LoadedScene>> done;
    std::vector<float> bar;  // what the loading window showed, frame by frame
    for (int i = 0; i < 6000 && !done; ++i) {
        bar.push_back(job.progress());
        done = job.take();
        if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(done.has_value());
    EXPECT_TRUE(std::is_sorted(bar.begin(), bar.end()));
    EXPECT_GT(bar.back(), 0.0f);
    ASSERT_TRUE(*done) << done->error().what();
    EXPECT_TRUE((*done)->bareMesh);
    EXPECT_EQ((*done)->scene.camera.width, 640);
    m.adopt(std::move(*done).value());
    EXPECT_GT(m.scene.mesh->triangleCount(), 99000u);

    job.start("/no/such/file.obj", OpenOptions{640, 360});
    for (int i = 0; i < 500 && !done; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    done.reset();
    for (int i = 0; i < 6000 && !done; ++i) {
        done = job.take();
        if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(done.has_value());
    EXPECT_FALSE(*done);
    EXPECT_NE(done->error().what().find("/no/such/file.obj"), std::string::npos);
    EXPECT_GT(m.scene.mesh->triangleCount(), 99000u);  // a failure changes nothing
}

TEST(ViewerModels, TheDefaultSavePathIsAFreeNameInTheOpenedFilesFolder) {
    EXPECT_EQ(defaultSavePath("/somewhere/read-only/teapot.obj"),
              "/somewhere/read-only/teapot.scene");
    const fs::path dir = scratchFolder();
    std::ofstream(dir / "teapot.scene") << "x";
    EXPECT_EQ(defaultSavePath((dir / "teapot.obj").string()), (dir / "teapot-0001.scene").string());
    // A relative name is made absolute: the save never lands silently in the working folder.
    const fs::path old = fs::current_path();
    fs::current_path(dir);
    EXPECT_EQ(defaultSavePath("teapot.obj"), (dir / "teapot-0001.scene").string());
    fs::current_path(old);
    fs::remove_all(dir);
}

}  // namespace

namespace {

// Conventions §9 by every route: a texture chosen in the browser, dropped, typed in the Texture
// panel or given as --texture all go through ViewerModel::loadTexture, which picks the settings
// that show it whatever was set before: the course's coloured wall shows the texel alone.
TEST(ViewerModels, ATextureByAnyRouteOpensWithTheSameSettings) {
    const std::string course = sharedData("course/");
    REQUIRE_SHARED_DATA(course + "textured_facet.off");
    Framebuffer first;
    for (const ShaderKind before : {ShaderKind::Depth, ShaderKind::Painter, ShaderKind::Texture}) {
        ViewerModel m;
        ASSERT_TRUE(m.load(course + "textured_facet.off"));
        m.settings.shader = before;
        m.settings.combine = true;
        m.settings.lighting = Lighting::Phong;
        ASSERT_TRUE(m.loadTexture(course + "brick.jpg"));
        RenderSettings expected = m.settings;
        applyOpeningSettings(m.scene, expected);
        EXPECT_EQ(m.settings, expected);
        EXPECT_EQ(m.settings.shader, ShaderKind::Texture);
        m.prepareFrame(640, 480);
        const Framebuffer& f = m.render();
        if (first.color.empty())
            first = f;
        else
            EXPECT_EQ(f.color, first.color);
    }
}

}  // namespace

namespace {

// Conventions §3b in the viewer: the up axis frames a bare mesh as --up does, is the axis the
// orbit turns about, and a saved scene carries it (its camera's up vector).
TEST(ViewerModels, TheUpAxisFramesOrbitsAndIsSavedWithTheScene) {
    const std::string cow = kModels + "/cow.obj";
    REQUIRE_SHARED_DATA(cow);
    ViewerModel opened;
    opened.up = UpAxis::Z;
    ASSERT_TRUE(opened.load(cow));
    EXPECT_EQ(opened.orbitAxis(), UpAxis::Z);
    ViewerModel chosen;
    ASSERT_TRUE(chosen.load(cow));
    EXPECT_EQ(chosen.orbitAxis(), UpAxis::Y);
    chosen.setUpAxis(UpAxis::Z);  // the Camera panel's choice: the same as opening with it
    EXPECT_EQ(chosen.sceneCamera, opened.sceneCamera);
    EXPECT_EQ(chosen.orbitAxis(), UpAxis::Z);

    // Orbiting turns about Z: the eye's height along Z stays.
    chosen.rotate(120.0, 0.0);
    const Camera& turned = chosen.prepareFrame(1280, 720);
    EXPECT_NEAR(turned.eye.z - turned.look.z, opened.sceneCamera.eye.z - opened.sceneCamera.look.z,
                1e-9);
    EXPECT_NE(turned.eye.x, opened.sceneCamera.eye.x);

    // Saved and opened again (with the default Y): still Z up.
    const fs::path dir = scratchFolder();
    const std::string saved = (dir / "cow_z.scene").string();
    ASSERT_TRUE(chosen.saveScene(saved));
    ViewerModel back;
    ASSERT_TRUE(back.load(saved));
    EXPECT_EQ(back.orbitAxis(), UpAxis::Z);

    // A .scene keeps the view shown when the axis changes; the orbit measures from the new one.
    ViewerModel scene;
    ASSERT_TRUE(scene.load(saved));
    const Camera before = scene.prepareFrame(1280, 720);
    scene.setUpAxis(UpAxis::Y);
    EXPECT_EQ(scene.orbitAxis(), UpAxis::Y);
    const Camera after = scene.prepareFrame(1280, 720);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(after.eye[i], before.eye[i], 1e-9);
        EXPECT_NEAR(after.look[i], before.look[i], 1e-9);
    }
    fs::remove_all(dir);
}

}  // namespace

namespace {

// The simple shader's see-through patchwork is explained where the shader is chosen.
// A frame the engine refuses (checkFrame) is not a crash or a silent black frame: the model keeps
// the last image and says why (the window shows it over the image), until a frame draws again.
TEST(ViewerModels, ARefusedRenderSaysWhyAndTheNextGoodOneClearsIt) {
    ViewerModel m;
    ASSERT_TRUE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    m.prepareFrame(64, 48);
    m.render();
    EXPECT_EQ(m.refused, "");
    const std::vector<std::uint32_t> drawn = m.frame.color;
    ASSERT_EQ(drawn.size(), 64u * 48u);

    // The largest frame with 4x4 supersampling, as the Render panel can ask: beyond memory.
    m.settings.supersample = 4;
    m.prepareFrame(kMaxImageSide, kMaxImageSide);
    m.render();
    EXPECT_NE(m.refused.find("16384x16384 frame at 4x4 supersampling needs"), std::string::npos)
        << m.refused;
    EXPECT_NE(m.refused.find("the limit is"), std::string::npos) << m.refused;
    EXPECT_EQ(m.frame.color, drawn);  // the last image stays
    EXPECT_EQ(m.stats.trianglesIn, 0u);

    // A camera with eye == look (an orbit at distance 0, as a scene's pose could give).
    m.settings.supersample = 1;
    m.orbit.distance = 0.0;
    m.orbitMoved = true;
    m.prepareFrame(64, 48);
    m.render();
    EXPECT_NE(m.refused.find("camera:"), std::string::npos) << m.refused;

    m.orbitEdited();  // clamps the distance back
    m.prepareFrame(64, 48);
    m.render();
    EXPECT_EQ(m.refused, "");
    EXPECT_GT(m.stats.trianglesIn, 0u);
}

TEST(ViewerModels, TheSimpleShaderSaysItHasNoDepthTest) {
    ViewerModel m;
    ASSERT_TRUE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    RenderSettings s = m.settings;
    s.shader = ShaderKind::Simple;
    EXPECT_NE(noEffectNote(m.scene, s).find("no depth test"), std::string::npos);
    s.shader = ShaderKind::Painter;
    EXPECT_EQ(noEffectNote(m.scene, s), "");
}

}  // namespace
