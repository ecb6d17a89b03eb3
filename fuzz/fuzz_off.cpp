// The OFF parser on arbitrary text.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "facet/mesh_io.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const facet::Result<facet::Mesh> mesh = facet::parseOff(text, "fuzz.off");
    if (mesh) {
        facet::fuzz::checkMesh(*mesh);
    } else {
        facet::fuzz::require(mesh.error().loc.file == "fuzz.off");
    }
    return 0;
}
