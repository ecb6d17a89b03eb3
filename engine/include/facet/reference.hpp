#pragma once
// The reference path: a deliberately simple renderer in double precision that follows the
// specification literally (no fixed point, no tiling, no cleverness). It is the oracle the fast
// path is tested against and the executable specification of what a correct image is.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/error.hpp"
#include "facet/lighting.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::reference {

/// Told how far a render got (0…1), from the rendering thread, every half percent or so of the
/// pixel work; returning false stops the render (Image::cancelled). Slow renders (a ground
/// truth at 8×8 the size) use it for a progress bar and a Cancel button.
using Progress = std::function<bool(double fraction)>;

/// A rendered image in double precision, plus where a correct fast path may differ from it.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> color;  ///< RGB in [0,1], row 0 at the top
    std::vector<double> depth;      ///< camera-space depth, +inf where nothing drew
    /// 1 where the outcome hinges on rounding: a pixel centre within 1/256 px of a triangle edge,
    /// a depth test decided by a relative margin under 1e-5, a line/point endpoint within
    /// 1/256 px of a pixel border, or a Nearest texel lookup within 1/256 texel of a texel
    /// border. Elsewhere a correct fast path must agree exactly.
    std::vector<std::uint8_t> ambiguous;
    bool cancelled = false;  ///< the Progress callback stopped it: the picture is incomplete

    /// 8-bit RGBA with spec §5's rounding (clamp, round to nearest), packed like
    /// Framebuffer::color.
    std::vector<std::uint32_t> toRgba() const;
};

/// Geometry in the same homogeneous clip space as the fast path, in double. Every per-vertex
/// stream may be empty (or short): a missing entry takes the default named below.
struct Input {
    std::span<const glm::dvec4> clip;        ///< one per vertex
    std::span<const glm::dvec3> colors;      ///< rgb, lit already for Gouraud; default white
    std::span<const glm::dvec2> uvs;         ///< texture coordinates; default (0, 0)
    std::span<const glm::dvec3> normals;     ///< world-space unit or zero normals; default zero
    std::span<const glm::dvec3> positions;   ///< world-space positions (Phong); default origin
    std::span<const std::uint32_t> indices;  ///< three per triangle
    /// The normals display (drawn when settings.showNormals): clip-space segment ends, two per
    /// segment (vertex, vertex + length·normal), for the vertices with a non-zero normal.
    std::span<const glm::dvec4> normalSegments;
    double nearPlane = 1e-3;
    const Texture* texture = nullptr;  ///< Texture shader; null samples as white
    LightingParams lighting;           ///< Phong: the §6 parameters
    glm::dvec3 eye{0.0};               ///< Phong: camera centre in world space
};

/// Clip-space positions of the scene's mesh, computed directly from spec §4 in double.
std::vector<glm::dvec4> projectScene(const Scene& scene);

/// Clip-space position of one world-space point, by the same formula as projectScene().
glm::dvec4 projectPoint(const Camera& camera, const glm::dvec3& world);

/// The normals display's segment ends in clip space (rule 14), as render() puts them in
/// Input::normalSegments: for each vertex with a non-zero normal, the vertex and the vertex
/// moved along its normal by settings.normalLength (or normalDisplayLength() when <= 0).
std::vector<glm::dvec4> projectNormals(const Scene& scene, const RenderSettings& settings);

/// Renders the scene at the camera's size with the given settings: builds every Input stream
/// from the scene (Gouraud colours lit per vertex, normals, uvs, the normals display). An error
/// (checkFrame's message, or the reference image's memory beyond kMaxReferenceBytes) instead of
/// an image for a refused camera or size; nothing is allocated then.
Result<Image> render(const Scene& scene, const RenderSettings& settings,
                     const Progress& progress = {});

/// A rectangle of an image's pixels: columns [x, x + width), rows [y, y + height).
struct Window {
    int x = 0, y = 0, width = 0, height = 0;

    /// Every field equal.
    bool operator==(const Window&) const = default;
};

/// render() for only the pixels of `window` (the returned image is the window's size; pixel
/// (0, 0) is the frame's (x, y)): the clip positions are moved by the window's corner, so a
/// pixel inspector or a ground truth of one pixel costs the triangles' setup, not the frame's
/// pixels. Rule 11's Subdivided spans start at the window's column 0, so for Subdivided N,
/// window.x must be a multiple of N for the frame's values; the Depth shader's colours map the
/// window's depth range, not the frame's.
/// An error for an invalid camera, a window that is empty or outside the frame, or beyond
/// kMaxReferenceBytes.
Result<Image> renderWindow(const Scene& scene, const RenderSettings& settings, const Window& window,
                           const Progress& progress = {});

/// renderWindow() of the scene seen `scale` times larger: the camera resized to width·scale ×
/// height·scale with the focal length scaled alike (resizedCamera), so the image's pixel centres
/// are a scale × scale grid of sub-samples inside each of the frame's pixels; `window` is in the
/// scaled image's pixels. The scaled camera may pass kMaxImageSide (the ground truth's
/// supersampling): the scene's own camera is checked as render() checks it, and the window's
/// memory against kMaxReferenceBytes. An error for those, a scale below 1 or a window outside
/// the scaled image.
Result<Image> renderScaledWindow(const Scene& scene, const RenderSettings& settings, int scale,
                                 const Window& window, const Progress& progress = {});

/// render()'s image of samples, before the resolve (drawSamples()); refuses what render() does.
Result<Image> renderSamples(const Scene& scene, const RenderSettings& settings);

/// Draws clip-space geometry onto a background-filled image of the given size (multisampled
/// when settings.msaa > 1 in Solid mode: drawSamples(), then resolveSamples()).
Image draw(const Input& input, const RenderSettings& settings, int width, int height,
           const Progress& progress = {});

/// The image of samples a multisampled draw resolves (Solid mode, settings.msaa > 1): each
/// sample a pixel of an image sampleBlock() times the frame (facet/multisample.hpp), before
/// the normals display; with one sample, the frame itself without it.
Image drawSamples(const Input& input, const RenderSettings& settings, int width, int height,
                  const Progress& progress = {});

/// The box-filter resolve of an image of `msaa` samples per pixel: per channel the rounded
/// mean of the samples' 8-bit values (rule 9), depth the nearest, ambiguous if any sample is.
Image resolveSamples(const Image& samples, int msaa);

}  // namespace facet::reference
