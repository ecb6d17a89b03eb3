// The vertex stage (see vertex_stage.hpp).

#include "pipeline/vertex_stage.hpp"

#include <cstddef>

#include "facet/camera.hpp"
#include "facet/normals.hpp"
#include "pipeline/variants.hpp"
#include "scene/fingerprint.hpp"
#include "scene/scratch.hpp"
#include "shading/fast_lighting.hpp"

namespace facet::detail {
namespace {

/// Below this many vertices the per-vertex loops stay on one thread: waking the others costs
/// more than the work.
constexpr std::ptrdiff_t kParallelVertices = 16384;

}  // namespace

std::span<const glm::vec4> VertexStage::transform(const Mesh& mesh, const glm::dmat4& clipFromWorld,
                                                  int threads) {
    const auto& positions = mesh.positions;
    clip_.resize(positions.size());
    const auto vertexCount = static_cast<std::ptrdiff_t>(positions.size());
#pragma omp parallel for num_threads(threads) if (vertexCount > kParallelVertices)
    for (std::ptrdiff_t i = 0; i < vertexCount; ++i)
        clip_[i] = clipPoint(clipFromWorld, positions[i]);
    return clip_;
}

std::span<const glm::vec3> VertexStage::normals(const Mesh& mesh) {
    const std::uint64_t h = fingerprint(
        std::span(mesh.normals),
        fingerprint(std::span(mesh.positionIds),
                    fingerprint(std::span(mesh.indices), fingerprint(std::span(mesh.positions)))));
    if (h != normalsFingerprint_ || normals_.size() != mesh.positions.size()) {
        computeVertexNormals(mesh, normals_, normalSums_);
        normalsFingerprint_ = h;
    }
    return normals_;
}

std::span<const glm::vec3> VertexStage::gouraud(const Mesh& mesh, const glm::vec3& eye,
                                                const FastLighting& lighting, int threads) {
    const auto& positions = mesh.positions;
    litColors_.resize(positions.size());
    const auto vertexCount = static_cast<std::ptrdiff_t>(positions.size());
#pragma omp parallel for num_threads(threads) if (vertexCount > kParallelVertices)
    for (std::ptrdiff_t i = 0; i < vertexCount; ++i) {
        const glm::vec3 rgb = mesh.hasColors() ? mesh.colors[i] : glm::vec3(1.0f);
        litColors_[i] = shade(rgb, lightIntensity(positions[i], normals_[i], eye, lighting));
    }
    return litColors_;
}

DrawInput prepareDrawInput(VertexStage& stage, const Scene& scene, const Camera& camera,
                           const RenderSettings& settings, int threads,
                           std::span<const glm::vec3>& vertexNormals) {
    const Mesh& mesh = *scene.mesh;
    DrawInput input{.clip = stage.transform(mesh, clipFromWorld(camera), threads),
                    .colors = mesh.colors,
                    .indices = mesh.indices,
                    .nearPlane = static_cast<float>(resolveNearPlane(settings, mesh)),
                    .texture = scene.texture.get(),
                    .lighting = prepareLighting(scene.lighting),
                    .eye = glm::vec3(camera.eye)};
    // Lighting only changes colour: a depth image or a bare texel needs no normals.
    const bool lit = settings.lighting != Lighting::Off && usesColor(settings);
    vertexNormals = {};
    if (lit || settings.showNormals) vertexNormals = stage.normals(mesh);
    if (lit && settings.lighting == Lighting::Gouraud)
        input.colors = stage.gouraud(mesh, input.eye, input.lighting, threads);
    if (lit && settings.lighting == Lighting::Phong) {
        input.normals = vertexNormals;
        input.positions = mesh.positions;
    }
    if (settings.shader == ShaderKind::Texture) input.uvs = mesh.uvs;
    return input;
}

}  // namespace facet::detail
