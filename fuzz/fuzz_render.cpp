// Load and render: the first 8 bytes choose a small frame and the settings, the rest is an OFF
// mesh, drawn in front of a fixed camera with a 4x4 texture. Coverage, clipping, interpolation
// and shading meet whatever geometry the parser lets through (huge, tiny, degenerate, behind the
// camera) at every combination of settings.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/mesh_io.hpp"
#include "facet/render.hpp"
#include "facet/texture.hpp"
#include "fuzz_check.hpp"

namespace {

constexpr std::size_t kSettingsBytes = 8;

facet::RenderSettings settingsFrom(const std::uint8_t* b) {
    facet::RenderSettings s;
    s.mode = static_cast<facet::DrawMode>(b[2] % 3);
    s.shader = static_cast<facet::ShaderKind>((b[2] >> 2) % 4);
    s.lighting = static_cast<facet::Lighting>((b[2] >> 4) % 3);
    s.cullBackFaces = (b[2] >> 6) & 1;
    s.combine = (b[2] >> 7) & 1;
    s.interp = static_cast<facet::Interp>(b[3] % 3);
    s.filter = static_cast<facet::TextureFilter>((b[3] >> 2) % 3);
    s.supersample = 1 + ((b[3] >> 4) & 3);
    s.showNormals = (b[3] >> 6) & 1;
    s.depthLegend = (b[3] >> 7) & 1;
    s.subPixelBits = facet::kMinSubPixelBits + b[4] % 7;
    s.subdivision = facet::kMinSubdivision + (b[4] >> 3);
    s.pointSize = 1 + b[6] % 16;
    s.msaa = 1 << ((b[6] >> 4) & 3);  // 1, 2, 4, 8
    s.nearPlane = (b[7] & 1) ? 0.0 : 1e-3 * (b[7] >> 1);
    s.threads = 1;
    return s;
}

std::shared_ptr<const facet::Texture> checker() {
    std::vector<std::uint32_t> texels(16);
    for (std::size_t i = 0; i < texels.size(); ++i)
        texels[i] = ((i + i / 4) % 2) ? facet::packRgba(255, 255, 255) : facet::packRgba(200, 0, 0);
    auto texture = facet::Texture::fromRgba(4, 4, std::move(texels), "checker");
    facet::fuzz::require(texture.ok());
    return std::make_shared<const facet::Texture>(std::move(*texture));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < kSettingsBytes) return 0;
    const std::string_view off(reinterpret_cast<const char*>(data) + kSettingsBytes,
                               size - kSettingsBytes);
    facet::Result<facet::Mesh> mesh = facet::parseOff(off, "fuzz.off");
    if (!mesh) return 0;

    static const std::shared_ptr<const facet::Texture> texture = checker();
    facet::Scene scene;
    scene.mesh = std::make_shared<const facet::Mesh>(std::move(*mesh));
    scene.texture = texture;
    scene.camera.width = 1 + data[0] % 64;
    scene.camera.height = 1 + data[1] % 64;
    scene.camera.focal = 1.0 + 4.0 * data[5];
    const facet::RenderSettings settings = settingsFrom(data);

    static facet::Renderer renderer;  // kept, as the viewer keeps it, so its caches are reused
    facet::Framebuffer frame;
    renderer.render(scene, settings, frame);
    facet::fuzz::require(frame.width == scene.camera.width && frame.height == scene.camera.height);
    facet::fuzz::require(frame.color.size() == static_cast<std::size_t>(frame.width) *
                                                   static_cast<std::size_t>(frame.height));
    return 0;
}
