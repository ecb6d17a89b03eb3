// The checks of `make lab-check`. Expected values come from facet itself: the camera matrices
// of facet/camera.hpp, the reference renderer (facet/reference.hpp) for the rasterizers, the
// normals and lighting of facet/normals.hpp and facet/lighting.hpp, and the reference sampler.

#include "lab/checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/lighting.hpp"
#include "facet/normals.hpp"
#include "facet/reference.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "reference/samplers.hpp"

namespace lab {
namespace {

struct Failure {
    std::string input, expected, got, hint;
};
using Verdict = std::optional<Failure>;

std::string num(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string vec(const glm::dvec2& v) {
    return "(" + num(v.x) + ", " + num(v.y) + ")";
}

std::string vec(const glm::dvec3& v) {
    return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")";
}

// A matrix as its rows, the way the course writes them (GLM stores columns).
template <int C, int R>
std::string rows(const glm::mat<C, R, double>& m) {
    std::string s = "[";
    for (int r = 0; r < R; ++r) {
        if (r > 0) s += "; ";
        for (int c = 0; c < C; ++c) {
            if (c > 0) s += ' ';
            s += num(m[c][r]);
        }
    }
    return s + "]";
}

template <int C, int R>
bool near(const glm::mat<C, R, double>& a, const glm::mat<C, R, double>& b, double tol) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!(std::abs(a[c][r] - b[c][r]) <= tol * std::max(1.0, std::abs(b[c][r]))))
                return false;
    return true;
}

bool near(double a, double b, double tol) {
    return std::abs(a - b) <= tol * std::max(1.0, std::abs(b));
}

template <int N>
bool near(const glm::vec<N, double>& a, const glm::vec<N, double>& b, double tol) {
    for (int i = 0; i < N; ++i)
        if (!near(a[i], b[i], tol)) return false;
    return true;
}

std::string fileName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The course's scenes, loaded once.
struct Context {
    std::string dir;
    std::vector<facet::Scene> scenes;  // example0, example1, example2, example_textured
    std::vector<std::shared_ptr<const facet::Texture>> textures;  // brick.jpg, world_map.jpg
    std::string error;                                            // a file that could not be read
};

Context loadContext(const std::string& dir) {
    Context ctx;
    ctx.dir = dir;
    for (const char* name :
         {"example0.scene", "example1.scene", "example2.scene", "example_textured.scene"}) {
        facet::Result<facet::Scene> s = facet::loadScene(dir + "/" + name);
        if (!s) {
            ctx.error = s.error().what();
            return ctx;
        }
        ctx.scenes.push_back(std::move(s).value());
    }
    for (const char* name : {"brick.jpg", "world_map.jpg"}) {
        facet::Result<facet::Texture> t = facet::loadTexture(dir + "/" + name);
        if (!t) {
            ctx.error = t.error().what();
            return ctx;
        }
        ctx.textures.push_back(std::make_shared<const facet::Texture>(std::move(t).value()));
    }
    return ctx;
}

std::string cameraInput(const facet::Scene& s) {
    return "eye " + vec(s.camera.eye) + ", look-at " + vec(s.camera.look) + ", up " +
           vec(s.camera.up) + " (" + fileName(s.path) + ")";
}

std::vector<glm::dvec3> positionsOf(const facet::Mesh& mesh) {
    return {mesh.positions.begin(), mesh.positions.end()};
}

// Rows 0, 1 and 3 of the engine's clip matrix (x, y and the homogeneous w = Z): K · [I | 0].
glm::dmat4x3 engineKP(const facet::Camera& camera) {
    const glm::dmat4 clip = facet::clipFromCamera(camera);
    glm::dmat4x3 m(0.0);
    for (int c = 0; c < 4; ++c) {
        m[c][0] = clip[c][0];
        m[c][1] = clip[c][1];
        m[c][2] = clip[c][3];
    }
    return m;
}

// ---- steps 1 to 4 ---------------------------------------------------------------------------

Verdict checkSetLookAt(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        const facet::Camera& c = s.camera;
        const glm::dmat4 got = setLookAt(c.eye, c.look, c.up);
        const glm::dmat4 want = facet::cameraFromWorld(c);
        if (near(got, want, 1e-9)) continue;
        std::string hint =
            "rows x, y, z with z = normalize(lookAt - eye), x = normalize(up x z), y = z x x, "
            "and the translation -R*eye";
        const auto row = [](const glm::dmat4& m, int r) {
            return glm::dvec3(m[0][r], m[1][r], m[2][r]);
        };
        const auto col = [](const glm::dmat4& m, int cc) { return glm::dvec3(m[cc]); };
        if (near(row(got, 2), -row(want, 2), 1e-9))
            hint =
                "the camera's Z axis must point from the eye to the look-at point "
                "(lookAt - eye), since the camera looks down +Z";
        else if (near(row(got, 0), -row(want, 0), 1e-9))
            hint = "x = up x z, in that order (glm::cross(up, z)); z x up points the other way";
        else if (near(col(got, 0), row(want, 0), 1e-9) && near(col(got, 1), row(want, 1), 1e-9))
            hint =
                "GLM indexes m[column][row]: x, y and z are the matrix's rows, you wrote them "
                "as columns";
        else if (near(row(got, 0), row(want, 0), 1e-9) && near(row(got, 1), row(want, 1), 1e-9) &&
                 near(row(got, 2), row(want, 2), 1e-9))
            hint =
                "the rotation is right; the translation must take the eye to the origin: "
                "-R*eye, i.e. -dot(x, eye), -dot(y, eye), -dot(z, eye) in column 3";
        else if (std::abs(glm::length(row(got, 0)) - 1.0) > 1e-6)
            hint = "normalise x and z: the rows of a rotation are unit vectors";
        return Failure{cameraInput(s), "worldToCamera = " + rows(want),
                       "worldToCamera = " + rows(got), hint};
    }
    return std::nullopt;
}

