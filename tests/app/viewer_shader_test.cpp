// The GLSL loading the viewer (frame.vert, frame.frag) and the OpenGL twin (twin.*) share
// (app/gl/gl_program.*): finding the folder, $FACET_SHADERS, and every failure as an Error that
// names the file and carries the driver's log. Compiling needs a context: a headless EGL one,
// and without EGL those tests are skipped and say why.

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "gl_context.hpp"
#include "gl_program.hpp"
#include "gl_renderer.hpp"
#include "shared_data.hpp"

namespace {

namespace fs = std::filesystem;
using facet::Result;
using facet::gl::Program;

const fs::path kShaders = fs::path(FACET_ASSETS_DIR).parent_path() / "shaders";

/// A folder with copies of the shaders, `file` replaced by `text` when given; removed after.
class ShaderFolder {
  public:
    explicit ShaderFolder(const std::string& file = "", const std::string& text = "") {
        dir_ = fs::temp_directory_path() / ("facet_shader_test_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        for (const auto& entry : fs::directory_iterator(kShaders))
            fs::copy_file(entry.path(), dir_ / entry.path().filename());
        if (!file.empty()) std::ofstream(dir_ / file, std::ios::trunc) << text;
        ::setenv("FACET_SHADERS", dir_.c_str(), 1);
    }
    ~ShaderFolder() {
        ::unsetenv("FACET_SHADERS");
        fs::remove_all(dir_);
    }
    std::string path(const std::string& file) const { return (dir_ / file).string(); }

  private:
    fs::path dir_;
};

/// One headless context for the binary, or why there is none.
struct Headless {
    std::optional<facet::GlContext> context;
    std::string whyNot;
};

Headless& headless() {
    static Headless h = [] {
        Headless made;
        Result<facet::GlContext> c = facet::GlContext::createHeadless();
        if (c)
            made.context.emplace(std::move(c).value());
        else
            made.whyNot = c.error().what();
        return made;
    }();
    return h;
}

// Without a context the test skips, or fails under CI=true (shared_data.hpp).
#define REQUIRE_CONTEXT() \
    REQUIRE_PREREQUISITE(headless().context, "no OpenGL context: " + headless().whyNot)

TEST(ShaderFiles, TheViewerAndTheTwinFindTheSameFolder) {
    const Result<std::string> frame = facet::gl::findShaderFolder("frame.vert");
    ASSERT_TRUE(frame.ok()) << frame.error().what();
    EXPECT_TRUE(fs::exists(fs::path(*frame) / "frame.frag"));
    const Result<std::string> twin = facet::gl::findShaderFolder("twin.vert");
    ASSERT_TRUE(twin.ok()) << twin.error().what();
    EXPECT_EQ(*twin, *frame);
}

TEST(ShaderFiles, FacetShadersIsLookedInFirstAndOnly) {
    const ShaderFolder folder;
    const Result<std::string> found = facet::gl::findShaderFolder("frame.vert");
    ASSERT_TRUE(found.ok()) << found.error().what();
    EXPECT_EQ(fs::path(*found) / "frame.vert", fs::path(folder.path("frame.vert")));
    // Asked for explicitly, a folder without the file is an error, not another folder's file.
    fs::remove(folder.path("twin.vert"));
    const Result<std::string> missing = facet::gl::findShaderFolder("twin.vert");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().what().find("twin.vert: not found in $FACET_SHADERS"),
              std::string::npos)
        << missing.error().what();
}

TEST(ShaderFiles, AnUnreadableFileIsNamed) {
    const Result<facet::gl::StageSource> r = facet::gl::readShaderFile("/no/such/frame.frag");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().what(), "/no/such/frame.frag: cannot read the shader");
}

TEST(ShaderPrograms, TheViewersFrameProgramBuilds) {
    REQUIRE_CONTEXT();
    const Result<Program> p = facet::gl::loadProgram("frame.vert", "frame.frag");
    ASSERT_TRUE(p.ok()) << p.error().what();
    EXPECT_NE(p->get(), 0u);
}

