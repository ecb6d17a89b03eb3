#include "facet/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

// Only the formats the conventions promise: less decoder surface for hostile files, and anything
// else is reported as unsupported rather than half-working. Sizes are checked in loadTexture()
// (stb's own cap is far larger) so the message can say what the limit is.
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wnull-dereference"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

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

Error fileError(const std::string& path, std::string message) {
    return Error{{path, 0}, std::move(message)};
}

Error sizeError(const std::string& path, std::uint64_t w, std::uint64_t h) {
    return fileError(path, "image is " + std::to_string(w) + "x" + std::to_string(h) +
                               " pixels; a texture side must be 1 to " +
                               std::to_string(kMaxTextureSize));
}

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 |
           std::uint32_t{p[3]};
}

/// Why stb_image could not read the header. stb tries every decoder in turn, so its own reason
/// is the last decoder's ("unknown image type") even for a PNG it refused as too large: the
/// signature tells which format the file claims to be, and a PNG's size is easy to read.
Error headerError(const std::string& path, const std::vector<unsigned char>& bytes,
                  const char* stbReason) {
    static constexpr unsigned char kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    const auto startsWith = [&](const unsigned char* magic, std::size_t n) {
        return bytes.size() >= n && std::equal(magic, magic + n, bytes.begin());
    };
    if (startsWith(kPng, sizeof kPng)) {
        if (bytes.size() >= 24 && std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
            const std::uint32_t w = bigEndian32(bytes.data() + 16);
            const std::uint32_t h = bigEndian32(bytes.data() + 20);
            if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
                return sizeError(path, w, h);
        }
        return fileError(path, "not a readable PNG image: its header is damaged");
    }
    static constexpr unsigned char kJpeg[] = {0xFF, 0xD8, 0xFF};
    if (startsWith(kJpeg, sizeof kJpeg))
        return fileError(path, "not a readable JPEG image: its header is damaged");
    return fileError(path, std::string("not a readable PNG, JPEG, BMP or TGA image (stb_image: ") +
                               (stbReason ? stbReason : "unknown reason") + ")");
}

}  // namespace

Texture::Texture() : levels_{MipLevel{1, 1, {0xFFFFFFFFu}}}, name_("white") {}

Result<Texture> Texture::fromRgba(int width, int height, std::vector<std::uint32_t> pixels,
                                  std::string name) {
    if (width < 1 || height < 1 || width > kMaxTextureSize || height > kMaxTextureSize) {
        return fileError(name, "texture is " + std::to_string(width) + "x" +
                                   std::to_string(height) + " pixels; each side must be 1 to " +
                                   std::to_string(kMaxTextureSize));
    }
    if (pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
        return fileError(name, "texture pixel count " + std::to_string(pixels.size()) +
                                   " does not match its size " + std::to_string(width) + "x" +
                                   std::to_string(height));
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

Result<Texture> loadTexture(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return fileError(path, "is a folder, not an image file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return fileError(path, "cannot open the texture file (missing or not readable)");
    const std::streamoff size = in.tellg();
    if (size < 0) return fileError(path, "cannot read the texture file");
    if (size == 0) return fileError(path, "the texture file is empty");
    if (size > std::numeric_limits<int>::max())
        return fileError(path, "the texture file is too large (over 2 GB)");
    const int length = static_cast<int>(size);

    try {
        std::vector<unsigned char> bytes(static_cast<std::size_t>(length));
        in.seekg(0);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), length))
            return fileError(path, "cannot read the texture file");

        // The header first: a forged size is refused before anything is decoded or allocated.
        int w = 0, h = 0, channels = 0;
        if (!stbi_info_from_memory(bytes.data(), length, &w, &h, &channels))
            return headerError(path, bytes, stbi_failure_reason());
        if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
            return sizeError(path, static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h));

        // Always four channels: grey, grey+alpha and RGB all become RGBA, one uint32 per texel.
        const std::unique_ptr<stbi_uc, void (*)(void*)> data(
            stbi_load_from_memory(bytes.data(), length, &w, &h, &channels, 4), stbi_image_free);
        if (!data) {
            const char* reason = stbi_failure_reason();
            return fileError(path, std::string("cannot decode the image, it may be damaged or "
                                               "truncated (stb_image: ") +
                                       (reason ? reason : "unknown reason") + ")");
        }
        std::vector<std::uint32_t> pixels(static_cast<std::size_t>(w) *
                                          static_cast<std::size_t>(h));
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            const stbi_uc* p = data.get() + 4 * i;
            pixels[i] = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                        static_cast<std::uint32_t>(p[2]) << 16 |
                        static_cast<std::uint32_t>(p[3]) << 24;
        }
        return Texture::fromRgba(w, h, std::move(pixels), path);
    } catch (const std::bad_alloc&) {
        return fileError(path, "not enough memory to load this texture");
    }
}

}  // namespace facet

