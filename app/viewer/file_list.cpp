#include "file_list.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace facet::view {

namespace fs = std::filesystem;

std::vector<std::string> listSceneFiles(const std::string& folder, std::string* error) {
    std::vector<std::string> files;
    std::error_code ec;
    // The error_code overloads: a folder that vanishes or cannot be read never throws.
    fs::directory_iterator it(folder.empty() ? "." : folder, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        std::error_code typeError;
        if (it->path().extension() == ".scene" && it->is_regular_file(typeError))
            files.push_back(it->path().string());
    }
    if (ec && error) *error = folder + ": " + ec.message();
    std::sort(files.begin(), files.end());
    return files;
}

void pushRecent(std::vector<std::string>& recent, const std::string& path, std::size_t max) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    const std::string entry = ec ? path : absolute.lexically_normal().string();
    recent.erase(std::remove(recent.begin(), recent.end(), entry), recent.end());
    // push_back and rotate rather than insert at the front: same result, and GCC 12 reports a
    // false null dereference inside vector::insert of a string.
    recent.push_back(entry);
    std::rotate(recent.begin(), recent.end() - 1, recent.end());
    if (recent.size() > max) recent.resize(max);
}

std::string nextFreePath(const std::string& folder, const std::string& stem) {
    const fs::path dir = folder.empty() ? fs::path(".") : fs::path(folder);
    std::error_code ec;
    for (int i = 1;; ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "-%04d.png", i);
        const fs::path candidate = dir / (stem + name);
        if (!fs::exists(candidate, ec) || i >= 99999) return candidate.string();
    }
}

}  // namespace facet::view