Verdict checkSetProjection(const Context&) {
    // [I | 0] is the engine's K·[I | 0] for a focal length of 1 and the principal point at 0.
    facet::Camera unit;
    unit.focal = 1.0;
    unit.width = 0;
    unit.height = 0;
    const glm::dmat4x3 want = engineKP(unit);
    const glm::dmat4x3 got = setProjection();
    if (near(got, want, 1e-12)) return std::nullopt;
    return Failure{"no input", "P = " + rows(want), "P = " + rows(got),
                   "P = [I | 0]: 3 rows and 4 columns, (X, Y, Z, 1) -> (X, Y, Z); the last "
                   "column is zero (GLM's dmat4x3 is m[column][row])"};
}

Verdict checkSetCalibration(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        const facet::Camera& c = s.camera;
        const glm::dmat4x3 kp = engineKP(c);
        const glm::dmat3 want{glm::dvec3(kp[0]), glm::dvec3(kp[1]), glm::dvec3(kp[2])};
        const glm::dmat3 got = setCalibration(c.focal, c.width, c.height);
        if (near(got, want, 1e-12)) continue;
        std::string hint =
            "K = [f 0 w/2; 0 f h/2; 0 0 1]: focal length in pixels, the optical "
            "axis through the image centre";
        if (near(got, glm::transpose(want), 1e-12))
            hint =
                "GLM lists columns: w/2 and h/2 belong in column 2 (m[2][0] and m[2][1]), "
                "you put them in row 2";
        else if (near(got[2][0], want[2][1], 1e-12) && near(got[2][1], want[2][0], 1e-12))
            hint = "w/2 goes with x (row 0), h/2 with y (row 1)";
        else if (near(got[2][0], 2.0 * want[2][0], 1e-12))
            hint = "the optical axis crosses the image at its centre: w/2 and h/2, not w and h";
        return Failure{"focal " + num(c.focal) + " px, image " + std::to_string(c.width) + " x " +
                           std::to_string(c.height) + " (" + fileName(s.path) + ")",
                       "K = " + rows(want), "K = " + rows(got), hint};
    }
    return std::nullopt;
}

Verdict checkProjectPoints(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        const facet::Camera& c = s.camera;
        const Transformation t{setLookAt(c.eye, c.look, c.up), setProjection(),
                               setCalibration(c.focal, c.width, c.height)};
        const std::vector<glm::dvec3> points = positionsOf(*s.mesh);
        const std::vector<glm::dvec3> got = projectPoints(t, points);
        if (got.size() != points.size())
            return Failure{std::to_string(points.size()) + " vertices of " + fileName(s.meshPath),
                           std::to_string(points.size()) + " projected points",
                           std::to_string(got.size()) + " points",
                           "return one projected point per input point, in the same order"};
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::dvec3 want = facet::projectToPixel(c, points[i]);
            if (near(got[i], want, 1e-9)) continue;
            std::string hint = "h = K * P * worldToCamera * (p, 1); return (h.x/h.z, h.y/h.z, h.z)";
            if (near(glm::dvec2(got[i]), glm::dvec2(want), 1e-9) && near(got[i].z, 1.0, 1e-12))
                hint = "keep z: the depth is h.z, do not divide it by itself to 1";
            else if (near(glm::dvec2(got[i]), glm::dvec2(want) * want.z, 1e-9))
                hint = "divide x and y by the homogeneous coordinate h.z";
            return Failure{"vertex " + std::to_string(i) + " of " + fileName(s.meshPath) + " at " +
                               vec(points[i]) + ", camera of " + fileName(s.path),
                           "(x, y, depth) = " + vec(want), "(x, y, depth) = " + vec(got[i]), hint};
        }
    }
    return std::nullopt;
}

