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
/// Depth (depth-tested, then depth mapped through viridis: near dark, far bright).
enum class ShaderKind { Simple, Painter, Depth };

/// Attribute interpolation across a primitive. Depth is always perspective-correct.
enum class Interp { Affine, Perspective };

/// Lighting (conventions §6): none (vertex colours as they are) or Gouraud (the lighting
/// formula evaluated per vertex, the lit colour interpolated).
enum class Lighting { Off, Gouraud };

/// Everything that selects a pipeline variant or changes a draw.
struct RenderSettings {
    DrawMode mode = DrawMode::Solid;
    ShaderKind shader = ShaderKind::Painter;
    Interp interp = Interp::Perspective;
    Lighting lighting = Lighting::Off;
    bool cullBackFaces = false;           ///< drop triangles seen from behind
    std::uint32_t background = 0x5C5C5C;  ///< 0xRRGGBB, the course's grey
    int pointSize = 5;                    ///< side of the vertex squares, in pixels
    double nearPlane = 0.0;               ///< camera-space near distance; <= 0 means auto
};

/// Parses names as the CLI spells them ("solid", "painter", "affine"...); nullopt if unknown.
std::optional<DrawMode> parseDrawMode(std::string_view name);
std::optional<ShaderKind> parseShader(std::string_view name);
std::optional<Interp> parseInterp(std::string_view name);
std::optional<Lighting> parseLighting(std::string_view name);

/// Every accepted name of each setting, in display order (CLI choices, UI combo boxes).
std::vector<std::string_view> drawModeNames();
std::vector<std::string_view> shaderNames();
std::vector<std::string_view> interpNames();
std::vector<std::string_view> lightingNames();

/// Lower-case names for messages and UI.
std::string_view toString(DrawMode mode);
std::string_view toString(ShaderKind shader);
std::string_view toString(Interp interp);
std::string_view toString(Lighting lighting);

}  // namespace facet
