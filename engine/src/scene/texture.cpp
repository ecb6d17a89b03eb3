// Textures in memory: the mip chain built from RGBA8 pixels (files are read in io/).

#include "facet/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "facet/camera.hpp"

namespace facet {
namespace {

/// One output texel's footprint along an axis: the source texels it overlaps (at most three when
/// a side is halved by rounding down) and the overlaps, as integers summing to the source size.
struct Taps {
    int first = 0;
    int count = 0;
    std::uint64_t weight[3] = {0, 0, 0};
};

/// Footprints of `dst` texels over `src` ones. Scaling both grids by dst·src makes every border
/// an integer: source texel k spans [k·dst, (k+1)·dst) and output texel i spans
/// [i·src, (i+1)·src), so the overlaps are exact and the mean can be rounded exactly.
std::vector<Taps> footprints(int src, int dst) {
    std::vector<Taps> out(static_cast<std::size_t>(dst));
    for (int i = 0; i < dst; ++i) {
        const std::int64_t a = std::int64_t{i} * src;
        const std::int64_t b = a + src;
        Taps& t = out[static_cast<std::size_t>(i)];
        t.first = static_cast<int>(a / dst);
        for (int k = t.first; k < src && t.count < 3; ++k) {
            const std::int64_t lo = std::max(a, std::int64_t{k} * dst);
            const std::int64_t hi = std::min(b, std::int64_t{k + 1} * dst);
            if (hi <= lo) break;
            t.weight[t.count++] = static_cast<std::uint64_t>(hi - lo);
        }
    }
    return out;
}

/// The next level of the chain, from the previous one: sides halved rounding down (at least 1),
/// each texel the exact area-weighted mean of its footprint, rounded half up per channel.
MipLevel reduce(const MipLevel& src) {
    MipLevel dst;
    dst.width = std::max(1, src.width / 2);
    dst.height = std::max(1, src.height / 2);
    const std::vector<Taps> tx = footprints(src.width, dst.width);
    const std::vector<Taps> ty = footprints(src.height, dst.height);
    // Weights along x sum to src.width and along y to src.height.
    const std::uint64_t total =
        static_cast<std::uint64_t>(src.width) * static_cast<std::uint64_t>(src.height);
    dst.texels.assign(static_cast<std::size_t>(dst.width) * static_cast<std::size_t>(dst.height),
                      0u);
    for (int y = 0; y < dst.height; ++y) {
        const Taps& fy = ty[static_cast<std::size_t>(y)];
        for (int x = 0; x < dst.width; ++x) {
            const Taps& fx = tx[static_cast<std::size_t>(x)];
            std::uint64_t sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < fy.count; ++j) {
                for (int i = 0; i < fx.count; ++i) {
                    const std::uint64_t w = fy.weight[j] * fx.weight[i];
                    const std::uint32_t p = src.at(fx.first + i, fy.first + j);
                    for (int c = 0; c < 4; ++c) sum[c] += w * ((p >> (8 * c)) & 0xFFu);
                }
            }
            std::uint32_t packed = 0;
            for (int c = 0; c < 4; ++c) {
                const std::uint64_t rounded = (2 * sum[c] + total) / (2 * total);
                packed |= static_cast<std::uint32_t>(rounded) << (8 * c);
            }
            dst.texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(dst.width) +
                       static_cast<std::size_t>(x)] = packed;
        }
    }
    return dst;
}

}  // namespace

Texture::Texture() : levels_{MipLevel{1, 1, {0xFFFFFFFFu}}}, name_("white") {}

Result<Texture> Texture::fromRgba(int width, int height, std::vector<std::uint32_t> pixels,
                                  std::string name) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        return Error{{name, 0},
                     "texture is " + std::to_string(width) + "x" + std::to_string(height) +
                         " pixels; each side must be 1 to " + std::to_string(kMaxImageSide)};
    }
    if (pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
        return Error{{name, 0},
                     "texture pixel count " + std::to_string(pixels.size()) +
                         " does not match its size " + std::to_string(width) + "x" +
                         std::to_string(height)};
    }
    Texture t;
    t.name_ = std::move(name);
    t.levels_.clear();
    t.levels_.push_back(MipLevel{width, height, std::move(pixels)});
    while (t.levels_.back().width > 1 || t.levels_.back().height > 1) {
        MipLevel next = reduce(t.levels_.back());
        t.levels_.push_back(std::move(next));
    }
    return t;
}

}  // namespace facet