// ---- steps 5 and 12: the rasterizers against the reference path ----------------------------

struct Triangle {
    std::array<glm::dvec4, 3> clip;
    std::array<glm::dvec3, 3> color;
    std::string name;
};

std::vector<Triangle> rasterTriangles(const Context& ctx) {
    std::vector<Triangle> out;
    // The cube and the textured wall whole, every 61st face of the monkey.
    const std::array<std::pair<std::size_t, std::size_t>, 3> picks{{{0, 1}, {3, 1}, {2, 61}}};
    for (const auto& [sceneIndex, stride] : picks) {
        const facet::Scene& s = ctx.scenes[sceneIndex];
        const std::vector<glm::dvec4> clip = facet::reference::projectScene(s);
        const facet::Mesh& m = *s.mesh;
        for (std::size_t t = 0; t < m.triangleCount(); t += stride) {
            Triangle tri;
            bool front = true;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = m.indices[3 * t + k];
                tri.clip[k] = clip[v];
                tri.color[k] = m.hasColors() ? glm::dvec3(m.colors[v]) : glm::dvec3(1.0);
                front = front && clip[v].w > 0.0;
            }
            tri.name = "triangle " + std::to_string(t) + " of " + fileName(s.meshPath) +
                       " seen by " + fileName(s.path);
            if (front) out.push_back(tri);
        }
    }
    // Colours beyond [0, 1] (a light's overshoot) must come out clamped.
    Triangle over = out.back();
    over.color = {glm::dvec3(1.6, -0.4, 0.5), glm::dvec3(-0.3, 1.2, 1.4), glm::dvec3(0.5)};
    over.name += ", with vertex colours beyond [0, 1]";
    out.push_back(over);
    return out;
}

