// Loaders: every error path with a malformed file (line number and the key words of the message),
// the course's and the shared data's files, and the OFF writer's exact round trip.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "facet/mesh.hpp"
#include "facet/mesh_io.hpp"
#include "facet/procedural.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace {

using facet::test::sharedData;
using facet::test::testData;

namespace fs = std::filesystem;
using facet::Mesh;
using facet::Result;

std::string course(const std::string& name) {
    return facet::test::sharedData("course/" + name);
}

// The result is an error at `line` of a file whose name ends in `file`, and its message contains
// every one of `parts`.
template <class T>
testing::AssertionResult failsAt(const Result<T>& result, std::string_view file, int line,
                                 const std::vector<std::string_view>& parts) {
    if (result.ok()) return testing::AssertionFailure() << "loaded without an error";
    const facet::Error& e = result.error();
    const std::string& name = e.loc.file;
    if (name.size() < file.size() || name.compare(name.size() - file.size(), file.size(), file)) {
        return testing::AssertionFailure() << "error names the wrong file: " << e.what();
    }
    if (e.loc.line != line) {
        return testing::AssertionFailure()
               << "error at line " << e.loc.line << ", expected " << line << ": " << e.what();
    }
    for (std::string_view part : parts) {
        if (e.message.find(part) == std::string::npos) {
            return testing::AssertionFailure() << "message lacks \"" << part << "\": " << e.what();
        }
    }
    return testing::AssertionSuccess() << e.what();
}

template <class T>
void expectLoaded(const Result<T>& result) {
    ASSERT_TRUE(result.ok()) << result.error().what();
}

void expectVec(glm::vec3 got, glm::vec3 want, float tol = 0.0f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}
void expectVec(glm::vec2 got, glm::vec2 want, float tol = 0.0f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
}
void expectVec(glm::dvec3 got, glm::dvec3 want) {
    EXPECT_DOUBLE_EQ(got.x, want.x);
    EXPECT_DOUBLE_EQ(got.y, want.y);
    EXPECT_DOUBLE_EQ(got.z, want.z);
}

// ---------------------------------------------------------------------------------------------
// OFF: valid files

TEST(OffLoader, ColoredSquare) {
    auto r = facet::loadOff(testData("mesh_square.off"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 4u);
    EXPECT_EQ(r->triangleCount(), 2u);
    ASSERT_TRUE(r->hasColors());
    EXPECT_FALSE(r->hasUvs());
    expectVec(r->positions[2], {1, 1, 0});
    expectVec(r->colors[1], {0, 1, 0});
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_TRUE(r->texturePath.empty());
}

TEST(OffLoader, NoColorsMeansEmptyColorArray) {
    auto r = facet::loadOff(testData("off_no_colors.off"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 3u);
    EXPECT_FALSE(r->hasColors());
    EXPECT_FALSE(r->hasUvs());
}

TEST(OffLoader, UvsAreKeptAsWritten) {
    auto r = facet::loadOff(testData("off_uv.off"));
    expectLoaded(r);
    ASSERT_EQ(r->uvs.size(), 3u);
    expectVec(r->uvs[0], {0.25f, 0.5f});  // no flip for OFF (spec §2)
    expectVec(r->uvs[1], {-1.0f, 3.0f});
    expectVec(r->colors[2], {0, 0, 1});
}

TEST(OffLoader, Coff255ColorsAreScaled) {
    auto r = facet::loadOff(testData("off_coff_255.off"));
    expectLoaded(r);
    ASSERT_EQ(r->colors.size(), 3u);
    expectVec(r->colors[0], {1, 0, 0}, 1e-6f);
    expectVec(r->colors[1], {0, 0.2f, 0}, 1e-6f);
    expectVec(r->colors[2], {0, 0, 0.4f}, 1e-6f);
}

TEST(OffLoader, IntegerColorsInUnitRangeAreNotScaled) {
    auto r = facet::loadOff(testData("off_colors_01_integers.off"));
    expectLoaded(r);
    expectVec(r->colors[0], {1, 0, 0});
}

TEST(OffLoader, PolygonsAreFanned) {
    auto r = facet::loadOff(testData("off_polygons.off"));
    expectLoaded(r);
    EXPECT_EQ(r->triangleCount(), 5u);  // quad: 2, pentagon: 3
    EXPECT_EQ(r->indices,
              (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 4, 7, 8}));
}

TEST(OffLoader, CommentsBomBlankLinesAndSameLineCounts) {
    auto r = facet::loadOff(testData("off_comments.off"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 4u);
    EXPECT_EQ(r->triangleCount(), 2u);
    expectVec(r->colors[3], {0.5f, 0.5f, 0.5f});
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(OffLoader, CrlfFile) {
    auto r = facet::loadOff(testData("off_crlf.off"));
    expectLoaded(r);
    EXPECT_EQ(r->triangleCount(), 1u);
    expectVec(r->colors[0], {0.2f, 0.4f, 0.6f});
}

TEST(OffLoader, ParseFromMemoryWithCrlfAndPlusSigns) {
    auto r = facet::parseOff("OFF 3 1 0\r\n+1 0 0\r\n0 1.5e0 0\r\n0 0 .5\r\n3 2 1 0", "mem.off");
    expectLoaded(r);
    expectVec(r->positions[0], {1, 0, 0});
    expectVec(r->positions[1], {0, 1.5f, 0});
    expectVec(r->positions[2], {0, 0, 0.5f});
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{2, 1, 0}));
}

TEST(OffLoader, TinyValuesUnderflowToZeroInsteadOfFailing) {
    auto r = facet::parseOff("OFF\n3 1 0\n1e-60 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "tiny.off");
    expectLoaded(r);
    EXPECT_EQ(r->positions[0].x, 0.0f);
}

TEST(OffLoader, CourseFiles) {
    REQUIRE_SHARED_DATA(sharedData("course"));
    struct Case {
        const char* file;
        std::size_t vertices, triangles;
    };
    for (const Case& c : {Case{"cube_multi_color.off", 8, 12}, Case{"cube_trigs_color.off", 8, 12},
                          Case{"monkey2.off", 2947, 5808}, Case{"colored_stfdbunny.off", 444, 884},
                          Case{"textured_facet.off", 4, 2}}) {
        SCOPED_TRACE(c.file);
        auto r = facet::loadOff(course(c.file));
        expectLoaded(r);
        EXPECT_EQ(r->vertexCount(), c.vertices);
        EXPECT_EQ(r->triangleCount(), c.triangles);
        EXPECT_TRUE(r->hasColors());
    }
}

TEST(OffLoader, CourseTexturedFacet) {
    REQUIRE_SHARED_DATA(course("textured_facet.off"));
    auto r = facet::loadOff(course("textured_facet.off"));
    expectLoaded(r);
    ASSERT_EQ(r->uvs.size(), 4u);
    expectVec(r->uvs[0], {0, 0});
    expectVec(r->uvs[1], {2, 0});
    expectVec(r->uvs[2], {2, 4});
    expectVec(r->uvs[3], {0, 4});
    expectVec(r->colors[0], {1, 0, 0});
    expectVec(r->colors[3], {0.8f, 0.1f, 0.1f});
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3}));
}

