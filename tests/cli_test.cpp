// The facet command line as a user meets it: real processes, real files, exit codes and the
// one-line error messages promised for bad input.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

struct Outcome {
    int exitCode = -1;
    std::string out;  // stdout and stderr together
};

Outcome run(const std::string& args) {
    const std::string cmd = std::string(FACET_CLI) + " " + args + " 2>&1";
    Outcome r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), static_cast<int>(buf.size()), p)) r.out += buf.data();
    const int status = pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
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
    const std::string scene = std::string(FACET_SHARED_DIR) + "/data/course/example2.scene";
    if (!fs::exists(scene)) GTEST_SKIP() << "shared data not available";
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

// The commands, as a user types them, on the course and Spot scenes.
TEST_F(Cli, ShadingCommandsOfTheCourse) {
    const std::string shared = std::string(FACET_SHARED_DIR) + "/data/";
    if (!fs::exists(shared + "course/brick.jpg")) GTEST_SKIP() << "shared data not available";
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
    // A mesh without colours interpolates depth only.
    std::ofstream(out("plain.scene")) << FACET_TEST_DATA << "/off_no_colors.off\n0 0 -4\n0 0 0\n"
                                      << "0 -1 0\n200\n64 48\n1\n0 0 -8 1\n0.5 0.5 0.5 1\n";
    const Outcome r = run("render " + out("plain.scene") + " -o " + out("p.png") + " --stats");
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
                            "--normal-length", "--legend", "subdivided"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST_F(Cli, GenerateWritesAMeshTheRendererLoads) {
    const Outcome g = run("generate sphere --detail 8 -o " + out("s.off"));
    ASSERT_EQ(g.exitCode, 0) << g.out;
    std::ofstream(out("s.scene"))
        << "s.off\n0 0 -4\n0 0 0\n0 -1 0\n200\n64 48\n1\n0 0 -8 1\n0.5 0.5 0.5 1\n";
    const Outcome r = run("render " + out("s.scene") + " -o " + out("s.png"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
}

}  // namespace
