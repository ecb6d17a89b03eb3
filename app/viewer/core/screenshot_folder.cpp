#include "screenshot_folder.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace facet::view {
namespace {

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

PicturesEnv picturesEnvFromProcess() {
    PicturesEnv e;
    e.xdgPicturesDir = env("XDG_PICTURES_DIR");
    e.home = env("HOME");
    std::string config = env("XDG_CONFIG_HOME");
    if (config.empty() && !e.home.empty()) config = e.home + "/.config";
    if (!config.empty()) {
        std::ifstream f(config + "/user-dirs.dirs");
        std::stringstream s;
        s << f.rdbuf();
        e.userDirs = s.str();
    }
    return e;
}

std::string picturesDirFromUserDirs(const std::string& text, const std::string& home) {
    std::istringstream in(text);
    std::string line;
    const std::string key = "XDG_PICTURES_DIR=";
    std::string value;
    while (std::getline(in, line)) {
        line = trim(line);
        if (line.rfind(key, 0) != 0) continue;
        value = trim(line.substr(key.size()));  // the last line wins, as in a shell
    }
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
    if (value.empty()) return "";
    if (value.rfind("$HOME", 0) == 0) {
        if (home.empty()) return "";
        value = home + value.substr(5);
    } else if (value.front() != '/') {
        if (home.empty()) return "";
        value = home + "/" + value;
    }
    // xdg-user-dirs writes "$HOME/" for a disabled folder: not a pictures folder.
    if (value == home || value == home + "/") return "";
    return value;
}

std::string screenshotFolder(const PicturesEnv& e) {
    std::string pictures = e.xdgPicturesDir;
    if (pictures.empty()) pictures = picturesDirFromUserDirs(e.userDirs, e.home);
    if (pictures.empty() && !e.home.empty()) pictures = e.home + "/Pictures";
    if (pictures.empty()) return "facet";
    return (std::filesystem::path(pictures) / "facet").string();
}

Status ensureFolder(const std::string& folder) {
    std::error_code ec;
    if (std::filesystem::is_directory(folder, ec)) return {};
    std::filesystem::create_directories(folder, ec);
    if (ec || !std::filesystem::is_directory(folder))
        return Error{{folder, 0}, "cannot create the screenshot folder (" + ec.message() + ")"};
    return {};
}

}  // namespace facet::view
