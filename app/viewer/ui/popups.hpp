#pragma once
// The ImGui panels. Each edits the App's model (scene fields, settings, view) in place; the
// frame rendered right after shows the change, with nothing reloaded.

namespace facet::view {

struct App;

/// Scene: path field, a folder's .scene files, recent files; mesh facts.
void scenePanel(App& app);
/// Texture: the current image and a path field to load another.
void texturePanel(App& app);
/// Render: mode, shader, interpolation, filter, lighting, combine, normals, culling, background.
void renderPanel(App& app);
/// Camera: yaw, pitch, distance, focal length, target, reset, and what resizing does.
void cameraPanel(App& app);
/// Light (position, point or directional, Ia, Id) and material (Ka, Kd, Ks, s).
void lightPanel(App& app);
/// Compare: the two interpolations, split or difference, divider, error numbers.
void comparePanel(App& app);
/// Compare's "Against the ground truth": samples, Measure, progress, the methods' table.
void accuracySection(App& app);
/// Screenshot: folder, whole window too, save button.
void screenshotPanel(App& app);
/// Stats panel: fps, frame time split (the engine's stages from the same frame as its total),
/// history plot, what the engine drew.
void statsPanel(App& app);
/// The ground-truth table in a window of its own (large: eight columns), when open.
void accuracyWindow(App& app);
/// Labels over the Compare view naming each side.
void compareOverlay(App& app);
/// The modal error popup, when one is pending or open.
void errorPopup(App& app);

}  // namespace facet::view