Verdict checkRasterizer(const Context& ctx, bool perspective) {
    const std::array<glm::dvec2, 3> uvs{glm::dvec2(0.1, 0.2), glm::dvec2(0.9, 0.3),
                                        glm::dvec2(0.4, 0.8)};
    const facet::Camera& cam0 = ctx.scenes[0].camera;
    (void)cam0;
    std::vector<Fragment> got;
    for (const Triangle& tri : rasterTriangles(ctx)) {
        // The scene's image size: the triangle's own scene.
        int width = 0, height = 0;
        for (const facet::Scene& s : ctx.scenes)
            if (tri.name.find(fileName(s.path)) != std::string::npos) {
                width = s.camera.width;
                height = s.camera.height;
            }
        std::array<Fragment, 3> v;
        for (int k = 0; k < 3; ++k) {
            v[k].position = glm::dvec2(tri.clip[k]) / tri.clip[k].w;
            v[k].depth = tri.clip[k].w;
            v[k].color = tri.color[k];
            v[k].uv = uvs[k];
        }
        got.clear();
        if (perspective)
            rasterizeFacePerspective(v[0], v[1], v[2], width, height, got);
        else
            rasterizeFace(v[0], v[1], v[2], width, height, got);

        // facet's reference: the same triangle, painter shader (which keeps the depth), once
        // with the colours and once
        // with (u, v, 0) as the colour to read the uvs back.
        facet::RenderSettings settings;
        settings.mode = facet::DrawMode::Solid;
        settings.shader = facet::ShaderKind::Painter;
        settings.interp = perspective ? facet::Interp::Perspective : facet::Interp::Affine;
        const std::array<std::uint32_t, 3> idx{0, 1, 2};
        const std::array<glm::dvec3, 3> uvColors{glm::dvec3(uvs[0], 0.0), glm::dvec3(uvs[1], 0.0),
                                                 glm::dvec3(uvs[2], 0.0)};
        facet::reference::Input in;
        in.clip = tri.clip;
        in.colors = tri.color;
        in.indices = idx;
        in.nearPlane = 1e-9;
        const facet::reference::Image ref = facet::reference::draw(in, settings, width, height);
        in.colors = uvColors;
        const facet::reference::Image refUv = facet::reference::draw(in, settings, width, height);

        const std::string input =
            tri.name + ": vertices at " + vec(v[0].position) + " " + vec(v[1].position) + " " +
            vec(v[2].position) + ", depths " + num(v[0].depth) + " " + num(v[1].depth) + " " +
            num(v[2].depth) + ", image " + std::to_string(width) + " x " + std::to_string(height);
        const char* weights = perspective
                                  ? "interpolate with (α/z1, β/z2, γ/z3) / q, q = α/z1 + β/z2 + "
                                    "γ/z3, and depth = 1/q"
                                  : "interpolate every attribute as α·a1 + β·a2 + γ·a3";
        std::map<std::size_t, const Fragment*> byPixel;
        for (const Fragment& f : got) {
            const glm::ivec2 p = pixelOf(f);
            const std::string where =
                "pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
            if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height)
                return Failure{input, "fragments inside the image only",
                               "a fragment at " + vec(f.position),
                               "only the pixels of the bounding box that are in the image"};
            if (f.position != glm::dvec2(p) + 0.5)
                return Failure{input, where + " at its centre " + vec(glm::dvec2(p) + 0.5),
                               "position " + vec(f.position),
                               "a fragment sits at its pixel's centre (i + 0.5, j + 0.5)"};
            const std::size_t i = static_cast<std::size_t>(p.y) * width + p.x;
            if (!byPixel.emplace(i, &f).second)
                return Failure{input, where + " once", where + " twice",
                               "one fragment per pixel: loop over each pixel of the box once"};
            const bool drawn = std::isfinite(ref.depth[i]);
            if (!drawn && !ref.ambiguous[i])
                return Failure{input, where + " outside the triangle: no fragment",
                               "a fragment with (α, β, γ) computed at its centre",
                               "a pixel is inside when all of C * (1, x, y) are >= 0, tested at "
                               "the pixel centre (i + 0.5, j + 0.5)"};
            if (!drawn) continue;
            const glm::dvec3 wantColor = glm::clamp(ref.color[i], 0.0, 1.0);
            if (!(glm::all(glm::greaterThanEqual(f.color, glm::dvec3(0.0))) &&
                  glm::all(glm::lessThanEqual(f.color, glm::dvec3(1.0)))))
                return Failure{input, where + ": colour " + vec(wantColor),
                               "colour " + vec(f.color),
                               "clamp the interpolated colour to [0, 1] (glm::clamp)"};
            if (!near(f.color, wantColor, 1e-6))
                return Failure{input, where + ": colour " + vec(wantColor),
                               "colour " + vec(f.color), weights};
            if (!near(f.depth, ref.depth[i], 1e-7))
                return Failure{input, where + ": depth " + num(ref.depth[i]),
                               "depth " + num(f.depth),
                               perspective ? "depth = 1/q, q = α/z1 + β/z2 + γ/z3"
                                           : "depth: 1/Z is linear in the image, so depth = "
                                             "1 / (α/z1 + β/z2 + γ/z3)"};
            const glm::dvec2 wantUv(refUv.color[i]);
            if (!near(f.uv, wantUv, 1e-6))
                return Failure{
                    input + ", uvs " + vec(uvs[0]) + " " + vec(uvs[1]) + " " + vec(uvs[2]),
                    where + ": uv " + vec(wantUv), "uv " + vec(f.uv), weights};
        }
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                if (!std::isfinite(ref.depth[i]) || ref.ambiguous[i] || byPixel.count(i)) continue;
                return Failure{input,
                               "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                   "), inside the triangle, to get a fragment",
                               got.empty() ? "no fragment at all" : "no fragment there",
                               "loop over every pixel of the triangle's bounding box (clamped to "
                               "the image) and keep those where α, β and γ are all >= 0"};
            }
    }
    return std::nullopt;
}

// ---- step 6 ---------------------------------------------------------------------------------

Verdict checkDepthBuffer(const Context&) {
    // Conventions §4: the LESS test, the first drawn stays on a tie; nothing outside the buffer.
    DepthBuffer b;
    b.clear(4, 3);
    const auto at = [](double x, double y, double depth) {
        Fragment f;
        f.position = glm::dvec2(x, y);
        f.depth = depth;
        return f;
    };
    const std::string input = "a 4 x 3 depth buffer, fresh (+infinity everywhere)";
    if (!b.testFragment(at(1.5, 2.5, 5.0)))
        return Failure{input, "testFragment(pixel (1, 2), depth 5) = true", "false",
                       "anything is nearer than +infinity: compare fragment.depth < stored"};
    b.writeFragment(at(1.5, 2.5, 5.0));
    if (b.depth[2 * 4 + 1] != 5.0)
        return Failure{input + ", then writeFragment(pixel (1, 2), depth 5)",
                       "depth[2 * 4 + 1] = 5", "depth[9] = " + num(b.depth[9]),
                       "store at y * width + x (row-major, row 0 at the top)"};
    for (std::size_t i = 0; i < b.depth.size(); ++i)
        if (i != 9 && !std::isinf(b.depth[i]))
            return Failure{input + ", then writeFragment(pixel (1, 2), depth 5)",
                           "only depth[9] changed",
                           "depth[" + std::to_string(i) + "] = " + num(b.depth[i]),
                           "store at y * width + x (row-major, row 0 at the top)"};
    const std::string after = input + ", depth 5 written at pixel (1, 2)";
    if (b.testFragment(at(1.5, 2.5, 5.0)))
        return Failure{after, "testFragment(depth 5) = false", "true",
                       "on a tie the fragment drawn first stays: strictly nearer (<), not <="};
    if (b.testFragment(at(1.5, 2.5, 6.0)))
        return Failure{after, "testFragment(depth 6) = false", "true",
                       "the nearer fragment wins: a smaller depth is nearer"};
    if (!b.testFragment(at(1.5, 2.5, 4.0)))
        return Failure{after, "testFragment(depth 4) = true", "false",
                       "the nearer fragment wins: a smaller depth is nearer"};
    for (const glm::dvec2 outside : {glm::dvec2(-0.5, 1.5), glm::dvec2(4.5, 1.5),
                                     glm::dvec2(1.5, 3.5), glm::dvec2(1.5, -0.5)}) {
        if (b.testFragment(at(outside.x, outside.y, 1.0)))
            return Failure{after, "testFragment(" + vec(outside) + ") = false", "true",
                           "a fragment outside the buffer never passes"};
        b.writeFragment(at(outside.x, outside.y, 1.0));
    }
    for (std::size_t i = 0; i < b.depth.size(); ++i)
        if (b.depth[i] != (i == 9 ? 5.0 : std::numeric_limits<double>::infinity()))
            return Failure{after + ", then writeFragment outside the buffer", "no change",
                           "depth[" + std::to_string(i) + "] = " + num(b.depth[i]),
                           "writeFragment does nothing outside the buffer"};
    return std::nullopt;
}

