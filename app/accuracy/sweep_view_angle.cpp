// The view-angle sweep (sweep_view_angle.hpp).
//
// Both surfaces lie in z = 0 with normal +z. The eye turns about the x axis through the point
// looked at, and the camera's y hint is the x axis, so depth changes along the image rows: the
// direction subdivision evaluates exactly every N pixels. The facet is the course's
// textured_facet.off rebuilt here (uv 0…2 across, 0…4 down, the texture repeating), so the sweep
// runs without the shared data; the floor is the same strip 16 times as long, two triangles
// whose far end runs towards the horizon as the angle grows: the worst case for affine, whose
// triangles span the widest range of depths.

#include "sweep_view_angle.hpp"

#include "facet/evaluation/frame_times.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>

#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/evaluation/reference_compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/texture.hpp"

namespace facet::app {
namespace {

/// A strip in z = 0 from (0, 0) to (1, length), texture repeating 2 times across and 4 times per
/// unit of length, as the course's facet.
Mesh texturedStrip(float length) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, length, 0}, {0, length, 0}};
    m.uvs = {{0, 0}, {2, 0}, {2, 4 * length}, {0, 4 * length}};
    m.indices = {0, 1, 3, 1, 2, 3};  // the course file's two triangles
    return m;
}

/// Bricks of 4 × 2 texels' proportions, mortar lines and a hue ramp, 256 × 256: enough contrast
/// at every scale for a misplaced texel to show.
std::shared_ptr<const Texture> generatedBricks() {
    const int n = 256;
    std::vector<std::uint32_t> px(static_cast<std::size_t>(n) * n);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const int row = y / 32;
            const int bx = (x + (row % 2) * 32) % 64;
            const bool mortar = y % 32 < 3 || bx < 3;
            const auto r = static_cast<std::uint32_t>(mortar ? 210 : 120 + (x * 100) / n);
            const auto g = static_cast<std::uint32_t>(mortar ? 205 : 50 + (y * 60) / n);
            const auto b = static_cast<std::uint32_t>(mortar ? 200 : 40);
            px[static_cast<std::size_t>(y) * n + x] = r | g << 8 | b << 16 | 0xFF000000u;
        }
    }
    Result<Texture> t = Texture::fromRgba(n, n, std::move(px), "generated bricks");
    return std::make_shared<const Texture>(std::move(t).value());
}

std::shared_ptr<const Texture> sweepTexture(const std::string& shared) {
    const std::string brick = shared + "/data/course/brick.jpg";
    if (!shared.empty() && std::filesystem::exists(brick)) {
        Result<Texture> t = loadTexture(brick);
        if (t.ok()) return std::make_shared<const Texture>(std::move(t).value());
    }
    return generatedBricks();
}

}  // namespace

std::vector<double> viewAngles(bool quick) {
    if (quick) return {0.0, 1.0, 5.0, 20.0, 40.0, 60.0, 80.0, 89.0};
    return {0.0,  0.5,  1.0,  2.0,  3.0,  4.0,  5.0,  7.5,  10.0, 15.0,
            20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 85.0, 89.0};
}

std::vector<ViewAnglePoint> sweepViewAngle(const SweepOptions& options) {
    const int size = options.quick ? 96 : 160;
    const auto texture = sweepTexture(options.shared);
    struct Surface {
        const char* name;
        float length;
        glm::dvec3 look;
    };
    // The facet is looked at in its centre from 1 unit; the floor near its start, so its far
    // end recedes 15 units away.
    const Surface surfaces[] = {{"facet", 1.0f, {0.5, 0.5, 0.0}},
                                {"floor", 16.0f, {0.5, 1.0, 0.0}}};
    struct Method {
        std::string name;
        Interp interp;
        int n;
    };
    const std::vector<Method> methods = {{"affine", Interp::Affine, 16},
                                         {"subdivided:8", Interp::Subdivided, 8},
                                         {"subdivided:16", Interp::Subdivided, 16},
                                         {"subdivided:32", Interp::Subdivided, 32},
                                         {"perspective", Interp::Perspective, 16}};
    std::vector<ViewAnglePoint> points;
    Renderer renderer;
    Framebuffer fb;
    for (const Surface& surface : surfaces) {
        Scene scene;
        scene.mesh = std::make_shared<const Mesh>(texturedStrip(surface.length));
        scene.texture = texture;
        scene.camera.width = scene.camera.height = size;
        scene.camera.focal = 110.0 * size / 160.0;
        scene.camera.look = surface.look;
        scene.camera.up = {1.0, 0.0, 0.0};
        RenderSettings s;
        s.shader = ShaderKind::Texture;
        // Trilinear: near edge-on the surface is minified many texels per pixel, and bilinear's
        // aliasing would turn any sub-texel shift into full-contrast noise.
        s.filter = TextureFilter::Trilinear;
        s.threads = 1;
        for (const double deg : viewAngles(options.quick)) {
            const double a = deg * std::numbers::pi / 180.0;
            scene.camera.eye = surface.look + glm::dvec3(0.0, -std::sin(a), std::cos(a));
            s.interp = Interp::Perspective;
            const GroundTruth truth = renderGroundTruth(scene, s, options.samples).value();
            const reference::Image ref = reference::render(scene, s).value();
            for (const Method& m : methods) {
                options.report("view angle: " + std::string(surface.name) + " " + cell(deg) +
                               " deg " + m.name);
                s.interp = m.interp;
                s.subdivision = m.n;
                ViewAnglePoint p{surface.name, deg, m.name};
                p.ms = timeRepeated(options.frames, [&] { renderer.render(scene, s, fb); }).median;
                const ImageError e = interiorError(fb, truth);
                p.rmse = e.rmse;
                p.maxError = e.maxError;
                p.over2Lsb = e.over2Lsb;
                p.pixels = e.pixels;
                const ImageError onReference = errorAgainstReference(fb, ref);
                p.rmseReference = onReference.rmse;
                p.maxReference = static_cast<int>(onReference.maxError);
                points.push_back(p);
            }
        }
    }
    // One run of rows per surface and method, by angle: the order the chart draws lines in.
    auto rank = [&methods](const ViewAnglePoint& p) {
        std::size_t i = 0;
        while (i < methods.size() && methods[i].name != p.method) ++i;
        return i;
    };
    std::stable_sort(points.begin(), points.end(),
                     [&](const ViewAnglePoint& a, const ViewAnglePoint& b) {
                         if (a.surface != b.surface) return a.surface < b.surface;
                         return rank(a) < rank(b);
                     });
    return points;
}

SweepTable viewAngleTable(const std::vector<ViewAnglePoint>& points) {
    SweepTable t{"view_angle",
                 "View angle: RMSE against the ground truth of a textured surface seen 0..89 deg "
                 "off its normal",
                 {"surface", "degrees", "method", "rmse", "max", "over2", "pixels",
                  "rmse_reference", "max_reference", "ms"},
                 {}};
    for (const ViewAnglePoint& p : points)
        t.add({p.surface, cell(p.degrees), p.method, cell(p.rmse), cell(p.maxError),
               cell(p.over2Lsb), cell(static_cast<double>(p.pixels)), cell(p.rmseReference),
               cell(p.maxReference), cell(p.ms)});
    return t;
}

}  // namespace facet::app
