#pragma once
// The pixel inspector: why one pixel of a frame has its colour. Every fragment that reached the
// pixel, in draw order, with what each stage decided about it (coverage and the top-left rule,
// the depth test, the weights, the interpolated values, the lighting terms, the texels), and
// beside the final colour the reference path's value. RenderDoc's pixel history is the model.
//
// It is computed by re-running the draw for that one pixel through the fast path's own stages
// (the front end, coverage, the fragment functions of the pixel loops), never by instrumenting
// the frame loop: a frame pays nothing for it, and the final colour is the frame's pixel exactly.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

/// One vertex of an inspected triangle, as the front end saw it before near clipping.
struct InspectedVertex {
    std::uint32_t index = 0;  ///< into the mesh's vertex arrays
    glm::vec3 world{0.0f};    ///< mesh position
    glm::vec4 clip{0.0f};     ///< clip position (x, y in homogeneous pixels, w the depth)
    glm::dvec2 screen{0.0};   ///< clip.xy / w, pixels (unsnapped; the planes use these)
    /// Snapped to the sub-pixel grid, in 1/256 px units (a coarser grid is a multiple of it).
    std::int64_t fixedX = 0, fixedY = 0;

    /// Every field equal.
    bool operator==(const InspectedVertex&) const = default;
};

/// One edge function of the coverage test at the pixel centre, on the sub-pixel grid.
struct InspectedEdge {
    int from = -1, to = -1;  ///< the vertices (0…2) it joins; −1 for a clipped piece's edge
    std::int64_t dx = 0, dy = 0;  ///< its direction, 1/256 px units, wound so inside is E ≥ 0
    std::int64_t value = 0;  ///< E at the pixel centre in 1/65536 px² (0: the centre is on it)
    bool topLeft = false;    ///< a top or left edge: the rule counts E = 0 as inside
    bool inside = false;     ///< E > 0, or E = 0 on a top-left edge

    /// Every field equal.
    bool operator==(const InspectedEdge&) const = default;
};

/// A texel a sampler read and its weight in the filtered colour.
struct InspectedTexel {
    int level = 0;  ///< mip level
    int x = 0, y = 0;
    glm::vec3 color{0.0f};
    float weight = 0.0f;  ///< share of this texel in the texture colour (all sum to 1)

    /// Every field equal.
    bool operator==(const InspectedTexel&) const = default;
};

/// The terms of the lighting formula (spec §6) at a Phong fragment.
struct InspectedLighting {
    glm::vec3 normal{0.0f};  ///< interpolated and renormalised (zero stays zero)
    glm::vec3 toLight{0.0f}, toEye{0.0f}, halfway{0.0f};  ///< l, v, h (unit or zero)
    float nDotL = 0.0f, nDotH = 0.0f;                     ///< n·l, and n·h clamped to [0, 1]
    float ambient = 0.0f;                                 ///< Ia·Ka
    float diffuse = 0.0f;                                 ///< Id·Kd·n·l where n·l > 0, else 0
    float specular = 0.0f;   ///< Id·Ks·(n·h)^s where n·l > 0, else 0
    float intensity = 0.0f;  ///< I, their sum

    /// Every field equal.
    bool operator==(const InspectedLighting&) const = default;
};

/// What the coverage test decided for a fragment.
enum class CoverageResult {
    Covered,   ///< the centre is inside every edge: a fragment
    Excluded,  ///< outside an edge; `onEdge` says when only the top-left rule excluded it
};

/// One triangle (or near-clip / guard-band piece of one) whose pixel box holds the pixel, in
/// draw order; only Covered ones are fragments and have the values after coverage.
struct InspectedFragment {
    std::size_t triangle = 0;  ///< triangle index (indices 3t, 3t+1, 3t+2 of the mesh)
    int sample = 0;            ///< supersampling: sample sy·N + sx of the pixel; else 0
    int piece = 0;             ///< the fan or guard-band piece, 0 for an unclipped triangle
    bool clipped = false;      ///< the near plane or the guard band cut it (edges from pieces)
    bool backFacing = false;   ///< clockwise on screen (y up); false for a clipped piece
    InspectedVertex vertices[3];
    InspectedEdge edges[3];
    CoverageResult coverage = CoverageResult::Excluded;
    bool onEdge = false;  ///< excluded with E = 0 on a non-top-left edge: the rule decided

    // Depth test (Simple tests nothing and always writes).
    bool depthTested = false;
    float depth = 0.0f;        ///< 1 / interpolated 1/w, camera-space z
    float storedDepth = 0.0f;  ///< what the pixel held before (+inf: nothing)
    bool passed = false;       ///< the fragment was written (always, untested)

    // Interpolation, the weights of vertices 0, 1, 2.
    glm::vec3 screenWeights{0.0f};       ///< screen-linear barycentrics at the centre
    glm::vec3 perspectiveWeights{0.0f};  ///< perspective-correct ones
    glm::vec3 weights{0.0f};             ///< those the interpolation mode used
    bool hasColor = false, hasUv = false, hasNormal = false;  ///< varyings the draw carries
    glm::vec3 color{1.0f};     ///< interpolated vertex (or Gouraud-lit) colour
    glm::vec2 uv{0.0f};        ///< interpolated texture coordinates
    glm::vec3 normal{0.0f};    ///< interpolated world normal (before renormalising)
    glm::vec3 position{0.0f};  ///< interpolated world position

    bool lit = false;  ///< Phong: `lighting` holds the terms
    InspectedLighting lighting;
    bool textured = false;  ///< Texture shader: lod and texels hold what was read
    float lod = 0.0f;       ///< level of detail (trilinear), else 0
    std::vector<InspectedTexel> texels;

    glm::vec3 shaded{0.0f};  ///< the fragment's colour before 8-bit rounding
    std::uint32_t rgba = 0;  ///< packed like Framebuffer::color (Depth shader: see history)

    /// Every field equal.
    bool operator==(const InspectedFragment&) const = default;
};

/// Everything the inspector found for one pixel.
struct PixelHistory {
    int x = 0, y = 0;
    int samples = 1;  ///< per axis: supersampling inspects every sample of the pixel
    std::vector<InspectedFragment> fragments;  ///< in draw order; each triangle's samples in turn
    std::uint32_t background = 0;              ///< packed clear colour
    std::uint32_t finalColor = 0;  ///< packed, what the frame holds at (x, y) after the draw
    float finalDepth = 0.0f;       ///< nearest depth left (+inf: none)
    /// Depth shader: the frame's visible depth range its colour maps through viridis (the only
    /// value the inspector takes from a whole frame, rendered for it).
    float depthNear = 0.0f, depthFar = 0.0f;

    bool hasReference = false;        ///< reference path values below were computed
    glm::dvec3 referenceColor{0.0};   ///< the reference path's colour in double
    std::uint32_t referenceRgba = 0;  ///< and rounded to 8 bits
    double referenceDepth = 0.0;      ///< +inf where nothing drew
    bool referenceAmbiguous = false;  ///< rounding may legitimately decide this pixel (rule 8)
    std::vector<std::string> notes;   ///< what was not inspected, and why
};

/// The history of pixel (x, y) of the frame Renderer::render(scene, settings) draws, with the
/// reference path's value; Solid mode only (lines and points are noted, not listed). The
/// overlays drawn after the triangles (normals display, depth legend) are not part of it.
PixelHistory inspectPixel(const Scene& scene, const RenderSettings& settings, int x, int y);

/// "v0", "v1" or "v2" for an InspectedEdge's end, "cut" for a clipped piece's new vertex (−1).
const char* vertexName(int vertex);

}  // namespace facet
