#include "sweep_camera.hpp"

#include "facet/evaluation/frame_times.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"

namespace facet::app {
namespace {

using Clock = std::chrono::steady_clock;

/// A mesh to fly around, with the scene's own camera as the starting pose.
struct Subject {
    std::string name;  ///< "spot", "bunny" or "knot"
    Scene scene;
};

/// Spot and the bunny from the shared data; a procedural torus knot when neither loads, so the
/// sweep always runs.
std::vector<Subject> subjects(const std::string& shared, int w, int h) {
    std::vector<Subject> out;
    for (const char* name : {"spot", "bunny"}) {
        const std::string path = shared + "/data/scenes/" + name + "_1280x720.scene";
        if (shared.empty() || !std::filesystem::exists(path)) continue;
        Result<Scene> loaded = loadScene(path);
        if (!loaded) continue;
        Subject s{name, std::move(loaded).value()};
        s.scene.texture.reset();
        s.scene.mesh = std::make_shared<const Mesh>(colouredByPosition(*s.scene.mesh));
        // The framing stays (focal length scaled with the width, as render --size).
        s.scene.camera = resizedCamera(s.scene.camera, w, h);
        out.push_back(std::move(s));
    }
    if (out.empty()) {
        Subject s{"knot", {}};
        s.scene.mesh = std::make_shared<const Mesh>(makeTorusKnot(2, 3, 192, 16));
        const Bounds b = computeBounds(*s.scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        s.scene.camera.look = centre;
        s.scene.camera.eye =
            centre + glm::dvec3(0.3, -0.4, -1.6) * static_cast<double>(b.diagonal());
        s.scene.camera.up = {0.0, -1.0, 0.0};
        s.scene.camera.width = w;
        s.scene.camera.height = h;
        s.scene.camera.focal = 1.1 * w;
        out.push_back(std::move(s));
    }
    return out;
}

/// A label like "k=1.01": short, no comma (it is a CSV cell).
std::string label(const char* name, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s=%.3g", name, v);
    return buf;
}

/// Renders one frame with both paths and measures it.
CameraPoint measure(const std::string& path, const std::string& lbl, int step, double param,
                    const Scene& scene, int frames, Renderer& renderer, Framebuffer& fb) {
    CameraPoint p;
    p.path = path;
    p.label = lbl;
    p.step = step;
    p.param = param;
    p.width = scene.camera.width;
    p.height = scene.camera.height;
    p.degenerate = !checkCamera(scene.camera).empty();
    // Perspective and Gouraud: the combination the engine claims matches the reference (no
    // coverage difference, colours within 1 LSB); lighting makes normals part of the test.
    RenderSettings s;
    s.interp = Interp::Perspective;
    s.lighting = Lighting::Gouraud;
    // One thread: on a loaded or small machine the thread pool's hand-offs make the frame time
    // noise; one thread's time is the frame's own cost.
    s.threads = 1;
    RenderStats stats;
    bool refused = false;
    const FrameTimes times = timeRepeated(frames, [&] {
        Result<RenderStats> r = renderer.render(scene, s, fb);
        refused = !r;
        if (r) stats = r.value();
    });
    if (refused) {
        // A camera the engine refuses (checkFrame) draws nothing: the frame is the background,
        // which is what the reference must agree with.
        (void)fb.resize(scene.camera.width, scene.camera.height);
        fb.clear(rgbaFromHex(s.background));
    }
    p.frames = times.frames;
    p.ms = times.median;
    p.msMin = times.min;
    p.msMax = times.max;
    p.triangles = stats.trianglesIn;
    p.clipped = stats.trianglesClipped;
    p.fragments = stats.fragments;
    const Clock::time_point t0 = Clock::now();
    // The reference refuses what the engine refuses (checkFrame): then it is the background too,
    // an empty draw onto the frame's size.
    Result<reference::Image> made = reference::render(scene, s);
    const reference::Image ref =
        made ? std::move(made).value()
             : reference::draw(reference::Input{}, s, scene.camera.width, scene.camera.height);
    p.refMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    p.diff = compareWithReference(fb, ref, s.shader, s.background);
    for (std::size_t i = 0; i < ref.depth.size(); ++i)
        p.mustDraw = p.mustDraw || (!ref.ambiguous[i] && std::isfinite(ref.depth[i]));
    return p;
}

}  // namespace

std::vector<CameraPoint> sweepCameraPaths(const SweepOptions& options) {
    const bool quick = options.quick;
    const int w = quick ? 64 : 160, h = quick ? 36 : 90;
    std::vector<Subject> meshes = subjects(options.shared, w, h);
    std::vector<CameraPoint> points;
    Renderer renderer;
    Framebuffer fb;
    auto run = [&](const std::string& path, const std::string& lbl, int step, double param,
                   const Scene& scene) {
        options.report("camera paths: " + path + " " + lbl);
        points.push_back(measure(path, lbl, step, param, scene, options.frames, renderer, fb));
    };

    // Through the mesh on a line that crosses it, so the near plane cuts it in the middle frames.
    for (const Subject& m : meshes) {
        Scene scene = m.scene;
        const Bounds b = computeBounds(*scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(-0.7, 0.15, 0.6));
        const double extent = b.diagonal();
        const int n = quick ? 6 : 24;
        for (int i = 0; i < n; ++i) {
            const double t = -0.7 + 1.4 * i / (n - 1);
            scene.camera.eye = centre + t * extent * dir + glm::dvec3(0.0, 0.02 * extent, 0.0);
            scene.camera.look = scene.camera.eye + dir;
            run("fly_" + m.name, label("t", t), i, t, scene);
        }
    }

    // The near plane grazing the surface: the eye a fraction of a near distance to ten of them
    // off the mesh's outermost vertex in +z, looking at it and along the surface. The last mesh
    // is the bunny when the shared data is there (its fine triangles are the hard case).
    {
        const Subject& m = meshes.back();
        Scene scene = m.scene;
        const Bounds b = computeBounds(*scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        const double nearPlane = resolveNearPlane(RenderSettings{}, *scene.mesh);
        glm::dvec3 surface = scene.mesh->positions[0];
        for (const auto& q : scene.mesh->positions)
            if (q.z > surface.z) surface = q;
        const glm::dvec3 outward = glm::normalize(surface - centre);
        const std::vector<double> ks =
            quick ? std::vector<double>{0.5, 1.0, 1.01, 10.0}
                  : std::vector<double>{0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0, 10.0};
        for (int look = 0; look < 2; ++look) {
            const glm::dvec3 dir =
                look == 0 ? -outward : glm::normalize(glm::cross(outward, glm::dvec3(0, 1, 0)));
            for (std::size_t i = 0; i < ks.size(); ++i) {
                scene.camera.eye = surface + ks[i] * nearPlane * outward;
                scene.camera.look = scene.camera.eye + dir;
                run(std::string(look == 0 ? "grazing_at_" : "grazing_along_") + m.name,
                    label("k", ks[i]), static_cast<int>(i), ks[i], scene);
            }
        }
    }

    // Backing away from the mesh's centre along the scene's view until the mesh is a few
    // pixels, then less than one: thousands of sub-pixel triangles must cover exactly the
    // reference's pixels. The camera is shifted so the centre lands on a pixel centre (the image
    // centre is a pixel corner), so the far frames still cover a pixel when the mesh is solid
    // there.
    for (const Subject& m : meshes) {
        Scene scene = m.scene;
        const Bounds b = computeBounds(*scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        const glm::dvec3 away = scene.camera.eye - centre;
        // The camera frame of spec §4; it does not change as the eye backs away.
        const glm::dvec3 z = glm::normalize(-away);
        const glm::dvec3 x = glm::normalize(glm::cross(scene.camera.up, z));
        const glm::dvec3 y = glm::cross(z, x);
        const std::vector<double> factors =
            quick ? std::vector<double>{1.0, 5.0, 30.0, 1e3, 1e5}
                  : std::vector<double>{1.0, 2.0, 5.0, 10.0, 30.0, 100.0, 300.0, 1e3, 1e4, 1e5};
        for (std::size_t i = 0; i < factors.size(); ++i) {
            // Half a pixel at the centre's distance, in world units.
            const double halfPixel = 0.5 * factors[i] * glm::length(away) / scene.camera.focal;
            const glm::dvec3 shift = -halfPixel * (x + y);
            scene.camera.look = centre + shift;
            scene.camera.eye = centre + factors[i] * away + shift;
            run("far_" + m.name, label("x", factors[i]), static_cast<int>(i), factors[i], scene);
        }
    }

    // Looking down the y axis with the y hint turned onto it: legal (if ill-conditioned) up to
    // exactly on the axis, where the look-at frame is undefined and nothing may draw.
    {
        const Subject& m = meshes.back();
        Scene scene = m.scene;
        const Bounds b = computeBounds(*scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        const double distance = glm::length(scene.camera.eye - scene.camera.look);
        scene.camera.look = centre;
        scene.camera.eye = centre + glm::dvec3(0.0, distance, 0.0);
        const std::vector<double> eps =
            quick ? std::vector<double>{1e-1, 1e-4, 1e-7, 0.0}
                  : std::vector<double>{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 0.0};
        for (std::size_t i = 0; i < eps.size(); ++i) {
            scene.camera.up = {eps[i], -1.0, 0.0};
            run("up_hint_" + m.name, label("eps", eps[i]), static_cast<int>(i), eps[i], scene);
        }
    }
    return points;
}

SweepTable cameraTable(const std::vector<CameraPoint>& points) {
    SweepTable t;
    t.name = "camera_paths";
    t.title = "Camera paths: fast path (perspective, Gouraud, one thread) against the reference";
    if (!points.empty())
        t.title += ", " + std::to_string(points[0].width) + "x" + std::to_string(points[0].height);
    t.columns = {"path",   "label",  "step",   "param",     "width",   "height",   "ms",
                 "ms_min", "ms_max", "ref_ms", "triangles", "clipped", "fragments"};
    for (std::string& c : referenceDiffColumns()) t.columns.push_back(std::move(c));
    t.columns.insert(t.columns.end(), {"must_draw", "degenerate"});
    for (const CameraPoint& p : points) {
        std::vector<std::string> row{p.path,
                                     p.label,
                                     cell(p.step),
                                     cell(p.param),
                                     cell(p.width),
                                     cell(p.height),
                                     cell(p.ms),
                                     cell(p.msMin),
                                     cell(p.msMax),
                                     cell(p.refMs),
                                     cell(static_cast<double>(p.triangles)),
                                     cell(static_cast<double>(p.clipped)),
                                     cell(static_cast<double>(p.fragments))};
        for (std::string& c : referenceDiffCells(p.diff)) row.push_back(std::move(c));
        row.insert(row.end(), {cell(p.mustDraw ? 1.0 : 0.0), cell(p.degenerate ? 1.0 : 0.0)});
        t.add(std::move(row));
    }
    return t;
}

}  // namespace facet::app
