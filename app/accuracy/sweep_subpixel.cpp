#include "sweep_subpixel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "accuracy_methods.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"

namespace facet::app {
namespace {

/// The engine's finest grid: snapped coordinates are integers in these units at every b.
constexpr int kUnitBits = kMaxSubPixelBits;

/// A vertex snapped to 1/2^bits px, in 1/256 px units: the engine's own snap, redone here so the
/// crack check knows where the snapped mesh's edges lie without reaching into the engine.
std::int64_t snapUnits(double v, int bits) {
    return std::llround(std::ldexp(v, bits)) * (std::int64_t{1} << (kUnitBits - bits));
}

/// The scene's mesh with every triangle on its own three vertices, coloured by its index + 1 (0
/// is the background): a Painter image then names the visible triangle of each pixel. Positions
/// are copied bit for bit, so shared edges stay shared after snapping.
Scene triangleIdScene(const Scene& scene) {
    Scene ids = scene;
    ids.texture.reset();
    Mesh m;
    const Mesh& src = *scene.mesh;
    const std::size_t n = src.triangleCount();
    m.positions.reserve(3 * n);
    m.colors.reserve(3 * n);
    m.indices.reserve(3 * n);
    for (std::size_t t = 0; t < n; ++t) {
        const auto id = static_cast<std::uint32_t>(t + 1);
        const glm::vec3 rgb(static_cast<float>(id & 0xFFu) / 255.0f,
                            static_cast<float>((id >> 8) & 0xFFu) / 255.0f,
                            static_cast<float>((id >> 16) & 0xFFu) / 255.0f);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = src.indices[3 * t + static_cast<std::size_t>(k)];
            m.positions.push_back(i < src.positions.size() ? src.positions[i] : glm::vec3(0.0f));
            m.colors.push_back(rgb);
            m.indices.push_back(static_cast<std::uint32_t>(m.indices.size()));
        }
    }
    ids.mesh = std::make_shared<const Mesh>(std::move(m));
    return ids;
}

/// The settings of the triangle-id images: flat colours, nothing lit, black background.
RenderSettings idSettings(int bits) {
    RenderSettings s;
    s.shader = ShaderKind::Painter;
    s.lighting = Lighting::Off;
    s.background = 0x000000;
    s.subPixelBits = bits;
    return s;
}

/// A directed edge of the mesh's open boundary, snapped, in 1/256 px units.
struct Edge {
    std::int64_t ax, ay, bx, by;
};

/// The open boundary of a triangle list: the directed edges whose reverse is not there as often
/// (seams of duplicated vertices count as open and cancel out geometrically).
std::vector<std::pair<std::uint32_t, std::uint32_t>> openEdges(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;  // (lo, hi) → lo→hi minus hi→lo
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[t + static_cast<std::size_t>(k)];
            const std::uint32_t b = mesh.indices[t + static_cast<std::size_t>((k + 1) % 3)];
            if (a == b) continue;
            net[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
        }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> open;
    for (const auto& [key, n] : net)
        for (int i = 0; i < std::abs(n); ++i)
            open.push_back(n > 0 ? key : std::pair{key.second, key.first});
    return open;
}

/// Per pixel, the winding number of the snapped open boundary around its centre, or
/// kOnBoundary where the centre lies on it (the fill rule, not the winding, decides there).
constexpr int kOnBoundary = std::numeric_limits<int>::min();

std::vector<int> boundaryWinding(const std::vector<Edge>& edges, int width, int height) {
    std::vector<int> wn(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    constexpr std::int64_t half = std::int64_t{1} << (kUnitBits - 1);
    std::vector<const Edge*> row;
    for (int y = 0; y < height; ++y) {
        const std::int64_t py = 2 * half * y + half;
        row.clear();
        for (const Edge& e : edges)
            if (std::min(e.ay, e.by) <= py && py <= std::max(e.ay, e.by)) row.push_back(&e);
        if (row.empty()) continue;
        for (int x = 0; x < width; ++x) {
            const std::int64_t px = 2 * half * x + half;
            int w = 0;
            bool on = false;
            for (const Edge* e : row) {
                const std::int64_t cross =
                    (e->bx - e->ax) * (py - e->ay) - (px - e->ax) * (e->by - e->ay);
                if (cross == 0 && std::min(e->ax, e->bx) <= px && px <= std::max(e->ax, e->bx)) {
                    on = true;
                    break;
                }
                if (e->ay <= py) {
                    if (e->by > py && cross > 0) ++w;  // upward, centre on its left
                } else if (e->by <= py && cross < 0) {
                    --w;  // downward, centre on its right
                }
            }
            wn[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x)] = on ? kOnBoundary : w;
        }
    }
    return wn;
}

/// Coverage counts of the scene's triangles at `bits`, all and front-facing only, through the
/// engine's own clip transform (float, like Renderer::render).
struct Counts {
    std::vector<std::uint16_t> all, front;
};

Counts countLayers(Renderer& renderer, const Scene& scene, const std::vector<glm::vec4>& clip,
                   int bits) {
    RenderSettings s;
    s.subPixelBits = bits;
    const DrawInput in{.clip = clip,
                       .indices = scene.mesh->indices,
                       .nearPlane = static_cast<float>(resolveNearPlane(s, *scene.mesh))};
    Counts c;
    const Camera& cam = scene.camera;
    facet::countCoverage(renderer, in, s, cam.width, cam.height, c.all);
    s.cullBackFaces = true;
    facet::countCoverage(renderer, in, s, cam.width, cam.height, c.front);
    return c;
}

/// Front-facing coverage minus back-facing coverage must equal minus the winding number of the
/// snapped open boundary (a back face is counter-clockwise in y-down pixels, winding +1), at
/// every centre off that boundary: whatever the grid, shared vertices snap alike and the fill
/// rule hands each centre on a shared edge to exactly one side.
std::size_t countCracks(const Counts& c, const std::vector<int>& winding) {
    std::size_t cracks = 0;
    for (std::size_t i = 0; i < c.all.size(); ++i) {
        if (winding[i] == kOnBoundary) continue;
        const int signedCover = 2 * static_cast<int>(c.front[i]) - static_cast<int>(c.all[i]);
        cracks += signedCover != -winding[i] ? 1 : 0;
    }
    return cracks;
}

/// A scene loaded from the shared folder at the given width (the height keeps the aspect), or
/// nothing when the file is missing or does not load.
std::optional<Scene> sharedScene(const std::string& shared, const std::string& file, int width) {
    const std::string path = shared + "/data/scenes/" + file;
    std::error_code ec;
    if (shared.empty() || !std::filesystem::exists(path, ec)) return std::nullopt;
    Result<Scene> loaded = loadScene(path);
    if (!loaded) return std::nullopt;
    Scene scene = std::move(loaded).value();
    Camera& cam = scene.camera;
    const int height = std::max(
        1, static_cast<int>(std::lround(static_cast<double>(cam.height) * width / cam.width)));
    cam = resizedCamera(cam, width, height);  // the framing stays (render --size)
    return scene;
}

/// Every grid of one scene.
void sweepScene(const std::string& name, const Scene& scene, const SweepOptions& options,
                std::vector<SubPixelPoint>& out) {
    const std::vector<int> bitsList = subPixelSweepBits(options.quick);
    const Camera& cam = scene.camera;
    const auto pixels = static_cast<std::size_t>(cam.width) * static_cast<std::size_t>(cam.height);

    // The exact coverage: which triangle the reference sees at each centre, unsnapped.
    const Scene ids = triangleIdScene(scene);
    const reference::Image exact = reference::render(ids, idSettings(kMaxSubPixelBits)).value();
    const std::vector<std::uint32_t> exactIds = exact.toRgba();
    std::size_t covered = 0;
    for (const double d : exact.depth) covered += std::isfinite(d) ? 1 : 0;

    const RenderSettings base = baseSettings(scene);
    const GroundTruth truth = renderGroundTruth(scene, base, options.samples).value();

    // The crack check's input: the engine's clip positions (in double, rounded once, as
    // Renderer::render computes them) and the open boundary.
    const glm::dmat4 clipFromWorldD = clipFromWorld(cam);
    std::vector<glm::vec4> clip;
    clip.reserve(scene.mesh->positions.size());
    for (const glm::vec3& p : scene.mesh->positions)
        clip.push_back(glm::vec4(clipFromWorldD * glm::dvec4(glm::dvec3(p), 1.0)));
    const auto open = openEdges(*scene.mesh);

    Renderer renderer;
    Framebuffer frame;
    const Counts finest = countLayers(renderer, scene, clip, kMaxSubPixelBits);
    std::vector<AccuracyMethod> methods;
    for (const int bits : bitsList) {
        options.report("subpixel: " + name + ", " + std::to_string(bits) + " bits");
        SubPixelPoint p;
        p.scene = name;
        p.bits = bits;
        p.width = cam.width;
        p.height = cam.height;
        p.triangles = scene.mesh->triangleCount();
        p.covered = covered;

        renderer.render(ids, idSettings(bits), frame);
        for (std::size_t i = 0; i < pixels; ++i)
            if (frame.color[i] != exactIds[i]) {
                ++p.differ;
                p.differAmbiguous += exact.ambiguous[i] ? 1 : 0;
            }

        std::vector<Edge> edges;
        edges.reserve(open.size());
        for (const auto& [a, b] : open) {
            const glm::dvec4 ca(clip[a]), cb(clip[b]);
            edges.push_back({snapUnits(ca.x / ca.w, bits), snapUnits(ca.y / ca.w, bits),
                             snapUnits(cb.x / cb.w, bits), snapUnits(cb.y / cb.w, bits)});
        }
        const Counts layers = countLayers(renderer, scene, clip, bits);
        p.cracks = countCracks(layers, boundaryWinding(edges, cam.width, cam.height));
        for (std::size_t i = 0; i < pixels; ++i)
            p.layersChanged += layers.all[i] != finest.all[i] ? 1 : 0;

        RenderSettings s = base;
        s.subPixelBits = bits;
        renderer.render(scene, s, frame);
        p.error = measureError(frame, truth);
        // Timed on one thread: the grid changes no per-pixel work, and one thread's time is the
        // least disturbed by whatever else the machine runs.
        s.threads = 1;
        methods.push_back({"subpixel", std::to_string(bits), s});
        out.push_back(std::move(p));
    }

    // Round-robin, so a busy moment slows every grid alike.
    const std::vector<std::vector<double>> ms =
        timeMethods(renderer, scene, methods, std::max(1, options.frames), 1, frame);
    for (std::size_t k = 0; k < methods.size(); ++k)
        out[out.size() - methods.size() + k].times = summarize(ms[k]);
}

}  // namespace

