#pragma once
// The resource limits for hostile or mistaken input, in one place (spec §12). Each is
// checked before the memory it guards is allocated, and the error names the limit.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "facet/error.hpp"

namespace facet {

/// Largest image side in pixels (spec §1): scene images, textures, --size, windows.
inline constexpr int kMaxImageSide = 16384;

/// Largest input file (scene, OFF, OBJ, MTL, texture) read into memory: 1 GiB.
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t{1} << 30;

/// Largest memory a frame's buffers may take (colour and depth, the supersampled frame and its
/// resolved copy, the per-sample buffer of multisampling): 4 GiB. A 16384x16384 frame takes 2 GiB;
/// 16384x16384 at 2x2 takes 10 GiB.
inline constexpr std::uint64_t kMaxFrameBytes = std::uint64_t{4} << 30;

/// Largest memory a mesh may take once loaded (its streams, and what a draw derives per vertex
/// and per triangle): 8 GiB.
inline constexpr std::uint64_t kMaxMeshBytes = std::uint64_t{8} << 30;

/// Bytes a mesh vertex costs at most: position, colour, normal (12 each), uv (8), and per draw
/// its clip position (16) and lit colour (12).
inline constexpr std::uint64_t kBytesPerVertex = 72;

/// Bytes a triangle costs: its three indices.
inline constexpr std::uint64_t kBytesPerTriangle = 12;

/// Most corners of one OBJ face. Fanning costs linear time, so this only refuses the absurd:
/// modelled polygons (disc caps, outlines) have at most a few thousand corners.
inline constexpr std::size_t kMaxObjFaceCorners = 65536;

/// Most scans a progressive JPEG may have. Each costs a pass over the image, so a file of
/// thousands of tiny scans could keep the decoder busy for minutes; encoders write about 10
/// (libjpeg's default progression), libjpeg-turbo suggests a limit of 500 for its own tools.
inline constexpr int kMaxJpegScans = 100;

/// Bytes of a frame's buffers at `width` x `height` with `supersample` x `supersample` samples
/// and `msaa` multisamples per (supersampled) pixel, whose per-sample buffer comes on top.
std::uint64_t frameBytes(int width, int height, int supersample, int msaa = 1);

/// Why a frame cannot be rendered within kMaxFrameBytes, or nothing when it can.
std::optional<std::string> frameMemoryProblem(int width, int height, int supersample, int msaa = 1);

/// Why a mesh of `vertices` and `triangles` would exceed kMaxMeshBytes, or nothing.
std::optional<std::string> meshMemoryProblem(std::uint64_t vertices, std::uint64_t triangles);

/// An image of width × height (1…kMaxImageSide each) whose buffers at `supersample` and `msaa`
/// fit in kMaxFrameBytes; otherwise the error says which limit and the numbers.
Status checkImageSize(int width, int height, int supersample, int msaa = 1);

/// Largest memory the reference renderer's image may take (spec §12): 8 GiB. It keeps colour and
/// depth in double per sample, so a ground truth at 8×8 samples of a 1280×720 frame takes 2 GiB.
inline constexpr std::uint64_t kMaxReferenceBytes = std::uint64_t{8} << 30;
/// Bytes the reference renderer keeps per sample: colour (three doubles), depth (a double) and
/// the ambiguity flag.
inline constexpr std::uint64_t kReferenceBytesPerSample = 3 * 8 + 8 + 1;
/// Why a reference image of width × height pixels with `samples` samples each cannot be made
/// within kMaxReferenceBytes (or a side below 1), or success.
Status checkReferenceImage(int width, int height, int samples = 1);

}  // namespace facet
