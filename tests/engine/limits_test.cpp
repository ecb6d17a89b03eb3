// Bounded resources (limits.hpp): frames and meshes over the memory limits are refused with a
// message before allocation, files over the size limit or that are not regular files are
// refused without reading, an OBJ face of thousands of corners loads as the engine's fan in linear
// time, and the OFF parser's fuzz finding stays fixed.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "facet/limits.hpp"
#include "facet/mesh_io.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;
using namespace facet;

namespace {

using facet::test::testData;

// A private folder for files a test makes, removed at the end.
class TempDir {
  public:
    TempDir() {
        path_ =
            fs::temp_directory_path() /
            ("facet-limits-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name, const std::string& text) const {
        const std::string p = (path_ / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    // A sparse file one byte over kMaxFileBytes: no disk space, no time.
    std::string oversized(const std::string& name) const {
        const std::string p = file(name, "");
        fs::resize_file(p, kMaxFileBytes + 1);
        return p;
    }
    std::string path(const std::string& name) const { return (path_ / name).string(); }

  private:
    fs::path path_;
};

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(FrameLimit, RefusesFramesOverTheLimitBeforeAllocating) {
    EXPECT_EQ(frameBytes(512, 512, 1), 8u * 512 * 512);
    EXPECT_EQ(frameBytes(512, 512, 2), 8u * 512 * 512 * 5);  // 4 samples + the resolved frame
    EXPECT_FALSE(frameMemoryProblem(16384, 16384, 1));       // 2 GiB: allowed
    EXPECT_FALSE(frameMemoryProblem(1920, 1080, 4));
    const auto problem = frameMemoryProblem(16384, 16384, 4);
    ASSERT_TRUE(problem);
    EXPECT_TRUE(contains(*problem, "16384x16384 frame at 4x4 supersampling needs 34.0 GiB"))
        << *problem;
    EXPECT_TRUE(contains(*problem, "the limit is 4.0 GiB")) << *problem;
    EXPECT_TRUE(frameMemoryProblem(16384, 16384, 2));
}

TEST(MeshLimit, RefusesCountsOverTheLimit) {
    EXPECT_FALSE(meshMemoryProblem(1'000'000, 2'000'000));
    const auto problem = meshMemoryProblem(200'000'000, 10);
    ASSERT_TRUE(problem);
    EXPECT_TRUE(contains(*problem, "200000000 vertices")) << *problem;
    EXPECT_TRUE(contains(*problem, "8.0 GiB")) << *problem;
    // Counts from a forged header do not overflow the sum.
    EXPECT_TRUE(meshMemoryProblem(UINT64_MAX, UINT64_MAX));
    EXPECT_TRUE(meshMemoryProblem(0, UINT64_MAX / 2));
}

TEST(FileLimit, OversizedFilesAreRefusedWithoutReading) {
    const TempDir dir;
    auto refusedForSize = [](const Error& e, const std::string& path) {
        return e.loc.file == path && contains(e.message, "the limit is 1073741824");
    };
    const std::string off = dir.oversized("big.off");
    const Result<Mesh> offMesh = loadMesh(off);
    ASSERT_FALSE(offMesh.ok());
    EXPECT_TRUE(refusedForSize(offMesh.error(), off)) << offMesh.error().what();
    const std::string obj = dir.oversized("big.obj");
    const Result<Mesh> objMesh = loadMesh(obj);
    ASSERT_FALSE(objMesh.ok());
    EXPECT_TRUE(refusedForSize(objMesh.error(), obj)) << objMesh.error().what();
    const std::string sceneFile = dir.oversized("big.scene");
    const Result<Scene> scene = loadScene(sceneFile);
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(refusedForSize(scene.error(), sceneFile)) << scene.error().what();
    const std::string image = dir.oversized("big.png");
    const Result<Texture> texture = loadTexture(image);
    ASSERT_FALSE(texture.ok());
    EXPECT_TRUE(refusedForSize(texture.error(), image)) << texture.error().what();
}

// A device or a pipe never ends (opening a pipe even blocks): refused by type, for every loader.
TEST(FileLimit, DevicesAndPipesAreRefused) {
    const TempDir dir;
    const std::string pipe = dir.path("pipe.png");
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    const Result<Texture> texture = loadTexture(pipe);
    ASSERT_FALSE(texture.ok());
    EXPECT_TRUE(contains(texture.error().message, "not a regular file")) << texture.error().what();
    if (fs::exists("/dev/zero")) {
        const Result<Mesh> mesh = loadOff("/dev/zero");
        ASSERT_FALSE(mesh.ok());
        EXPECT_TRUE(contains(mesh.error().message, "not a regular file")) << mesh.error().what();
    }
    // An OBJ whose material library is a pipe: skipped like a missing one, the mesh loads.
    ASSERT_EQ(::mkfifo(dir.path("pipe.mtl").c_str(), 0600), 0);
    const std::string obj =
        dir.file("piped.obj", "mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Result<Mesh> piped = loadObj(obj);
    ASSERT_TRUE(piped.ok()) << piped.error().what();
    EXPECT_EQ(piped->triangleCount(), 1u);
    // An oversized material library is an error naming it.
    dir.oversized("big.mtl");
    const std::string big =
        dir.file("big_mtl.obj", "mtllib big.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Result<Mesh> refused = loadObj(big);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().loc.file, dir.path("big.mtl"));
    EXPECT_TRUE(contains(refused.error().message, "the limit is")) << refused.error().what();
}

namespace {

// A regular polygon of `corners` vertices as OBJ lines (lines 1 to `corners`), with
// `corners` texture coordinates and one normal when `textured`, then its face on the next line;
// corner i uses vt corners + 1 - i (reversed, so that a lost or shifted triplet shows).
std::string objPolygon(int corners, bool textured = false) {
    std::string text;
    for (int i = 0; i < corners; ++i) {
        const double a = 6.283185307179586 * i / corners;
        text.append("v ").append(std::to_string(std::cos(a)));
        text.append(" ").append(std::to_string(std::sin(a))).append(" 0\n");
    }
    if (textured) {
        for (int i = 0; i < corners; ++i) {
            text.append("vt ").append(std::to_string(i)).append(" 0\n");
        }
        text += "vn 0 0 2\n";
    }
    text += "f";
    for (int i = 1; i <= corners; ++i) {
        text.append(" ").append(std::to_string(i));
        if (textured) text.append("/").append(std::to_string(corners + 1 - i)).append("/1");
    }
    return text.append("\n");
}

}  // namespace

// tinyobjloader keeps a face's corner count in 8 bits; the loader hands it a longer face as
// several that share the first corner, and the mesh is the fan from the first corner that a
// short polygon gets: triangle k is (0, k + 1, k + 2), same order and winding.
TEST(ObjLimit, FiveThousandCornerFaceIsTheFan) {
    const TempDir dir;
    const Result<Mesh> mesh = loadObj(dir.file("huge.obj", objPolygon(5000)));
    ASSERT_TRUE(mesh.ok()) << mesh.error().what();
    ASSERT_EQ(mesh->vertexCount(), 5000u);
    ASSERT_EQ(mesh->triangleCount(), 4998u);
    for (std::uint32_t k = 0; k < 4998; ++k) {
        ASSERT_EQ(mesh->indices[3 * k], 0u) << "triangle " << k;
        ASSERT_EQ(mesh->indices[3 * k + 1], k + 1) << "triangle " << k;
        ASSERT_EQ(mesh->indices[3 * k + 2], k + 2) << "triangle " << k;
    }
    // Corners keep their positions: vertex i is the polygon's corner i.
    EXPECT_NEAR(mesh->positions[2500].x, -1.0f, 1e-6f);
    EXPECT_NEAR(mesh->positions[4999].y, std::sin(6.283185307179586 * 4999 / 5000), 2e-6);
}

// The split keeps each corner's v/vt/vn triplet: corner i has texture coordinate n - 1 - i
// (stored with v flipped) and the one normal, also across the pieces' shared corners.
TEST(ObjLimit, SplitFaceKeepsCornerTriplets) {
    const TempDir dir;
    const int n = 600;  // three pieces: 255, 255 and 94 corners
    const Result<Mesh> mesh = loadObj(dir.file("textured.obj", objPolygon(n, true)));
    ASSERT_TRUE(mesh.ok()) << mesh.error().what();
    ASSERT_EQ(mesh->vertexCount(), static_cast<std::size_t>(n));
    ASSERT_EQ(mesh->triangleCount(), static_cast<std::size_t>(n - 2));
    ASSERT_EQ(mesh->uvs.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(mesh->normals.size(), static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        ASSERT_EQ(mesh->uvs[static_cast<std::size_t>(i)], glm::vec2(n - 1 - i, 1.0f)) << i;
        ASSERT_EQ(mesh->normals[static_cast<std::size_t>(i)], glm::vec3(0, 0, 1)) << i;
    }
    EXPECT_EQ(mesh->indices[3 * 253 + 1], 254u);  // the second piece starts at corner 254
    EXPECT_EQ(mesh->indices[3 * (n - 3) + 2], static_cast<std::uint32_t>(n - 1));
}

// Errors found after a split face name the file's lines: in the split face itself (the last
// piece), on the next face line (counted from the loader's face list), and on a line
// tinyobjloader refuses (its own line count, over the longer text it read).
TEST(ObjLimit, LineNumbersSurviveASplitFace) {
    const TempDir dir;
    std::string lastCornerBad = objPolygon(1000);
    lastCornerBad.replace(lastCornerBad.rfind(" 1000"), 5, " 1001");
    const Result<Mesh> inFace = loadObj(dir.file("in_face.obj", lastCornerBad));
    ASSERT_FALSE(inFace.ok());
    EXPECT_EQ(inFace.error().loc.line, 1001) << inFace.error().what();
    EXPECT_TRUE(contains(inFace.error().message, "refers to vertex 1001")) << inFace.error().what();

    const Result<Mesh> after =
        loadObj(dir.file("after.obj", objPolygon(1000) + "# fine\nf 1 2 3\nf 1 2 2000\n"));
    ASSERT_FALSE(after.ok());
    EXPECT_EQ(after.error().loc.line, 1004) << after.error().what();

    const Result<Mesh> parser =
        loadObj(dir.file("parser.obj", objPolygon(1000) + "f 1 2 3\nl 1 0\n"));
    ASSERT_FALSE(parser.ok());
    EXPECT_EQ(parser.error().loc.line, 1003) << parser.error().what();
    EXPECT_TRUE(contains(parser.error().message, "cannot parse OBJ: Failed parse `l' line"))
        << parser.error().what();
}

// Beyond kMaxObjFaceCorners a face is refused from its line's token count, naming the line.
TEST(ObjLimit, AbsurdFaceIsRefusedNamingItsLine) {
    const TempDir dir;
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (std::size_t i = 0; i <= kMaxObjFaceCorners; ++i) text += " 1";
    const Result<Mesh> mesh = loadObj(dir.file("absurd.obj", text + "\n"));
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error().loc.line, 4);
    EXPECT_TRUE(contains(mesh.error().message,
                         "a face has " + std::to_string(kMaxObjFaceCorners + 1) +
                             " vertices; at most " + std::to_string(kMaxObjFaceCorners)))
        << mesh.error().what();
}

// Fuzz finding: a colour of 4.4e35 was cast to int64_t (undefined behaviour) to test whether it
// is a whole number. It is one, so the file's colours are 0-255 and scaled.
TEST(OffLimit, HugeColourIsAWholeNumberWithoutOverflow) {
    const Result<Mesh> mesh = loadOff(testData("off_color_huge.off"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().what();
    ASSERT_EQ(mesh->colors.size(), 2u);
    EXPECT_FLOAT_EQ(mesh->colors[1].g, 55.0f / 255.0f);
    EXPECT_FLOAT_EQ(mesh->colors[1].b, 4.4444444e35f / 255.0f);
}
