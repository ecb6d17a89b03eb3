// The .scene reader (spec §1). Fields are the non-blank, comment-free lines in a fixed
// order; each error names the physical line and what that field expects, so a missing or extra
// line shows up as "field X needs N numbers" at the first field that no longer fits.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/mesh_io.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "io/load_progress.hpp"
#include "io/text_scan.hpp"

namespace facet {

namespace {

constexpr std::size_t requiredFields = 9;
constexpr std::size_t maxFields = 10;

// One field: its physical line and its text without comment and outer white space.
struct Field {
    int line = 0;
    std::string_view text;
};

// A parsed scene plus the lines that loadScene's path errors point at.
struct ParsedScene {
    Scene scene;
    int meshLine = 0;
    int textureLine = 0;
};

// Shortest text that reads back as `v`, for messages.
std::string number(double v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;  // 32 bytes always hold the shortest form of a double
    return std::string(buf, end);
}

bool hasMeshExtension(std::string_view path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return ext == ".off" || ext == ".obj";
}

class SceneParser {
  public:
    explicit SceneParser(const std::string& fileName) : fileName_(fileName) {}

    Result<ParsedScene> parse(std::string_view text) {
        std::vector<Field> fields;
        text::LineReader lines(text::skipBom(text));
        std::string_view line;
        while (lines.next(line)) {
            const std::string_view content = text::stripComment(line);
            if (!content.empty()) fields.push_back({lines.lineNumber(), content});
        }
        static const char* const names[requiredFields] = {
            "mesh file",          "camera position", "look-at point",
            "camera y hint (up)", "focal length",    "image size",
            "ambient intensity",  "point light",     "material"};
        if (fields.size() < requiredFields) {
            return error(lines.lineNumber(),
                         "file ends before the " + std::string(names[fields.size()]) +
                             " line (field " + std::to_string(fields.size() + 1) + " of " +
                             std::to_string(requiredFields) + " required)");
        }

        ParsedScene out;
        Scene& s = out.scene;
        s.path = fileName_;

        // 1: mesh path (may contain spaces: the whole line is the path).
        out.meshLine = fields[0].line;
        s.meshPath = std::string(fields[0].text);
        if (!hasMeshExtension(s.meshPath)) {
            return error(fields[0], "mesh file must end in .off or .obj, got " +
                                        text::quoted(s.meshPath, std::string::npos));
        }

        // 2-4: camera pose.
        double v[5];
        if (auto e = numbers(fields[1], names[1], "x y z", 3, 3, v)) return *e;
        s.camera.eye = {v[0], v[1], v[2]};
        if (auto e = numbers(fields[2], names[2], "x y z", 3, 3, v)) return *e;
        s.camera.look = {v[0], v[1], v[2]};
        if (s.camera.look == s.camera.eye) {
            return error(fields[2],
                         "look-at point equals the camera position; the camera needs a "
                         "direction to look in");
        }
        if (auto e = numbers(fields[3], names[3], "x y z", 3, 3, v)) return *e;
        s.camera.up = {v[0], v[1], v[2]};
        const glm::dvec3 forward = s.camera.look - s.camera.eye;
        const double upLength = glm::length(s.camera.up);
        if (upLength == 0.0) return error(fields[3], "camera y hint (up) must not be zero");
        // Relative tolerance: the test must not depend on the scene's scale.
        if (glm::length(glm::cross(s.camera.up, forward)) <=
            1e-12 * upLength * glm::length(forward)) {
            return error(fields[3],
                         "camera y hint (up) is parallel to the viewing direction (look-at - "
                         "camera position); it must point across it");
        }

        // 5-6: intrinsics.
        if (auto e = numbers(fields[4], names[4], "f", 1, 1, v)) return *e;
        if (!(v[0] > 0.0)) return error(fields[4], "focal length must be > 0, got " + number(v[0]));
        s.camera.focal = v[0];
        if (auto e = imageSize(fields[5], s.camera)) return *e;

        // 7-9: lighting.
        if (auto e = numbers(fields[6], names[6], "Ia", 1, 1, v)) return *e;
        if (!(v[0] >= 0.0)) {
            return error(fields[6], "ambient intensity Ia must be >= 0, got " + number(v[0]));
        }
        s.lighting.ambient = v[0];
        if (auto e = light(fields[7], s.lighting.light)) return *e;
        if (auto e = numbers(fields[8], names[8], "Ka Kd Ks s", 4, 4, v)) return *e;
        static const char* const coefficients[] = {"Ka", "Kd", "Ks", "s"};
        for (int i = 0; i < 4; ++i) {
            if (!(v[i] >= 0.0)) {
                return error(fields[8], "material coefficients (Ka Kd Ks s) must be >= 0, got " +
                                            std::string(coefficients[i]) + " = " + number(v[i]));
            }
        }
        s.lighting.material = {v[0], v[1], v[2], v[3]};

        // 10: optional texture.
        if (fields.size() > requiredFields) {
            out.textureLine = fields[9].line;
            s.texturePath = std::string(fields[9].text);
        }
        if (fields.size() > maxFields) {
            return error(
                fields[maxFields],
                "unexpected extra line: a scene has at most 10 fields (mesh, eye, look-at, "
                "up, f, w h, Ia, light, material, texture)");
        }
        return out;
    }

