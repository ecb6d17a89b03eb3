#include "facet/settings.hpp"

#include <array>
#include <utility>

namespace facet {
namespace {

// One table per enum keeps parsing and printing in step.
constexpr std::array<std::pair<std::string_view, DrawMode>, 3> kModes{{
    {"vertices", DrawMode::Vertices},
    {"wireframe", DrawMode::Wireframe},
    {"solid", DrawMode::Solid},
}};
constexpr std::array<std::pair<std::string_view, ShaderKind>, 3> kShaders{{
    {"simple", ShaderKind::Simple},
    {"painter", ShaderKind::Painter},
    {"depth", ShaderKind::Depth},
}};
constexpr std::array<std::pair<std::string_view, Interp>, 2> kInterps{{
    {"affine", Interp::Affine},
    {"perspective", Interp::Perspective},
}};

constexpr std::array<std::pair<std::string_view, Lighting>, 2> kLightings{{
    {"off", Lighting::Off},
    {"gouraud", Lighting::Gouraud},
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

}  // namespace facet
