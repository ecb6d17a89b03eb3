#include "facet/multisample.hpp"

namespace facet {
namespace {

// D3D11_STANDARD_MULTISAMPLE_PATTERN (Direct3D 11 docs, "D3D11_STANDARD_MULTISAMPLE_QUALITY_
// LEVELS"), in 1/16 px from the pixel centre, y down; equal to Vulkan's standard sample
// locations. Every point lies in [-8, 7]/16, inside the pixel.
constexpr SampleOffset kOne[] = {{0, 0}};
constexpr SampleOffset kTwo[] = {{4, 4}, {-4, -4}};
constexpr SampleOffset kFour[] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
constexpr SampleOffset kEight[] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                   {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};

}  // namespace

int msaaSamples(int requested) {
    if (requested >= 8) return 8;
    if (requested >= 4) return 4;
    if (requested >= 2) return 2;
    return 1;
}

std::span<const SampleOffset> samplePositions(int count) {
    switch (msaaSamples(count)) {
        case 2:
            return kTwo;
        case 4:
            return kFour;
        case 8:
            return kEight;
        default:
            return kOne;
    }
}

SampleBlock sampleBlock(int count) {
    const int n = msaaSamples(count);
    return {n == 1 ? 1 : (n == 8 ? 4 : 2), n >= 4 ? 2 : 1};
}

}  // namespace facet
