#include "facet/limits.hpp"

#include <algorithm>

#include "facet/multisample.hpp"

namespace facet {
namespace {

// "4.0 GiB": one decimal is enough to see how far over a limit a request is.
std::string gib(std::uint64_t bytes) {
    const std::uint64_t tenths = (bytes * 10 + (std::uint64_t{1} << 29)) >> 30;
    return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " GiB";
}

}  // namespace

std::uint64_t frameBytes(int width, int height, int supersample, int msaa) {
    // Colour (4 bytes) and depth (4 bytes) per pixel; a supersampled frame is drawn at n x n
    // the size and then resolved into a frame of the asked size.
    const auto pixels = static_cast<std::uint64_t>(std::max(width, 0)) *
                        static_cast<std::uint64_t>(std::max(height, 0));
    const auto n = static_cast<std::uint64_t>(std::max(supersample, 1));
    // Multisampling adds its per-sample buffer (colour and depth per sample) at the size it
    // is drawn: n x n the frame when supersampled too.
    const auto samples = static_cast<std::uint64_t>(msaaSamples(msaa));
    const std::uint64_t perSample = samples > 1 ? n * n * samples : 0;
    return 8 * pixels * ((n > 1 ? n * n + 1 : 1) + perSample);
}

std::optional<std::string> frameMemoryProblem(int width, int height, int supersample, int msaa) {
    const std::uint64_t bytes = frameBytes(width, height, supersample, msaa);
    if (bytes <= kMaxFrameBytes) return std::nullopt;
    const int n = std::max(supersample, 1);
    const int samples = msaaSamples(msaa);
    return "a " + std::to_string(width) + "x" + std::to_string(height) + " frame" +
           (n > 1 ? " at " + std::to_string(n) + "x" + std::to_string(n) + " supersampling" : "") +
           (samples > 1
                ? std::string(n > 1 ? " and" : " at") + " MSAA " + std::to_string(samples) + "x"
                : "") +
           " needs " + gib(bytes) + " of frame buffers; the limit is " + gib(kMaxFrameBytes) +
           " (choose a smaller size, supersampling or MSAA)";
}

std::optional<std::string> meshMemoryProblem(std::uint64_t vertices, std::uint64_t triangles) {
    // Counts come from file headers: divide instead of multiplying so nothing overflows.
    if (vertices <= kMaxMeshBytes / kBytesPerVertex &&
        triangles <= kMaxMeshBytes / kBytesPerTriangle &&
        vertices * kBytesPerVertex + triangles * kBytesPerTriangle <= kMaxMeshBytes) {
        return std::nullopt;
    }
    return std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
           " triangles would need more than the " + gib(kMaxMeshBytes) + " a mesh may take (" +
           std::to_string(kBytesPerVertex) + " bytes per vertex, " +
           std::to_string(kBytesPerTriangle) + " per triangle)";
}

Status checkImageSize(int width, int height, int supersample, int msaa) {
    if (width < 1 || width > kMaxImageSide || height < 1 || height > kMaxImageSide)
        return Error{{},
                     "image size must be 1.." + std::to_string(kMaxImageSide) +
                         " pixels in each direction, got " + std::to_string(width) + "x" +
                         std::to_string(height)};
    if (auto problem = frameMemoryProblem(width, height, supersample, msaa))
        return Error{{}, *problem};
    return {};
}

Status checkReferenceImage(int width, int height, int samples) {
    if (width < 1 || height < 1)
        return Error{{},
                     "image size must be at least 1x1 pixels, got " + std::to_string(width) + "x" +
                         std::to_string(height)};
    // Sides up to a ground truth's 16 × kMaxImageSide: the products below stay far from 2^64.
    const std::uint64_t bytes =
        static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) *
        static_cast<std::uint64_t>(std::max(samples, 1)) * kReferenceBytesPerSample;
    if (bytes <= kMaxReferenceBytes) return {};
    return Error{{},
                 "a reference image of " + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels" +
                     (samples > 1 ? " with " + std::to_string(samples) + " samples each" : "") +
                     " needs " + gib(bytes) + "; the limit is " + gib(kMaxReferenceBytes) +
                     " (choose a smaller size or fewer samples)"};
}

}  // namespace facet
