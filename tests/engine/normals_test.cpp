// Vertex normals (spec §6) against hand-computed values: the course cube, a regular
// tetrahedron, degenerate input, and a fine sphere; plus the normals display length (§8).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/mesh.hpp"
#include "facet/mesh_io.hpp"
#include "facet/normals.hpp"
#include "facet/procedural.hpp"
#include "shared_data.hpp"

namespace {

using facet::Mesh;

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Six times the signed volume sums to ∑ p0 · (p1 × p2): positive when the triangles face out.
double signedVolume(const Mesh& m) {
    double sum = 0.0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::dvec3 a(m.positions[m.indices[3 * t]]);
        const glm::dvec3 b(m.positions[m.indices[3 * t + 1]]);
        const glm::dvec3 c(m.positions[m.indices[3 * t + 2]]);
        sum += glm::dot(a, glm::cross(b, c));
    }
    return sum / 6.0;
}

void reverseWinding(Mesh& m) {
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// The unit cube as the course's cube_multi_color.off triangulates it.
Mesh courseCube() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.indices = {0, 1, 4, 1, 5, 4, 1, 2, 5, 2, 6, 5, 2, 3, 6, 3, 7, 6,
                 3, 0, 7, 0, 4, 7, 4, 5, 7, 5, 6, 7, 3, 2, 0, 2, 1, 0};
    return m;
}

// Every triangle of the cube has area 1/2, so its cross product is exactly its unit outward
// normal. Grouped by face (checked by hand: (v1 − v0) × (v2 − v0) of each):
//   y = 0 (0,−1,0): (0,1,4) (1,5,4)     x = 1 (1,0,0):  (1,2,5) (2,6,5)
//   y = 1 (0,1,0):  (2,3,6) (3,7,6)     x = 0 (−1,0,0): (3,0,7) (0,4,7)
//   z = 1 (0,0,1):  (4,5,7) (5,6,7)     z = 0 (0,0,−1): (3,2,0) (2,1,0)
// A corner's sum counts how many triangles of each of its three faces touch it (1 or 2, since
// each face's diagonal runs through two of its corners):
//   v0: y0×1, x0×2, z0×2 → (−2,−1,−2), length 3      v1: y0×2, x1×1, z0×1 → (1,−2,−1), √6
//   v2: x1×2, y1×1, z0×2 → (2,1,−2), length 3        v3: y1×2, x0×1, z0×1 → (−1,2,−1), √6
//   v4: y0×2, x0×1, z1×1 → (−1,−2,1), √6             v5: y0×1, x1×2, z1×2 → (2,−1,2), length 3
//   v6: x1×1, y1×2, z1×1 → (1,2,1), √6               v7: y1×1, x0×2, z1×2 → (−2,1,2), length 3
// (Triangles per corner 5,4,5,4,4,5,4,5: 36 = 12 × 3.)
const std::vector<glm::vec3> kCubeNormals = {
    glm::vec3(-2, -1, -2) / 3.0f,
    glm::vec3(1, -2, -1) / std::sqrt(6.0f),
    glm::vec3(2, 1, -2) / 3.0f,
    glm::vec3(-1, 2, -1) / std::sqrt(6.0f),
    glm::vec3(-1, -2, 1) / std::sqrt(6.0f),
    glm::vec3(2, -1, 2) / 3.0f,
    glm::vec3(1, 2, 1) / std::sqrt(6.0f),
    glm::vec3(-2, 1, 2) / 3.0f,
};

TEST(Normals, CourseCubeBuiltInCode) {
    const std::vector<glm::vec3> n = facet::computeVertexNormals(courseCube());
    ASSERT_EQ(n.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        SCOPED_TRACE(i);
        expectNear(n[i], kCubeNormals[i], 1e-6f);
    }
}

TEST(Normals, CourseCubeFile) {
    const std::string path = facet::test::sharedData("course/cube_multi_color.off");
    REQUIRE_SHARED_DATA(path);
    const facet::Result<Mesh> mesh = facet::loadOff(path);
    ASSERT_TRUE(mesh.ok()) << mesh.error().what();
    ASSERT_EQ(mesh.value().indices, courseCube().indices);
    const std::vector<glm::vec3> n = facet::computeVertexNormals(mesh.value());
    ASSERT_EQ(n.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        SCOPED_TRACE(i);
        expectNear(n[i], kCubeNormals[i], 1e-6f);
    }
}