TEST(ShaderPrograms, ACompileErrorNamesTheFileWithTheGlslLog) {
    REQUIRE_CONTEXT();
    const ShaderFolder folder("frame.frag", "#version 330 core\nvoid main() { oops; }\n");
    const Result<Program> p = facet::gl::loadProgram("frame.vert", "frame.frag");
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().loc.file, folder.path("frame.frag"));
    EXPECT_NE(p.error().message.find("oops"), std::string::npos) << p.error().what();
    EXPECT_NE(p.error().message.find("error"), std::string::npos) << p.error().what();
}

TEST(ShaderPrograms, ALinkErrorNamesBothFiles) {
    REQUIRE_CONTEXT();
    // frame.vert writes a vec2 `uv`; a fragment stage reading a vec3 one does not link.
    const ShaderFolder folder("frame.frag",
                              "#version 330 core\nin vec3 uv;\nout vec4 color;\n"
                              "void main() { color = vec4(uv, 1.0); }\n");
    const Result<Program> p = facet::gl::loadProgram("frame.vert", "frame.frag");
    ASSERT_FALSE(p.ok());
    const std::string what = p.error().what();
    EXPECT_EQ(p.error().loc.file, folder.path("frame.vert"));
    EXPECT_NE(what.find("linking with " + folder.path("frame.frag") + " failed"), std::string::npos)
        << what;
    EXPECT_NE(what.find("uv"), std::string::npos) << what;
}

TEST(ShaderPrograms, TheTwinsVariantsBuildAndABrokenOneNamesItself) {
    REQUIRE_CONTEXT();
    const Result<facet::gl::ShaderSources> sources = facet::gl::loadShaderSources();
    ASSERT_TRUE(sources.ok()) << sources.error().what();
    const Result<Program> plain = facet::gl::buildProgram(*sources, "");
    ASSERT_TRUE(plain.ok()) << plain.error().what();
    const Result<Program> broken = facet::gl::buildProgram(*sources, "#error broken variant\n");
    ASSERT_FALSE(broken.ok());
    EXPECT_EQ(broken.error().loc.file, sources->folder + "/twin.vert");
    EXPECT_NE(broken.error().message.find("broken variant"), std::string::npos)
        << broken.error().what();
    EXPECT_NE(broken.error().message.find("variant:\n#error broken variant"), std::string::npos)
        << broken.error().what();
}

TEST(ShaderPrograms, AMissingTwinShaderIsNamed) {
    const ShaderFolder folder;
    fs::remove(folder.path("twin_lighting.glsl"));
    const Result<facet::gl::ShaderSources> sources = facet::gl::loadShaderSources();
    ASSERT_FALSE(sources.ok());
    EXPECT_EQ(sources.error().what(),
              folder.path("twin_lighting.glsl") + ": cannot read the shader");
}

// The viewer's Render panel says where the twin's picture departs from the engine's; nothing
// is said where they agree within rounding.
TEST(TwinDifferences, NamedForTheSettingsThatHaveThem) {
    facet::RenderSettings s;
    EXPECT_EQ(facet::GlRenderer::differences(s), "");
    s.lighting = facet::Lighting::Phong;
    s.shader = facet::ShaderKind::Texture;  // bilinear: within a step
    EXPECT_EQ(facet::GlRenderer::differences(s), "");
    s.interp = facet::Interp::Subdivided;
    EXPECT_NE(facet::GlRenderer::differences(s).find("perspective-correct"), std::string::npos);
    s.filter = facet::TextureFilter::Trilinear;
    s.mode = facet::DrawMode::Wireframe;
    const std::string all = facet::GlRenderer::differences(s);
    EXPECT_EQ(std::count(all.begin(), all.end(), '\n'), 2) << all;  // three lines
    EXPECT_NE(all.find("mip level"), std::string::npos);
    EXPECT_NE(all.find("Bresenham"), std::string::npos);
    // The engine's supersampling and sub-pixel grid have no twin counterpart (solid mode).
    s = facet::RenderSettings{};
    s.supersample = 2;
    s.subPixelBits = 4;
    const std::string grid = facet::GlRenderer::differences(s);
    EXPECT_NE(grid.find("supersample"), std::string::npos) << grid;
    EXPECT_NE(grid.find("sub-pixel"), std::string::npos) << grid;
}

}  // namespace
