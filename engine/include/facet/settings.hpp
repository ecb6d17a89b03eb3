#pragma once
// How to draw: one plain struct shared by the CLI, the viewer and both renderers.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace facet {

/// The course's three draw modes.
enum class DrawMode { Vertices, Wireframe, Solid };

/// The course's shaders: Simple (no depth test, last wins), Painter (LESS depth test),
/// Depth (depth-tested, then depth mapped through viridis: near dark, far bright), Texture
/// (LESS depth test, the pixel is the texel, or texel × lit colour with `combine`).
enum class ShaderKind { Simple, Painter, Depth, Texture };

/// Attribute interpolation across a primitive. Depth is always perspective-correct.
/// Subdivided is exact (perspective-correct) every `subdivision` pixels along a row and affine
/// in between: the classic speed/accuracy compromise of 1990s software renderers.
enum class Interp { Affine, Subdivided, Perspective };

/// Lighting (spec §6): none (vertex colours as they are), Gouraud (the formula per
/// vertex, the lit colour interpolated) or Phong (normal interpolated, renormalised, lit per
/// pixel).
enum class Lighting { Off, Gouraud, Phong };

/// Texture filtering (spec §7); Trilinear picks the mip level from the screen-space
/// derivatives of (u, v).
enum class TextureFilter { Nearest, Bilinear, Trilinear };

/// Debug views (docs/debug-views.md): the frame coloured by what the pipeline did at each
/// pixel instead of by the shader, with a legend. None is the normal image.
enum class DebugView { None, Overdraw, TriangleSize, BinLoad, DepthTest, TextureLod, InterpError };

/// Smallest and largest span of the Subdivided interpolation, in pixels.
inline constexpr int kMinSubdivision = 2;
inline constexpr int kMaxSubdivision = 256;

/// Fewest and most fractional bits of the sub-pixel grid vertices are snapped to (spec
/// §5); the engine clamps RenderSettings::subPixelBits to this range.
inline constexpr int kMinSubPixelBits = 2;
inline constexpr int kMaxSubPixelBits = 8;

/// Everything that selects a pipeline variant or changes a draw.
struct RenderSettings {
    DrawMode mode = DrawMode::Solid;
    ShaderKind shader = ShaderKind::Painter;
    Interp interp = Interp::Perspective;
    Lighting lighting = Lighting::Off;
    int subdivision = 16;  ///< pixels between exact evaluations for Interp::Subdivided (2…256)
    TextureFilter filter = TextureFilter::Bilinear;
    bool combine = false;                 ///< Texture shader: texel × (lit) vertex colour
    bool showNormals = false;             ///< draw each vertex normal as a red segment
    double normalLength = 0.0;            ///< world length of those segments; <= 0: diagonal/100
    bool depthLegend = false;             ///< Depth shader: draw the near/far legend bar
    bool cullBackFaces = false;           ///< drop triangles seen from behind
    std::uint32_t background = 0x5C5C5C;  ///< 0xRRGGBB, the course's grey
    int pointSize = 5;                    ///< side of the vertex squares, in pixels
    double nearPlane = 0.0;               ///< camera-space near distance; <= 0 means auto
    int threads = 0;                      ///< engine worker threads; <= 0 means all cores
    int subPixelBits = 8;  ///< fractional bits of the coverage grid (2…8, clamped); 8 = 1/256 px
    /// Samples per pixel axis, 1…4 (clamped): the frame is rendered at N×N the size and each
    /// N×N block averaged (supersampling); Solid mode only, lines and points stay one sample.
    int supersample = 1;
    DebugView view = DebugView::None;  ///< a debug view instead of the shaded image
    /// Samples per pixel of multisampling: 1 (off), 2, 4 or 8 (others normalised by
    /// msaaSamples()). Coverage and depth per sample at the standard positions, shading once per
    /// pixel, a box-filter resolve (spec §11); Solid mode only, lines and points
    /// stay one sample. Combines with supersample (each supersampled pixel multisampled).
    int msaa = 1;

    /// Every field equal (the viewer's "did anything change" and "same method" checks).
    bool operator==(const RenderSettings&) const = default;
};

/// Parses names as the CLI spells them ("solid", "painter", "affine"...); nullopt if unknown.
std::optional<DrawMode> parseDrawMode(std::string_view name);
std::optional<ShaderKind> parseShader(std::string_view name);
std::optional<Interp> parseInterp(std::string_view name);
std::optional<Lighting> parseLighting(std::string_view name);
std::optional<TextureFilter> parseFilter(std::string_view name);
std::optional<DebugView> parseDebugView(std::string_view name);

/// An interpolation as the CLI spells it: "affine", "perspective", "subdivided" (N = 16) or
/// "subdivided:N" with N in 2…256.
struct InterpSpec {
    Interp interp = Interp::Perspective;
    int subdivision = 16;  ///< N, meaningful for Subdivided only

    /// Every field equal.
    bool operator==(const InterpSpec&) const = default;
};
std::optional<InterpSpec> parseInterpSpec(std::string_view text);

/// Every accepted name of each setting, in display order (CLI choices, UI combo boxes).
std::vector<std::string_view> drawModeNames();
std::vector<std::string_view> shaderNames();
std::vector<std::string_view> interpNames();
std::vector<std::string_view> lightingNames();
std::vector<std::string_view> filterNames();
std::vector<std::string_view> debugViewNames();

/// Lower-case names for messages and UI.
std::string_view toString(DrawMode mode);
std::string_view toString(ShaderKind shader);
std::string_view toString(Interp interp);
std::string_view toString(Lighting lighting);
std::string_view toString(TextureFilter filter);
std::string_view toString(DebugView view);

}  // namespace facet