// Corners of alternate cube vertices: A(1,1,1) B(1,−1,−1) C(−1,1,−1) D(−1,−1,1), centroid 0,
// every face of the same area. The face opposite a vertex has outward normal −vertex/√3, e.g.
// (B − A) × (C − A) = (0,−2,−2) × (−2,0,−2) = (4,4,−4) for face ABC, opposite D. A vertex's three
// faces are the ones opposite the other three, so the sum is −(B + C + D)/√3 · k = A/√3 · k
// (A + B + C + D = 0): each vertex normal is its own direction from the centroid, A/√3, which is
// also −(unit normal of the opposite face).
TEST(Normals, RegularTetrahedronPointsAwayFromCentroid) {
    Mesh m;
    m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    m.indices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    const std::vector<glm::vec3> n = facet::computeVertexNormals(m);
    ASSERT_EQ(n.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        expectNear(n[i], m.positions[i] / std::sqrt(3.0f), 1e-6f);
    }
    // Face ABC's unit normal is (1,1,−1)/√3 = −D/√3, so D's normal is its negation.
    const glm::vec3 abc = glm::normalize(
        glm::cross(m.positions[1] - m.positions[0], m.positions[2] - m.positions[0]));
    expectNear(n[3], -abc, 1e-6f);
}

TEST(Normals, AreaWeighting) {
    // Vertex 0 is shared by a triangle of area 2 in z = 0 (normal +z) and one of area 1/2 in
    // x = 0 (normal +x): cross products (0,0,4) and (1,0,0) → (1,0,4)/√17.
    Mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}};
    m.indices = {0, 1, 2, 0, 3, 4};
    const std::vector<glm::vec3> n = facet::computeVertexNormals(m);
    expectNear(n[0], glm::vec3(1, 0, 4) / std::sqrt(17.0f), 1e-6f);
    expectNear(n[1], glm::vec3(0, 0, 1), 0.0f);
    expectNear(n[3], glm::vec3(1, 0, 0), 0.0f);
}

