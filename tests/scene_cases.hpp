#pragma once
// The scene cases the image comparisons share (fast path vs reference, OpenGL twin vs
// reference): a case names a shared scene and the settings to draw it with; scenes are loaded
// once per test binary.

#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "shared_data.hpp"

namespace facet::test {

/// One image to compare: a scene under FACET_SHARED_DIR/data and how to draw it.
struct SceneCase {
    std::string scene;  ///< path relative to FACET_SHARED_DIR/data, without ".scene"
    DrawMode mode = DrawMode::Solid;
    ShaderKind shader = ShaderKind::Painter;
    Interp interp = Interp::Perspective;
    Lighting lighting = Lighting::Off;
    TextureFilter filter = TextureFilter::Bilinear;
    bool combine = false;
    bool cull = false;
    bool normals = false;
    double dolly = 1.0;   ///< eye moved to look + dolly·(eye − look): < 1 moves in, clips
    int subdivision = 8;  ///< N for Interp::Subdivided
};

/// A readable, gtest-safe name: scene_mode_shader_interp, then what differs from the defaults.
inline std::string caseName(const SceneCase& c) {
    std::string name = std::filesystem::path(c.scene).filename().string();
    // Appends one piece at a time: GCC 12 warns falsely (-Wrestrict) on "_" + std::string.
    for (const std::string_view part : {toString(c.mode), toString(c.shader), toString(c.interp)}) {
        name += '_';
        name += part;
    }
    if (c.interp == Interp::Subdivided) name += std::to_string(c.subdivision);
    if (c.cull) name += "_cull";
    if (c.lighting != Lighting::Off) {
        name += '_';
        name += toString(c.lighting);
    }
    if (c.shader == ShaderKind::Texture) {
        name += '_';
        name += toString(c.filter);
        if (c.combine) name += "_combine";
    }
    if (c.normals) name += "_normals";
    if (c.dolly != 1.0) name += "_dolly" + std::to_string(static_cast<int>(c.dolly * 1000));
    return name;
}

/// Names the case in gtest's messages instead of dumping its bytes.
inline void PrintTo(const SceneCase& c, std::ostream* os) {
    *os << caseName(c);
}

/// The settings the case asks for (everything else at its default).
inline RenderSettings settingsFor(const SceneCase& c) {
    RenderSettings s;
    s.mode = c.mode;
    s.shader = c.shader;
    s.interp = c.interp;
    s.subdivision = c.subdivision;
    s.lighting = c.lighting;
    s.filter = c.filter;
    s.combine = c.combine;
    s.cullBackFaces = c.cull;
    s.showNormals = c.normals;
    return s;
}

/// The .scene file of a case's scene.
inline std::string sharedScenePath(const std::string& name) {
    return sharedData(name + ".scene");
}

/// The course's textured facet names no texture; the course pairs it with the brick image.
inline std::string textureFor(const std::string& scene) {
    return scene == "course/example_textured" ? "course/brick.jpg" : "";
}

/// The scene (with its course texture), loaded once and shared by all its cases: the bunny OBJ
/// is the slow part. Null with `error` set when it cannot be loaded.
inline const Scene* loadCached(const std::string& name, std::string& error) {
    static std::map<std::string, std::unique_ptr<Scene>> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second.get();
    Result<Scene> loaded = loadScene(sharedScenePath(name));
    if (!loaded) {
        error = loaded.error().what();
        return nullptr;
    }
    auto scene = std::make_unique<Scene>(std::move(loaded).value());
    if (!textureFor(name).empty()) {
        const std::string image = sharedData(textureFor(name));
        if (Status st = loadSceneTexture(*scene, image); !st) {
            error = st.error().what();
            return nullptr;
        }
    }
    return cache.emplace(name, std::move(scene)).first->second.get();
}

/// The case's scene with its camera dollied: `loaded` itself, or a copy kept in `storage`.
inline const Scene* dollied(const Scene* loaded, double dolly, Scene& storage) {
    if (dolly == 1.0) return loaded;
    storage = *loaded;
    Camera& cam = storage.camera;
    cam.eye = cam.look + dolly * (cam.eye - cam.look);
    return &storage;
}

}  // namespace facet::test

/// Declares `const Scene* var`, the shared scene `name` (loadCached): the test ends by the one rule
/// (shared_data.hpp) when the scene's file is missing, and fails when it does not load.
#define REQUIRE_SHARED_SCENE(var, name)                                              \
    REQUIRE_SHARED_DATA(::facet::test::sharedScenePath(name));                       \
    std::string var##Error;                                                          \
    const ::facet::Scene* const var = ::facet::test::loadCached((name), var##Error); \
    ASSERT_NE(var, nullptr) << var##Error
