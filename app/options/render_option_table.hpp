#pragma once
// The render options the command line (`facet render`, `render-gl`, `inspect`) and the viewer
// (`facet-view`) share, declared once: each option's name, help, choices and the field it
// fills; one parser for --size; one function that applies them to RenderSettings. Both front
// ends register from this table, so the same flag takes the same values and sets the same
// setting in either.

#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "facet/error.hpp"
#include "facet/settings.hpp"

namespace facet::app {

/// The shared options as the user typed them; an empty string means "not given".
struct RenderOptionValues {
    std::string scene;    ///< the .scene file or bare .off/.obj mesh
    std::string size;     ///< --size WxH (parseSize)
    std::string texture;  ///< --texture: an image replacing the scene's
    std::string up;       ///< --up x|y|z: the axis a bare mesh stands on (spec §3b)
    std::string mode = "solid";
    std::string shader;  ///< empty: what the scene opens with (applyOpeningSettings)
    std::string interp = "perspective";
    std::string lighting;       ///< empty: what the scene opens with (applyOpeningSettings)
    std::string filter;         ///< empty: left as it is (bilinear unless changed)
    std::string view = "none";  ///< --view: a debug view instead of the shaded image
    bool combine = false;       ///< --combine: on, whatever the scene opens with
    bool noCombine = false;     ///< --no-combine: off, whatever the scene opens with
    bool cull = false;
    bool normals = false;
};

/// One shared option as a row of the table.
struct RenderOptionSpec {
    std::string name;                  ///< "--shader"; a positional's bare name ("scene")
    std::string help;                  ///< the --help text both front ends show
    std::vector<std::string> choices;  ///< the accepted values; empty: any text, or a flag
    /// The field it fills: a string for an option with a value, a bool for a flag.
    std::variant<std::string RenderOptionValues::*, bool RenderOptionValues::*> field;
};

/// Every shared option, in the order --help lists them.
const std::vector<RenderOptionSpec>& renderOptionTable();

/// The engine's names for a setting as CLI11 wants them; one list serves parsing and --help.
std::vector<std::string> choices(const std::vector<std::string_view>& names);

/// The registered options by name (RenderOptionSpec::name), for a front end to re-word, require
/// or hide one.
using RegisteredOptions = std::map<std::string, CLI::Option*, std::less<>>;

/// Registers every option of renderOptionTable() on `cmd`, filling `values`.
RegisteredOptions addRenderOptionTable(CLI::App& cmd, RenderOptionValues& values);

/// Parses "WxH" with 1…kMaxImageSide each; `width` and `height` are left alone otherwise.
bool parseSize(const std::string& text, int& width, int& height);

/// Checks what CLI11 does not (--size, --interp, --up): an Error whose message names the option
/// and what it wants otherwise.
Status checkRenderOptions(const RenderOptionValues& values);

/// Applies the options to `settings`: after applyOpeningSettings, so a given shader, lighting
/// or combine overrides what the scene opens with and one not given leaves it. An Error for a
/// name the engine does not know (CLI11 has refused those already; this guards direct callers).
Status applyRenderOptions(const RenderOptionValues& values, RenderSettings& settings);

}  // namespace facet::app