namespace facet::reference {

double wrapCoord(double t) {
    if (!std::isfinite(t)) return 0.0;
    return t - std::floor(t);
}

glm::dvec3 texelColor(const MipLevel& level, int x, int y) {
    const std::uint32_t p = level.at(x, y);
    return glm::dvec3(p & 0xFFu, (p >> 8) & 0xFFu, (p >> 16) & 0xFFu) / 255.0;
}

glm::dvec3 sampleNearest(const Texture& tex, glm::dvec2 uv) {
    const MipLevel& l = tex.level(0);
    const double x = std::floor(wrapCoord(uv.x) * l.width);
    const double y = std::floor(wrapCoord(uv.y) * l.height);
    return reference::texelColor(l, static_cast<int>(std::min(x, l.width - 1.0)),
                                 static_cast<int>(std::min(y, l.height - 1.0)));
}

glm::dvec3 sampleBilinear(const Texture& tex, glm::dvec2 uv, int level) {
    const MipLevel& l = tex.level(std::clamp(level, 0, tex.levelCount() - 1));
    // Continuous texel coordinates with texel i's centre at i.
    const double x = wrapCoord(uv.x) * l.width - 0.5;
    const double y = wrapCoord(uv.y) * l.height - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    const auto wrapIndex = [](double i, int n) {
        const int k = static_cast<int>(i) % n;
        return k < 0 ? k + n : k;
    };
    const int i0 = wrapIndex(x0, l.width);
    const int i1 = wrapIndex(x0 + 1.0, l.width);
    const int j0 = wrapIndex(y0, l.height);
    const int j1 = wrapIndex(y0 + 1.0, l.height);
    return (1.0 - fx) * (1.0 - fy) * reference::texelColor(l, i0, j0) +
           fx * (1.0 - fy) * reference::texelColor(l, i1, j0) +
           (1.0 - fx) * fy * reference::texelColor(l, i0, j1) +
           fx * fy * reference::texelColor(l, i1, j1);
}

double mipLevel(const Texture& tex, glm::dvec2 duvDx, glm::dvec2 duvDy) {
    if (std::isnan(duvDx.x) || std::isnan(duvDx.y) || std::isnan(duvDy.x) || std::isnan(duvDy.y))
        return 0.0;
    const double w = tex.width();
    const double h = tex.height();
    const double rho =
        std::max(std::hypot(duvDx.x * w, duvDx.y * h), std::hypot(duvDy.x * w, duvDy.y * h));
    const double lod = std::log2(rho);
    if (lod <= 0.0) return 0.0;
    return std::min(lod, tex.levelCount() - 1.0);
}

glm::dvec3 sampleTrilinear(const Texture& tex, glm::dvec2 uv, double lod) {
    const double l = std::isnan(lod) ? 0.0 : std::clamp(lod, 0.0, tex.levelCount() - 1.0);
    const double l0 = std::floor(l);
    const double f = l - l0;
    const int level = static_cast<int>(l0);
    if (f == 0.0) return reference::sampleBilinear(tex, uv, level);
    return (1.0 - f) * reference::sampleBilinear(tex, uv, level) +
           f * reference::sampleBilinear(tex, uv, level + 1);
}

}  // namespace facet::reference
