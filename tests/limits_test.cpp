// Bounded resources (limits.hpp): frames and meshes over the memory limits are refused with a
// message before allocation, files over the size limit or that are not regular files are
// refused without reading, an OBJ face of thousands of corners costs one pass over its line, and
// the OFF parser's fuzz finding stays fixed.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "facet/limits.hpp"
#include "facet/mesh_io.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"

namespace fs = std::filesystem;
using namespace facet;

namespace {

std::string data(const std::string& name) {
    return std::string(FACET_TEST_DATA) + "/" + name;
}

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

// tinyobjloader keeps a face's corner count in 8 bits and its ear-clipper is quadratic; the line
// check refuses a 5,000-corner face before either sees it, naming the line, and the engine fans
// the largest face tinyobjloader can hold.
TEST(ObjLimit, HugePolygonsAreBoundedAndFanned) {
    const TempDir dir;
    auto polygon = [](int corners) {
        std::string text;
        for (int i = 0; i < corners; ++i) {
            const double a = 6.283185307179586 * i / corners;
            text.append("v ").append(std::to_string(std::cos(a)));
            text.append(" ").append(std::to_string(std::sin(a))).append(" 0\n");
        }
        text += "f";
        for (int i = 1; i <= corners; ++i) text.append(" ").append(std::to_string(i));
        return text.append("\n");
    };
    const Result<Mesh> huge = loadObj(dir.file("huge.obj", polygon(5000)));
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().loc.line, 5001);
    EXPECT_TRUE(contains(huge.error().message, "a face has 5000 vertices; at most 255"))
        << huge.error().what();

    const Result<Mesh> largest = loadObj(dir.file("largest.obj", polygon(255)));
    ASSERT_TRUE(largest.ok()) << largest.error().what();
    EXPECT_EQ(largest->vertexCount(), 255u);
    EXPECT_EQ(largest->triangleCount(), 253u);
    EXPECT_EQ(largest->indices[3 * 252 + 2],
              254u);  // the fan's last triangle ends at the last corner
}

// Fuzz finding: a colour of 4.4e35 was cast to int64_t (undefined behaviour) to test whether it
// is a whole number. It is one, so the file's colours are 0-255 and scaled.
TEST(OffLimit, HugeColourIsAWholeNumberWithoutOverflow) {
    const Result<Mesh> mesh = loadOff(data("off_color_huge.off"));
    ASSERT_TRUE(mesh.ok()) << mesh.error().what();
    ASSERT_EQ(mesh->colors.size(), 2u);
    EXPECT_FLOAT_EQ(mesh->colors[1].g, 55.0f / 255.0f);
    EXPECT_FLOAT_EQ(mesh->colors[1].b, 4.4444444e35f / 255.0f);
}
