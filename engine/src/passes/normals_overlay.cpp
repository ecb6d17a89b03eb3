// The normals display (see normals_overlay.hpp).

#include "passes/normals_overlay.hpp"

#include <cstddef>

#include "facet/camera.hpp"
#include "facet/normals.hpp"
#include "lines/lines_points.hpp"
#include "pipeline/vertex_stage.hpp"

namespace facet::detail {

void NormalsOverlay::draw(const Mesh& mesh, std::span<const glm::vec3> normals,
                          const Camera& camera, const RenderSettings& settings, float nearPlane,
                          Framebuffer& frame, RenderStats& stats) {
    const float length = settings.normalLength > 0.0 ? static_cast<float>(settings.normalLength)
                                                     : normalDisplayLength(mesh);
    const glm::dmat4 clipFromWorldD = clipFromWorld(camera);
    clip_.clear();
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (normals[i] == glm::vec3(0.0f)) continue;  // no face: no direction to show
        const glm::vec3 p = mesh.positions[i];
        clip_.push_back(clipPoint(clipFromWorldD, p));
        clip_.push_back(clipPoint(clipFromWorldD, p + length * normals[i]));
    }
    edges_.resize(clip_.size());
    for (std::size_t i = 0; i < edges_.size(); ++i) edges_[i] = static_cast<std::uint32_t>(i);
    const DrawInput segments{.clip = clip_, .nearPlane = nearPlane};
    const DrawConstants red{&whiteTexture(), {}, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    // Simple overwrites; every other shader keeps the depth test.
    constexpr Interp P = Interp::Perspective;
    constexpr TextureFilter N = TextureFilter::Nearest;
    RenderStats lines;
    if (settings.shader == ShaderKind::Simple)
        drawLines<Variant<ShaderKind::Simple, P, false, false, false, N, false>>(segments, edges_,
                                                                                 frame, red, lines);
    else
        drawLines<Variant<ShaderKind::Painter, P, false, false, false, N, false>>(
            segments, edges_, frame, red, lines);
    stats.normalsDrawn = lines.linesDrawn;
    stats.fragments += lines.fragments;
}

}  // namespace facet::detail