TEST(OffLoader, CourseCubeColors) {
    REQUIRE_SHARED_DATA(course("cube_multi_color.off"));
    auto r = facet::loadOff(course("cube_multi_color.off"));
    expectLoaded(r);
    expectVec(r->colors[0], {0.9f, 0.9f, 0.9f});
    expectVec(r->positions[6], {1, 1, 1});
}

// ---------------------------------------------------------------------------------------------
// OFF: errors

/// A malformed file of tests/data and the error loading it must give: at `line` of that file,
/// the message holding every one of `parts`. `name` names the case.
struct BadFile {
    const char* name;
    const char* file;
    int line;
    std::vector<std::string_view> parts;
};

/// Names the case in gtest's messages.
void PrintTo(const BadFile& f, std::ostream* os) {
    *os << f.file;
}

/// Loads `file` with the loader its extension names (.off, .obj, .scene).
testing::AssertionResult loadFailsAt(const BadFile& f) {
    const std::string path = testData(f.file);
    const std::string_view file = f.file;
    if (file.ends_with(".off")) return failsAt(facet::loadOff(path), file, f.line, f.parts);
    if (file.ends_with(".obj")) return failsAt(facet::loadObj(path), file, f.line, f.parts);
    return failsAt(facet::loadScene(path), file, f.line, f.parts);
}

class MalformedFile : public testing::TestWithParam<BadFile> {};

TEST_P(MalformedFile, FailsAtItsLineNamingTheCause) {
    EXPECT_TRUE(loadFailsAt(GetParam()));
}

std::string badFileName(const testing::TestParamInfo<BadFile>& info) {
    return info.param.name;
}

// OFF files.
const BadFile kOffErrors[] = {
    {"BadMagic", "off_bad_magic.off", 1, {"OFF or COFF", "'PLY'"}},
    {"NonIntegerCount", "off_counts_non_integer.off", 3, {"face count NF", "'2.5'"}},
    {"NegativeCount", "off_counts_negative.off", 2, {"vertex count NV", "'-4'"}},
    {"MissingCount", "off_counts_missing.off", 2, {"NV NF NE", "got 1"}},
    {"NoFaces", "off_no_faces.off", 2, {"no faces"}},
    {"FacesWithoutVertices", "off_faces_without_vertices.off", 2, {"1 face", "no vertices"}},
    {"IndexOutOfRange", "off_bad_index.off", 10, {"vertex index 4", "out of range", "4 vertices"}},
    {"NegativeIndex", "off_negative_index.off", 6, {"vertex index -1", "out of range"}},
    {"NaN", "off_nan.off", 4, {"non-finite", "'nan'"}},
    {"Inf", "off_inf.off", 5, {"non-finite", "'-inf'"}},
    {"FloatOverflow", "off_overflow.off", 4, {"non-finite", "'1e39'"}},
    {"TruncatedInFaces", "off_truncated_faces.off", 8, {"file ends after 2 of 3 faces"}},
    {"TruncatedInVertices", "off_truncated_vertices.off", 5, {"file ends after 2 of 4 vertices"}},
    {"VertexWithTooFewNumbers",
     "off_vertex_too_few_numbers.off",
     4,
     {"3, 6, 7 or 8 numbers", "got 2"}},
    {"VertexWithFiveNumbers", "off_vertex_5_numbers.off", 3, {"3, 6, 7 or 8 numbers", "got 5"}},
    {"VertexLayoutChanges",
     "off_layout_mismatch.off",
     5,
     {"3 numbers", "first vertex (line 3) has 6", "same layout"}},
    {"GarbageToken", "off_garbage.off", 4, {"expected a number", "'zero'"}},
    {"FaceWithTwoVertices", "off_face_too_few.off", 7, {"at least 3 vertices", "n = 2"}},
    {"FaceMissingAnIndex",
     "off_face_missing_index.off",
     7,
     {"face says 4 vertices but lists only 3 indices"}},
    {"NonIntegerIndex", "off_face_non_integer_index.off", 6, {"vertex index", "'1.5'"}},
    {"BadFaceCount", "off_face_bad_count.off", 6, {"vertex count n", "'three'"}},
};
INSTANTIATE_TEST_SUITE_P(OffErrors, MalformedFile, testing::ValuesIn(kOffErrors), badFileName);