  private:
    Error error(int line, std::string message) const {
        return Error{{fileName_, line}, std::move(message)};
    }
    Error error(const Field& f, std::string message) const {
        return error(f.line, std::move(message));
    }

    // Parses a line of `min`..`max` finite numbers into `out`; names the field and its form.
    std::optional<Error> numbers(const Field& f, const char* name, const char* form,
                                 std::size_t min, std::size_t max, double* out) {
        text::splitTokens(f.text, tokens_);
        for (std::size_t i = 0; i < tokens_.size(); ++i) {
            double value = 0.0;
            switch (text::parseReal(tokens_[i], value)) {
                case text::NumberStatus::ok:
                    break;
                case text::NumberStatus::notANumber:
                    return error(f, std::string(name) + ": expected a number, got " +
                                        text::quoted(tokens_[i]));
                case text::NumberStatus::nonFinite:
                    return error(
                        f, std::string(name) + ": non-finite number " + text::quoted(tokens_[i]));
            }
            if (i < max) out[i] = value;
        }
        if (tokens_.size() < min || tokens_.size() > max) {
            const std::string expected =
                min == max ? text::countNoun(min, "number")
                           : std::to_string(min) + " or " + std::to_string(max) + " numbers";
            return error(f, std::string(name) + " needs " + expected + " (" + form + "), got " +
                                std::to_string(tokens_.size()));
        }
        return std::nullopt;
    }

    std::optional<Error> imageSize(const Field& f, Camera& camera) {
        text::splitTokens(f.text, tokens_);
        std::int64_t size[2] = {0, 0};
        for (std::size_t i = 0; i < tokens_.size() && i < 2; ++i) {
            if (!text::parseInt(tokens_[i], size[i])) {
                return error(f, "image size: width and height must be integers, got " +
                                    text::quoted(tokens_[i]));
            }
        }
        if (tokens_.size() != 2) {
            return error(
                f, "image size needs 2 integers (w h), got " + std::to_string(tokens_.size()));
        }
        static const char* const which[] = {"width", "height"};
        for (int i = 0; i < 2; ++i) {
            if (size[i] < 1 || size[i] > kMaxImageSide) {
                return error(f, "image " + std::string(which[i]) + " must be 1 to " +
                                    std::to_string(kMaxImageSide) + " pixels, got " +
                                    std::to_string(size[i]));
            }
        }
        camera.width = static_cast<int>(size[0]);
        camera.height = static_cast<int>(size[1]);
        return std::nullopt;
    }

    std::optional<Error> light(const Field& f, Light& light) {
        double v[5];
        if (auto e = numbers(f, "point light", "x y z Id | x y z w Id", 4, 5, v)) return e;
        // 4 numbers: a point (w = 1); 5: homogeneous, w = 0 a direction.
        const bool homogeneous = tokens_.size() == 5;
        const double w = homogeneous ? v[3] : 1.0;
        const double intensity = homogeneous ? v[4] : v[3];
        if (!(intensity >= 0.0)) {
            return error(f, "light intensity Id must be >= 0, got " + number(intensity));
        }
        if (w == 0.0 && v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) {
            return error(f, "a directional light (w = 0) needs a non-zero direction");
        }
        light.position = {v[0], v[1], v[2], w};
        light.intensity = intensity;
        return std::nullopt;
    }