std::vector<int> subPixelSweepBits(bool quick) {
    if (quick) return {4, 6, 8};
    std::vector<int> bits;
    for (int b = kMinSubPixelBits; b <= kMaxSubPixelBits; ++b) bits.push_back(b);
    return bits;
}

Scene subPixelScene(const std::string& name, int width, int height) {
    Scene scene;
    Camera& cam = scene.camera;
    cam.width = width;
    cam.height = height;
    cam.up = {0.0, -1.0, 0.0};
    scene.lighting.light.position = {2.0, 3.0, 4.0, 1.0};
    if (name == "fan") {
        // 720 slivers of half a degree around one vertex: at the rim 0.9 px apart, near the
        // centre far thinner than any grid step. Tilted, so no edge lines up with the grid.
        Mesh m;
        constexpr int kSlices = 720;
        m.positions.push_back({0.0f, 0.0f, 0.0f});
        m.colors.push_back({1.0f, 1.0f, 1.0f});
        for (int k = 0; k < kSlices; ++k) {
            const double a = 2.0 * std::numbers::pi * k / kSlices;
            m.positions.push_back(
                {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f});
            m.colors.push_back({0.5f + 0.5f * static_cast<float>(std::cos(3.0 * a)),
                                0.5f + 0.5f * static_cast<float>(std::sin(5.0 * a)), 0.6f});
        }
        for (std::uint32_t k = 0; k < kSlices; ++k)
            m.indices.insert(m.indices.end(), {0u, 1u + k, 1u + (k + 1) % kSlices});
        scene.mesh = std::make_shared<const Mesh>(std::move(m));
        cam.eye = {0.31, -0.47, 3.0};
        cam.look = {0.013, 0.021, 0.0};
    } else {  // "sphere": slivers at the poles, a silhouette all around
        scene.mesh = std::make_shared<const Mesh>(makeUvSphere(16, 32));
        cam.eye = {0.4, 1.1, 3.2};
        cam.look = {0.0, 0.0, 0.0};
    }
    cam.focal = 0.38 * std::min(width, height) * 3.3;  // the object spans about 3/4 of the height
    return scene;
}