// ---- step 7 ---------------------------------------------------------------------------------

Verdict checkComputeNormals(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        facet::Mesh mesh = *s.mesh;
        mesh.positions.push_back(glm::vec3(9.0f));  // a vertex no face uses
        if (mesh.hasColors()) mesh.colors.push_back(glm::vec3(1.0f));
        if (mesh.hasUvs()) mesh.uvs.push_back(glm::vec2(0.0f));
        const std::vector<glm::vec3> want = facet::computeVertexNormals(mesh);
        const std::vector<glm::dvec3> got = computeNormals(positionsOf(mesh), mesh.indices);
        const std::string input = fileName(s.meshPath) + " (" + std::to_string(mesh.vertexCount()) +
                                  " vertices, the last " + "one in no face)";
        if (got.size() != want.size())
            return Failure{input, std::to_string(want.size()) + " normals",
                           std::to_string(got.size()), "one normal per vertex"};
        for (std::size_t i = 0; i < want.size(); ++i) {
            const glm::dvec3 w(want[i]);
            if (near(got[i], w, 2e-5)) continue;
            std::string hint =
                "add cross(b - a, c - a) of each face to its three vertices, then "
                "normalise each sum";
            if (near(got[i], -w, 2e-5))
                hint = "cross(b - a, c - a), in that order: the other order points inwards";
            else if (glm::length(w) == 0.0)
                hint = "a vertex with no face gets the zero vector (never NaN)";
            else if (std::abs(glm::length(got[i]) - 1.0) > 1e-6)
                hint = "normalise each vertex's sum";
            else
                hint =
                    "sum the unnormalised cross products (area-weighted, as facet does) "
                    "before normalising";
            return Failure{input + ", vertex " + std::to_string(i) + " at " +
                               vec(glm::dvec3(mesh.positions[i])),
                           "normal " + vec(w), "normal " + vec(got[i]), hint};
        }
    }
    return std::nullopt;
}

// ---- steps 8 and 9 --------------------------------------------------------------------------

Material materialOf(const facet::LightingParams& p) {
    return {p.material.ka, p.material.kd, p.material.ks, p.material.s};
}

std::string lightInput(const facet::LightingParams& p) {
    return "Ia " + num(p.ambient) + ", light (" + num(p.light.position.x) + ", " +
           num(p.light.position.y) + ", " + num(p.light.position.z) + ", w " +
           num(p.light.position.w) + ") Id " + num(p.light.intensity) + ", Ka Kd Ks s " +
           num(p.material.ka) + " " + num(p.material.kd) + " " + num(p.material.ks) + " " +
           num(p.material.s);
}

Verdict checkAmbient(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        const facet::LightingParams& p = s.lighting;
        // With no normal the formula keeps only its ambient term.
        const double want =
            facet::lightIntensity(glm::dvec3(0.0), glm::dvec3(0.0), s.camera.eye, p);
        const double got = AmbientLight{p.ambient}.getContribution(materialOf(p));
        if (near(got, want, 1e-12)) continue;
        return Failure{lightInput(p) + " (" + fileName(s.path) + ")", "I_ambient = " + num(want),
                       num(got), "I_ambient = Ia * Ka"};
    }
    return std::nullopt;
}

