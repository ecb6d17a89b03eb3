#include "resources.hpp"

#include <filesystem>
#include <system_error>

#ifndef FACET_ASSETS_DIR
#define FACET_ASSETS_DIR ""
#endif

namespace facet::view {

namespace fs = std::filesystem;

std::string findResource(const std::string& relative, const std::string& compiledDir) {
    std::error_code ec;
    if (!compiledDir.empty() && fs::exists(fs::path(compiledDir) / relative, ec))
        return (fs::path(compiledDir) / relative).string();
    // /proc/self/exe: the executable wherever it was started from (Linux, which is all we run on).
    fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    for (int up = 0; !ec && up < 4 && !dir.empty(); ++up, dir = dir.parent_path()) {
        if (fs::exists(dir / relative, ec)) return (dir / relative).string();
        if (dir == dir.parent_path()) break;
    }
    if (fs::exists(relative, ec)) return relative;
    return {};
}

std::string defaultScenePath() {
    const std::string found = findResource("default.scene", FACET_ASSETS_DIR);
    return found.empty() ? findResource("assets/default.scene", "") : found;
}

}  // namespace facet::view
