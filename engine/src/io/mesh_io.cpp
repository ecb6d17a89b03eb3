// Format dispatch and the OFF writer. The writer uses the course's vertex layout so its output
// opens in the course framework, and shortest round-trip float text so parseOff reads back the
// exact same bits (std::to_chars is also independent of the C locale a GUI may have set).

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>

#include "facet/mesh_io.hpp"

#include "facet/limits.hpp"

namespace facet {

namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

void appendFloat(std::string& out, float v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;  // 32 bytes always hold the shortest form of a float
    out.append(buf, end);
}

void appendUint(std::string& out, std::uint64_t v) {
    char buf[24];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    out.append(buf, end);
}

}  // namespace

Result<Mesh> loadMesh(const std::string& path, const LoadControl* control) {
    const std::string ext = lowercase(std::filesystem::path(path).extension().string());
    if (ext == ".off") return loadOff(path, control);
    if (ext == ".obj") return loadObj(path, control);
    if (ext.empty()) return Error{{path, 0}, "mesh file has no extension: expected .off or .obj"};
    return Error{{path, 0}, "unknown mesh format '" + ext + "': expected .off or .obj"};
}

Status writeOff(const Mesh& mesh, const std::string& path) {
    const std::size_t nv = mesh.vertexCount();
    if ((mesh.hasColors() && mesh.colors.size() != nv) ||
        (mesh.hasUvs() && mesh.uvs.size() != nv) || mesh.indices.size() % 3 != 0) {
        return Error{{path, 0}, "cannot write an inconsistent mesh (attribute or index counts)"};
    }
    // What the loaders would refuse is not written (limits.hpp): a mesh over the memory limit,
    // or a file over the size limit, checked as the text grows, before the file is opened.
    if (auto problem = meshMemoryProblem(nv, mesh.triangleCount()))
        return Error{{path, 0}, *problem};
    const auto tooLarge = [&] {
        return Error{{path, 0},
                     "the OFF file would exceed " + std::to_string(kMaxFileBytes >> 30) +
                         " GiB, the largest file facet reads (" + std::to_string(nv) +
                         " vertices, " + std::to_string(mesh.triangleCount()) +
                         " triangles); choose less detail"};
    };

    std::string out = "OFF\n";
    appendUint(out, nv);
    out += ' ';
    appendUint(out, mesh.triangleCount());
    out += " 0\n";
    for (std::size_t i = 0; i < nv; ++i) {
        const glm::vec3 p = mesh.positions[i];
        // The course layout always has colours; white is what "no colours" means.
        const glm::vec3 c = mesh.hasColors() ? mesh.colors[i] : glm::vec3(1.0f);
        for (const float v : {p.x, p.y, p.z, c.r, c.g, c.b}) {
            appendFloat(out, v);
            out += ' ';
        }
        if (mesh.hasUvs()) {
            appendFloat(out, mesh.uvs[i].x);
            out += ' ';
            appendFloat(out, mesh.uvs[i].y);
        } else {
            out.pop_back();
        }
        out += '\n';
        if (out.size() > kMaxFileBytes) return tooLarge();
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        out += '3';
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            appendUint(out, mesh.indices[3 * t + static_cast<std::size_t>(k)]);
        }
        out += '\n';
        if (out.size() > kMaxFileBytes) return tooLarge();
    }

    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return Error{{path, 0}, "cannot open file for writing"};
    const bool written = std::fwrite(out.data(), 1, out.size(), file) == out.size();
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed) return Error{{path, 0}, "cannot write file (disk full?)"};
    return {};
}

}  // namespace facet
