// Step 6 (assignment section 5, "Depth buffering"). Write both functions, delete their
// notStarted lines, then run `make lab-check` and choose the painter shader.

#include <cstddef>

#include "lab/steps.hpp"

namespace lab {

// Step 6a. True when the fragment's pixel (pixelOf(fragment)) is inside the buffer and the
// fragment is strictly nearer (smaller depth) than the depth stored there. Outside the buffer:
// false. On a tie the first fragment drawn stays, so equal is not nearer.
bool DepthBuffer::testFragment(const Fragment& fragment) const {
    (void)fragment;
    return notStarted(Step::DepthBuffer, true);
}

// Step 6b. Store the fragment's depth at its pixel, row-major (index y · width + x); do nothing
// outside the buffer.
void DepthBuffer::writeFragment(const Fragment& fragment) {
    (void)fragment;
    markNotStarted(Step::DepthBuffer);
}

}  // namespace lab
