// Opening what users bring and saving it back (spec §1, §3b; issue 14, points 1-2):
// what a file is, the scene a bare mesh gets, and a saved .scene that loads as the same scene
// and renders the same image byte for byte.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/mesh_io.hpp"
#include "facet/render.hpp"
#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "shared_data.hpp"

namespace {

namespace fs = std::filesystem;
using namespace facet;

const std::string kShared = facet::test::sharedDir() + "/data";

class SceneIo : public ::testing::Test {
  protected:
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("facet_scene_io_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = dir / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
};

const char* const kTriangleObj =
    "# a comment first\nmtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const char* const kTriangleOff = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

Framebuffer renderOnce(const Scene& scene, const RenderSettings& settings) {
    Renderer renderer;
    Framebuffer frame;
    renderer.render(scene, settings, frame);
    return frame;
}

TEST_F(SceneIo, FileKindByContentThenExtension) {
    EXPECT_EQ(fileKind(write("a.obj", kTriangleObj)), FileKind::mesh);
    EXPECT_EQ(fileKind(write("a.off", kTriangleOff)), FileKind::mesh);
    // Content wins over a misleading or missing extension.
    EXPECT_EQ(fileKind(write("mesh.scene", kTriangleObj)), FileKind::mesh);
    EXPECT_EQ(fileKind(write("noext", kTriangleOff)), FileKind::mesh);
    EXPECT_EQ(fileKind(write("s.txt", "# scene\nmodels/a mesh.OBJ\n0 0 5\n")), FileKind::scene);
    EXPECT_EQ(fileKind(write("p.dat", "\x89PNG\r\n\x1a\n")), FileKind::image);
    EXPECT_EQ(fileKind(write("t.tga", std::string("\0\0\2\0", 4))), FileKind::image);
    EXPECT_EQ(fileKind(write("x.txt", "hello world\n")), FileKind::unknown);
    EXPECT_EQ(fileKind((dir / "missing.obj").string()), FileKind::unknown);
    REQUIRE_SHARED_DATA(kShared + "/models/teapot.obj");
    REQUIRE_SHARED_DATA(kShared + "/scenes/spot_1280x720.scene");
    EXPECT_EQ(fileKind(kShared + "/models/teapot.obj"), FileKind::mesh);
    EXPECT_EQ(fileKind(kShared + "/scenes/spot_1280x720.scene"), FileKind::scene);
}

TEST_F(SceneIo, AFileThatIsNeitherSaysWhatWasExpected) {
    Result<Scene> r = openSceneFile(write("notes.txt", "hello world\n"));
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().what().find("notes.txt: not a scene or a mesh: expected a .scene file"),
              std::string::npos)
        << r.error().what();
    EXPECT_NE(r.error().what().find("'hello world'"), std::string::npos);
    REQUIRE_SHARED_DATA(kShared + "/models/spot_texture.png");
    Result<Scene> image = openSceneFile(kShared + "/models/spot_texture.png");
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().what().find("is an image"), std::string::npos);
    // A mesh's own errors keep its file and line.
    Result<Scene> bad = openSceneFile(write("bad.obj", "v 0 0 0\nv 1 0 nan\nf 1 2 1\n"));
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().what().find("bad.obj:2:"), std::string::npos) << bad.error().what();
}

TEST_F(SceneIo, ABareMeshIsFramedFromAThreeQuarterViewWithTheCourseUp) {
    for (const char* name : {"teapot.obj", "cow.obj", "stanford-bunny.obj", "suzanne.obj"}) {
        const std::string path = kShared + "/models/" + name;
        REQUIRE_SHARED_DATA(path);
        for (const auto& [w, h] : {std::pair(1280, 720), std::pair(600, 900)}) {
            Result<Scene> r = openSceneFile(path, w, h);
            ASSERT_TRUE(r) << r.error().what();
            const Scene& s = *r;
            EXPECT_EQ(s.camera.width, w);
            EXPECT_EQ(s.camera.height, h);
            EXPECT_EQ(s.camera.up, glm::dvec3(0, -1, 0));
            EXPECT_EQ(checkCamera(s.camera), "");
            // Above and to the side: the eye is higher than the look-at point and off every
            // axis.
            const glm::dvec3 d = s.camera.eye - s.camera.look;
            EXPECT_GT(d.y, 0.0);
            EXPECT_GT(std::abs(d.x), 0.3 * glm::length(d));
            EXPECT_GT(std::abs(d.z), 0.3 * glm::length(d));
            // Every vertex in the image with a margin, and the model not tiny in it.
            glm::dvec2 lo(1e30), hi(-1e30);
            for (const glm::vec3& p : s.mesh->positions) {
                const glm::dvec3 px = projectToPixel(s.camera, glm::dvec3(p));
                ASSERT_GT(px.z, 0.0);
                lo = glm::min(lo, glm::dvec2(px));
                hi = glm::max(hi, glm::dvec2(px));
            }
            EXPECT_GT(lo.x, 0.02 * w) << name;
            EXPECT_GT(lo.y, 0.02 * h) << name;
            EXPECT_LT(hi.x, 0.98 * w) << name;
            EXPECT_LT(hi.y, 0.98 * h) << name;
            EXPECT_GT(std::max((hi.x - lo.x) / w, (hi.y - lo.y) / h), 0.4) << name;
            // The light is a point near the camera, lighting the side the camera sees.
            EXPECT_EQ(s.lighting.light.position.w, 1.0);
            const glm::dvec3 light(s.lighting.light.position);
            EXPECT_LT(glm::length(light - s.camera.eye), glm::length(d));
            EXPECT_GT(s.lighting.light.intensity, 0.0);
            EXPECT_GT(s.lighting.material.kd, 0.0);
        }
    }
}

