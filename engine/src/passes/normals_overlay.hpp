#pragma once
// The normals display (RenderSettings::showNormals): a red segment per vertex normal, drawn
// after the main pass with the depth test of the frame's shader, so hidden normals stay hidden.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/draw.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::detail {

/// Draws the segments; keeps its buffers between frames.
class NormalsOverlay {
  public:
    /// Draws a segment from each vertex of `mesh` along its (non-zero) normal; adds the
    /// segments and their fragments to `stats`.
    void draw(const Mesh& mesh, std::span<const glm::vec3> normals, const Camera& camera,
              const RenderSettings& settings, float nearPlane, Framebuffer& frame,
              RenderStats& stats);

  private:
    std::vector<glm::vec4> clip_;  // two clip points per segment
    std::vector<std::uint32_t> edges_;
};

}  // namespace facet::detail
