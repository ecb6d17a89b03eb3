// The reference path's entry point from a scene: the vertex streams (rules 3, 10, 14) built in
// double from the mesh, then draw() (raster.cpp); and the 8-bit rounding of rule 9.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/lighting.hpp"
#include "facet/limits.hpp"
#include "facet/multisample.hpp"
#include "facet/normals.hpp"
#include "facet/reference.hpp"

namespace facet::reference {

std::vector<std::uint32_t> Image::toRgba() const {
    auto channel = [](double c) -> std::uint32_t {
        if (std::isnan(c)) return 0;
        return static_cast<std::uint32_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
    };
    std::vector<std::uint32_t> out(color.size());
    for (std::size_t i = 0; i < color.size(); ++i) {
        out[i] = packRgba(channel(color[i].r), channel(color[i].g), channel(color[i].b));
    }
    return out;
}

std::vector<glm::dvec4> projectNormals(const Scene& scene, const RenderSettings& settings) {
    const std::vector<glm::vec3> normals = computeVertexNormals(*scene.mesh);
    const double length = settings.normalLength > 0.0
                              ? settings.normalLength
                              : static_cast<double>(normalDisplayLength(*scene.mesh));
    std::vector<glm::dvec4> ends;
    for (std::size_t i = 0; i < normals.size(); ++i) {
        if (normals[i] == glm::vec3(0.0f)) continue;
        const glm::dvec3 p(scene.mesh->positions[i]);
        ends.push_back(projectPoint(scene.camera, p));
        ends.push_back(projectPoint(scene.camera, p + length * glm::dvec3(normals[i])));
    }
    return ends;
}

namespace {

/// Clip positions moved so that pixel (x, y) lands on (0, 0): pixel = clip.xy / w, so subtract
/// (x, y)·w.
void moveToWindow(std::vector<glm::dvec4>& clip, const Window& window) {
    if (window.x == 0 && window.y == 0) return;  // the whole frame: the positions as they are
    for (glm::dvec4& p : clip) {
        p.x -= window.x * p.w;
        p.y -= window.y * p.w;
    }
}

/// The whole frame as a window.
Window wholeFrame(const Scene& scene) {
    return {0, 0, scene.camera.width, scene.camera.height};
}

// Builds every Input stream of the scene (rules 3, 10, 14), moved to `window`, and calls
// draw(input, width, height) with the window's size.
template <class Draw>
Image withSceneInput(const Scene& scene, const RenderSettings& settings, const Window& window,
                     Draw&& draw) {
    const Mesh& mesh = *scene.mesh;
    const std::size_t n = mesh.positions.size();
    std::vector<glm::dvec4> clip = projectScene(scene);
    moveToWindow(clip, window);
    std::vector<glm::dvec3> positions(mesh.positions.begin(), mesh.positions.end());
    std::vector<glm::dvec3> colors(mesh.colors.begin(), mesh.colors.end());
    colors.resize(n, glm::dvec3(1.0));  // rule 3: white when there are none
    const std::vector<glm::dvec2> uvs(mesh.uvs.begin(), mesh.uvs.end());
    // Normals only when something reads them (Phong, Gouraud, the normals display).
    std::vector<glm::dvec3> normals;
    if (settings.lighting != Lighting::Off || settings.showNormals) {
        const std::vector<glm::vec3> computed = computeVertexNormals(mesh);
        normals.assign(computed.begin(), computed.end());
    }
    if (settings.lighting == Lighting::Gouraud) {
        // spec §6, per vertex: colour = clamp(rgb · I), I from the formula in double.
        for (std::size_t i = 0; i < n; ++i) {
            const double intensity =
                lightIntensity(positions[i], normals[i], scene.camera.eye, scene.lighting);
            colors[i] = facet::shade(colors[i], intensity);
        }
    }
    std::vector<glm::dvec4> segments;
    if (settings.showNormals) segments = projectNormals(scene, settings);
    moveToWindow(segments, window);

    Input input;
    input.clip = clip;
    input.colors = colors;
    input.uvs = uvs;
    input.normals = normals;
    input.positions = positions;
    input.indices = mesh.indices;
    input.normalSegments = segments;
    input.nearPlane = resolveNearPlane(settings, mesh);
    input.texture = scene.texture.get();
    input.lighting = scene.lighting;
    input.eye = scene.camera.eye;
    return draw(input, window.width, window.height);
}

/// Samples per pixel of the reference image the settings draw (multisampling in Solid mode).
int referenceSamples(const RenderSettings& settings) {
    return settings.mode == DrawMode::Solid ? msaaSamples(settings.msaa) : 1;
}

/// checkFrame() for the reference, which does not supersample, then its own image's memory.
Status checkSceneFrame(const Scene& scene, const RenderSettings& settings) {
    RenderSettings one = settings;
    one.supersample = 1;
    if (Status st = checkFrame(scene.camera, one); !st) return st;
    if (!scene.mesh) return Error{{}, "the scene has no mesh"};
    return checkReferenceImage(scene.camera.width, scene.camera.height, referenceSamples(settings));
}

/// The draw of `window` without the checks: the callers below have checked the camera, the
/// window and the memory.
Image renderWindowUnchecked(const Scene& scene, const RenderSettings& settings,
                            const Window& window, const Progress& progress) {
    return withSceneInput(scene, settings, window, [&](const Input& input, int width, int height) {
        return draw(input, settings, width, height, progress);
    });
}

/// An error unless `window` lies inside a width × height image.
Status checkWindow(const Window& window, long long width, long long height) {
    if (window.width >= 1 && window.height >= 1 && window.x >= 0 && window.y >= 0 &&
        window.x <= width - window.width && window.y <= height - window.height)
        return {};
    return Error{{},
                 "window " + std::to_string(window.width) + "x" + std::to_string(window.height) +
                     " at (" + std::to_string(window.x) + ", " + std::to_string(window.y) +
                     ") is not inside the " + std::to_string(width) + "x" + std::to_string(height) +
                     " frame"};
}

}  // namespace

Result<Image> render(const Scene& scene, const RenderSettings& settings, const Progress& progress) {
    if (Status st = checkSceneFrame(scene, settings); !st) return st.error();
    return renderWindowUnchecked(scene, settings, wholeFrame(scene), progress);
}

Result<Image> renderWindow(const Scene& scene, const RenderSettings& settings, const Window& window,
                           const Progress& progress) {
    if (Status st = checkFrame(scene.camera, RenderSettings{}); !st) return st.error();
    if (!scene.mesh) return Error{{}, "the scene has no mesh"};
    if (Status st = checkWindow(window, scene.camera.width, scene.camera.height); !st)
        return st.error();
    if (Status st = checkReferenceImage(window.width, window.height, referenceSamples(settings));
        !st)
        return st.error();
    return renderWindowUnchecked(scene, settings, window, progress);
}

Result<Image> renderScaledWindow(const Scene& scene, const RenderSettings& settings, int scale,
                                 const Window& window, const Progress& progress) {
    RenderSettings one = settings;
    one.supersample = 1;
    if (Status st = checkFrame(scene.camera, one); !st) return st.error();
    if (!scene.mesh) return Error{{}, "the scene has no mesh"};
    if (scale < 1) return Error{{}, "scale " + std::to_string(scale) + " is below 1"};
    const long long width = static_cast<long long>(scene.camera.width) * scale;
    const long long height = static_cast<long long>(scene.camera.height) * scale;
    if (width > std::numeric_limits<int>::max() || height > std::numeric_limits<int>::max())
        return Error{{}, "scale " + std::to_string(scale) + " is too large for the frame"};
    if (Status st = checkWindow(window, width, height); !st) return st.error();
    if (Status st = checkReferenceImage(window.width, window.height, referenceSamples(settings));
        !st)
        return st.error();
    Scene scaled = scene;  // the mesh and the texture are shared
    scaled.camera = resizedCamera(scene.camera, static_cast<int>(width), static_cast<int>(height));
    return renderWindowUnchecked(scaled, settings, window, progress);
}

Result<Image> renderSamples(const Scene& scene, const RenderSettings& settings) {
    if (Status st = checkSceneFrame(scene, settings); !st) return st.error();
    return withSceneInput(scene, settings, wholeFrame(scene),
                          [&](const Input& input, int width, int height) {
                              return drawSamples(input, settings, width, height);
                          });
}

}  // namespace facet::reference