TEST_F(SceneIo, ASavedSceneLoadsAsTheSameSceneAndRendersTheSameBytes) {
    const std::string spot = kShared + "/scenes/spot_1280x720.scene";
    REQUIRE_SHARED_DATA(spot);
    Result<Scene> original = loadScene(spot);
    ASSERT_TRUE(original) << original.error().what();
    // Numbers that need every digit, and a directional light (5 numbers).
    original->camera.eye = {2.5000000000000004, 1.1, -2.3};
    original->camera.focal = 1100.0 / 3.0;
    original->lighting.light.position = {0.3, -1.0, 0.1, 0.0};
    const std::string saved = (dir / "sub" / "spot copy.scene").string();
    fs::create_directories(dir / "sub");
    ASSERT_TRUE(writeScene(*original, saved));

    std::stringstream buffer;
    buffer << std::ifstream(saved).rdbuf();
    const std::string text = buffer.str();
    EXPECT_EQ(text.find(kShared), std::string::npos) << "paths must be relative:\n" << text;
    EXPECT_NE(text.find("spot_triangulated.obj\n"), std::string::npos);
    EXPECT_NE(text.find("\n0.3 -1 0.1 0 0.9\n"), std::string::npos) << text;

    Result<Scene> back = loadScene(saved);
    ASSERT_TRUE(back) << back.error().what();
    EXPECT_EQ(back->camera.eye, original->camera.eye);
    EXPECT_EQ(back->camera.look, original->camera.look);
    EXPECT_EQ(back->camera.up, original->camera.up);
    EXPECT_EQ(back->camera.focal, original->camera.focal);
    EXPECT_EQ(back->camera.width, original->camera.width);
    EXPECT_EQ(back->camera.height, original->camera.height);
    EXPECT_EQ(back->lighting.ambient, original->lighting.ambient);
    EXPECT_EQ(back->lighting.light.position, original->lighting.light.position);
    EXPECT_EQ(back->lighting.light.intensity, original->lighting.light.intensity);
    EXPECT_EQ(back->lighting.material.s, original->lighting.material.s);
    EXPECT_EQ(fs::canonical(back->texturePath), fs::canonical(original->texturePath));

    RenderSettings settings;
    settings.shader = ShaderKind::Texture;
    settings.combine = true;
    settings.lighting = Lighting::Phong;
    EXPECT_EQ(renderOnce(*back, settings).color, renderOnce(*original, settings).color);
}

TEST_F(SceneIo, ABareMeshSavedAfterMovingTheCameraRendersTheSameBytes) {
    const std::string cow = kShared + "/models/cow.obj";
    REQUIRE_SHARED_DATA(cow);
    Result<Scene> scene = openSceneFile(cow, 640, 480);
    ASSERT_TRUE(scene) << scene.error().what();
    scene->camera.eye += glm::dvec3(0.1234567, -0.3, 0.7654321);  // as an orbit would
    scene->camera.up = {0.01, -1.0, 0.02};
    const std::string saved = write("cow view.scene", "");
    ASSERT_TRUE(writeScene(*scene, saved));
    Result<Scene> back = openSceneFile(saved);
    ASSERT_TRUE(back) << back.error().what();
    RenderSettings settings;
    settings.lighting = Lighting::Gouraud;
    const Framebuffer a = renderOnce(*scene, settings);
    const Framebuffer b = renderOnce(*back, settings);
    EXPECT_EQ(b.width, 640);
    EXPECT_EQ(a.color, b.color);
}

