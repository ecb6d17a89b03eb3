// The OBJ loader (line checks, tinyobjloader, fanning, its material file). The input is the OBJ
// text, then optionally a NUL byte and the text of fuzz.mtl beside it; both are written to a
// private folder because loadObj reads files, as the engine does for real.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "facet/mesh_io.hpp"
#include "fuzz_check.hpp"

namespace {

std::filesystem::path folder;

void write(const std::filesystem::path& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string pattern = (std::filesystem::temp_directory_path() / "facet-fuzz-obj-XXXXXX");
    if (!mkdtemp(pattern.data())) std::abort();
    folder = pattern;
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(folder, ec);
    });
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    write(folder / "fuzz.obj", input.substr(0, nul));
    write(folder / "fuzz.mtl", nul == std::string_view::npos ? "" : input.substr(nul + 1));
    const std::string path = (folder / "fuzz.obj").string();
    const facet::Result<facet::Mesh> mesh = facet::loadObj(path);
    if (mesh) {
        facet::fuzz::checkMesh(*mesh);
    } else {
        facet::fuzz::require(!mesh.error().loc.file.empty());
    }
    return 0;
}