TEST(OffErrors, HugeHeaderFailsBeforeAllocating) {
    EXPECT_TRUE(failsAt(facet::loadOff(testData("off_huge_header.off")), "off_huge_header.off", 2,
                        {"promises 2000000000 vertices and 2000000000 faces", "only 0 bytes"}));
    // Counts near the 64-bit limit must not overflow the size check.
    EXPECT_TRUE(failsAt(
        facet::parseOff("OFF\n9223372036854775807 9223372036854775807 0\n0 0 0\n", "max.off"),
        "max.off", 2, {"promises", "bytes"}));
    // One vertex too many for the bytes that follow.
    EXPECT_TRUE(failsAt(facet::parseOff("OFF\n3 1 0\n0 0 0\n0 0 0\n3 0 1 2\n", "short.off"),
                        "short.off", 2, {"promises 3 vertices and 1 faces", "only 20 bytes"}));
}

TEST(OffErrors, MissingFileAndEmptyText) {
    EXPECT_TRUE(failsAt(facet::loadOff(testData("no_such_file.off")), "no_such_file.off", 0,
                        {"cannot open"}));
    EXPECT_TRUE(failsAt(facet::parseOff("", "empty.off"), "empty.off", 0, {"empty file"}));
    EXPECT_TRUE(
        failsAt(facet::parseOff("# only a comment\n\n", "c.off"), "c.off", 2, {"empty file"}));
}

TEST(OffErrors, WhatNamesFileAndLine) {
    auto r = facet::parseOff("OFF\n3 1 0\n0 0 0\n", "f.off");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().what(),
              "f.off:2: header promises 3 vertices and 1 faces but the file "
              "has only 6 bytes after it");
}

// ---------------------------------------------------------------------------------------------
// OFF writer

// The process id keeps two builds' runs on one machine apart.
std::string tempFile(const std::string& name) {
    return (fs::path(testing::TempDir()) /
            ("facet_loader_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

std::uint32_t bits(float v) {
    return std::bit_cast<std::uint32_t>(v);
}

TEST(OffWriter, RoundTripsExactly) {
    Mesh m;
    m.positions = {{0.1f, -1e-7f, 3.4e38f},
                   {1.0f / 3.0f, 2.0f / 3.0f, -0.0f},
                   {std::numeric_limits<float>::denorm_min(), 123456.789f, -0.5f},
                   {16777217.0f, -1.17549435e-38f, 7.0f}};
    m.colors = {{0.1f, 0.2f, 0.3f}, {1, 0, 0}, {0.333333343f, 0.999999f, 0.5f}, {0, 0, 0}};
    m.uvs = {{0.1f, 5.5f}, {-2.0f, 1e-3f}, {0.7f, 0.3f}, {1e10f, -1e-10f}};
    m.indices = {0, 1, 2, 2, 1, 3};
    const std::string path = tempFile("roundtrip.off");
    const facet::Status s = facet::writeOff(m, path);
    ASSERT_TRUE(s) << s.error().what();
    auto r = facet::loadOff(path);
    expectLoaded(r);
    ASSERT_EQ(r->vertexCount(), m.vertexCount());
    ASSERT_EQ(r->colors.size(), m.colors.size());
    ASSERT_EQ(r->uvs.size(), m.uvs.size());
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(bits(r->positions[i][k]), bits(m.positions[i][k])) << i << " " << k;
            EXPECT_EQ(bits(r->colors[i][k]), bits(m.colors[i][k])) << i << " " << k;
        }
        for (int k = 0; k < 2; ++k) EXPECT_EQ(bits(r->uvs[i][k]), bits(m.uvs[i][k]));
    }
    EXPECT_EQ(r->indices, m.indices);
    fs::remove(path);
}

TEST(OffWriter, MeshWithoutColorsIsWrittenWhite) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    const std::string path = tempFile("white.off");
    ASSERT_TRUE(facet::writeOff(m, path));
    auto r = facet::loadOff(path);
    expectLoaded(r);
    ASSERT_EQ(r->colors.size(), 3u);
    expectVec(r->colors[1], {1, 1, 1});
    EXPECT_FALSE(r->hasUvs());
    fs::remove(path);
}

TEST(OffWriter, CourseMonkeyRoundTrips) {
    REQUIRE_SHARED_DATA(course("monkey2.off"));
    auto a = facet::loadOff(course("monkey2.off"));
    expectLoaded(a);
    const std::string path = tempFile("monkey2.off");
    ASSERT_TRUE(facet::writeOff(*a, path));
    auto b = facet::loadOff(path);
    expectLoaded(b);
    EXPECT_EQ(b->positions, a->positions);
    EXPECT_EQ(b->colors, a->colors);
    EXPECT_EQ(b->indices, a->indices);
    fs::remove(path);
}