TEST(Normals, DegenerateInputGivesFiniteOrZeroNormals) {
    Mesh m;
    m.positions = {
        {0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // 0–2: a proper triangle, normal +z
        {2, 2, 2}, {3, 3, 3}, {4, 4, 4},  // 3–5: collinear, a zero-area face
        {9, 9, 9},                        // 6: used by no face
        {5, 5, 5},                        // 7: only in a point triangle
    };
    m.indices = {0, 1, 2, 3, 4, 5,
                 7, 7, 7, 1, 1, 2,  // zero area at vertices 1 and 2: must change nothing
                 0, 1, 3};  // (1,0,0) × (2,2,2) = (0,−2,2), which gives vertex 3 a normal
    const std::vector<glm::vec3> n = facet::computeVertexNormals(m);
    ASSERT_EQ(n.size(), m.positions.size());
    for (const glm::vec3& v : n) EXPECT_TRUE(finite(v));
    // Vertices 0 and 1 get +z plus (0,−2,2): (0,0,1) + (0,−2,2) = (0,−2,3) → /√13.
    expectNear(n[0], glm::vec3(0, -2, 3) / std::sqrt(13.0f), 1e-6f);
    expectNear(n[2], glm::vec3(0, 0, 1), 0.0f);
    expectNear(n[3], glm::vec3(0, -1, 1) / std::sqrt(2.0f), 1e-6f);
    expectNear(n[4], glm::vec3(0.0f), 0.0f);
    expectNear(n[5], glm::vec3(0.0f), 0.0f);
    expectNear(n[6], glm::vec3(0.0f), 0.0f);
    expectNear(n[7], glm::vec3(0.0f), 0.0f);
}

TEST(Normals, CancellingFacesGiveZero) {
    // A two-sided sheet: the same triangle in both windings sums to exactly zero at every corner.
    Mesh m;
    m.positions = {{0.1f, 0.2f, 0.3f}, {1.7f, -0.4f, 0.9f}, {-0.6f, 1.3f, 2.2f}};
    m.indices = {0, 1, 2, 0, 2, 1};
    for (const glm::vec3& v : facet::computeVertexNormals(m)) {
        EXPECT_TRUE(finite(v));
        expectNear(v, glm::vec3(0.0f), 0.0f);
    }
}

TEST(Normals, EmptyMesh) {
    EXPECT_TRUE(facet::computeVertexNormals(Mesh{}).empty());
    EXPECT_EQ(facet::normalDisplayLength(Mesh{}), 0.0f);
}

TEST(Normals, UnitSphereNormalsAreThePositions) {
    // The error shrinks only linearly with the cell size (each quad's diagonal split tilts the
    // area weighting): about 0.5 × the ring spacing next to the poles, so 64 rings for 1e-2.
    const int rings = 64, sectors = 128;
    Mesh m = facet::makeUvSphere(rings, sectors);
    // Normals follow the winding (see Normals.ReversedWindingNegatesNormals). This test is about
    // the normals, not the generator, so orient the sphere outward (positive signed volume)
    // first: makeUvSphere has wound it clockwise seen from outside, against mesh.hpp's contract.
    if (signedVolume(m) < 0.0) reverseWinding(m);
    const std::vector<glm::vec3> n = facet::computeVertexNormals(m);
    ASSERT_EQ(n.size(), m.positions.size());
    float worst = 0.0f;
    // Pole rows are excluded (each pole copy has one thin triangle), and so are the seam columns
    // s = 0 and s = sectors: they duplicate positions and see the faces of one side only, as
    // normals follow vertex indices.
    for (int r = 1; r < rings; ++r)
        for (int s = 1; s < sectors; ++s) {
            const std::size_t i = static_cast<std::size_t>(r * (sectors + 1) + s);
            EXPECT_NEAR(glm::length(n[i]), 1.0f, 1e-6f);
            worst = std::max(worst, glm::length(n[i] - m.positions[i]));
        }
    EXPECT_LT(worst, 1e-2f);
}

TEST(Normals, ReversedWindingNegatesNormals) {
    Mesh m = courseCube();
    reverseWinding(m);
    const std::vector<glm::vec3> n = facet::computeVertexNormals(m);
    for (std::size_t i = 0; i < 8; ++i) {
        SCOPED_TRACE(i);
        expectNear(n[i], -kCubeNormals[i], 1e-6f);
    }
}

TEST(Normals, DisplayLengthIsDiagonalOverHundred) {
    EXPECT_NEAR(facet::normalDisplayLength(courseCube()), std::sqrt(3.0f) / 100.0f, 1e-7f);
    Mesh m;
    m.positions = {{-1, 2, 0}, {2, 6, 12}};  // box 3 × 4 × 12: diagonal 13
    EXPECT_NEAR(facet::normalDisplayLength(m), 0.13f, 1e-7f);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Normals per position and from the file (spec §3, §6; issue 14, point 5).

namespace seams {

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::filesystem::path p = std::filesystem::temp_directory_path() / name;
    FILE* f = std::fopen(p.string().c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
    return p.string();
}

// A unit cube of 8 positions; with `uvs` every face has its own four texture coordinates, so
// the loader splits each corner into three vertices.
std::string cubeObj(bool uvs) {
    std::string s = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    if (uvs)
        for (int face = 0; face < 6; ++face) s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    const int faces[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                             {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
    for (int face = 0; face < 6; ++face) {
        const auto& f = faces[face];
        s += "f";
        for (int k = 0; k < 4; ++k) {
            s += ' ';
            s += std::to_string(f[k]);
            if (uvs) {
                s += '/';
                s += std::to_string(4 * face + k + 1);
            }
        }
        s += "\n";
    }
    return s;
}

}  // namespace seams

TEST(NormalsPerPosition, ACubeWithSeparateFaceUvsSharesOneNormalPerCorner) {
    const auto split = facet::loadObj(seams::writeTemp("facet_cube_uv.obj", seams::cubeObj(true)));
    const auto welded =
        facet::loadObj(seams::writeTemp("facet_cube_plain.obj", seams::cubeObj(false)));
    ASSERT_TRUE(split && welded);
    ASSERT_EQ(split->vertexCount(), 24u);  // 8 corners × 3 faces each
    ASSERT_EQ(welded->vertexCount(), 8u);
    ASSERT_EQ(split->positionIds.size(), 24u);
    EXPECT_TRUE(welded->positionIds.empty());  // nothing was split

    const std::vector<glm::vec3> n = facet::computeVertexNormals(*split);
    const std::vector<glm::vec3> w = facet::computeVertexNormals(*welded);
    for (std::size_t i = 0; i < n.size(); ++i) {
        // Each of the three vertices of a corner has the welded cube's normal at that corner
        // (pointing out along the diagonal's octant), not its own face's.
        const auto same =
            std::find(welded->positions.begin(), welded->positions.end(), split->positions[i]);
        ASSERT_NE(same, welded->positions.end());
        EXPECT_EQ(n[i], w[static_cast<std::size_t>(same - welded->positions.begin())])
            << "vertex " << i;
        EXPECT_LT(split->positionIds[i], 8u);  // the file's position it was split from
        const glm::vec3 outwards = split->positions[i] - glm::vec3(0.5f);
        EXPECT_GT(glm::dot(n[i], outwards), 0.0f);
        EXPECT_LT(std::abs(n[i].x), 0.99f);  // not a face normal
    }
}

TEST(NormalsPerPosition, OffVerticesAreEachTheirOwnPosition) {
    // Two triangles meeting at a fold, the shared corner written twice: OFF has no positions
    // to share, so the two copies keep their own face's normal (spec §6).
    const auto m = facet::parseOff(
        "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n0 1 0\n0 0 1\n"
        "3 0 1 2\n3 3 4 5\n",
        "fold.off");
    ASSERT_TRUE(m);
    const std::vector<glm::vec3> n = facet::computeVertexNormals(*m);
    EXPECT_EQ(n[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(n[3], glm::vec3(1, 0, 0));
}

TEST(NormalsFromTheFile, SuzannesVnAreUsed) {
    const std::string path = facet::test::sharedData("models/suzanne.obj");
    REQUIRE_SHARED_DATA(path);
    const auto m = facet::loadObj(path);
    ASSERT_TRUE(m) << m.error().what();
    ASSERT_TRUE(m->hasNormals());
    ASSERT_EQ(m->normals.size(), m->vertexCount());
    const std::vector<glm::vec3> used = facet::computeVertexNormals(*m);
    EXPECT_EQ(used, m->normals);
    // Every file normal is unit length, and they are not what the faces would give: Suzanne's
    // vn are Blender's smooth normals, which differ from area-weighted sums.
    Mesh computed = *m;
    computed.normals.clear();
    const std::vector<glm::vec3> own = facet::computeVertexNormals(computed);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < used.size(); ++i) {
        EXPECT_NEAR(glm::length(used[i]), 1.0f, 1e-5f);
        differ += glm::length(used[i] - own[i]) > 1e-3f;
    }
    EXPECT_GT(differ, used.size() / 10);
}

TEST(NormalsFromTheFile, PartialVnAreIgnoredAndBadIndicesNamed) {
    // One face without vn: the file's normals are not used at all.
    const auto partial = facet::loadObj(seams::writeTemp(
        "facet_partial_vn.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 -1\nf 1//1 2//1 3//1\nf 2 4 3\n"));
    ASSERT_TRUE(partial) << partial.error().what();
    EXPECT_FALSE(partial->hasNormals());
    EXPECT_EQ(facet::computeVertexNormals(*partial)[0], glm::vec3(0, 0, 1));

    const auto full = facet::loadObj(seams::writeTemp(
        "facet_full_vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -2\nf 1//1 2//1 3//1\n"));
    ASSERT_TRUE(full);
    EXPECT_EQ(facet::computeVertexNormals(*full)[0], glm::vec3(0, 0, -1));  // normalised

    const auto bad = facet::loadObj(seams::writeTemp(
        "facet_bad_vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n"));
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().what().find(":5: normal index out of range"), std::string::npos)
        << bad.error().what();
}
