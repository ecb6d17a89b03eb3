#include "settings_map.hpp"

#include <algorithm>
#include <cmath>

#include "facet/camera.hpp"

namespace facet::view {

int nameIndex(const std::vector<std::string_view>& names, std::string_view name) {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? 0 : static_cast<int>(it - names.begin());
}

std::uint32_t hexFromRgb(const float rgb[3]) {
    std::uint32_t hex = 0;
    for (int i = 0; i < 3; ++i) {
        const float v = rgb[i] > 0.0f ? std::min(rgb[i], 1.0f) : 0.0f;  // NaN → 0
        hex = (hex << 8) | static_cast<std::uint32_t>(std::lround(v * 255.0f));
    }
    return hex;
}

void rgbFromHex(std::uint32_t hex, float rgb[3]) {
    for (int i = 0; i < 3; ++i) rgb[i] = static_cast<float>((hex >> (16 - 8 * i)) & 0xFFu) / 255.0f;
}

InterpSpec interpOf(const RenderSettings& settings) {
    return {settings.interp, settings.subdivision};
}

void applyInterp(RenderSettings& settings, InterpSpec spec) {
    settings.interp = spec.interp;
    settings.subdivision = std::clamp(spec.subdivision, kMinSubdivision, kMaxSubdivision);
}

std::string interpLabel(InterpSpec spec) {
    std::string label(toString(spec.interp));
    if (spec.interp == Interp::Subdivided)
        label.append(" ").append(std::to_string(spec.subdivision));
    return label;
}

Camera frameCamera(const Camera& scene, SizePolicy policy, int windowWidth, int windowHeight) {
    if (policy == SizePolicy::SceneSize) return scene;
    // Scaling f with the height keeps the vertical field of view; a wider window shows more at
    // the sides instead of cropping the top and bottom.
    return resizedCamera(scene, std::clamp(windowWidth, 1, kMaxImageSide),
                         std::clamp(windowHeight, 1, kMaxImageSide), KeepFov::Vertical);
}

}  // namespace facet::view
