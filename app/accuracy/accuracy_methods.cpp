#include "accuracy_methods.hpp"

namespace facet::app {

RenderSettings baseSettings(const Scene& scene) {
    RenderSettings s;
    s.mode = DrawMode::Solid;
    s.interp = Interp::Perspective;
    s.filter = TextureFilter::Trilinear;
    s.lighting = Lighting::Phong;  // the exact lighting, so other axes show their own error
    if (scene.texture && !scene.mesh.uvs.empty()) {
        s.shader = ShaderKind::Texture;
        s.combine = true;  // so the lighting axis changes the picture
    } else {
        s.shader = ShaderKind::Painter;
    }
    return s;
}

std::vector<AccuracyMethod> accuracyMethods(const Scene& scene) {
    const RenderSettings base = baseSettings(scene);
    std::vector<AccuracyMethod> methods;
    auto add = [&](const char* axis, std::string name, auto change) {
        RenderSettings s = base;
        change(s);
        methods.push_back({axis, std::move(name), s});
    };
    add("interp", "affine", [](RenderSettings& s) { s.interp = Interp::Affine; });
    for (const int n : {8, 16, 32}) {
        add("interp", "subdivided:" + std::to_string(n), [n](RenderSettings& s) {
            s.interp = Interp::Subdivided;
            s.subdivision = n;
        });
    }
    add("interp", "perspective", [](RenderSettings&) {});
    if (base.shader == ShaderKind::Texture) {
        add("filter", "nearest", [](RenderSettings& s) { s.filter = TextureFilter::Nearest; });
        add("filter", "bilinear", [](RenderSettings& s) { s.filter = TextureFilter::Bilinear; });
        add("filter", "trilinear", [](RenderSettings&) {});
    }
    add("lighting", "gouraud", [](RenderSettings& s) { s.lighting = Lighting::Gouraud; });
    add("lighting", "phong", [](RenderSettings&) {});
    return methods;
}

}  // namespace facet::app
