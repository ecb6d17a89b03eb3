// The facet command line as a user meets it: real processes, real files, exit codes and the
// one-line error messages promised for bad input.

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "facet/camera.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "facet/texture.hpp"
#include "facet/version.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using facet_test::Outcome;

Outcome run(const std::string& args) {
    return facet_test::runCommand(std::string(FACET_CLI) + " " + args);
}

int countLines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23).
std::pair<int, int> pngSize(const fs::path& path) {
    std::ifstream f(path, std::ios::binary);
    unsigned char h[24] = {};
    f.read(reinterpret_cast<char*>(h), 24);
    if (!f || h[1] != 'P' || h[2] != 'N' || h[3] != 'G') return {0, 0};
    auto be = [&](int o) { return (h[o] << 24) | (h[o + 1] << 16) | (h[o + 2] << 8) | h[o + 3]; };
    return {be(16), be(20)};
}

class Cli : public ::testing::Test {
  protected:
    fs::path dir = fs::temp_directory_path() / ("facet_cli_test_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }
    std::string out(const std::string& name) const { return (dir / name).string(); }
};

TEST_F(Cli, RendersTheDefaultAssetSceneToAPngOfTheSceneSize) {
    const Outcome r =
        run(std::string("render ") + FACET_ASSETS_DIR + "/default.scene -o " + out("d.png"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("wrote"), std::string::npos);
    EXPECT_EQ(pngSize(out("d.png")), std::make_pair(1280, 720));
}

TEST_F(Cli, SizeOptionResizesAndFramesTimesArePrinted) {
    const Outcome r =
        run(std::string("render ") + FACET_ASSETS_DIR + "/default.scene -o " + out("s.png") +
            " --size 320x200 --mode wireframe --shader depth --interp affine --cull --frames 3 "
            "--lighting gouraud");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(pngSize(out("s.png")), std::make_pair(320, 200));
    EXPECT_NE(r.out.find("median"), std::string::npos) << r.out;
}

TEST_F(Cli, CourseScenesRenderInEveryMode) {
    const std::string scene = facet::test::sharedData("course/example2.scene");
    REQUIRE_SHARED_DATA(scene);
    for (const char* mode : {"vertices", "wireframe", "solid"}) {
        const Outcome r =
            run("render " + scene + " -o " + out("m.png") + " --shader painter --mode " + mode);
        EXPECT_EQ(r.exitCode, 0) << mode << ": " << r.out;
        EXPECT_EQ(pngSize(out("m.png")), std::make_pair(800, 600)) << mode;
    }
}

TEST_F(Cli, BadInputGivesOneLineOnStderrAndExitCode2) {
    const std::string data = FACET_TEST_DATA;
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    const std::string cases[] = {
        "render " + data + "/scene_light_3_numbers.scene -o " + out("x.png"),
        "render " + dir.string() + "/no_such.scene -o " + out("x.png"),
        "render " + scene + " -o " + out("x.png") + " --mode sketch",
        "render " + scene + " -o " + out("x.png") + " --size 0x10",
        "render " + scene + " -o " + out("x.png") + " --size big",
        "render " + scene + " -o " + out("x.png") + " --background 12345G",
        "render " + scene + " -o " + out("x.png") + " --interp subdivided:1",
        "render " + scene + " -o " + out("x.png") + " --interp subdivided:x",
        "render " + scene + " -o " + out("x.png") + " --interp affine:8",
        "render " + scene + " -o " + out("x.png") + " --lighting flat",
        "render " + scene + " -o " + out("x.png") + " --filter cubic",
        "render " + scene + " -o " + out("x.png") + " --shader texture",
        "render " + scene + " -o " + out("x.png") + " --texture " + data + "/no_such.png",
        "render " + scene + " -o " + out("x.png") + " --texture " + data + "/tex_not_an_image.png",
        "render " + scene + " -o " + out("x.png") + " --normal-length -1",
        "render " + scene,
        "render --frobnicate",
        "",
    };
    for (const auto& args : cases) {
        const Outcome r = run(args);
        EXPECT_EQ(r.exitCode, 2) << "facet " << args << "\n" << r.out;
        EXPECT_EQ(countLines(r.out), 1) << "facet " << args << "\n" << r.out;
    }
    // The message names the file and line of a scene error.
    const Outcome r = run("render " + data + "/scene_light_3_numbers.scene -o " + out("x.png"));
    EXPECT_NE(r.out.find("scene_light_3_numbers.scene:16: point light needs 4 or 5 numbers"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(out("x.png")));
}

TEST_F(Cli, TextureErrorsNameTheImage) {
    const std::string data = FACET_TEST_DATA;
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    Outcome r = run("render " + scene + " -o " + out("x.png") + " --texture " + data +
                    "/tex_truncated.png --shader texture");
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_NE(r.out.find("tex_truncated.png"), std::string::npos) << r.out;
    r = run("render " + scene + " -o " + out("x.png") + " --shader texture");
    EXPECT_NE(r.out.find("needs a texture"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out("x.png")));
}

// A truncated photograph given as --texture: exit 2, one line naming the file and the damage,
// and no image (before, libjpeg's warning was swallowed and a grey wall written with exit 0).
TEST_F(Cli, TruncatedJpegTextureIsBadInput) {
    const std::string course = facet::test::sharedData("course/");
    REQUIRE_SHARED_DATA(course + "brick.jpg");
    std::ostringstream bytes;
    bytes << std::ifstream(course + "brick.jpg", std::ios::binary).rdbuf();
    const std::string whole = bytes.str();
    ASSERT_GT(whole.size(), 4000u);
    std::ofstream(out("brick_cut.jpg"), std::ios::binary) << whole.substr(0, whole.size() * 3 / 4);
    const std::string scene = course + "example_textured.scene";
    const Outcome good = run("render " + scene + " -o " + out("good.png") + " --texture " + course +
                             "brick.jpg --size 64x48");
    ASSERT_EQ(good.exitCode, 0) << good.out;
    const Outcome r = run("render " + scene + " -o " + out("x.png") + " --texture " +
                          out("brick_cut.jpg") + " --size 64x48");
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_EQ(countLines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(out("brick_cut.jpg") + ": cannot decode the image, it may be damaged or "
                                                "truncated (libjpeg: Premature end of JPEG file)"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(out("x.png")));
}

// Progress on renders that take seconds: nothing for a fast render; once past the delay (a
// second; FACET_PROGRESS_AFTER sets it, 0 here so the test need not wait) each phase on stderr,
// with its percentage where it is known, and stdout keeps only the report.
TEST_F(Cli, ProgressShowsThePhasesOfASlowRenderOnly) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    const Outcome fast = run("render " + scene + " -o " + out("f.png") + " --size 64x48");
    ASSERT_EQ(fast.exitCode, 0) << fast.out;
    EXPECT_EQ(fast.out.find("facet render:"), std::string::npos) << fast.out;
    EXPECT_EQ(countLines(fast.out), 1) << fast.out;

    const Outcome slow =
        facet_test::runCommand("FACET_PROGRESS_AFTER=0 " + std::string(FACET_CLI) + " render " +
                               scene + " -o " + out("s.png") + " --size 64x48 --frames 2");
    ASSERT_EQ(slow.exitCode, 0) << slow.out;
    for (const std::string& line :
         {"facet render: loading " + scene, std::string("facet render: drawing frame 1 of 2 0%"),
          std::string("facet render: drawing frame 2 of 2 50%"),
          "facet render: encoding " + out("s.png") + " 0%"})
        EXPECT_NE(slow.out.find(line), std::string::npos) << line << "\n" << slow.out;
    // The lines go to stderr: with -o - stdout holds the PNG alone.
    const Outcome piped =
        facet_test::runCommand("FACET_PROGRESS_AFTER=0 " + std::string(FACET_CLI) + " render " +
                               scene + " -o - --size 64x48 2>/dev/null | head -c 8 | od -c");
    EXPECT_NE(piped.out.find("P   N   G"), std::string::npos) << piped.out;
}

// A frame over kMaxFrameBytes is refused with the sizes before anything is allocated (the
// command returns at once instead of being killed for memory).
TEST_F(Cli, FramesOverTheMemoryLimitAreRefused) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    const Outcome r =
        run("render " + scene + " -o " + out("x.png") + " --size 16384x16384 --supersample 4");
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_EQ(countLines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find("16384x16384 frame at 4x4 supersampling needs 34.0 GiB"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(out("x.png")));
}

// The issue's commands, as a user types them, on the course and Spot scenes.
TEST_F(Cli, ShadingCommandsOfTheCourse) {
    const std::string shared = facet::test::sharedData("");
    REQUIRE_SHARED_DATA(shared + "course/brick.jpg");
    const std::string wall = shared + "course/example_textured.scene --shader texture --texture " +
                             shared + "course/brick.jpg";
    const std::string cases[] = {
        shared + "course/example2.scene --shader painter --lighting gouraud",
        shared + "course/example2.scene --lighting phong --normals",
        wall + " --interp affine",
        wall + " --interp perspective --filter trilinear",
        wall + " --interp subdivided:8 --filter nearest",
        shared + "scenes/spot_1280x720.scene --shader texture --combine --lighting gouraud",
        shared + "scenes/spot_1280x720.scene --shader depth --legend",
    };
    for (const std::string& args : cases) {
        const Outcome r = run("render " + args + " -o " + out("c.png") + " --stats");
        EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.out;
        EXPECT_GT(pngSize(out("c.png")).first, 0) << args;
        fs::remove(out("c.png"));
    }
}

// "Only what the scene needs": the varyings and bytes per vertex follow the settings and mesh.
TEST_F(Cli, StatsReportVaryingsAndBytesPerVertex) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";  // has colours
    auto stats = [&](const std::string& opts) {
        return run("render " + scene + " -o " + out("v.png") + " --size 64x36 --stats " + opts).out;
    };
    EXPECT_NE(stats("").find("per vertex: 40 bytes; varyings: 4 floats (1/w rgb)"),
              std::string::npos)
        << stats("");
    EXPECT_NE(stats("--shader depth").find("varyings: 1 floats (1/w)"), std::string::npos);
    EXPECT_NE(stats("--lighting gouraud").find("varyings: 4 floats (1/w rgb)"), std::string::npos);
    EXPECT_NE(stats("--lighting phong").find("varyings: 10 floats (1/w rgb n p)"),
              std::string::npos);
    // A depth image needs no normals even with lighting on.
    EXPECT_NE(stats("--shader depth --lighting phong").find("per vertex: 28 bytes; varyings: 1 "),
              std::string::npos);
    // A mesh without colours, unlit, interpolates depth only (it opens lit: spec §9).
    std::ofstream(out("plain.scene")) << FACET_TEST_DATA << "/off_no_colors.off\n0 0 -4\n0 0 0\n"
                                      << "0 -1 0\n200\n64 48\n1\n0 0 -8 1\n0.5 0.5 0.5 1\n";
    const Outcome r =
        run("render " + out("plain.scene") + " -o " + out("p.png") + " --stats --lighting off");
    EXPECT_NE(r.out.find("per vertex: 28 bytes; varyings: 1 floats (1/w)"), std::string::npos)
        << r.out;
}

TEST_F(Cli, UnwritableOutputIsAFailureNotACrash) {
    const Outcome r = run(std::string("render ") + FACET_ASSETS_DIR + "/default.scene -o " +
                          dir.string() + "/missing/folder/x.png --size 64x64");
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_NE(r.out.find("cannot write"), std::string::npos) << r.out;
}

TEST_F(Cli, HelpListsTheOptions) {
    const Outcome r = run("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* opt : {"--mode", "--shader", "--interp", "--lighting", "--cull", "--size",
                            "--background", "--texture", "--filter", "--combine", "--normals",
                            "--normal-length", "--legend", "subdivided", "--view", "bin-load"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

/// Whether `help` lists `option` as one of its own (an option line starts "  --name").
bool listsOption(const std::string& help, const std::string& option) {
    return help.find("\n  " + option + " ") != std::string::npos ||
           help.find("\n  " + option + "\n") != std::string::npos ||
           help.find("," + option + " ") != std::string::npos;
}

// Each sub-command lists only what it uses; an option it would ignore, given anyway, is bad
// input (exit 2) with one line naming the option and why, before anything is loaded or drawn.
struct UnusedOption {
    const char* option;
    const char* args;  // the option as given, with a value where it takes one
    const char* why;   // a word of the reason the message must give
};

void expectOnlyUsedOptions(const std::string& command, const std::string& tail,
                           const std::vector<UnusedOption>& unused,
                           const std::vector<const char*>& used) {
    const Outcome help = run(command + " --help");
    ASSERT_EQ(help.exitCode, 0) << help.out;
    for (const char* option : used) EXPECT_TRUE(listsOption(help.out, option)) << option;
    for (const UnusedOption& u : unused) {
        EXPECT_FALSE(listsOption(help.out, u.option)) << command << " lists " << u.option;
        const Outcome r =
            run(command + " " + FACET_ASSETS_DIR + "/default.scene " + tail + " " + u.args);
        EXPECT_EQ(r.exitCode, 2) << command << " " << u.args << ": " << r.out;
        EXPECT_EQ(countLines(r.out), 1) << r.out;
        EXPECT_NE(r.out.find(std::string(u.option) + " has no use here"), std::string::npos)
            << r.out;
        EXPECT_NE(r.out.find(u.why), std::string::npos) << r.out;
    }
}

TEST_F(Cli, RenderListsEveryRenderOption) {
    expectOnlyUsedOptions("render", "-o " + out("r.png"), {},
                          {"--output", "--threads", "--subpixel-bits", "--supersample", "--view",
                           "--msaa", "--frames", "--stats", "--write-scene", "--normals",
                           "--legend", "--point-size", "--renderer"});
}

TEST_F(Cli, RenderGlListsOnlyWhatTheOpenGlTwinUses) {
    expectOnlyUsedOptions("render-gl", "-o " + out("g.png"),
                          {{"--threads", "--threads 2", "LP_NUM_THREADS"},
                           {"--subpixel-bits", "--subpixel-bits 4", "sub-pixel grid"},
                           {"--supersample", "--supersample 2", "one sample per pixel"},
                           {"--view", "--view overdraw", "CPU engine"}},
                          {"--output", "--msaa", "--frames", "--stats", "--normals", "--legend",
                           "--mode", "--shader", "--texture", "--size"});
}

TEST_F(Cli, InspectListsOnlyWhatDecidesThePixel) {
    expectOnlyUsedOptions("inspect", "3 3",
                          {{"--output", "--output x.png", "writes no image"},
                           {"--frames", "--frames 3", "times nothing"},
                           {"--threads", "--threads 2", "one thread"},
                           {"--stats", "--stats", "frame statistics"},
                           {"--write-scene", "--write-scene x.scene", "writes no files"},
                           {"--normals", "--normals", "overlays"},
                           {"--normal-length", "--normal-length 0.5", "overlays"},
                           {"--legend", "--legend", "overlays"},
                           {"--point-size", "--point-size 3", "points"},
                           {"--view", "--view overdraw", "facet render --view"}},
                          {"--mode", "--shader", "--interp", "--supersample", "--msaa",
                           "--subpixel-bits", "--truth-samples", "--size", "--eye"});
    EXPECT_FALSE(fs::exists("x.scene"));
}

TEST_F(Cli, VersionPrintsTheProjectVersion) {
    const Outcome r = run("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, std::string("facet ") + facet::kVersionString + "\n");
    EXPECT_NE(run("--help").out.find("--version"), std::string::npos);
}

// --view NAME writes the debug view: the PNG holds exactly the image Renderer::render() makes
// with that view (heat map and legend), which is not the shaded image; a wrong name and the
// OpenGL twin (which has no debug views) are bad input.
TEST_F(Cli, ViewWritesTheDebugView) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    facet::Result<facet::Scene> loaded = facet::loadScene(scene);
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    facet::Scene s = std::move(loaded).value();
    s.camera = facet::resizedCamera(s.camera, 200, 150);
    facet::Renderer renderer;
    facet::Framebuffer shaded;
    renderer.render(s, {}, shaded);
    for (const std::string_view name : facet::debugViewNames()) {
        const std::string png = out(std::string(name) + ".png");
        const Outcome r =
            run("render " + scene + " --size 200x150 --view " + std::string(name) + " -o " + png);
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.out;
        facet::Result<facet::Texture> written = facet::loadTexture(png);
        ASSERT_TRUE(written.ok()) << name;
        facet::RenderSettings settings;
        settings.view = *facet::parseDebugView(name);
        facet::Framebuffer expected;
        renderer.render(s, settings, expected);
        EXPECT_EQ(written.value().level(0).texels, expected.color) << name;
        if (name != "none") {
            EXPECT_NE(expected.color, shaded.color) << name;
        }
    }
    const Outcome bad = run("render " + scene + " --view heat -o " + out("x.png"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(countLines(bad.out), 1) << bad.out;
    EXPECT_NE(bad.out.find("--view"), std::string::npos) << bad.out;
    const Outcome gl = run("render-gl " + scene + " --view overdraw -o " + out("x.png"));
    EXPECT_EQ(gl.exitCode, 2) << gl.out;
    EXPECT_NE(gl.out.find("CPU engine"), std::string::npos) << gl.out;
}

TEST_F(Cli, GenerateWritesAMeshTheRendererLoads) {
    const Outcome g = run("generate sphere --detail 8 -o " + out("s.off"));
    ASSERT_EQ(g.exitCode, 0) << g.out;
    std::ofstream(out("s.scene"))
        << "s.off\n0 0 -4\n0 0 0\n0 -1 0\n200\n64 48\n1\n0 0 -8 1\n0.5 0.5 0.5 1\n";
    const Outcome r = run("render " + out("s.scene") + " -o " + out("s.png"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
}

// facet bench: --quick runs the whole machinery (engine, OpenGL peers per thread count, CSV,
// chart) on tiny generated cases in about a second.
struct CsvRow {
    std::string caseName, config, renderer;
    int threads = 0, width = 0, height = 0, frames = 0;
    long triangles = 0;
    double median = 0, min = 0, max = 0, mtri = 0, mpix = 0;
    std::string frontEndNs, binningNs, rasterRestNs;  ///< blank where not measured
};

struct Csv {
    std::vector<std::string> comments;
    std::string header;
    std::vector<CsvRow> rows;
    bool has(const std::string& comment) const {
        for (const std::string& c : comments)
            if (c.rfind(comment, 0) == 0) return true;
        return false;
    }
    int count(const std::string& renderer) const {
        int n = 0;
        for (const CsvRow& r : rows) n += r.renderer == renderer;
        return n;
    }
};

Csv readCsv(const std::string& path) {
    Csv csv;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("# ", 0) == 0) {
            csv.comments.push_back(line.substr(2));
            continue;
        }
        if (csv.header.empty()) {
            csv.header = line;
            continue;
        }
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string field; std::getline(ss, field, ',');) f.push_back(field);
        if (!line.empty() && line.back() == ',') f.emplace_back();  // a blank last field
        if (f.size() != 16) {
            ADD_FAILURE() << "bad row: " << line;
            continue;
        }
        csv.rows.push_back({f[0], f[1], f[2], std::stoi(f[3]), std::stoi(f[4]), std::stoi(f[5]),
                            std::stoi(f[7]), std::stol(f[6]), std::stod(f[8]), std::stod(f[9]),
                            std::stod(f[10]), std::stod(f[11]), std::stod(f[12]), f[13], f[14],
                            f[15]});
    }
    return csv;
}

using facet::test::haveGnuplot;

// Without an OpenGL context facet bench measures the engine alone (exit 1, "opengl: unavailable");
// a test that checked only the engine's rows then ends saying so (a failure under CI=true).
#define REQUIRE_OPENGL_MEASURED(csv)                        \
    REQUIRE_PREREQUISITE(!(csv).has("opengl: unavailable"), \
                         "no OpenGL context: facet bench measured the engine only")

/// Median within min..max, positive, finite; rates consistent with the median.
void expectSane(const CsvRow& r) {
    SCOPED_TRACE(r.caseName + " " + r.config + " " + r.renderer);
    EXPECT_GT(r.median, 0.0);
    EXPECT_LT(r.max, 60000.0);
    EXPECT_LE(r.min, r.median);
    EXPECT_LE(r.median, r.max);
    EXPECT_NEAR(r.mpix, static_cast<double>(r.width) * r.height / (r.median * 1e3),
                1e-2 * r.mpix + 1e-3);
}

TEST_F(Cli, BenchQuickWritesTheTableCsvAndChart) {
    const Outcome r = run("bench --quick --threads 2 --csv " + out("b.csv") +
                          (haveGnuplot() ? " --chart " + out("b.png") : std::string()));
    const Csv csv = readCsv(out("b.csv"));
    // Without OpenGL the engine is still measured, and the exit status says what is missing.
    const bool noGl = csv.has("opengl: unavailable");
    ASSERT_EQ(r.exitCode, noGl ? 1 : 0) << r.out;
    EXPECT_NE(r.out.find("[1/40] sphere_quick painter engine t=1 ... "), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("engine/opengl"), std::string::npos) << r.out;
    for (const char* c : {"date: ", "cpu: ", "cores: ", "opengl: ", "compiler: ", "threads: 1, 2"})
        EXPECT_TRUE(csv.has(c)) << c;
    EXPECT_EQ(csv.header,
              "case,config,renderer,threads,width,height,triangles,frames,median_ms,min_ms,"
              "max_ms,mtri_per_s,mpix_per_s,frontend_ns_per_tri,binning_ns_per_tri,"
              "raster_rest_ns_per_tri");
    // What each side's time includes, in the CSV, the table and --help.
    for (const char* c :
         {"engine time: everything Renderer::render does per frame",
          "opengl time: clear and draw up to glFinish, the mesh resident", "*_ns_per_tri: "})
        EXPECT_TRUE(csv.has(c)) << c;
    EXPECT_NE(r.out.find("opengl time: clear and draw up to glFinish"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ns/triangle"), std::string::npos) << r.out;
    const Outcome help = run("bench --help");
    EXPECT_NE(help.out.find("the mesh resident"), std::string::npos) << help.out;
    // 2 cases x 5 configs (gouraud_msaa4 included) x 2 thread counts per renderer, and 3
    // floors per case.
    EXPECT_EQ(csv.count("engine"), 20);
    EXPECT_EQ(csv.count("floor_fill_color") + csv.count("floor_fill_color_depth") +
                  csv.count("floor_copy_color"),
              6);
    if (!noGl) {
        EXPECT_EQ(csv.count("opengl"), 20) << r.out;
    }
    for (const CsvRow& row : csv.rows) {
        expectSane(row);
        if (row.renderer == "engine" || row.renderer == "opengl") {
            EXPECT_EQ(row.frames, 2);
            EXPECT_GT(row.triangles, 0);
            EXPECT_TRUE(row.threads == 1 || row.threads == 2);
        }
        // Stage costs are the engine's: its raster time is always there (front end and
        // binning once the engine reports them), the other rows leave all three blank.
        if (row.renderer == "engine") {
            EXPECT_GT(std::stod(row.rasterRestNs), 0.0) << row.caseName << " " << row.config;
            for (const std::string& ns : {row.frontEndNs, row.binningNs}) {
                if (!ns.empty()) {
                    EXPECT_GT(std::stod(ns), 0.0);
                }
            }
        } else {
            EXPECT_EQ(row.frontEndNs + row.binningNs + row.rasterRestNs, "") << row.renderer;
        }
    }
    // Interleaved: a case and config's OpenGL measurements follow its engine ones at once.
    if (!noGl) {
        const std::size_t engine2 = r.out.find("sphere_quick painter engine t=2 ... ");
        const std::size_t gl1 = r.out.find("sphere_quick painter opengl t=1 ... ");
        const std::size_t nextEngine = r.out.find("sphere_quick gouraud engine t=1 ... ");
        EXPECT_TRUE(engine2 < gl1 && gl1 < nextEngine) << r.out;
    }
    if (haveGnuplot()) {
        EXPECT_EQ(pngSize(out("b.png")), std::make_pair(1600, 1100));
    }
    REQUIRE_GNUPLOT();
    REQUIRE_OPENGL_MEASURED(csv);
}

TEST_F(Cli, BenchScalingQuickSweepsTrianglesAndPixels) {
    const Outcome r = run("bench --scaling --quick --threads 2 --csv " + out("s.csv") +
                          (haveGnuplot() ? " --chart " + out("s.png") : std::string()));
    const Csv csv = readCsv(out("s.csv"));
    ASSERT_EQ(r.exitCode, csv.has("opengl: unavailable") ? 1 : 0) << r.out;
    // Three triangle counts and three sizes, Gouraud only by default.
    EXPECT_EQ(csv.count("engine"), 12);
    long lastTriangles = 0;
    for (const CsvRow& row : csv.rows) {
        expectSane(row);
        if (row.renderer != "engine" && row.renderer != "opengl") continue;
        EXPECT_EQ(row.config, "gouraud");
        if (row.caseName.rfind("tri_", 0) == 0 && row.renderer == "engine" && row.threads == 1) {
            EXPECT_GT(row.triangles, lastTriangles) << row.caseName;
            lastTriangles = row.triangles;
        }
    }
    EXPECT_EQ(lastTriangles, 16384);
    if (haveGnuplot()) {
        EXPECT_GT(pngSize(out("s.png")).first, 0);
    }
    REQUIRE_GNUPLOT();
    REQUIRE_OPENGL_MEASURED(csv);
}

TEST_F(Cli, BenchFiltersAndFrameCounts) {
    const Outcome r =
        run("bench --quick --threads 2 --cases overdraw --configs 'phong|textured' "
            "--frames 3 --warmup 0 --csv " +
            out("f.csv"));
    const Csv csv = readCsv(out("f.csv"));
    ASSERT_EQ(r.exitCode, csv.has("opengl: unavailable") ? 1 : 0) << r.out;
    EXPECT_EQ(csv.count("engine"), 4);
    for (const CsvRow& row : csv.rows) {
        EXPECT_EQ(row.caseName, "overdraw_quick");
        if (row.renderer == "engine" || row.renderer == "opengl") {
            EXPECT_TRUE(row.config == "phong" || row.config == "textured") << row.config;
            EXPECT_EQ(row.frames, 3);
        }
    }
    REQUIRE_OPENGL_MEASURED(csv);
}

TEST_F(Cli, BenchChartWithoutGnuplotFailsButKeepsTheCsv) {
    const Outcome r =
        run("bench --quick --cases sphere --configs painter --csv " + out("g.csv") + " --chart " +
            out("g.png") + " --gnuplot " + dir.string() + "/no/gnuplot");
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_NE(r.out.find("gnuplot-nox"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out("g.png")));
    EXPECT_EQ(readCsv(out("g.csv")).count("floor_fill_color"), 1);
}

TEST_F(Cli, BenchBadFiltersAreBadInput) {
    for (const char* args : {"bench --quick --cases '('", "bench --quick --cases no_such_case",
                             "bench --quick --configs flat", "bench --frames 0"}) {
        const Outcome r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.out;
        EXPECT_EQ(countLines(r.out), 1) << args << "\n" << r.out;
    }
}

TEST_F(Cli, AccuracyBadInputIsOneLine) {
    for (const std::string& args :
         {"accuracy " + out("missing.scene"),
          std::string("accuracy ") + FACET_ASSETS_DIR + "/default.scene --samples 0"}) {
        const Outcome r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.out;
        EXPECT_EQ(countLines(r.out), 1) << args << "\n" << r.out;
    }
}

// facet sweeps in quick mode: one CSV per sweep named, with the `#` notes, the header the chart
// scripts read and finite cells; with gnuplot, one PNG each.
TEST_F(Cli, SweepsWriteACsvAndAChartPerSweep) {
    const bool chart = haveGnuplot();
    const Outcome r = run("sweeps --quick --frames 1 --samples 2 --only depth,highlights --out " +
                          out("sweeps") + (chart ? "" : " --no-chart"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("highlights: 18 steps, 18 rows"), std::string::npos) << r.out;
    for (const auto& [name, header] :
         {std::pair<std::string, std::string>{"depth",
                                              "distance,relative_gap,fighting,smallest_resolved"},
          {"highlights",
           "rings,shininess,gouraud_peak,phong_peak,ratio,gouraud_rmse,phong_rmse,gouraud_ms,"
           "phong_ms"}}) {
        std::ifstream csv(out("sweeps/" + name + ".csv"));
        ASSERT_TRUE(csv) << name;
        std::string line;
        int comments = 0, rows = 0;
        bool sawHeader = false;
        while (std::getline(csv, line)) {
            if (line.rfind("#", 0) == 0) {
                ++comments;
            } else if (!sawHeader) {
                EXPECT_EQ(line, header) << name;
                sawHeader = true;
            } else {
                ++rows;
                EXPECT_EQ(line.find("nan"), std::string::npos) << name << ": " << line;
            }
        }
        EXPECT_EQ(comments, 3) << name;
        EXPECT_EQ(rows, name == "depth" ? 3 * 80 : 3 * 6) << name;
        if (chart) {
            std::ifstream png(out("sweeps/" + name + ".png"), std::ios::binary);
            char magic[4] = {};
            png.read(magic, 4);
            EXPECT_EQ(std::string(magic + 1, 3), "PNG") << name;
        }
    }
    REQUIRE_GNUPLOT();
}

TEST_F(Cli, SweepsBadInputIsOneLine) {
    for (const std::string& args :
         {std::string("sweeps --only no_such_sweep --no-chart --out ") + out("s1"),
          std::string("sweeps --no-chart --out /proc/facet_no_such/dir"),
          std::string("sweeps --samples 0")}) {
        const Outcome r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.out;
        EXPECT_EQ(countLines(r.out), 1) << args << "\n" << r.out;
    }
}

}  // namespace

namespace {

using facet::test::readFile;

const std::string kModelsDir = facet::test::sharedData("models");

TEST_F(Cli, ABareMeshRendersLitAndItsSavedSceneRendersTheSameBytes) {
    const std::string teapot = kModelsDir + "/teapot.obj";
    REQUIRE_SHARED_DATA(teapot);
    Outcome r = run("render " + teapot + " -o " + out("a.png") + " --size 640x400 --write-scene " +
                    out("teapot.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("lighting gouraud"), std::string::npos) << r.out;  // lit by default
    EXPECT_EQ(pngSize(out("a.png")), std::make_pair(640, 400));
    // The saved scene opens by the same rule as the mesh (spec §9): with no options it
    // renders the same bytes.
    r = run("render " + out("teapot.scene") + " -o " + out("b.png"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(readFile(out("a.png")), readFile(out("b.png")));
    const std::string text = readFile(out("teapot.scene"));
    EXPECT_EQ(text.find(kModelsDir), std::string::npos) << "relative path expected:\n" << text;
    EXPECT_NE(text.find("\n640 400\n"), std::string::npos) << text;
}

// One set of defaults (spec §9, applyOpeningSettings): Spot's scene names a texture and
// its mesh has no colours, so it opens textured, combined and lit, as the viewer opens it; a
// course scene (coloured mesh) stays unlit painter. Options override each part.
TEST_F(Cli, ScenesOpenWithTheDefaultsOfTheirContents) {
    const std::string spot = facet::test::sharedData("scenes/spot_1280x720.scene");
    REQUIRE_SHARED_DATA(spot);
    Outcome r = run("render " + spot + " -o " + out("default.png") + " --size 320x180");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("texture"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("combined"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lighting gouraud"), std::string::npos) << r.out;
    r = run("render " + spot + " -o " + out("explicit.png") +
            " --size 320x180 --shader texture --combine --lighting gouraud");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(readFile(out("default.png")), readFile(out("explicit.png")));
    r = run("render " + spot + " -o " + out("flat.png") +
            " --size 320x180 --shader painter --lighting off");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(readFile(out("default.png")), readFile(out("flat.png")));
    // --no-combine turns the default off; with --combine it is refused.
    r = run("render " + spot + " -o " + out("texel.png") + " --size 320x180 --no-combine");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(r.out.find("combined"), std::string::npos) << r.out;
    EXPECT_EQ(run("render " + spot + " -o " + out("x.png") + " --combine --no-combine").exitCode,
              2);

    const std::string course = facet::test::sharedData("course/example0.scene");
    REQUIRE_SHARED_DATA(course);
    r = run("render " + course + " -o " + out("course.png"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("painter"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lighting off"), std::string::npos) << r.out;
}

TEST_F(Cli, AResizedScenesSavedCopyRendersTheSameBytes) {
    const std::string spot = facet::test::sharedData("scenes/spot_1280x720.scene");
    REQUIRE_SHARED_DATA(spot);
    const std::string opts = " --shader texture --combine --lighting phong";
    Outcome r = run("render " + spot + " -o " + out("a.png") + opts + " --size 480x270" +
                    " --write-scene " + out("spot.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    r = run("render " + out("spot.scene") + " -o " + out("b.png") + opts);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(pngSize(out("b.png")), std::make_pair(480, 270));
    EXPECT_EQ(readFile(out("a.png")), readFile(out("b.png")));
    EXPECT_NE(readFile(out("spot.scene")).find("spot_texture.png"), std::string::npos);
}

TEST_F(Cli, AFileThatIsNoSceneOrMeshSaysWhatWasExpected) {
    std::ofstream(out("notes.txt")) << "hello\n";
    Outcome r = run("render " + out("notes.txt") + " -o " + out("x.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(countLines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find("not a scene or a mesh: expected a .scene file"), std::string::npos)
        << r.out;
    // An OBJ is never read as a scene (the message the issue quotes).
    std::ofstream(out("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    r = run("render " + out("tri.obj") + " -o " + out("x.png"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(r.out.find("must end in"), std::string::npos) << r.out;
}

// Typos get a suggestion by edit distance: a misspelt command and a misspelt option, each on one
// line with exit code 2; a word near nothing lists the commands.
TEST_F(Cli, MisspeltCommandsAndOptionsGetASuggestion) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    Outcome r = run("rendr " + scene + " -o " + out("x.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("unknown command 'rendr': did you mean 'render'?"), std::string::npos)
        << r.out;
    r = run("render " + scene + " -o " + out("x.png") + " --lightng phong");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("unknown option '--lightng' for 'render': did you mean '--lighting'?"),
              std::string::npos)
        << r.out;
    r = run("frobnicate");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("unknown command 'frobnicate' (the commands: render,"), std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(out("x.png")));
}

// A pipe or a device is refused before anything reads it: a FIFO nobody writes to would block
// a read forever, /dev/zero would never end.
TEST_F(Cli, PipesAndDevicesAreRefusedBeforeReading) {
    const std::string fifo = out("pipe.scene");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const std::string& path : {fifo, std::string("/dev/zero")}) {
        // timeout: a regression fails in seconds instead of hanging the suite.
        const Outcome r = facet_test::runCommand("timeout 20 " + std::string(FACET_CLI) +
                                                 " render " + path + " -o " + out("x.png"));
        EXPECT_EQ(r.exitCode, 2) << path;
        EXPECT_NE(r.out.find(path + ": is not a regular file"), std::string::npos) << r.out;
        EXPECT_EQ(countLines(r.out), 1) << r.out;
    }
}

// -o by extension: PNG only, anything else refused before rendering with a clear line (no
// PNG bytes under a .jpg name); -o - puts the PNG on standard output and the report on stderr.
TEST_F(Cli, OutputIsAPngFileOrStandardOutput) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    Outcome r = run("render " + scene + " -o " + out("x.jpg"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("only PNG is written"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out("x.jpg")));
    ASSERT_EQ(run("render " + scene + " -o " + out("file.PNG") + " --size 64x36").exitCode, 0);
    // The braces keep runCommand's 2>&1 off the redirected stdout.
    r = facet_test::runCommand("{ " + std::string(FACET_CLI) + " render " + scene +
                               " --size 64x36 -o - > " + out("piped.png") + "; }");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("wrote - (64x36"), std::string::npos) << r.out;  // the report, stderr
    EXPECT_EQ(readFile(out("piped.png")), readFile(out("file.PNG")));
    EXPECT_FALSE(fs::exists("-"));
}

// A Z-up model (Nefertiti, a scan) is framed standing with --up z (spec §3b): the written
// scene's y hint is -Z, and the image differs from the default +Y framing; --up on a .scene has
// no effect and is refused naming what it needs; --eye and --look replace the camera's pose.
TEST_F(Cli, UpEyeAndLookFrameABareMesh) {
    const std::string nefertiti = kModelsDir + "/nefertiti.obj";
    REQUIRE_SHARED_DATA(nefertiti);
    Outcome r = run("render " + nefertiti + " -o " + out("z.png") + " --size 160x120 --up z" +
                    " --write-scene " + out("z.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const facet::Result<facet::Scene> zUp =
        facet::parseScene(readFile(out("z.scene")), out("z.scene"));
    ASSERT_TRUE(zUp) << zUp.error().what();
    EXPECT_EQ(zUp.value().camera.up, glm::dvec3(0, 0, -1));
    ASSERT_EQ(run("render " + nefertiti + " -o " + out("y.png") + " --size 160x120").exitCode, 0);
    EXPECT_NE(readFile(out("z.png")), readFile(out("y.png")));

    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    r = run("render " + scene + " -o " + out("x.png") + " --up z");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("--up frames a bare .off/.obj mesh"), std::string::npos) << r.out;

    r = run("render " + scene + " -o " + out("moved.png") + " --size 64x36 --eye 0,0,4 " +
            "--look 0,0,0 --write-scene " + out("moved.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const facet::Result<facet::Scene> moved =
        facet::parseScene(readFile(out("moved.scene")), out("moved.scene"));
    ASSERT_TRUE(moved) << moved.error().what();
    EXPECT_EQ(moved.value().camera.eye, glm::dvec3(0, 0, 4));
    EXPECT_EQ(moved.value().camera.look, glm::dvec3(0, 0, 0));
    r = run("render " + scene + " -o " + out("x.png") + " --eye 1,2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("--eye wants X,Y,Z"), std::string::npos) << r.out;
    r = run("render " + scene + " -o " + out("x.png") + " --eye 0,0,0 --look 0,0,0");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("look-at point equals the camera position"), std::string::npos) << r.out;
}

// An option the others leave without effect is a one-line warning naming what it needs; the image
// is still written.
TEST_F(Cli, OptionsWithoutEffectWarnNamingWhatTheyNeed) {
    const std::string scene = std::string(FACET_ASSETS_DIR) + "/default.scene";
    const auto warnings = [&](const std::string& opts) {
        const Outcome r = run("render " + scene + " -o " + out("w.png") + " --size 64x36 " + opts);
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return r.out;
    };
    EXPECT_NE(warnings("--combine")
                  .find("warning: --combine and --no-combine apply to the "
                        "texture shader (--shader texture)"),
              std::string::npos);
    EXPECT_NE(warnings("--filter nearest").find("warning: --filter applies to the texture shader"),
              std::string::npos);
    EXPECT_NE(warnings("--legend").find("warning: --legend is the depth shader's legend"),
              std::string::npos);
    EXPECT_NE(warnings("--mode wireframe --msaa 4").find("warning: --supersample and --msaa apply"),
              std::string::npos);
    EXPECT_EQ(warnings("--shader depth --legend").find("warning"), std::string::npos);
    EXPECT_EQ(warnings("").find("warning"), std::string::npos);
}

}  // namespace