TEST(OffWriter, UnwritablePathIsAnError) {
    Mesh m;
    m.positions = {{0, 0, 0}};
    const auto s = facet::writeOff(m, testData("no_such_folder/out.off"));
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("cannot open"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// OBJ

TEST(ObjLoader, TexturedQuadWithMaterial) {
    auto r = facet::loadObj(testData("obj_textured_quad.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 4u);
    EXPECT_EQ(r->triangleCount(), 2u);  // the quad is fanned
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    ASSERT_EQ(r->uvs.size(), 4u);
    expectVec(r->uvs[0], {0, 1});  // v flipped: OBJ's v = 0 is the image bottom
    expectVec(r->uvs[2], {1, 0});
    expectVec(r->uvs[3], {0, 0.75f});
    EXPECT_FALSE(r->hasColors());
    EXPECT_EQ(r->texturePath, testData("texture_checker.png"));
}

TEST(ObjLoader, MissingMapKdIsKeptResolved) {
    auto r = facet::loadObj(testData("obj_missing_texture.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->texturePath, testData("textures/not_here.png"));
}

TEST(ObjLoader, VertexColors) {
    auto r = facet::loadObj(testData("obj_colors.obj"));
    expectLoaded(r);
    ASSERT_EQ(r->colors.size(), 3u);
    expectVec(r->colors[0], {1, 0, 0});
    expectVec(r->colors[2], {0, 0, 1});
    EXPECT_FALSE(r->hasUvs());
}

TEST(ObjLoader, PolygonsWithRelativeIndicesAreFanned) {
    auto r = facet::loadObj(testData("obj_polygons.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 9u);
    EXPECT_EQ(r->indices,
              (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 4, 7, 8}));
    expectVec(r->positions[7], {2.5f, 2, 0});
    EXPECT_FALSE(r->hasColors());
    EXPECT_FALSE(r->hasUvs());
}

TEST(ObjLoader, PositionTexcoordPairsAreMerged) {
    auto r = facet::loadObj(testData("obj_uv_seam.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->vertexCount(), 5u);  // vertex 3 is split along the seam, vertex 2 is shared
    EXPECT_EQ(r->indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 4}));
    expectVec(r->positions[4], {0, 1, 0});
    expectVec(r->uvs[2], {0, 0});
    expectVec(r->uvs[4], {0.5f, 0.5f});
}

TEST(ObjLoader, SharedModels) {
    REQUIRE_SHARED_DATA(sharedData("models"));
    struct Case {
        const char* file;
        std::size_t triangles;
    };
    for (const Case& c : {Case{"cow.obj", 5804}, Case{"nefertiti.obj", 99938},
                          Case{"stanford-bunny.obj", 69451}, Case{"suzanne.obj", 968},
                          Case{"teapot.obj", 6320}, Case{"spot_triangulated.obj", 5856}}) {
        SCOPED_TRACE(c.file);
        auto r = facet::loadMesh(sharedData(std::string("models/") + c.file));
        expectLoaded(r);
        EXPECT_EQ(r->triangleCount(), c.triangles);
        EXPECT_FALSE(r->hasColors());
    }
}

TEST(ObjLoader, StanfordBunny) {
    REQUIRE_SHARED_DATA(sharedData("models/stanford-bunny.obj"));
    auto r = facet::loadObj(sharedData("models/stanford-bunny.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->triangleCount(), 69451u);
    EXPECT_EQ(r->vertexCount(), 34834u);  // of 35947 `v` lines: unused ones are dropped
    EXPECT_FALSE(r->hasUvs());
    EXPECT_TRUE(r->texturePath.empty());
}

TEST(ObjLoader, SpotHasFlippedUvs) {
    REQUIRE_SHARED_DATA(sharedData("models/spot_triangulated.obj"));
    auto r = facet::loadObj(sharedData("models/spot_triangulated.obj"));
    expectLoaded(r);
    EXPECT_EQ(r->triangleCount(), 5856u);
    ASSERT_TRUE(r->hasUvs());
    EXPECT_EQ(r->uvs.size(), r->vertexCount());
    // The first face is "f 739/1 735/2 736/3"; v 739 is "0.317288 -0.397295 0.364448" and
    // vt 1 is "0.800375 0.667457".
    const std::uint32_t first = r->indices[0];
    expectVec(r->positions[first], {0.317288f, -0.397295f, 0.364448f}, 1e-6f);
    expectVec(r->uvs[first], {0.800375f, 1.0f - 0.667457f}, 1e-6f);
    EXPECT_TRUE(r->texturePath.empty());  // spot has no mtllib; its scene names the texture
}

// OBJ files.
const BadFile kObjErrors[] = {
    {"IndexOutOfRange", "obj_bad_index.obj", 7, {"out of range", "vertex 9", "has 4"}},
    {"IndexOutOfRangeInPolygon", "obj_bad_polygon_index.obj", 7, {"out of range", "vertex 50"}},
    {"TexcoordIndexOutOfRange",
     "obj_bad_texcoord_index.obj",
     6,
     {"texture coordinate index out of range", "vt 3"}},
    {"NaN", "obj_nan.obj", 3, {"non-finite", "'nan'"}},
    {"Inf", "obj_inf.obj", 2, {"non-finite", "'inf'"}},
    {"GarbageCoordinate", "obj_garbage.obj", 3, {"expected a number", "'abc'"}},
    {"VertexWithTwoNumbers", "obj_vertex_two_numbers.obj", 2, {"3 numbers", "got 2"}},
    {"ZeroIndex", "obj_zero_index.obj", 4, {"index 0", "start at 1"}},
    {"BadCorner", "obj_bad_corner.obj", 5, {"face corner", "'1/x'"}},
    {"FaceWithTwoVertices", "obj_face_two_vertices.obj", 4, {"at least 3 vertices"}},
    {"NoFaces", "obj_no_faces.obj", 0, {"no faces"}},
    {"MissingFile", "no_such_file.obj", 0, {"cannot open"}},
};
INSTANTIATE_TEST_SUITE_P(ObjErrors, MalformedFile, testing::ValuesIn(kObjErrors), badFileName);

// ---------------------------------------------------------------------------------------------
// loadMesh dispatch

TEST(LoadMesh, ExtensionIsCaseInsensitive) {
    auto r = facet::loadMesh(testData("mesh_square_upper.OFF"));
    expectLoaded(r);
    EXPECT_EQ(r->triangleCount(), 2u);
    auto o = facet::loadMesh(testData("obj_colors.obj"));
    expectLoaded(o);
    EXPECT_EQ(o->triangleCount(), 1u);
}

TEST(LoadMesh, UnknownExtensionNamesTheFile) {
    EXPECT_TRUE(failsAt(facet::loadMesh(testData("texture_checker.png")), "texture_checker.png", 0,
                        {"unknown mesh format", ".png", ".off or .obj"}));
    EXPECT_TRUE(failsAt(facet::loadMesh("no_extension"), "no_extension", 0, {"no extension"}));
}

// ---------------------------------------------------------------------------------------------
// Mesh queries

TEST(MeshQueries, BoundsAndDiagonal) {
    Mesh empty;
    EXPECT_EQ(facet::computeBounds(empty).diagonal(), 0.0f);
    Mesh m;
    m.positions = {{1, 2, 3}, {-1, 5, 3}, {0, 0, 4}};
    const facet::Bounds b = facet::computeBounds(m);
    expectVec(b.min, {-1, 0, 3});
    expectVec(b.max, {1, 5, 4});
    EXPECT_FLOAT_EQ(b.diagonal(), std::sqrt(4.0f + 25.0f + 1.0f));
    EXPECT_EQ(b, (facet::Bounds{{-1, 0, 3}, {1, 5, 4}}));
    EXPECT_NE(b, facet::computeBounds(empty));
}

TEST(MeshQueries, ColouredByPositionSpansTheBoundingBox) {
    Mesh m;
    m.positions = {{1, 2, 3}, {-1, 5, 3}, {0, 0, 3}};  // flat in z: that channel is 0
    m.colors = {{9, 9, 9}};                            // replaced, not kept
    const Mesh c = facet::colouredByPosition(m);
    EXPECT_EQ(c.positions, m.positions);
    ASSERT_EQ(c.colors.size(), 3u);
    expectVec(c.colors[0], glm::vec3(1.0f, 0.4f, 0.0f));
    expectVec(c.colors[1], glm::vec3(0.0f, 1.0f, 0.0f));
    expectVec(c.colors[2], glm::vec3(0.5f, 0.0f, 0.0f));
}

TEST(MeshQueries, UniqueEdgesAreSortedPairs) {
    Mesh m;
    m.positions.resize(4);
    m.indices = {0, 1, 2, 2, 1, 3, 3, 3, 0};  // the last triangle is degenerate
    EXPECT_EQ(facet::uniqueEdges(m),
              (std::vector<std::uint32_t>{0, 1, 0, 2, 0, 3, 1, 2, 1, 3, 2, 3}));
}

TEST(MeshQueries, CubeHas18Edges) {
    REQUIRE_SHARED_DATA(course("cube_multi_color.off"));
    auto r = facet::loadOff(course("cube_multi_color.off"));
    expectLoaded(r);
    EXPECT_EQ(facet::uniqueEdges(*r).size(), 2u * 18u);  // 12 cube edges + 6 face diagonals
}

// ---------------------------------------------------------------------------------------------
// Scenes: valid files

TEST(SceneLoader, ValidScene) {
    auto r = facet::loadScene(testData("scene_valid.scene"));
    expectLoaded(r);
    const facet::Scene& s = *r;
    EXPECT_EQ(s.path, testData("scene_valid.scene"));
    EXPECT_EQ(s.meshPath, testData("mesh_square.off"));
    EXPECT_TRUE(s.texturePath.empty());
    EXPECT_EQ(s.mesh->triangleCount(), 2u);
    expectVec(s.camera.eye, {0, 0, -3});
    expectVec(s.camera.look, {0, 0, 0});
    expectVec(s.camera.up, {0, -1, 0});
    EXPECT_EQ(s.camera.focal, 256.0);
    EXPECT_EQ(s.camera.width, 320);
    EXPECT_EQ(s.camera.height, 240);
    EXPECT_EQ(s.lighting.ambient, 0.5);
    EXPECT_EQ(s.lighting.light.position, glm::dvec4(1, 2, -4, 1));
    EXPECT_EQ(s.lighting.light.intensity, 0.75);
    EXPECT_EQ(s.lighting.material.ka, 0.1);
    EXPECT_EQ(s.lighting.material.kd, 0.6);
    EXPECT_EQ(s.lighting.material.ks, 0.3);
    EXPECT_EQ(s.lighting.material.s, 12.0);
}

TEST(SceneLoader, CrlfScene) {
    auto r = facet::loadScene(testData("scene_crlf.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->camera.width, 320);
    EXPECT_EQ(r->lighting.material.s, 12.0);
}

TEST(SceneLoader, ParseFromMemoryWithBomCrlfAndTrailingComments) {
    const std::string text =
        "\xEF\xBB\xBF\r\nmy mesh.obj  # a path with a space\r\n1 2 3\r\n0 0 0 # look\r\n"
        "0 1 0\r\n500\r\n64 32\r\n0\r\n1 1 1 0 2\r\n0 0 0 0\r\n  sub dir/tex.png  \r\n";
    auto r = facet::parseScene(text, "mem.scene");
    expectLoaded(r);
    EXPECT_EQ(r->meshPath, "my mesh.obj");
    EXPECT_EQ(r->texturePath, "sub dir/tex.png");
    EXPECT_EQ(r->camera.height, 32);
    EXPECT_EQ(r->lighting.ambient, 0.0);
    EXPECT_EQ(r->lighting.light.position, glm::dvec4(1, 1, 1, 0));
    EXPECT_EQ(r->lighting.light.intensity, 2.0);
}

TEST(SceneLoader, FiveNumberLight) {
    auto r = facet::loadScene(testData("scene_light_5_numbers.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->lighting.light.position, glm::dvec4(1, 2, -4, 2));
    EXPECT_EQ(r->lighting.light.intensity, 0.75);  // the 5th number, not w (the course code's bug)
}

TEST(SceneLoader, DirectionalLight) {
    auto r = facet::loadScene(testData("scene_light_directional.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->lighting.light.position, glm::dvec4(0, 0, -1, 0));
    EXPECT_EQ(r->lighting.light.intensity, 0.9);
}

TEST(SceneLoader, TextureLine) {
    auto r = facet::loadScene(testData("scene_texture.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->texturePath, testData("texture_checker.png"));
    ASSERT_NE(r->texture, nullptr);  // loaded with the scene, mip chain and all
    EXPECT_GT(r->texture->levelCount(), 1);
}

TEST(SceneLoader, ObjMaterialTextureBecomesTheScenesTexture) {
    auto r = facet::loadScene(testData("scene_obj_texture.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->mesh->texturePath, testData("texture_checker.png"));
    EXPECT_EQ(r->texturePath, testData("texture_checker.png"));
    ASSERT_NE(r->texture, nullptr);
}

TEST(SceneLoader, SceneWithoutTextureHasNone) {
    auto r = facet::loadScene(testData("scene_valid.scene"));
    expectLoaded(r);
    EXPECT_EQ(r->texture, nullptr);
    EXPECT_TRUE(r->texturePath.empty());
}

TEST(SceneLoader, ReplacingTheTextureKeepsTheOldOneOnFailure) {
    auto r = facet::loadScene(testData("scene_texture.scene"));
    expectLoaded(r);
    const auto before = r->texture;
    const facet::Status bad = facet::loadSceneTexture(*r, testData("tex_not_an_image.png"));
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().what().find("tex_not_an_image.png"), std::string::npos)
        << bad.error().what();
    EXPECT_EQ(r->texture, before);
    EXPECT_EQ(r->texturePath, testData("texture_checker.png"));
    const facet::Status missing = facet::loadSceneTexture(*r, testData("no_such_file.png"));
    ASSERT_FALSE(missing);
    EXPECT_EQ(r->texture, before);

    const facet::Status good = facet::loadSceneTexture(*r, testData("tex_4x4.png"));
    EXPECT_TRUE(good) << good.error().what();
    ASSERT_NE(r->texture, nullptr);
    EXPECT_EQ(r->texture->width(), 4);
    EXPECT_EQ(r->texturePath, testData("tex_4x4.png"));
}

TEST(SceneLoader, CourseScenes) {
    REQUIRE_SHARED_DATA(sharedData("course"));
    {
        auto r = facet::loadScene(course("example0.scene"));
        expectLoaded(r);
        EXPECT_EQ(r->meshPath, course("cube_multi_color.off"));  // found by the bare name
        EXPECT_EQ(r->mesh->vertexCount(), 8u);
        EXPECT_EQ(r->mesh->triangleCount(), 12u);
        expectVec(r->camera.eye, {1.2, 2.0, 2.0});
        expectVec(r->camera.look, {0, 0, 0});
        expectVec(r->camera.up, {0, -1, 0});
        EXPECT_EQ(r->camera.focal, 512.0);
        EXPECT_EQ(r->camera.width, 512);
        EXPECT_EQ(r->camera.height, 512);
        EXPECT_EQ(r->lighting.ambient, 1.8);
        EXPECT_EQ(r->lighting.light.position, glm::dvec4(0, 0, 8, 1));
        EXPECT_EQ(r->lighting.light.intensity, 9.0);
        EXPECT_EQ(r->lighting.material.ka, 0.5);
        EXPECT_EQ(r->lighting.material.s, 1.0);
    }
    {
        auto r = facet::loadScene(course("example1.scene"));
        expectLoaded(r);
        EXPECT_EQ(r->mesh->vertexCount(), 444u);
        EXPECT_EQ(r->mesh->triangleCount(), 884u);
        expectVec(r->camera.eye, {1.0, 1.0, 1.5});
        expectVec(r->camera.look, {-0.05, 0.1, 0.0});
        EXPECT_EQ(r->camera.focal, 3500.0);
        EXPECT_EQ(r->camera.width, 640);
        EXPECT_EQ(r->camera.height, 480);
        EXPECT_EQ(r->lighting.ambient, 0.5);
        EXPECT_EQ(r->lighting.light.position, glm::dvec4(5, 8, 8, 1));
        EXPECT_EQ(r->lighting.light.intensity, 4.0);
    }
    {
        auto r = facet::loadScene(course("example2.scene"));
        expectLoaded(r);
        EXPECT_EQ(r->mesh->vertexCount(), 2947u);
        EXPECT_EQ(r->mesh->triangleCount(), 5808u);
        expectVec(r->camera.eye, {-1.5, 4.5, 6.0});
        EXPECT_EQ(r->camera.focal, 2000.0);
        EXPECT_EQ(r->camera.width, 800);
        EXPECT_EQ(r->camera.height, 600);
        EXPECT_EQ(r->lighting.ambient, 1.0);
        EXPECT_EQ(r->lighting.light.intensity, 0.8);
        EXPECT_EQ(r->lighting.material.s, 3.0);
    }
    {
        auto r = facet::loadScene(course("example_textured.scene"));
        expectLoaded(r);
        EXPECT_EQ(r->mesh->vertexCount(), 4u);
        EXPECT_EQ(r->mesh->triangleCount(), 2u);
        EXPECT_EQ(r->mesh->uvs.size(), 4u);
        expectVec(r->camera.eye, {0.75, 1.25, 0.5});
        expectVec(r->camera.look, {0.5, 0.5, 0.0});
        expectVec(r->camera.up, {0, 0, 1});
        EXPECT_EQ(r->camera.focal, 256.0);
        EXPECT_EQ(r->lighting.ambient, 0.1);
        EXPECT_EQ(r->lighting.light.intensity, 0.9);
        EXPECT_EQ(r->lighting.material.s, 10.0);
        EXPECT_TRUE(r->texturePath.empty());
    }
}

TEST(SceneLoader, SharedScenes) {
    REQUIRE_SHARED_DATA(sharedData("scenes"));
    auto spot = facet::loadScene(sharedData("scenes/spot_1280x720.scene"));
    expectLoaded(spot);
    EXPECT_EQ(spot->mesh->triangleCount(), 5856u);
    EXPECT_TRUE(spot->mesh->hasUvs());
    EXPECT_EQ(spot->camera.width, 1280);
    EXPECT_EQ(spot->camera.height, 720);
    ASSERT_FALSE(spot->texturePath.empty());
    EXPECT_TRUE(fs::equivalent(spot->texturePath, sharedData("models/spot_texture.png")));
    EXPECT_TRUE(fs::equivalent(spot->meshPath, sharedData("models/spot_triangulated.obj")));

    auto bunny = facet::loadScene(sharedData("scenes/bunny_1920x1080.scene"));
    expectLoaded(bunny);
    EXPECT_EQ(bunny->mesh->triangleCount(), 69451u);
    EXPECT_EQ(bunny->camera.focal, 1950.0);
    EXPECT_EQ(bunny->lighting.material.s, 20.0);
}

/// A fresh folder tree made current for one test; the previous current folder comes back and
/// the tree goes away when it ends, also after a failed ASSERT.
class TempCurrentFolder {
  public:
    TempCurrentFolder() : previous_(fs::current_path()), root_(tempFile("tree")) {
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    ~TempCurrentFolder() {
        fs::current_path(previous_);
        fs::remove_all(root_);
    }
    TempCurrentFolder(const TempCurrentFolder&) = delete;
    TempCurrentFolder& operator=(const TempCurrentFolder&) = delete;

    /// Creates an empty file (and its folders) at `relative` under the tree; its full path.
    std::string touch(const std::string& relative) const {
        const fs::path path = root_ / relative;
        fs::create_directories(path.parent_path());
        std::ofstream(path).put('\n');
        return path.string();
    }
    /// Makes the folder `relative` under the tree (created if needed) the current folder.
    void enter(const std::string& relative) const {
        fs::create_directories(root_ / relative);
        fs::current_path(root_ / relative);
    }
    std::string path(const std::string& relative) const { return (root_ / relative).string(); }

  private:
    fs::path previous_, root_;
};

// The three places, in order, in a tree the test owns: what the build folder or the current
// folder holds cannot make a rule pass or fail by accident.
TEST(SceneLoader, ResolveScenePathRules) {
    TempCurrentFolder tree;
    const std::string scene = tree.path("scenes/x.scene");  // never read, only its folder
    tree.enter("here");

    // 1: next to the scene file.
    const std::string next = tree.touch("scenes/next.off");
    EXPECT_EQ(facet::resolveScenePath(scene, "next.off"), next);
    // 2: relative to the current folder, returned as written.
    tree.touch("here/meshes/cwd.off");
    EXPECT_EQ(facet::resolveScenePath(scene, "meshes/cwd.off"), "meshes/cwd.off");
    // 3: the bare file name next to the scene file (the course's "data/..." paths).
    const std::string bare = tree.touch("scenes/bare.off");
    EXPECT_EQ(facet::resolveScenePath(scene, "data/bare.off"), bare);

    // The order: next to the scene beats the current folder, which beats the bare name.
    const std::string both = tree.touch("scenes/meshes/both.off");
    tree.touch("here/meshes/both.off");
    EXPECT_EQ(facet::resolveScenePath(scene, "meshes/both.off"), both);
    tree.touch("here/data/two.off");
    tree.touch("scenes/two.off");
    EXPECT_EQ(facet::resolveScenePath(scene, "data/two.off"), "data/two.off");

    // Rule 2 follows the current folder: from elsewhere the same name is not found.
    tree.enter("scenes");
    EXPECT_EQ(facet::resolveScenePath(scene, "meshes/cwd.off"), "");

    // Nothing found.
    EXPECT_EQ(facet::resolveScenePath(scene, "no_such_mesh.off"), "");
    EXPECT_EQ(facet::resolveScenePath(scene, ""), "");
}

// ---------------------------------------------------------------------------------------------
// Scenes: errors

TEST(SceneErrors, LightWithThreeNumbers) {
    auto r = facet::loadScene(testData("scene_light_3_numbers.scene"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().what(), testData("scene_light_3_numbers.scene") +
                                    ":16: point light needs 4 or 5 numbers (x y z Id | x y z w "
                                    "Id), got 3");
}

// .scene files.
const BadFile kSceneErrors[] = {
    {"LightWithSixNumbers", "scene_light_6_numbers.scene", 16, {"4 or 5 numbers", "got 6"}},
    {"NegativeLightIntensity",
     "scene_light_negative_intensity.scene",
     16,
     {"Id must be >= 0", "-1"}},
    {"DirectionalLightWithoutDirection",
     "scene_light_zero_direction.scene",
     16,
     {"non-zero direction"}},
    {"MissingMesh", "scene_missing_mesh.scene", 2, {"'does_not_exist.off'", "not found"}},
    {"MissingTexture", "scene_missing_texture.scene", 20, {"'no_such_texture.png'", "not found"}},
    {"CorruptTextureNamesTheSceneLineAndTheImage",
     "scene_corrupt_texture.scene",
     20,
     {"cannot load texture", "tex_not_an_image.png"}},
    {"MeshWithUnknownExtension",
     "scene_bad_mesh_extension.scene",
     2,
     {".off or .obj", "mesh_square.ply"}},
    {"EyeEqualsLook", "scene_eye_equals_look.scene", 6, {"look-at point equals the camera"}},
    {"UpParallelToView", "scene_up_parallel.scene", 8, {"up", "parallel"}},
    {"UpZero", "scene_up_zero.scene", 8, {"up", "must not be zero"}},
    {"FocalZero", "scene_focal_zero.scene", 10, {"focal length must be > 0", "got 0"}},
    {"FocalNegative", "scene_focal_negative.scene", 10, {"focal length must be > 0", "-256"}},
    {"SizeZero", "scene_size_zero.scene", 12, {"width", "1 to 16384", "got 0"}},
    {"SizeTooLarge", "scene_size_too_large.scene", 12, {"height", "1 to 16384", "got 20000"}},
    {"SizeNotInteger", "scene_size_non_integer.scene", 12, {"integers", "'320.5'"}},
    {"SizeWithOneNumber", "scene_size_one_number.scene", 12, {"needs 2 integers (w h), got 1"}},
    {"TooManyNumbers",
     "scene_too_many_numbers.scene",
     4,
     {"camera position needs 3 numbers (x y z), got 4"}},
    {"GarbageToken",
     "scene_garbage_token.scene",
     6,
     {"look-at point: expected a number, got 'zero'"}},
    {"TrailingGarbage", "scene_trailing_garbage.scene", 14, {"expected a number", "'abc'"}},
    {"NaN", "scene_nan.scene", 4, {"camera position", "non-finite", "'nan'"}},
    {"Inf", "scene_inf.scene", 10, {"focal length", "non-finite", "'inf'"}},
    {"NegativeAmbient", "scene_negative_ambient.scene", 14, {"Ia must be >= 0", "-0.5"}},
    {"NegativeMaterial", "scene_material_negative.scene", 18, {">= 0", "Kd = -0.6"}},
    {"MaterialWithThreeNumbers",
     "scene_material_3_numbers.scene",
     18,
     {"material needs 4 numbers (Ka Kd Ks s), got 3"}},
    {"Truncated", "scene_truncated.scene", 14, {"file ends before the point light line"}},
    {"ExtraLine", "scene_extra_line.scene", 22, {"at most 10 fields"}},
};
INSTANTIATE_TEST_SUITE_P(SceneErrors, MalformedFile, testing::ValuesIn(kSceneErrors), badFileName);

TEST(SceneErrors, MissingMapKdTextureNamesTheObj) {
    EXPECT_TRUE(failsAt(facet::loadScene(testData("scene_obj_missing_texture.scene")),
                        "obj_missing_texture.obj", 0, {"map_Kd", "not_here.png"}));
}

TEST(SceneErrors, MeshErrorKeepsTheMeshFileAndLine) {
    EXPECT_TRUE(failsAt(facet::loadScene(testData("scene_bad_mesh.scene")), "off_bad_index.off", 10,
                        {"out of range"}));
}

TEST(SceneErrors, UpNearlyParallelAtAnyScale) {
    // The tolerance is relative: tiny but clearly non-parallel vectors are fine.
    const std::string base = "m.off\n0 0 0\n0 0 1e-20\n";
    EXPECT_TRUE(facet::parseScene(base + "1e-20 0 1e-20\n1\n1 1\n0\n0 0 0 1\n0 0 0 0\n", "s").ok());
    EXPECT_TRUE(
        failsAt(facet::parseScene(base + "1e-30 0 1e10\n1\n1 1\n0\n0 0 0 1\n0 0 0 0\n", "s.scene"),
                "s.scene", 4, {"parallel"}));
}

TEST(SceneErrors, MissingSceneFile) {
    EXPECT_TRUE(
        failsAt(facet::loadScene(testData("no_such.scene")), "no_such.scene", 0, {"cannot open"}));
    EXPECT_TRUE(failsAt(facet::loadScene(FACET_TEST_DATA), "data", 0, {"folder"}));
}

}  // namespace
