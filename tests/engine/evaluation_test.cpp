// The evaluation library's own rules (facet/evaluation/): frame-time summaries, the histogram of
// pixel errors, and the frame-against-reference comparison every accuracy test and sweep uses,
// on hand-made images whose answers are known.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "facet/evaluation/frame_times.hpp"
#include "facet/evaluation/image_diff.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/evaluation/reference_compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"

namespace {

using facet::packRgba;

TEST(FrameTimes, SummaryOfAnyOrder) {
    const facet::FrameTimes odd = facet::summarize({5.0, 1.0, 3.0});
    EXPECT_EQ(odd, (facet::FrameTimes{3, 3.0, 1.0, 5.0}));
    // An even count: the mean of the middle two.
    const facet::FrameTimes even = facet::summarize({4.0, 1.0, 3.0, 2.0});
    EXPECT_EQ(even, (facet::FrameTimes{4, 2.5, 1.0, 4.0}));
    EXPECT_EQ(facet::summarize({}), facet::FrameTimes{});
    EXPECT_EQ(facet::medianOf({}), 0.0);
    EXPECT_EQ(facet::medianOf({7.0}), 7.0);
    EXPECT_EQ(facet::medianOf({9.0, 1.0, 8.0, 2.0, 7.0, 3.0}), 5.0);
}

TEST(FrameTimes, TimeRepeatedWarmsUpOnceThenTimesEachFrame) {
    int calls = 0;
    const facet::FrameTimes t = facet::timeRepeated(4, [&] { ++calls; });
    EXPECT_EQ(calls, 5);
    EXPECT_EQ(t.frames, 4);
    EXPECT_LE(t.min, t.median);
    EXPECT_LE(t.median, t.max);
    calls = 0;
    EXPECT_EQ(facet::timeRepeated(0, [&] { ++calls; }).frames, 1);  // at least one timed frame
    EXPECT_EQ(calls, 2);
}

TEST(DiffHistogram, PercentilesAndTail) {
    facet::DiffHistogram h;
    EXPECT_EQ(h.percentile(0.5), 0);
    EXPECT_EQ(h.max(), 0);
    EXPECT_EQ(h.shareAbove(0), 0.0);
    for (int i = 0; i < 90; ++i) h.add(0);
    for (int i = 0; i < 9; ++i) h.add(1);
    h.add(7);
    EXPECT_EQ(h.total, 100u);
    EXPECT_EQ(h.percentile(0.5), 0);
    EXPECT_EQ(h.percentile(0.95), 1);
    EXPECT_EQ(h.percentile(0.99), 1);
    EXPECT_EQ(h.percentile(1.0), 7);
    EXPECT_EQ(h.max(), 7);
    EXPECT_EQ(h.above(0), 10u);
    EXPECT_EQ(h.above(1), 1u);
    EXPECT_EQ(h.above(7), 0u);
    EXPECT_DOUBLE_EQ(h.shareAbove(1), 0.01);
}

/// A 4×2 reference image: the top row drawn (depth 2), the bottom row empty, pixel (3, 0)
/// ambiguous. Colours are exact bytes, so toRgba() gives them back.
facet::reference::Image smallReference() {
    facet::reference::Image ref;
    ref.width = 4;
    ref.height = 2;
    const double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 8; ++i) {
        const bool drawn = i < 4;
        ref.color.push_back(drawn ? glm::dvec3(100.0 / 255.0, 50.0 / 255.0, 0.0)
                                  : glm::dvec3(0x40 / 255.0));
        ref.depth.push_back(drawn ? 2.0 : inf);
        ref.ambiguous.push_back(i == 3 ? 1 : 0);
    }
    return ref;
}

/// A frame equal to smallReference(): background 0x404040.
facet::Framebuffer sameFrame() {
    facet::Framebuffer f;
    f.resize(4, 2);
    f.clear(facet::rgbaFromHex(0x404040));
    for (int x = 0; x < 4; ++x) {
        f.color[f.index(x, 0)] = packRgba(100, 50, 0);
        f.depth[f.index(x, 0)] = 2.0f;
    }
    return f;
}

TEST(ReferenceDiff, EqualImagesAgree) {
    const facet::ReferenceDiff d = facet::compareWithReference(
        sameFrame(), smallReference(), facet::ShaderKind::Painter, 0x404040);
    EXPECT_EQ(d.pixels, 8u);
    EXPECT_EQ(d.ambiguous, 1u);
    EXPECT_EQ(d.compared, 7u);
    EXPECT_EQ(d.comparedCovered, 3u);
    EXPECT_EQ(d.refCovered, 4u);
    EXPECT_EQ(d.fastCovered, 4u);
    EXPECT_EQ(d.coverageDiffers, 0u);
    EXPECT_EQ(d.maxColorDiff, 0);
    EXPECT_EQ(d.nanDepth, 0u);
    EXPECT_TRUE(d.examples.empty());
}

