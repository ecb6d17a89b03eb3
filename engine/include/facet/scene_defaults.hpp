#pragma once
// What a scene opens with (spec §9): one rule for the CLI, the viewer and library users,
// whichever route opened the file (a .scene, a bare mesh, a scene saved from a bare mesh).

#include "facet/mesh.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

/// True when the mesh's per-vertex colours differ somewhere (the course's coloured meshes); a
/// mesh without colours, or with every vertex the same colour, is uncoloured.
bool hasVaryingColors(const Mesh& mesh);

/// Sets shader, combine and lighting to what the scene has, leaving every other field alone:
/// texture and uvs on an uncoloured mesh: texture shader, combine, Gouraud (Spot); texture and
/// uvs on a coloured mesh: texture shader, no combine, unlit (the texel alone, as the course
/// shows its brick wall); no texture, uncoloured: painter, Gouraud (never a white silhouette);
/// no texture, coloured: painter, unlit (as the course shows its scenes). Explicit options are
/// applied after this and override it.
void applyOpeningSettings(const Scene& scene, RenderSettings& settings);

}  // namespace facet
