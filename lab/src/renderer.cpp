// The course's Renderer, through the lab's steps: project the vertices, light them, then draw
// vertices, edges or faces and hand every fragment to the chosen shader.

#include "lab/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include <glm/common.hpp>

#include "facet/mesh.hpp"
#include "facet/render.hpp"
#include "facet/texture.hpp"

namespace lab {
namespace {

glm::dvec3 colorOfHex(std::uint32_t rgb) {
    return glm::dvec3((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF) / 255.0;
}

// 8 bits per channel, rounded to nearest (spec §5).
std::uint32_t toRgba8(const glm::dvec3& c) {
    const auto channel = [](double v) {
        if (std::isnan(v)) return 0u;
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return facet::packRgba(channel(c.r), channel(c.g), channel(c.b));
}

// The shader the settings choose, for one fragment.
void shade(Canvas& canvas, const Fragment& f, const Texture& texture,
           const facet::RenderSettings& settings) {
    switch (settings.shader) {
        case facet::ShaderKind::Simple:
            simpleShade(canvas, f);
            break;
        case facet::ShaderKind::Texture:
            textureShade(canvas, f, texture, settings.combine);
            break;
        case facet::ShaderKind::Painter:
        case facet::ShaderKind::Depth:
            painterShade(canvas, f);
            break;
    }
}

// Rasterizer.rasterizeVertex: a square of pointSize pixels around the vertex's pixel (odd sizes
// centred, even sizes one more pixel right and down), every pixel with the vertex's values.
void drawVertex(Canvas& canvas, const Fragment& v, const Texture& texture,
                const facet::RenderSettings& settings) {
    const glm::ivec2 p = pixelOf(v);
    const int lo = -(settings.pointSize - 1) / 2;
    const int hi = lo + settings.pointSize - 1;
    for (int y = p.y + lo; y <= p.y + hi; ++y) {
        for (int x = p.x + lo; x <= p.x + hi; ++x) {
            Fragment f = v;
            f.position = glm::dvec2(x + 0.5, y + 0.5);
            shade(canvas, f, texture, settings);
        }
    }
}

// Rasterizer.rasterizeEdge: Bresenham's line between the two vertices' pixels, endpoints
// included, written in closed form: at step k of n along the major axis the minor coordinate
// is the start's plus k·d/n rounded to nearest (ties upwards), which is what the incremental
// algorithm computes. The attributes are interpolated at t = k/n (the course's interpolate2);
// the depth, as in the faces, through 1/Z.
void drawEdge(Canvas& canvas, const Fragment& a, const Fragment& b, const Texture& texture,
              const facet::RenderSettings& settings) {
    const glm::ivec2 p0 = pixelOf(a), p1 = pixelOf(b);
    const long long dx = p1.x - p0.x, dy = p1.y - p0.y;
    const long long n = std::max(std::llabs(dx), std::llabs(dy));
    const bool xMajor = std::llabs(dx) >= std::llabs(dy);
    const long long dMinor = xMajor ? dy : dx;
    const long long step = (xMajor ? dx : dy) > 0 ? 1 : -1;
    for (long long k = 0; k <= n; ++k) {
        long long num = 2 * k * dMinor + n;  // round(k·dMinor / n), ties towards +infinity
        long long den = 2 * std::max(n, 1LL);
        long long minor = num / den;
        if (num % den != 0 && num < 0) --minor;
        const long long major = k * step;
        const long long x = p0.x + (xMajor ? major : minor);
        const long long y = p0.y + (xMajor ? minor : major);
        if (x < 0 || y < 0 || x >= canvas.width || y >= canvas.height) continue;

        const double t = n == 0 ? 0.0 : static_cast<double>(k) / static_cast<double>(n);
        const double q = (1.0 - t) / a.depth + t / b.depth;
        // Affine: the weights (1 − t, t); perspective-correct: divided by Z, then by q.
        double wa = 1.0 - t, wb = t;
        if (settings.interp != facet::Interp::Affine) {
            wa = (1.0 - t) / a.depth / q;
            wb = t / b.depth / q;
        }
        Fragment f;
        f.position = glm::dvec2(static_cast<double>(x) + 0.5, static_cast<double>(y) + 0.5);
        f.depth = 1.0 / q;
        f.color = glm::clamp(wa * a.color + wb * b.color, 0.0, 1.0);
        f.normal = wa * a.normal + wb * b.normal;
        f.uv = wa * a.uv + wb * b.uv;
        shade(canvas, f, texture, settings);
    }
}

}  // namespace

std::string differences(const facet::RenderSettings& s) {
    std::string out;
    const auto add = [&out](const char* sentence) {
        if (!out.empty()) out += ' ';
        out += sentence;
    };
    if (s.shader == facet::ShaderKind::Depth)
        add("The depth shader is drawn as the painter shader (the course has no depth view).");
    if (s.lighting == facet::Lighting::Phong)
        add("Phong lighting is drawn as Gouraud (the course lights the vertices).");
    if (s.interp == facet::Interp::Subdivided)
        add("Subdivided interpolation is drawn perspective-correct.");
    if (s.shader == facet::ShaderKind::Texture && s.filter != facet::TextureFilter::Nearest)
        add("Textures are sampled nearest (Texture.sample), not bilinear or trilinear.");
    if (s.supersample > 1 || s.msaa > 1)
        add("No antialiasing: one sample per pixel, at its centre.");
    if (s.cullBackFaces) add("Back faces are drawn (the course does not cull).");
    if (s.showNormals) add("Normals are not drawn.");
    if (s.view != facet::DebugView::None) add("No debug views: the shaded image.");
    return out;
}

Report Renderer::render(const facet::Scene& scene, const facet::RenderSettings& settings,
                        facet::Framebuffer& frame) {
    clearNotStarted();
    Report report;
    const facet::Camera& cam = scene.camera;
    const facet::Mesh& mesh = *scene.mesh;

    // The texture as the steps see it (converted once per facet texture).
    const facet::Texture* from = scene.texture.get();
    if (from != textureFrom || texture.texels.empty()) {
        textureFrom = from;
        if (from == nullptr) {
            texture = Texture{1, 1, {glm::dvec3(1.0)}};  // no texture samples as white
        } else {
            const facet::MipLevel& level = from->level(0);
            texture.width = level.width;
            texture.height = level.height;
            texture.texels.resize(level.texels.size());
            for (std::size_t i = 0; i < level.texels.size(); ++i) {
                const std::uint32_t t = level.texels[i];
                texture.texels[i] = glm::dvec3(t & 0xFF, (t >> 8) & 0xFF, (t >> 16) & 0xFF) / 255.0;
            }
        }
    }

    // Section 3: the camera's matrices, then every vertex projected (pixel x, y and depth z).
    const Transformation transformation{setLookAt(cam.eye, cam.look, cam.up), setProjection(),
                                        setCalibration(cam.focal, cam.width, cam.height)};
    const std::vector<glm::dvec3> positions(mesh.positions.begin(), mesh.positions.end());
    const std::vector<glm::dvec3> projected = projectPoints(transformation, positions);

    // Section 6: Gouraud lighting, one intensity per vertex.
    const bool lit = settings.lighting != facet::Lighting::Off;
    std::vector<glm::dvec3> normals;
    if (lit) normals = computeNormals(positions, mesh.indices);
    const Material material{scene.lighting.material.ka, scene.lighting.material.kd,
                            scene.lighting.material.ks, scene.lighting.material.s};
    const AmbientLight ambient{scene.lighting.ambient};
    const PointLight light{scene.lighting.light.position, scene.lighting.light.intensity};

    std::vector<Fragment> vertices(projected.size() == positions.size() ? positions.size() : 0);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        Fragment& v = vertices[i];
        v.position = glm::dvec2(projected[i]);
        v.depth = projected[i].z;
        v.color = mesh.hasColors() ? glm::dvec3(mesh.colors[i]) : glm::dvec3(1.0);
        if (mesh.hasUvs()) v.uv = glm::dvec2(mesh.uvs[i]);
        if (lit && normals.size() == vertices.size()) {
            v.normal = normals[i];
            const double intensity =
                ambient.getContribution(material) +
                light.getContribution(positions[i], v.normal, cam.eye, material);
            v.color = glm::clamp(v.color * intensity, 0.0, 1.0);
        }
    }

    // Sections 3 to 5: draw onto the background, vertices in front of the near plane only (the
    // course does not clip: a face or edge reaching behind it is left out whole).
    canvas.clear(cam.width, cam.height, colorOfHex(settings.background));
    const double near = facet::resolveNearPlane(settings, mesh);
    const auto inFront = [&](std::uint32_t i) {
        return i < vertices.size() && vertices[i].depth >= near &&
               std::isfinite(vertices[i].position.x) && std::isfinite(vertices[i].position.y);
    };
    switch (settings.mode) {
        case facet::DrawMode::Vertices:
            for (std::uint32_t i = 0; i < vertices.size(); ++i)
                if (inFront(i)) drawVertex(canvas, vertices[i], texture, settings);
            break;
        case facet::DrawMode::Wireframe: {
            const std::vector<std::uint32_t> edges = facet::uniqueEdges(mesh);
            for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
                if (!inFront(edges[e]) || !inFront(edges[e + 1])) continue;
                drawEdge(canvas, vertices[edges[e]], vertices[edges[e + 1]], texture, settings);
            }
            break;
        }
        case facet::DrawMode::Solid:
            for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1],
                                    c = mesh.indices[t + 2];
                if (!inFront(a) || !inFront(b) || !inFront(c)) continue;
                fragments.clear();
                if (settings.interp == facet::Interp::Affine)
                    rasterizeFace(vertices[a], vertices[b], vertices[c], cam.width, cam.height,
                                  fragments);
                else
                    rasterizeFacePerspective(vertices[a], vertices[b], vertices[c], cam.width,
                                             cam.height, fragments);
                report.fragments += fragments.size();
                for (const Fragment& f : fragments) shade(canvas, f, texture, settings);
            }
            break;
    }

    frame.resize(cam.width, cam.height);
    for (std::size_t i = 0; i < canvas.color.size(); ++i) {
        frame.color[i] = toRgba8(canvas.color[i]);
        const double d = canvas.depth.depth.empty() ? facet::kEmptyDepth : canvas.depth.depth[i];
        frame.depth[i] = static_cast<float>(d);
    }
    for (int s = 0; s < kStepCount; ++s)
        if (wasNotStarted(static_cast<Step>(s))) report.notStarted.push_back(static_cast<Step>(s));
    return report;
}

}  // namespace lab