TEST(ReferenceDiff, CountsWhatDiffersOutsideTheMaskOnly) {
    facet::Framebuffer f = sameFrame();
    f.color[f.index(0, 0)] = packRgba(101, 50, 0);  // 1 LSB: within the rules
    f.color[f.index(1, 0)] = packRgba(100, 47, 0);  // 3 LSB
    f.depth[f.index(2, 0)] =
        std::numeric_limits<float>::quiet_NaN();  // NaN: not drawn, and counted
    f.depth[f.index(3, 0)] = facet::kEmptyDepth;  // ambiguous: not judged
    f.depth[f.index(0, 1)] = 5.0f;                // drawn where the reference did not
    facet::DiffHistogram both;
    const facet::ReferenceDiff d = facet::compareWithReference(
        f, smallReference(), facet::ShaderKind::Painter, 0x404040, &both);
    EXPECT_EQ(d.coverageDiffers, 2u);  // (2, 0) and (0, 1)
    EXPECT_EQ(d.maxColorDiff, 3);
    EXPECT_EQ(d.offByOne, 1u);
    EXPECT_EQ(d.nanDepth, 1u);
    EXPECT_EQ(d.fastCovered, 3u);  // (0, 0), (1, 0) and (0, 1)
    EXPECT_NE(d.examples.find("pixel (1,0)"), std::string::npos) << d.examples;
    EXPECT_NE(d.examples.find("pixel (0,1)"), std::string::npos) << d.examples;
    EXPECT_EQ(d.examples.find("pixel (0,0)"), std::string::npos) << d.examples;
    // Drawn in both outside the mask: (0, 0) off by 1 and (1, 0) off by 3.
    EXPECT_EQ(both.total, 2u);
    EXPECT_EQ(both.count[1], 1u);
    EXPECT_EQ(both.count[3], 1u);
}

TEST(ReferenceDiff, SimpleShaderJudgedByColour) {
    // The Simple shader writes no depth: coverage is "not the background".
    facet::Framebuffer f = sameFrame();
    for (float& z : f.depth) z = facet::kEmptyDepth;
    const facet::ReferenceDiff same =
        facet::compareWithReference(f, smallReference(), facet::ShaderKind::Simple, 0x404040);
    EXPECT_EQ(same.fastCovered, 4u);
    EXPECT_EQ(same.coverageDiffers, 0u);
    f.color[f.index(0, 0)] = facet::rgbaFromHex(0x404040);
    const facet::ReferenceDiff hole =
        facet::compareWithReference(f, smallReference(), facet::ShaderKind::Simple, 0x404040);
    EXPECT_EQ(hole.coverageDiffers, 1u);
}

TEST(ReferenceDiff, ErrorOverTheUnambiguousDrawnPixels) {
    facet::Framebuffer f = sameFrame();
    f.color[f.index(0, 0)] = packRgba(103, 50, 0);  // 3 steps in one channel
    f.color[f.index(3, 0)] = packRgba(0, 0, 0);     // ambiguous: left out
    f.color[f.index(2, 1)] = packRgba(255, 0, 0);   // not drawn by the reference: left out
    const facet::ImageError e = facet::errorAgainstReference(f, smallReference());
    EXPECT_EQ(e.pixels, 3u);
    EXPECT_EQ(e.maxError, 3.0);
    EXPECT_DOUBLE_EQ(e.meanError, 3.0 / 9.0);
    EXPECT_DOUBLE_EQ(e.rmse, std::sqrt(9.0 / 9.0));
    EXPECT_DOUBLE_EQ(e.over2Lsb, 1.0 / 3.0);
}

TEST(ImageError, EightBitImagesWithAMask) {
    const std::vector<std::uint32_t> a{packRgba(10, 0, 0), packRgba(0, 0, 0), packRgba(9, 9, 9)};
    const std::vector<std::uint32_t> b{packRgba(12, 0, 0), packRgba(0, 0, 0), packRgba(0, 0, 0)};
    const facet::ImageError all = facet::measureError(a, b);
    EXPECT_EQ(all.pixels, 3u);
    EXPECT_EQ(all.maxError, 9.0);
    EXPECT_DOUBLE_EQ(all.meanError, 29.0 / 9.0);
    const std::vector<std::uint8_t> firstTwo{1, 1, 0};
    const facet::ImageError masked = facet::measureError(a, b, firstTwo);
    EXPECT_EQ(masked.pixels, 2u);
    EXPECT_EQ(masked.maxError, 2.0);
    EXPECT_DOUBLE_EQ(masked.rmse, std::sqrt(4.0 / 6.0));
    EXPECT_EQ(masked.over2Lsb, 0.0);  // exactly 2 is not more than 2
    EXPECT_EQ(facet::measureError(a, std::vector<std::uint32_t>{0u}).pixels, 0u);  // sizes differ
}

}  // namespace
