// The vertex stage (see vertex_stage.hpp).

#include "pipeline/vertex_stage.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

#include <omp.h>

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
                                                  int threads, Bounds& bounds) {
    const auto& positions = mesh.positions;
    clip_.resize(positions.size());
    bounds = Bounds{};
    if (positions.empty()) return clip_;
    // The bounds in the same pass: computeBounds() on the calling thread cost as much as a
    // thread's share of the transform (the 2M-triangle sphere: 21 M instructions a frame), serial.
    const auto vertexCount = static_cast<std::ptrdiff_t>(positions.size());
    const int parts = vertexCount > kParallelVertices ? std::max(1, threads) : 1;
    constexpr float kInf = std::numeric_limits<float>::infinity();
    boundsParts_.assign(static_cast<std::size_t>(parts), Bounds{glm::vec3(kInf), glm::vec3(-kInf)});
#pragma omp parallel num_threads(parts)
    {
        const int team = omp_get_num_threads();
        for (int part = omp_get_thread_num(); part < parts; part += team) {
            const std::ptrdiff_t begin = vertexCount * part / parts;
            const std::ptrdiff_t end = vertexCount * (part + 1) / parts;
            Bounds b = boundsParts_[static_cast<std::size_t>(part)];
            for (std::ptrdiff_t i = begin; i < end; ++i) {
                const glm::vec3& p = positions[static_cast<std::size_t>(i)];
                clip_[static_cast<std::size_t>(i)] = clipPoint(clipFromWorld, p);
                b.min = glm::min(b.min, p);
                b.max = glm::max(b.max, p);
            }
            boundsParts_[static_cast<std::size_t>(part)] = b;
        }
    }
    // computeBounds() starts from the first position and folds glm::min and max over all:
    // a NaN is then kept only where the first position has it, and the parts (started from
    // ±inf, which every other value replaces) give the same least and greatest values.
    Bounds b = boundsParts_[0];
    for (std::size_t part = 1; part < boundsParts_.size(); ++part) {
        b.min = glm::min(b.min, boundsParts_[part].min);
        b.max = glm::max(b.max, boundsParts_[part].max);
    }
    bounds.min = glm::min(positions.front(), b.min);
    bounds.max = glm::max(positions.front(), b.max);
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
    // The mesh's bounds (for the near plane when the settings leave it open) come from the
    // transform's pass over the positions.
    Bounds bounds;
    DrawInput input{.clip = stage.transform(mesh, clipFromWorld(camera), threads, bounds),
                    .colors = mesh.colors,
                    .indices = mesh.indices,
                    .nearPlane = static_cast<float>(resolveNearPlane(settings, bounds)),
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