    const std::string& fileName_;
    std::vector<std::string_view> tokens_;
};

Result<ParsedScene> parseWithLines(std::string_view text, const std::string& fileName) {
    return SceneParser(fileName).parse(text);
}

}  // namespace

Result<Scene> parseScene(std::string_view text, const std::string& fileName) {
    auto parsed = parseWithLines(text, fileName);
    if (!parsed) return parsed.error();
    return std::move(parsed->scene);
}

std::string resolveScenePath(const std::string& sceneFile, const std::string& named) {
    if (named.empty()) return {};
    namespace fs = std::filesystem;
    std::string portable = named;
    std::replace(portable.begin(), portable.end(), '\\', '/');  // written on Windows
    const fs::path dir = fs::path(sceneFile).parent_path();
    const fs::path path(portable);
    for (const fs::path& candidate : {dir / path, path, dir / path.filename()}) {
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
    }
    return {};
}

Result<Scene> loadScene(const std::string& path, const LoadControl* control) {
    io::ProgressMeter meter(control);
    if (meter.cancelled()) return io::ProgressMeter::cancelledError(path);
    auto text = text::readFile(path);
    if (!text) return text.error();
    auto parsed = parseWithLines(*text, path);
    if (!parsed) return parsed.error();
    Scene& scene = parsed->scene;
    static const std::string where =
        " (looked next to the scene file, in the current folder, and for the bare file name next "
        "to the scene file)";

    // The texture is checked first: it is cheap, and the mesh may take a while to load.
    if (!scene.texturePath.empty()) {
        const std::string texture = resolveScenePath(path, scene.texturePath);
        if (texture.empty()) {
            return Error{{path, parsed->textureLine},
                         "texture file " + text::quoted(scene.texturePath, std::string::npos) +
                             " not found" + where};
        }
        scene.texturePath = texture;
    }
    const std::string meshFile = resolveScenePath(path, scene.meshPath);
    if (meshFile.empty()) {
        return Error{
            {path, parsed->meshLine},
            "mesh file " + text::quoted(scene.meshPath, std::string::npos) + " not found" + where};
    }
    const bool textured = !scene.texturePath.empty();
    // The mesh is most of the work; a texture's decoding is the rest.
    const float meshShare = textured ? 0.9f : 0.97f;
    const LoadControl meshControl = meter.sub(0.0f, meshShare);
    auto mesh = loadMesh(meshFile, control ? &meshControl : nullptr);
    if (!mesh) return mesh.error();  // keeps the mesh file's own name and line
    scene.meshPath = meshFile;
    scene.mesh = std::make_shared<const Mesh>(std::move(*mesh));

    // The scene's own texture wins over the OBJ's map_Kd (spec §3).
    const LoadControl textureControl = meter.sub(meshShare, 1.0f);
    const LoadControl* const texturing = control ? &textureControl : nullptr;
    if (!scene.texturePath.empty()) {
        auto texture = loadTexture(scene.texturePath, texturing);
        if (!texture && texture.error().cancelled) return texture.error();
        if (!texture) {
            return Error{{path, parsed->textureLine},
                         "cannot load texture: " + texture.error().what()};
        }
        scene.texture = std::make_shared<const Texture>(std::move(*texture));
    } else if (!scene.mesh->texturePath.empty()) {
        auto texture = loadTexture(scene.mesh->texturePath, texturing);
        if (!texture && texture.error().cancelled) return texture.error();
        if (!texture) {
            return Error{
                {meshFile, 0},
                "cannot load the map_Kd texture of its material: " + texture.error().what()};
        }
        scene.texturePath = scene.mesh->texturePath;
        scene.texture = std::make_shared<const Texture>(std::move(*texture));
    }
    meter.finish();
    return std::move(parsed->scene);
}

Status loadSceneTexture(Scene& scene, const std::string& path, const LoadControl* control) {
    auto texture = loadTexture(path, control);
    if (!texture) return texture.error();
    scene.texture = std::make_shared<const Texture>(std::move(*texture));
    scene.texturePath = path;
    return {};
}

}  // namespace facet
