// The .scene parser on arbitrary text (the mesh and texture it names are not loaded).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <glm/geometric.hpp>

#include "facet/limits.hpp"
#include "facet/scene_io.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using facet::fuzz::require;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const facet::Result<facet::Scene> scene = facet::parseScene(text, "fuzz.scene");
    if (scene) {
        // What the renderer takes for granted once a scene parsed.
        const facet::Camera& c = scene->camera;
        require(c.width >= 1 && c.width <= facet::kMaxImageSide);
        require(c.height >= 1 && c.height <= facet::kMaxImageSide);
        require(c.focal > 0.0 && std::isfinite(c.focal));
        require(c.eye != c.look && glm::length(c.up) > 0.0);
    } else {
        require(scene.error().loc.file == "fuzz.scene" && !scene.error().message.empty());
    }
    return 0;
}