Verdict checkPointLight(const Context& ctx) {
    for (const facet::Scene& s : ctx.scenes) {
        const std::vector<glm::vec3> normals = facet::computeVertexNormals(*s.mesh);
        // The scene's light, the same light at w = 2 and a light at infinity.
        std::vector<facet::LightingParams> variants(3, s.lighting);
        variants[1].light.position *= 2.0;
        variants[2].light.position.w = 0.0;
        for (const facet::LightingParams& p : variants) {
            const PointLight light{p.light.position, p.light.intensity};
            const double ambient = p.ambient * p.material.ka;
            for (std::size_t i = 0; i < normals.size(); ++i) {
                const glm::dvec3 pos(s.mesh->positions[i]);
                const glm::dvec3 n(normals[i]);
                const double want = facet::lightIntensity(pos, n, s.camera.eye, p) - ambient;
                const double got = light.getContribution(pos, n, s.camera.eye, materialOf(p));
                if (near(got, want, 1e-9)) continue;
                const glm::dvec3 l = facet::directionToLight(pos, p.light.position);
                std::string hint =
                    "Id * (Kd * n.l + Ks * max(0, n.h)^s), l from the point to "
                    "the light, v from the point to the eye, h = normalize(l + v)";
                if (glm::dot(n, l) <= 0.0)
                    hint =
                        "the light is behind the surface here (n.l <= 0): no diffuse and no "
                        "highlight, return 0";
                else if (p.light.position.w == 0.0)
                    hint =
                        "w = 0 is a light at infinity coming from (x, y, z): l = "
                        "normalize(x, y, z) everywhere";
                else if (p.light.position.w != 1.0)
                    hint = "the light is at (x, y, z) / w";
                return Failure{lightInput(p) + "; vertex " + std::to_string(i) + " of " +
                                   fileName(s.meshPath) + " at " + vec(pos) + ", normal " + vec(n) +
                                   ", eye " + vec(s.camera.eye),
                               "I_diffuse + I_specular = " + num(want), num(got), hint};
            }
        }
    }
    return std::nullopt;
}

// ---- steps 10 and 11 ------------------------------------------------------------------------

Texture labTexture(const facet::Texture& t) {
    const facet::MipLevel& level = t.level(0);
    Texture out{level.width, level.height, {}};
    out.texels.reserve(level.texels.size());
    for (const std::uint32_t p : level.texels)
        out.texels.emplace_back(glm::dvec3(p & 0xFF, (p >> 8) & 0xFF, (p >> 16) & 0xFF) / 255.0);
    return out;
}

Verdict checkTextureSample(const Context& ctx) {
    const std::array<double, 10> coords{0.0,    0.1003, 0.4507,  0.9991,  1.2509,
                                        2.6001, 4.0,    -0.2497, -0.7501, -1.3003};
    const std::array<const char*, 2> names{"brick.jpg", "world_map.jpg"};
    for (std::size_t k = 0; k < ctx.textures.size(); ++k) {
        const Texture tex = labTexture(*ctx.textures[k]);
        for (const double u : coords)
            for (const double v : coords) {
                const glm::dvec3 want =
                    facet::reference::sampleNearest(*ctx.textures[k], glm::dvec2(u, v));
                const glm::dvec3 got = tex.sample(u, v);
                if (near(got, want, 1e-12)) continue;
                std::string hint =
                    "nearest texel: column floor(u' * width), row floor(v' * "
                    "height), with u' = u - floor(u)";
                if ((u < 0.0 || u >= 1.0 || v < 0.0 || v >= 1.0) &&
                    near(tex.sample(u - std::floor(u), v - std::floor(v)), want, 1e-12))
                    hint =
                        "the texture repeats: use the fractional part u - floor(u) (so -0.75 "
                        "is a quarter across, 2.25 too)";
                else if (near(got,
                              tex.at(std::clamp(static_cast<int>((u - std::floor(u)) * tex.width),
                                                0, tex.width - 1),
                                     std::clamp(
                                         static_cast<int>((1.0 - (v - std::floor(v))) * tex.height),
                                         0, tex.height - 1)),
                              1e-12))
                    hint = "v = 0 is the top row of the image: no flip";
                return Failure{std::string(names[k]) + " (" + std::to_string(tex.width) + " x " +
                                   std::to_string(tex.height) +
                                   "), (u, v) = " + vec(glm::dvec2(u, v)),
                               "colour " + vec(want), "colour " + vec(got), hint};
            }
    }
    return std::nullopt;
}

