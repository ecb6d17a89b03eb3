// Opening whatever file a user brings (spec §3b): a .scene, or a bare mesh that gets a
// camera, a light and a material of its own. What a file is comes from its first bytes where
// they tell (so teapot.obj is never parsed as a scene), else from its extension.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "facet/mesh_io.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "io/load_progress.hpp"
#include "io/text_scan.hpp"

namespace facet {

namespace {

// Enough of a file to see its signature and first statements past a comment header.
constexpr std::size_t kSniffBytes = 4096;

std::string lowercase(std::string s) {
    for (char& c : s) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return s;
}

std::string extensionOf(const std::string& path) {
    return lowercase(std::filesystem::path(path).extension().string());
}

bool endsWithMeshExtension(std::string_view line) {
    if (line.size() < 4) return false;
    const std::string tail = lowercase(std::string(line.substr(line.size() - 4)));
    return tail == ".off" || tail == ".obj";
}

bool isObjKeyword(std::string_view token) {
    static constexpr std::array<std::string_view, 12> keywords = {
        "v", "vt", "vn", "vp", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl"};
    return std::find(keywords.begin(), keywords.end(), token) != keywords.end();
}

// The text up to the first white space (`line` has no leading white space).
std::string_view firstWord(std::string_view line) {
    return line.substr(0, std::min(line.size(), line.find_first_of(" \t")));
}

std::string readHead(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(kSniffBytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    return head;
}

// The kind the first bytes show, unknown when they do not decide it. Also returns the first
// line with content, for the message about a file that is none of them.
FileKind kindFromContent(std::string_view head, std::string_view& firstLine) {
    if (head.starts_with("\x89PNG") || head.starts_with("\xFF\xD8\xFF") || head.starts_with("BM"))
        return FileKind::image;
    text::LineReader lines(text::skipBom(head));
    std::string_view line;
    while (lines.next(line)) {
        const std::string_view content = text::stripComment(line);
        if (content.empty()) continue;
        firstLine = content;
        // A scene's first field is a path; it may contain spaces, so it is tested whole first.
        if (endsWithMeshExtension(content)) return FileKind::scene;
        const std::string_view word = firstWord(content);
        if (word == "OFF" || word == "COFF" || isObjKeyword(word)) return FileKind::mesh;
        return FileKind::unknown;
    }
    return FileKind::unknown;
}

FileKind kindFromExtension(const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext == ".scene") return FileKind::scene;
    if (ext == ".off" || ext == ".obj") return FileKind::mesh;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tga")
        return FileKind::image;
    return FileKind::unknown;
}

// OFF or OBJ by content (a mesh may have any extension once its content says which).
Result<Mesh> loadMeshFile(const std::string& path, std::string_view head,
                          const LoadControl* control) {
    std::string_view first;
    if (kindFromContent(head, first) == FileKind::mesh) {
        const std::string_view word = firstWord(first);
        if (word == "OFF" || word == "COFF") return loadOff(path, control);
        return loadObj(path, control);
    }
    return loadMesh(path, control);  // by extension, with its own message for anything else
}

}  // namespace

FileKind fileKind(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return FileKind::unknown;
    std::string_view first;
    const FileKind byContent = kindFromContent(readHead(path), first);
    return byContent != FileKind::unknown ? byContent : kindFromExtension(path);
}

std::optional<UpAxis> parseUpAxis(std::string_view name) {
    if (name == "x" || name == "X") return UpAxis::X;
    if (name == "y" || name == "Y") return UpAxis::Y;
    if (name == "z" || name == "Z") return UpAxis::Z;
    return std::nullopt;
}

std::string_view toString(UpAxis axis) {
    switch (axis) {
        case UpAxis::X:
            return "x";
        case UpAxis::Z:
            return "z";
        case UpAxis::Y:
            break;
    }
    return "y";
}

glm::dvec3 upVector(UpAxis axis) {
    switch (axis) {
        case UpAxis::X:
            return {1.0, 0.0, 0.0};
        case UpAxis::Z:
            return {0.0, 0.0, 1.0};
        case UpAxis::Y:
            break;
    }
    return {0.0, 1.0, 0.0};
}

Scene sceneForMesh(Mesh mesh, const std::string& meshPath, int width, int height, UpAxis up) {
    Scene scene;
    scene.path = meshPath;
    scene.meshPath = meshPath;
    scene.mesh = std::make_shared<const Mesh>(std::move(mesh));

    // Bounding sphere: the box centre and the farthest vertex from it.
    const Bounds bounds = computeBounds(*scene.mesh);
    glm::dvec3 centre(0.0);
    double radius = 0.0;
    if (bounds.min.x <= bounds.max.x) {
        centre = 0.5 * (glm::dvec3(bounds.min) + glm::dvec3(bounds.max));
        for (const glm::vec3& p : scene.mesh->positions)
            radius = std::max(radius, glm::length(glm::dvec3(p) - centre));
    }
    if (!(radius > 0.0)) radius = 1.0;  // a point or an empty mesh: any view shows it

    // The model's own right, up and front (towards the viewer), right-handed: +X, +Y, +Z for
    // Y-up; for Z-up the front is −Y (the front view of Z-up modelling tools); for X-up the
    // axes turned once more (+Z, +X, +Y).
    const glm::dvec3 upDir = upVector(up);
    const glm::dvec3 rightDir = up == UpAxis::X ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 frontDir = glm::cross(rightDir, upDir);

    // Three-quarter view: from the front, 35° to the right and 25° above.
    constexpr double deg = std::numbers::pi / 180.0;
    const double azimuth = 35.0 * deg;
    const double elevation = 25.0 * deg;
    const glm::dvec3 towardsEye = std::sin(azimuth) * std::cos(elevation) * rightDir +
                                  std::sin(elevation) * upDir +
                                  std::cos(azimuth) * std::cos(elevation) * frontDir;
    // f = 1.25 × the shorter side (a field of view of about 44° across it); the sphere's
    // silhouette, f·r / √(d² − r²) pixels in radius, takes 1/1.08 of half the shorter side.
    const double shortSide = static_cast<double>(std::min(width, height));
    const double focal = 1.25 * shortSide;
    const double k = 2.0 * 1.08 * focal / shortSide;
    const double distance = radius * std::sqrt(1.0 + k * k);

    Camera& camera = scene.camera;
    camera.look = centre;
    camera.eye = centre + distance * towardsEye;
    camera.up = -upDir;  // the y hint points down the image: (0, −1, 0), the course's, for +Y
    camera.focal = focal;
    camera.width = width;
    camera.height = height;

    // The light above and to the left of the camera, so the model is modelled, not flat.
    const glm::dvec3 forward = glm::normalize(camera.look - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(camera.up, forward));
    const glm::dvec3 down = glm::cross(forward, right);
    const glm::dvec3 light = camera.eye + distance * (-0.4 * down - 0.3 * right);
    scene.lighting.light.position = glm::dvec4(light, 1.0);
    scene.lighting.light.intensity = 1.0;
    scene.lighting.ambient = 1.0;
    scene.lighting.material = Material{0.15, 0.8, 0.25, 40.0};
    return scene;
}

Result<Scene> openSceneFile(const std::string& path, int width, int height,
                            const LoadControl* control) {
    OpenOptions options;
    options.width = width;
    options.height = height;
    return openSceneFile(path, options, control);
}

Result<Scene> openSceneFile(const std::string& path, const OpenOptions& options,
                            const LoadControl* control) {
    const int width = options.width;
    const int height = options.height;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return Error{{path, 0}, "is a folder, not a file"};
    if (!std::filesystem::exists(path, ec)) return Error{{path, 0}, "file not found"};
    // Before anything reads it: a pipe would block the read, a device would never end.
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{{path, 0}, "is not a regular file (a pipe, device or socket)"};
    const std::string head = readHead(path);
    std::string_view first;
    FileKind kind = kindFromContent(head, first);
    if (kind == FileKind::unknown) kind = kindFromExtension(path);
    switch (kind) {
        case FileKind::scene:
            return loadScene(path, control);
        case FileKind::mesh: {
            io::ProgressMeter meter(control);
            const float meshShare = 0.95f;  // the rest frames it and loads its map_Kd
            const LoadControl meshControl = meter.sub(0.0f, meshShare);
            auto mesh = loadMeshFile(path, head, control ? &meshControl : nullptr);
            if (!mesh) return mesh.error();
            const std::string mapKd = mesh->texturePath;
            Scene scene = sceneForMesh(std::move(*mesh), path, width, height, options.up);
            const LoadControl textureControl = meter.sub(meshShare, 1.0f);
            if (!mapKd.empty()) {
                if (Status st = loadSceneTexture(scene, mapKd, control ? &textureControl : nullptr);
                    !st) {
                    if (st.error().cancelled) return st.error();
                    return Error{
                        {path, 0},
                        "cannot load the map_Kd texture of its material: " + st.error().what()};
                }
            }
            if (meter.cancelled()) return io::ProgressMeter::cancelledError(path);
            meter.finish();
            return scene;
        }
        case FileKind::image:
            return Error{{path, 0},
                         "is an image, not a scene or a mesh: open a mesh or a .scene and use "
                         "the image as its texture"};
        case FileKind::unknown:
            break;
    }
    std::string got =
        first.empty() ? std::string("no text line") : "first line " + text::quoted(first);
    return Error{{path, 0},
                 "not a scene or a mesh: expected a .scene file (its first line names a .off or "
                 ".obj mesh), an OFF mesh (starting with OFF) or an OBJ mesh (v and f lines); "
                 "got " +
                     got};
}

}  // namespace facet