std::vector<SubPixelPoint> sweepSubPixel(const SweepOptions& options) {
    const int w = options.quick ? 160 : 320;
    std::vector<SubPixelPoint> points;
    for (const char* name : {"sphere", "fan"})
        sweepScene(name, subPixelScene(name, w, w * 3 / 4), options, points);
    for (const auto& [name, file] :
         {std::pair{"bunny", "bunny_1280x720.scene"}, std::pair{"spot", "spot_1280x720.scene"}})
        if (const std::optional<Scene> scene = sharedScene(options.shared, file, w))
            sweepScene(name, *scene, options, points);
    return points;
}

SweepTable subPixelTable(const std::vector<SubPixelPoint>& points) {
    SweepTable t;
    t.name = "subpixel";
    t.title = "Sub-pixel precision: coverage, error and time against the snapping grid's bits";
    t.columns = {"scene",        "bits",      "width",      "height", "triangles",      "covered",
                 "differ",       "ambiguous", "differ_pct", "cracks", "layers_changed", "rmse",
                 "over2lsb_pct", "median_ms", "min_ms",     "max_ms"};
    for (const SubPixelPoint& p : points) {
        const double pct =
            p.covered > 0 ? 100.0 * static_cast<double>(p.differ) / static_cast<double>(p.covered)
                          : 0.0;
        t.add({p.scene, std::to_string(p.bits), std::to_string(p.width), std::to_string(p.height),
               std::to_string(p.triangles), std::to_string(p.covered), std::to_string(p.differ),
               std::to_string(p.differAmbiguous), cell(pct), std::to_string(p.cracks),
               std::to_string(p.layersChanged), cell(p.error.rmse), cell(100.0 * p.error.over2Lsb),
               cell(p.times.median), cell(p.times.min), cell(p.times.max)});
    }
    return t;
}

}  // namespace facet::app
