// Solution of step 6 (assignment section 5): the z-buffer's test and write.

#include <cstddef>

#include "lab/steps.hpp"

namespace lab {

bool DepthBuffer::testFragment(const Fragment& fragment) const {
    const glm::ivec2 p = pixelOf(fragment);
    if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height) return false;
    // Strictly nearer: on a tie the fragment drawn first stays.
    return fragment.depth < depth[static_cast<std::size_t>(p.y) * width + p.x];
}

void DepthBuffer::writeFragment(const Fragment& fragment) {
    const glm::ivec2 p = pixelOf(fragment);
    if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height) return;
    depth[static_cast<std::size_t>(p.y) * width + p.x] = fragment.depth;
}

}  // namespace lab
