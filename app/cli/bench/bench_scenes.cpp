#include "bench_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/scene_io.hpp"

namespace facet::app {
namespace {

constexpr int kCheckerSize = 512;
constexpr int kCheckerCell = 32;

/// Light and material shared by the generated scenes: a highlight somewhere in view, so Phong
/// does real work on most pixels.
void lightGenerated(Scene& scene, const glm::dvec4& light) {
    scene.lighting = {0.4, Light{light, 1.0}, Material{0.5, 0.7, 0.3, 20.0}};
}

}  // namespace

std::shared_ptr<const Texture> checkerTexture() {
    // Built once: every generated case shares the same immutable texture.
    static const std::shared_ptr<const Texture> texture = [] {
        std::vector<std::uint32_t> px(static_cast<std::size_t>(kCheckerSize) * kCheckerSize);
        for (int y = 0; y < kCheckerSize; ++y)
            for (int x = 0; x < kCheckerSize; ++x) {
                const bool dark = ((x / kCheckerCell) + (y / kCheckerCell)) % 2 != 0;
                const std::uint32_t r = static_cast<std::uint32_t>(x * 255 / (kCheckerSize - 1));
                const std::uint32_t g = static_cast<std::uint32_t>(y * 255 / (kCheckerSize - 1));
                const std::uint32_t k = dark ? 90u : 255u;
                px[static_cast<std::size_t>(y) * kCheckerSize + static_cast<std::size_t>(x)] =
                    packRgba(r * k / 255u, g * k / 255u, 160u * k / 255u);
            }
        Result<Texture> t =
            Texture::fromRgba(kCheckerSize, kCheckerSize, std::move(px), "checker (generated)");
        return std::make_shared<const Texture>(std::move(t).value());
    }();
    return texture;
}

Scene sphereScene(int triangles, int width, int height) {
    // makeUvSphere(r, 2r) has 2·r·2r = 4r² triangles (those at the poles degenerate).
    const int rings = std::max(2, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    Scene scene;
    scene.path = "sphere (generated)";
    scene.meshPath = scene.path;
    scene.mesh = std::make_shared<const Mesh>(makeUvSphere(rings, 2 * rings));
    scene.texture = checkerTexture();
    scene.texturePath = scene.texture->name();
    const glm::dvec3 eye(0.0, 0.6, -3.0);
    const double d = glm::length(eye);
    // The unit sphere's silhouette subtends atan(1 / sqrt(d² − 1)) from the eye: 45 % of the
    // height on either side of the centre.
    scene.camera = Camera{
        eye,   glm::dvec3(0.0), glm::dvec3(0.0, -1.0, 0.0), 0.45 * height * std::sqrt(d * d - 1.0),
        width, height};
    lightGenerated(scene, glm::dvec4(-2.0, 3.0, -4.0, 1.0));
    return scene;
}

Scene overdrawScene(int layers, int width, int height) {
    Scene scene;
    scene.path = "overdraw quads (generated)";
    scene.meshPath = scene.path;
    const double focal = 0.5 * width;  // 90° horizontal field of view
    scene.camera =
        Camera{glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.0, -1.0, 0.0), focal, width,
               height};
    Mesh m;
    const float aspect = static_cast<float>(height) / static_cast<float>(width);
    // Back to front: the farthest layer is drawn first, every later one is nearer and wins.
    for (int layer = layers - 1; layer >= 0; --layer) {
        const float z = 2.0f + static_cast<float>(layer);
        const float hx = 1.05f * static_cast<float>(0.5 * width / focal) * z;
        const float hy = 1.05f * static_cast<float>(0.5 * height / focal) * z;
        const float du = 0.37f * static_cast<float>(layer);
        const float dv = 0.21f * static_cast<float>(layer);
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        const float corners[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
        for (const auto& c : corners) {
            m.positions.emplace_back(c[0] * hx, c[1] * hy, z);
            m.uvs.emplace_back(du + 2.0f * (c[0] + 1.0f), dv + 2.0f * aspect * (c[1] + 1.0f));
            const float t = static_cast<float>(layer) / static_cast<float>(std::max(1, layers));
            m.colors.emplace_back(0.4f + 0.6f * t, 0.9f - 0.5f * t, 0.6f);
        }
        // (a, b, c) and (a, c, d) are counter-clockwise seen from the camera: they face it.
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    scene.mesh = std::make_shared<const Mesh>(std::move(m));
    scene.texture = checkerTexture();
    scene.texturePath = scene.texture->name();
    lightGenerated(scene, glm::dvec4(1.0, 1.0, 0.0, 1.0));
    return scene;
}

Result<Scene> fileScene(const std::string& path, int width, int height) {
    Result<Scene> loaded = loadScene(path);
    if (!loaded) return loaded;
    Scene scene = std::move(loaded).value();
    if (width > 0 && height > 0) {
        // As `facet render --size`: the horizontal field of view stays.
        scene.camera = resizedCamera(scene.camera, width, height);
    }
    return scene;
}

std::string completeForTexturing(Scene& scene, const std::string& fallbackTexture) {
    std::string added;
    if (!scene.mesh->hasUvs() && scene.mesh->vertexCount() > 0) {
        Mesh m = *scene.mesh;  // shared and immutable: the uvs go on a copy
        const Bounds b = computeBounds(m);
        const glm::vec3 ext = b.max - b.min;
        // Project along the smallest axis, so the image lies on the mesh's broadest side.
        int drop = 0;
        for (int a = 1; a < 3; ++a)
            if (ext[a] < ext[drop]) drop = a;
        const int ua = drop == 0 ? 1 : 0;
        const int va = drop == 2 ? 1 : 2;
        const float scale = 4.0f / std::max({ext.x, ext.y, ext.z, 1e-12f});
        m.uvs.reserve(m.vertexCount());
        for (const glm::vec3& p : m.positions)
            m.uvs.emplace_back((p[ua] - b.min[ua]) * scale, (p[va] - b.min[va]) * scale);
        scene.mesh = std::make_shared<const Mesh>(std::move(m));
        added = "planar uvs";
    }
    if (!scene.texture) {
        if (!fallbackTexture.empty() && std::filesystem::exists(fallbackTexture) &&
            loadSceneTexture(scene, fallbackTexture)) {
            added += std::string(added.empty() ? "" : ", ") + "texture " +
                     std::filesystem::path(fallbackTexture).filename().string();
        } else {
            scene.texture = checkerTexture();
            scene.texturePath = scene.texture->name();
            added += std::string(added.empty() ? "" : ", ") + "checker texture";
        }
    }
    if (!added.empty()) added += " (added for the textured config)";
    return added;
}

}  // namespace facet::app