Verdict checkTextureShader(const Context& ctx) {
    const facet::Texture& ft = *ctx.textures[0];
    const Texture tex = labTexture(ft);
    Canvas canvas;
    const glm::dvec3 background(0.25);
    canvas.clear(4, 4, background);
    Fragment f;
    f.position = glm::dvec2(1.5, 1.5);
    f.depth = 2.0;
    f.color = glm::dvec3(0.5, 0.25, 1.0);
    f.uv = glm::dvec2(1.3, -0.45);
    const std::string input =
        "brick.jpg, a 4 x 4 canvas; fragment at pixel (1, 1), depth 2, "
        "colour " +
        vec(f.color) + ", uv " + vec(f.uv);
    const glm::dvec3 texel = facet::reference::sampleNearest(ft, f.uv);
    textureShade(canvas, f, tex, false);
    if (!near(canvas.color[5], texel, 1e-12))
        return Failure{input + ", combine off", "pixel (1, 1) = the texel " + vec(texel),
                       vec(canvas.color[5]), "the pixel's colour is texture.sample(uv.x, uv.y)"};
    if (canvas.depth.depth[5] != 2.0)
        return Failure{input + ", combine off", "depth 2 written", num(canvas.depth.depth[5]),
                       "write the depth too (canvas.depth.writeFragment)"};
    Fragment behind = f;
    behind.depth = 3.0;
    behind.uv = glm::dvec2(0.61, 0.13);
    textureShade(canvas, behind, tex, false);
    if (!near(canvas.color[5], texel, 1e-12))
        return Failure{input + ", then one behind it (depth 3)", "pixel (1, 1) unchanged",
                       vec(canvas.color[5]),
                       "test the depth first (canvas.depth.testFragment) and draw only when it "
                       "passes"};
    Fragment combined = f;
    combined.position = glm::dvec2(2.5, 1.5);
    textureShade(canvas, combined, tex, true);
    const glm::dvec3 want = texel * combined.color;
    if (!near(canvas.color[6], want, 1e-12))
        return Failure{input + ", at pixel (2, 1) with combine on",
                       "pixel (2, 1) = texel x colour " + vec(want), vec(canvas.color[6]),
                       "with combine, multiply the texel by the fragment's (lit) colour"};
    for (const std::size_t i : {0u, 4u, 7u, 10u, 15u})
        if (canvas.color[i] != background)
            return Failure{input, "the other pixels untouched",
                           "pixel " + std::to_string(i) + " = " + vec(canvas.color[i]),
                           "write only the fragment's pixel (pixelOf(fragment))"};
    return std::nullopt;
}

// ---- the table ------------------------------------------------------------------------------

using CheckFn = Verdict (*)(const Context&);

struct StepCheck {
    Step step;
    CheckFn check;
    std::vector<Step> uses;  // steps the check calls: until they pass, this one waits
};

Verdict checkRasterizeFace(const Context& ctx) {
    return checkRasterizer(ctx, false);
}

Verdict checkPerspective(const Context& ctx) {
    return checkRasterizer(ctx, true);
}

const std::vector<StepCheck>& table() {
    static const std::vector<StepCheck> t{
        {Step::SetLookAt, checkSetLookAt, {}},
        {Step::SetProjection, checkSetProjection, {}},
        {Step::SetCalibration, checkSetCalibration, {}},
        {Step::ProjectPoints,
         checkProjectPoints,
         {Step::SetLookAt, Step::SetProjection, Step::SetCalibration}},
        {Step::RasterizeFace, checkRasterizeFace, {}},
        {Step::DepthBuffer, checkDepthBuffer, {}},
        {Step::ComputeNormals, checkComputeNormals, {}},
        {Step::AmbientLight, checkAmbient, {}},
        {Step::PointLight, checkPointLight, {}},
        {Step::TextureSample, checkTextureSample, {}},
        {Step::TextureShader, checkTextureShader, {Step::TextureSample, Step::DepthBuffer}},
        {Step::PerspectiveRasterizer, checkPerspective, {}},
    };
    return t;
}

