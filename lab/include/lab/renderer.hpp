#pragma once
// The lab renderer: the course's pipeline (its Renderer class) run through the steps of
// steps.hpp, the student's or the solution's, whichever the build linked. Plain loops over
// vertices, edges, triangles and fragments in double precision, readable in an hour; it draws a
// facet::Scene into a facet::Framebuffer so the CLI and the viewer can show it, compare it with
// the engine's picture and save it.

#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"
#include "lab/steps.hpp"

namespace lab {

/// What one render did.
struct Report {
    std::vector<Step> notStarted;  ///< the steps whose stub ran, in the course's order
    std::size_t fragments = 0;     ///< fragments the rasterizers produced
};

/// "" when the lab pipeline draws `settings` as the engine would, else what it does instead
/// (e.g. the Phong lighting drawn as Gouraud), one sentence per setting.
std::string differences(const facet::RenderSettings& settings);

/// The course's Renderer. Keeps its buffers and the texture converted to lab::Texture between
/// frames.
struct Renderer {
    Canvas canvas;
    std::vector<Fragment> fragments;              ///< one face's fragments, reused
    const facet::Texture* textureFrom = nullptr;  ///< the facet texture `texture` was made from
    Texture texture;

    /// Renders `scene` with `settings` into `frame` (resized to the camera's image).
    Report render(const facet::Scene& scene, const facet::RenderSettings& settings,
                  facet::Framebuffer& frame);
};

}  // namespace lab
