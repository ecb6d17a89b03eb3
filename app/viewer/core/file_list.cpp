#include "file_list.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "facet/scene_io.hpp"

namespace facet::view {

namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string s) {
    for (char& c : s) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return s;
}

}  // namespace

std::optional<EntryKind> entryKind(const std::string& fileName) {
    const std::string ext = lowercase(fs::path(fileName).extension().string());
    if (ext == ".scene") return EntryKind::scene;
    if (ext == ".off" || ext == ".obj") return EntryKind::mesh;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tga")
        return EntryKind::image;
    return std::nullopt;
}

std::vector<FolderEntry> listFolder(const std::string& folder, std::string* error) {
    std::error_code ec;
    const fs::path dir = fs::absolute(folder.empty() ? "." : folder, ec).lexically_normal();
    std::vector<FolderEntry> folders, files;
    // The error_code overloads: a folder that vanishes or cannot be read never throws.
    fs::directory_iterator it(dir, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) {
            folders.push_back({name + "/", it->path().string(), EntryKind::folder});
        } else if (const auto kind = entryKind(name); kind && it->is_regular_file(typeError)) {
            files.push_back({name, it->path().string(), *kind});
        }
    }
    if (ec && error) *error = dir.string() + ": " + ec.message();
    const auto byName = [](const FolderEntry& a, const FolderEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    std::vector<FolderEntry> out;
    // lexically_normal leaves a trailing separator on some paths: "/a/b/" has parent "/a/b".
    fs::path self = dir;
    if (!self.has_filename()) self = self.parent_path();
    if (self.has_parent_path() && self.parent_path() != self)
        out.push_back({"..", self.parent_path().string(), EntryKind::parent});
    out.insert(out.end(), folders.begin(), folders.end());
    out.insert(out.end(), files.begin(), files.end());
    return out;
}

std::string configFolder() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    if (xdg && *xdg) return (fs::path(xdg) / "facet").string();
    const char* home = std::getenv("HOME");
    if (home && *home) return (fs::path(home) / ".config" / "facet").string();
    return {};
}

std::vector<std::string> readRecent(const std::string& file, std::size_t max) {
    std::vector<std::string> recent;
    std::ifstream in(file);
    std::string line;
    while (recent.size() < max && std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!line.empty() && std::find(recent.begin(), recent.end(), line) == recent.end())
            recent.push_back(line);
    }
    return recent;
}

bool writeRecent(const std::string& file, const std::vector<std::string>& recent) {
    std::error_code ec;
    fs::create_directories(fs::path(file).parent_path(), ec);
    std::ofstream out(file, std::ios::trunc);
    for (const std::string& path : recent) out << path << '\n';
    out.close();
    return static_cast<bool>(out);
}

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

std::string defaultSavePath(const std::string& opened) {
    std::error_code ec;
    const fs::path full = fs::absolute(fs::path(opened), ec).lexically_normal();
    const std::string stem = full.stem().string();
    const std::string name = (stem.empty() ? std::string("scene") : stem);
    const fs::path folder = full.parent_path();
    if (!fs::exists(folder / (name + ".scene"), ec)) return (folder / (name + ".scene")).string();
    return nextFreePath(folder.string(), name, ".scene");
}

DropPlan planDrop(const std::vector<std::string>& paths) {
    DropPlan plan;
    for (const std::string& path : paths) {
        std::error_code ec;
        if (fs::is_directory(path, ec)) {
            plan.folder = path;
            continue;
        }
        switch (fileKind(path)) {
            case FileKind::scene:
            case FileKind::mesh:
                plan.open = path;
                break;
            case FileKind::image:
                plan.texture = path;
                break;
            case FileKind::unknown:
                plan.refused.push_back(path +
                                       ": not a .scene, .off/.obj mesh or PNG/JPEG/BMP/TGA image");
                break;
        }
    }
    return plan;
}

std::string nextFreePath(const std::string& folder, const std::string& stem,
                         const std::string& extension) {
    const fs::path dir = folder.empty() ? fs::path(".") : fs::path(folder);
    std::error_code ec;
    for (int i = 1;; ++i) {
        char number[16];
        std::snprintf(number, sizeof number, "-%04d", i);
        const fs::path candidate = dir / (stem + number + extension);
        if (!fs::exists(candidate, ec) || i >= 99999) return candidate.string();
    }
}

}  // namespace facet::view