// Calls a step once on a trivial input, to see whether it is still the stub.
bool isStub(Step step) {
    clearNotStarted();
    Fragment a, b, c;
    a.position = {0.0, 0.0};
    b.position = {2.0, 0.0};
    c.position = {0.0, 2.0};
    a.depth = b.depth = c.depth = 1.0;
    std::vector<Fragment> out;
    switch (step) {
        case Step::SetLookAt:
            setLookAt({0, 0, 0}, {0, 0, 1}, {0, -1, 0});
            break;
        case Step::SetProjection:
            setProjection();
            break;
        case Step::SetCalibration:
            setCalibration(1.0, 2, 2);
            break;
        case Step::ProjectPoints:
            projectPoints(Transformation{}, {glm::dvec3(0, 0, 1)});
            break;
        case Step::RasterizeFace:
            rasterizeFace(a, b, c, 2, 2, out);
            break;
        case Step::DepthBuffer: {
            DepthBuffer d;
            d.clear(1, 1);
            (void)d.testFragment(a);
            d.writeFragment(a);
            break;
        }
        case Step::ComputeNormals:
            computeNormals({}, {});
            break;
        case Step::AmbientLight:
            (void)AmbientLight{}.getContribution(Material{});
            break;
        case Step::PointLight:
            (void)PointLight{}.getContribution({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, Material{});
            break;
        case Step::TextureSample:
            (void)Texture{1, 1, {glm::dvec3(1.0)}}.sample(0.5, 0.5);
            break;
        case Step::TextureShader: {
            Canvas canvas;
            canvas.clear(1, 1, glm::dvec3(0.0));
            textureShade(canvas, a, Texture{1, 1, {glm::dvec3(1.0)}}, false);
            break;
        }
        case Step::PerspectiveRasterizer:
            rasterizeFacePerspective(a, b, c, 2, 2, out);
            break;
    }
    const bool stub = wasNotStarted(step);
    clearNotStarted();
    return stub;
}

const char* fileOf(Step step) {
    switch (step) {
        case Step::SetLookAt:
        case Step::SetProjection:
        case Step::SetCalibration:
        case Step::ProjectPoints:
            return "transformation.cpp";
        case Step::RasterizeFace:
            return "rasterizer.cpp";
        case Step::DepthBuffer:
            return "depth_buffer.cpp";
        case Step::ComputeNormals:
            return "mesh.cpp";
        case Step::AmbientLight:
        case Step::PointLight:
            return "lights.cpp";
        case Step::TextureSample:
        case Step::TextureShader:
            return "texture.cpp";
        case Step::PerspectiveRasterizer:
            return "perspective_rasterizer.cpp";
    }
    return "";
}

}  // namespace

std::string_view toString(Outcome outcome) {
    switch (outcome) {
        case Outcome::Passed:
            return "ok";
        case Outcome::Failed:
            return "FAILED";
        case Outcome::NotStarted:
            return "not started";
        case Outcome::Waiting:
            return "waiting";
        case Outcome::NotChecked:
            return "not checked";
    }
    return "";
}

std::vector<StepResult> runChecks(const std::string& courseDir) {
    const Context ctx = loadContext(courseDir);
    std::vector<StepResult> results;
    bool stopped = false;
    for (const StepCheck& sc : table()) {
        StepResult r;
        r.step = sc.step;
        const bool stub = isStub(sc.step);
        std::string waitingFor;
        for (const Step u : sc.uses) {
            const auto it = std::find_if(results.begin(), results.end(),
                                         [u](const StepResult& x) { return x.step == u; });
            if (it != results.end() && it->outcome != Outcome::Passed &&
                it->outcome != Outcome::NotChecked)
                waitingFor += (waitingFor.empty() ? "" : ", ") + std::string(stepName(u));
        }
        if (stub) {
            r.outcome = Outcome::NotStarted;
            r.hint = std::string("still the stub in ") + fileOf(sc.step);
            stopped = true;
        } else if (!waitingFor.empty()) {
            r.outcome = Outcome::Waiting;
            r.hint = "needs " + waitingFor;
        } else if (stopped) {
            r.outcome = Outcome::NotChecked;
            r.hint = "written; checked once the steps before it pass";
        } else if (!ctx.error.empty()) {
            r.outcome = Outcome::Failed;
            r.input = "the course's files in " + courseDir;
            r.got = ctx.error;
            r.expected = "readable course data";
            r.hint = "pass the course's data folder (lab_check DIR)";
            stopped = true;
        } else {
            clearNotStarted();
            const Verdict v = sc.check(ctx);
            if (v) {
                r.outcome = Outcome::Failed;
                r.input = v->input;
                r.expected = v->expected;
                r.got = v->got;
                r.hint = v->hint;
                stopped = true;
            } else {
                r.outcome = Outcome::Passed;
            }
        }
        results.push_back(std::move(r));
    }
    return results;
}

std::string formatResults(const std::vector<StepResult>& results) {
    std::string out;
    int passed = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const StepResult& r = results[i];
        char head[160];
        std::snprintf(head, sizeof head, "%2zu  %-40s %s", i + 1,
                      std::string(stepName(r.step)).c_str(),
                      std::string(toString(r.outcome)).c_str());
        out += head;
        if (r.outcome == Outcome::Passed) ++passed;
        if (r.outcome == Outcome::Failed) {
            out += "\n      input:    " + r.input;
            out += "\n      expected: " + r.expected;
            out += "\n      got:      " + r.got;
            out += "\n      hint:     " + r.hint;
        } else if (r.outcome != Outcome::Passed && !r.hint.empty()) {
            out += " (" + r.hint + ")";
        }
        out += "\n";
    }
    out += std::to_string(passed) + " of " + std::to_string(results.size()) + " steps pass\n";
    return out;
}

}  // namespace lab