TEST_F(SceneIo, PathsTheFormatCannotHoldAreRefused) {
    const std::string mesh = write("odd#name.off", kTriangleOff);
    Result<Scene> scene = openSceneFile(mesh);
    ASSERT_TRUE(scene) << scene.error().what();
    const Status st = writeScene(*scene, (dir / "x.scene").string());
    ASSERT_FALSE(st);
    EXPECT_NE(st.error().what().find("cannot hold '#'"), std::string::npos) << st.error().what();
    EXPECT_FALSE(fs::exists(dir / "x.scene"));
}

// spec §9: the four cells of the table, and the "all one colour counts as uncoloured" rule.
TEST(OpeningSettings, FollowTheTableOfWhatTheSceneHas) {
    auto mesh = [](bool colors, bool oneColor, bool uvs) {
        Mesh m;
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        m.indices = {0, 1, 2};
        if (colors)
            m.colors = oneColor ? std::vector<glm::vec3>(3, glm::vec3(0.3f, 0.6f, 0.9f))
                                : std::vector<glm::vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        if (uvs) m.uvs = {{0, 0}, {1, 0}, {0, 1}};
        return std::make_shared<const Mesh>(std::move(m));
    };
    const auto texture = std::make_shared<const Texture>();
    struct Case {
        bool colors, oneColor, uvs, tex;
        ShaderKind shader;
        bool combine;
        Lighting lighting;
    };
    const Case cases[] = {
        {false, false, true, true, ShaderKind::Texture, true, Lighting::Gouraud},     // Spot
        {true, true, true, true, ShaderKind::Texture, true, Lighting::Gouraud},       // one colour
        {true, false, true, true, ShaderKind::Texture, false, Lighting::Off},         // brick wall
        {false, false, false, false, ShaderKind::Painter, false, Lighting::Gouraud},  // bunny
        {true, true, false, false, ShaderKind::Painter, false, Lighting::Gouraud},
        {true, false, false, false, ShaderKind::Painter, false, Lighting::Off},      // course cube
        {false, false, false, true, ShaderKind::Painter, false, Lighting::Gouraud},  // no uvs
        {true, false, true, false, ShaderKind::Painter, false, Lighting::Off},  // uvs, no image
    };
    for (const Case& c : cases) {
        Scene scene;
        scene.mesh = mesh(c.colors, c.oneColor, c.uvs);
        if (c.tex) scene.texture = texture;
        RenderSettings s;
        s.mode = DrawMode::Wireframe;  // untouched by the rule
        s.shader = ShaderKind::Depth;
        s.combine = !c.combine;
        applyOpeningSettings(scene, s);
        SCOPED_TRACE(::testing::Message() << "colors " << c.colors << " one " << c.oneColor
                                          << " uvs " << c.uvs << " texture " << c.tex);
        EXPECT_EQ(s.shader, c.shader);
        EXPECT_EQ(s.combine, c.combine);
        EXPECT_EQ(s.lighting, c.lighting);
        EXPECT_EQ(s.mode, DrawMode::Wireframe);
        EXPECT_EQ(hasVaryingColors(*scene.mesh), c.colors && !c.oneColor);
    }
}

// spec §3b: the up axis. The camera's y hint is the axis's opposite, the eye is above the
// centre along that axis, and the default (+Y) is the course's (0, −1, 0).
TEST(UpAxis, FramesABareMeshWithTheNamedAxisUp) {
    EXPECT_EQ(parseUpAxis("z"), UpAxis::Z);
    EXPECT_EQ(parseUpAxis("X"), UpAxis::X);
    EXPECT_EQ(parseUpAxis("w"), std::nullopt);
    for (UpAxis axis : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
        EXPECT_EQ(parseUpAxis(toString(axis)), axis);
        Mesh m;
        m.positions = {{-1, -2, -3}, {1, 2, 3}, {1, -2, 3}};
        m.indices = {0, 1, 2};
        const Scene s = sceneForMesh(m, "m.off", 640, 480, axis);
        const glm::dvec3 up = upVector(axis);
        EXPECT_EQ(s.camera.up, -up);
        const glm::dvec3 toEye = glm::normalize(s.camera.eye - s.camera.look);
        EXPECT_NEAR(glm::dot(toEye, up), std::sin(25.0 * std::numbers::pi / 180.0), 1e-12);
    }
    const Scene y = sceneForMesh(Mesh{}, "m.off", 640, 480);
    EXPECT_EQ(y.camera.up, glm::dvec3(0, -1, 0));
    // Z-up: seen from the front, −Y, as Z-up modelling tools show it.
    const Scene z = sceneForMesh(Mesh{}, "m.off", 640, 480, UpAxis::Z);
    EXPECT_LT(z.camera.eye.y, z.camera.look.y);
}

}  // namespace
