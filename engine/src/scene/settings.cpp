#include "facet/settings.hpp"

#include <array>
#include <charconv>
#include <system_error>
#include <utility>

namespace facet {
namespace {

// One table per enum keeps parsing and printing in step.
constexpr std::array<std::pair<std::string_view, DrawMode>, 3> kModes{{
    {"vertices", DrawMode::Vertices},
    {"wireframe", DrawMode::Wireframe},
    {"solid", DrawMode::Solid},
}};
constexpr std::array<std::pair<std::string_view, ShaderKind>, 4> kShaders{{
    {"simple", ShaderKind::Simple},
    {"painter", ShaderKind::Painter},
    {"depth", ShaderKind::Depth},
    {"texture", ShaderKind::Texture},
}};
constexpr std::array<std::pair<std::string_view, Interp>, 3> kInterps{{
    {"affine", Interp::Affine},
    {"subdivided", Interp::Subdivided},
    {"perspective", Interp::Perspective},
}};
constexpr std::array<std::pair<std::string_view, Lighting>, 3> kLightings{{
    {"off", Lighting::Off},
    {"gouraud", Lighting::Gouraud},
    {"phong", Lighting::Phong},
}};
constexpr std::array<std::pair<std::string_view, TextureFilter>, 3> kFilters{{
    {"nearest", TextureFilter::Nearest},
    {"bilinear", TextureFilter::Bilinear},
    {"trilinear", TextureFilter::Trilinear},
}};
constexpr std::array<std::pair<std::string_view, DebugView>, 7> kViews{{
    {"none", DebugView::None},
    {"overdraw", DebugView::Overdraw},
    {"triangle-size", DebugView::TriangleSize},
    {"bin-load", DebugView::BinLoad},
    {"depth-test", DebugView::DepthTest},
    {"texture-lod", DebugView::TextureLod},
    {"interp-error", DebugView::InterpError},
}};

template <class E, std::size_t N>
std::optional<E> lookup(const std::array<std::pair<std::string_view, E>, N>& table,
                        std::string_view name) {
    for (const auto& [key, value] : table)
        if (key == name) return value;
    return std::nullopt;
}

template <class E, std::size_t N>
std::string_view nameOf(const std::array<std::pair<std::string_view, E>, N>& table, E value) {
    for (const auto& [key, v] : table)
        if (v == value) return key;
    return "?";
}

template <class E, std::size_t N>
std::vector<std::string_view> namesOf(const std::array<std::pair<std::string_view, E>, N>& table) {
    std::vector<std::string_view> names;
    for (const auto& entry : table) names.push_back(entry.first);
    return names;
}

}  // namespace

std::vector<std::string_view> drawModeNames() {
    return namesOf(kModes);
}
std::vector<std::string_view> shaderNames() {
    return namesOf(kShaders);
}
std::vector<std::string_view> interpNames() {
    return namesOf(kInterps);
}
std::vector<std::string_view> lightingNames() {
    return namesOf(kLightings);
}
std::vector<std::string_view> filterNames() {
    return namesOf(kFilters);
}

std::vector<std::string_view> debugViewNames() {
    return namesOf(kViews);
}

std::optional<DrawMode> parseDrawMode(std::string_view name) {
    return lookup(kModes, name);
}
std::optional<ShaderKind> parseShader(std::string_view name) {
    return lookup(kShaders, name);
}
std::optional<Interp> parseInterp(std::string_view name) {
    return lookup(kInterps, name);
}
std::optional<Lighting> parseLighting(std::string_view name) {
    return lookup(kLightings, name);
}
std::optional<TextureFilter> parseFilter(std::string_view name) {
    return lookup(kFilters, name);
}
std::optional<DebugView> parseDebugView(std::string_view name) {
    return lookup(kViews, name);
}

std::optional<InterpSpec> parseInterpSpec(std::string_view text) {
    const std::size_t colon = text.find(':');
    const std::optional<Interp> interp = parseInterp(text.substr(0, colon));
    if (!interp) return std::nullopt;
    InterpSpec spec{*interp, 16};
    if (colon == std::string_view::npos) return spec;
    if (*interp != Interp::Subdivided) return std::nullopt;  // only subdivided takes an N
    const std::string_view digits = text.substr(colon + 1);
    int n = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (ec != std::errc{} || end != digits.data() + digits.size() || n < kMinSubdivision ||
        n > kMaxSubdivision)
        return std::nullopt;
    spec.subdivision = n;
    return spec;
}

std::string_view toString(DrawMode mode) {
    return nameOf(kModes, mode);
}
std::string_view toString(ShaderKind shader) {
    return nameOf(kShaders, shader);
}
std::string_view toString(Interp interp) {
    return nameOf(kInterps, interp);
}
std::string_view toString(Lighting lighting) {
    return nameOf(kLightings, lighting);
}
std::string_view toString(TextureFilter filter) {
    return nameOf(kFilters, filter);
}
std::string_view toString(DebugView view) {
    return nameOf(kViews, view);
}

}  // namespace facet
