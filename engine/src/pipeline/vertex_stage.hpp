#pragma once
// The vertex stage of a frame: every position to clip space, the vertex normals (cached while
// the mesh is unchanged), and Gouraud's lit colour per vertex. Its buffers are kept between
// frames so a steady frame allocates nothing.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/draw.hpp"
#include "facet/lighting.hpp"
#include "facet/mesh.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::detail {

/// A world point in clip space, computed in double and rounded once: the fast path's clip
/// coordinates are then the reference's, to float rounding. A float matrix product lost the
/// camera-space depth to cancellation when the eye was a near distance or two from a surface
/// far from the world origin (a surface crossed the near plane a pixel off), and its per-vertex
/// rounding bent tiny silhouette triangles by more than the 1/256 px the rules allow.
inline glm::vec4 clipPoint(const glm::dmat4& clipFromWorld, const glm::vec3& p) {
    return glm::vec4(clipFromWorld * glm::dvec4(glm::dvec3(p), 1.0));
}

/// The per-vertex work of the fast path.
class VertexStage {
  public:
    /// Clip coordinates of every position of `mesh`, and into `bounds` computeBounds() of the
    /// mesh, from the same pass over the positions (the same bounds, on every thread count).
    std::span<const glm::vec4> transform(const Mesh& mesh, const glm::dmat4& clipFromWorld,
                                         int threads, Bounds& bounds);

    /// Unit (or zero) vertex normals of `mesh`; recomputed only when its positions or indices
    /// change.
    std::span<const glm::vec3> normals(const Mesh& mesh);

    /// Gouraud: the lighting formula once per vertex in world space, the lit colour of each
    /// vertex (white where the mesh has no colours). Needs normals() of the same mesh first.
    std::span<const glm::vec3> gouraud(const Mesh& mesh, const glm::vec3& eye,
                                       const FastLighting& lighting, int threads);

  private:
    std::vector<glm::vec4> clip_;
    std::vector<Bounds> boundsParts_;  // transform()'s bounds, one part per thread
    std::vector<glm::vec3> litColors_;
    std::vector<glm::vec3> normals_;
    std::uint64_t normalsFingerprint_ = 0;  // of the mesh normals_ belong to
    std::vector<glm::dvec4> normalSums_;
};

/// The draw input of a frame of `scene` seen by `camera`: the vertex stage run for only the
/// streams the settings need (clip positions; Gouraud colours, Phong normals and positions,
/// uvs). `vertexNormals` receives the normals when lighting or the normals display needs them.
/// The spans point into `stage` and the mesh.
DrawInput prepareDrawInput(VertexStage& stage, const Scene& scene, const Camera& camera,
                           const RenderSettings& settings, int threads,
                           std::span<const glm::vec3>& vertexNormals);

}  // namespace facet::detail
