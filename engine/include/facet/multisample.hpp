#pragma once
// Multisampling (RenderSettings::msaa): where the samples of a pixel are, and how a frame's
// samples are laid out in the per-sample buffer. The one table both renderers, the tests and
// the OpenGL twin's comparison read.

#include <array>
#include <span>

namespace facet {

/// A sample's offset from its pixel's centre in 1/16 px, x right and y down.
struct SampleOffset {
    int x = 0;
    int y = 0;

    /// Both coordinates equal.
    bool operator==(const SampleOffset&) const = default;
};

/// The sample counts multisampling accepts besides 1 (one sample at the centre: no MSAA).
inline constexpr std::array<int, 3> kMsaaCounts{2, 4, 8};

/// The standard sample positions for `count` samples (1, 2, 4 or 8; anything else is first
/// normalised by msaaSamples()). Source: Direct3D 11's D3D11_STANDARD_MULTISAMPLE_PATTERN table
/// (in 1/16 px from the centre); Vulkan's standard sample locations (VkPhysicalDeviceLimits::
/// standardSampleLocations) are the same points written in [0, 1) from the pixel's corner.
std::span<const SampleOffset> samplePositions(int count);

/// `requested` as a supported count: values below 2 give 1, others the largest of 2, 4, 8 not
/// above them (3 gives 2, 6 gives 4, 100 gives 8).
int msaaSamples(int requested);

/// How the per-sample buffer stores a pixel's samples: a block of `x` × `y` (2: 2×1, 4: 2×2,
/// 8: 4×2); sample k of pixel (px, py) is at (px·x + k mod x, py·y + k div x). The box-filter
/// resolve averages such blocks (the supersample resolve, one implementation).
struct SampleBlock {
    int x = 1;
    int y = 1;

    /// Both sides equal.
    bool operator==(const SampleBlock&) const = default;
};

/// The block of `count` samples (normalised by msaaSamples()).
SampleBlock sampleBlock(int count);

}  // namespace facet
