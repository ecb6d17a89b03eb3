#pragma once
// The viewer's document: the loaded scene, the user's view of it and the render settings, with
// the operations the panels and the mouse perform. No window and no OpenGL, so tests drive it
// directly (a Ks change shows in the next frame; a malformed scene keeps the old one).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "load_job.hpp"
#include "orbit.hpp"
#include "renderer_choice.hpp"
#include "settings_map.hpp"

namespace facet::view {

/// Most entries kept in ViewerModel::recent.
inline constexpr std::size_t kMaxRecent = 10;

/// What "unsaved changes" compares: the view, the light, the material, the settings and the
/// texture (not the window's size, which a saved scene does not need to keep).
struct DocumentState {
    bool orbitMoved = false;  ///< false: the orbit fields below are left at zero
    glm::dvec3 target{0.0};
    glm::dvec3 vertical{0.0};
    double yaw = 0.0;
    double pitch = 0.0;
    double distance = 0.0;
    double focal = 0.0;
    LightingParams lighting;
    RenderSettings settings;
    std::string texturePath;

    /// Every field equal.
    bool operator==(const DocumentState&) const = default;
};

/// Scene, view and settings, edited in place between frames.
struct ViewerModel {
    Scene scene;         ///< what is drawn; scene.camera is rewritten by prepareFrame()
    Camera sceneCamera;  ///< the camera as the scene file gave it ("reset")
    Orbit orbit;         ///< the user's view around the look-at point
    bool orbitMoved =
        false;             ///< false: the scene's own pose bit for bit (frames equal facet render)
    double focal = 512.0;  ///< focal length in pixels for the scene's image size
    RenderSettings settings;
    RendererChoice rendererChoice = RendererChoice::Cpu;  ///< who draws: engine, twin or both
    SizePolicy sizePolicy = SizePolicy::FollowWindow;
    std::vector<std::string> recent;  ///< scene and mesh files opened, most recent first
    std::string recentFile;           ///< where `recent` is kept across runs; empty: not kept
    bool bareMesh = false;            ///< the scene was made for a bare mesh (spec §3b)
    UpAxis up = UpAxis::Y;            ///< the world axis a bare mesh opens with up (--up)
    std::uint64_t sceneVersion = 0;   ///< counts loads, so copies know when the mesh changed

    DocumentState saved;  ///< the state when the scene was opened or last saved

    Renderer renderer;  ///< keeps its scratch buffers from frame to frame
    Framebuffer frame;  ///< the last frame rendered
    RenderStats stats;  ///< what the last render did
    /// Why the last render drew nothing (checkFrame's message: the camera, the frame's size or
    /// memory), shown over the image; empty when it drew.
    std::string refused;

    /// Loads a scene file or a bare mesh (a scene of kBareMeshWidth × kBareMeshHeight); on
    /// success it replaces the scene as adopt() does; on failure nothing changes and the error
    /// names the file and line.
    Status load(const std::string& path);

    /// Takes a loaded scene: resets the view, picks the settings that show what the scene has
    /// (applyOpeningSettings, spec §9) and puts the file first in the recent list.
    void adopt(LoadedScene loaded);

    /// Writes what is shown as a .scene file; it joins the recent list. The camera keeps the
    /// scene's image size (the view, focal length and pose shown, as --keep-scene-size draws
    /// them), or with `windowSize` is the last prepareFrame()'s, so the file renders that frame.
    Status saveScene(const std::string& path, bool windowSize = false);

    /// The user's camera at the scene's own image size (what saveScene writes by default).
    Camera userCamera() const;

    /// The document's state now, for unsaved().
    DocumentState documentState() const;

    /// The current state becomes the saved one (after opening, options and saving).
    void markSaved();

    /// True when camera, light, material, settings or texture changed since markSaved().
    bool unsaved() const;

    /// Puts `path` first in the recent list and writes the list to recentFile.
    void rememberFile(const std::string& path);

    /// Replaces the scene's texture with an image file and picks the settings that show it
    /// (applyOpeningSettings: every route to a texture gives the same picture); on failure
    /// nothing changes.
    Status loadTexture(const std::string& path);

    /// How a bare mesh is opened: its image size and `up`.
    OpenOptions openOptions() const;

    /// Makes `axis` the world direction shown up and orbited about (spec §3b): a bare
    /// mesh is framed again for it (camera and light, as if opened with --up); a .scene keeps
    /// the view shown and turns the orbit's vertical to the axis.
    void setUpAxis(UpAxis axis);

    /// The axis the orbit turns about, when it is a world axis (either sign); nullopt otherwise.
    std::optional<UpAxis> orbitAxis() const;

    /// Back to the scene file's camera (pose and focal length).
    void resetCamera();

    /// Mouse: turn, pan and zoom the orbit (pixels in frame units, wheel steps).
    void rotate(double dx, double dy);
    void pan(double dx, double dy);
    void zoom(double steps);

    /// Call after editing `orbit` fields directly (sliders): clamps and marks the view moved.
    void orbitEdited();

    /// The camera of the next frame for a window (framebuffer) of the given size; also written
    /// into scene.camera.
    const Camera& prepareFrame(int windowWidth, int windowHeight);

    /// Renders the scene with the camera set by prepareFrame() into `frame`.
    const Framebuffer& render();
};

}  // namespace facet::view
