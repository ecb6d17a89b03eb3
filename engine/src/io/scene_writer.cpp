// The .scene writer (spec §1). Numbers are written in the shortest form that reads back
// as the same double (std::to_chars, independent of the C locale a GUI may have set), so the
// loaded scene equals the saved one bit for bit and renders the same image.

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "facet/scene_io.hpp"

namespace facet {

namespace {

void appendNumbers(std::string& out, std::initializer_list<double> values) {
    bool first = true;
    for (const double v : values) {
        if (!first) out += ' ';
        first = false;
        char buf[32];
        const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        (void)ec;  // 32 bytes always hold the shortest form of a double
        out.append(buf, end);
    }
    out += '\n';
}

// `target` relative to `folder` when both are on one root, else absolute; '/' separators.
std::string relativePath(const std::string& target, const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::absolute(target, ec).lexically_normal();
    if (ec) return target;
    const fs::path relative = absolute.lexically_relative(folder);
    return (relative.empty() ? absolute : relative).generic_string();
}

// A path line must read back as the same path: the loader cuts a `#` comment and trims spaces.
std::optional<Error> checkPathLine(const std::string& line, const std::string& sceneFile,
                                   const char* what) {
    const bool spaceAtEnd = !line.empty() && (line.front() == ' ' || line.front() == '\t' ||
                                              line.back() == ' ' || line.back() == '\t');
    if (line.find_first_of("#\n\r") != std::string::npos || spaceAtEnd || line.empty()) {
        return Error{{sceneFile, 0},
                     std::string("cannot write the ") + what + " path '" + line +
                         "': a .scene line cannot hold '#', a line break or "
                         "surrounding spaces (rename or move the file)"};
    }
    return std::nullopt;
}

}  // namespace

Result<std::string> sceneText(const Scene& scene, const std::string& sceneFile) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path parent = fs::path(sceneFile).parent_path();
    const fs::path folder = fs::absolute(parent.empty() ? "." : parent, ec).lexically_normal();
    const std::string mesh = relativePath(scene.meshPath, folder);
    if (auto e = checkPathLine(mesh, sceneFile, "mesh")) return *e;
    std::string texture;
    if (scene.texture && !scene.texturePath.empty()) {
        texture = relativePath(scene.texturePath, folder);
        if (auto e = checkPathLine(texture, sceneFile, "texture")) return *e;
    }

    const Camera& c = scene.camera;
    const glm::dvec4& l = scene.lighting.light.position;
    const Material& m = scene.lighting.material;
    std::string out = "# written by facet\n";
    out += mesh + '\n';
    out += "# camera position\n";
    appendNumbers(out, {c.eye.x, c.eye.y, c.eye.z});
    out += "# look at\n";
    appendNumbers(out, {c.look.x, c.look.y, c.look.z});
    out += "# camera y vector\n";
    appendNumbers(out, {c.up.x, c.up.y, c.up.z});
    out += "# focal length (pixels)\n";
    appendNumbers(out, {c.focal});
    out += "# w h\n";
    out += std::to_string(c.width) + ' ' + std::to_string(c.height) + '\n';
    out += "# Ia\n";
    appendNumbers(out, {scene.lighting.ambient});
    // Four numbers mean w = 1, what the course files write; anything else needs the fifth.
    if (l.w == 1.0) {
        out += "# point light x y z Id\n";
        appendNumbers(out, {l.x, l.y, l.z, scene.lighting.light.intensity});
    } else {
        out += l.w == 0.0 ? "# directional light x y z 0 Id\n" : "# light x y z w Id\n";
        appendNumbers(out, {l.x, l.y, l.z, l.w, scene.lighting.light.intensity});
    }
    out += "# Ka Kd Ks s\n";
    appendNumbers(out, {m.ka, m.kd, m.ks, m.s});
    if (!texture.empty()) {
        out += "# texture\n";
        out += texture + '\n';
    }
    return out;
}

Status writeScene(const Scene& scene, const std::string& sceneFile) {
    Result<std::string> text = sceneText(scene, sceneFile);
    if (!text) return text.error();
    std::FILE* file = std::fopen(sceneFile.c_str(), "wb");
    if (!file) return Error{{sceneFile, 0}, "cannot open file for writing"};
    const bool written = std::fwrite(text->data(), 1, text->size(), file) == text->size();
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed) return Error{{sceneFile, 0}, "cannot write file (disk full?)"};
    return {};
}

}  // namespace facet
