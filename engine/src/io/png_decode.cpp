// PNG through libpng. libpng reports errors by longjmp, so everything it touches lives in a
// PngJob owned by the caller of the one function that calls setjmp: no C++ object with a
// destructor is skipped by the jump. The transforms give what stb_image gave before: palette and
// low bit depths expanded, tRNS as alpha, 16 bits cut to their high byte, grey copied to RGB,
// opaque alpha added, no gamma or colour-space conversion.

#include <png.h>

#include <bit>
#include <csetjmp>
#include <cstring>
#include <new>

#include "io/image_decode.hpp"

namespace facet::detail {
namespace {

struct PngJob {
    std::span<const unsigned char> bytes;
    std::size_t pos = 0;
    DecodeLimits limits;
    DecodeEnd end;
    std::uint32_t width = 0, height = 0;
    DecodedImage image;
    std::vector<png_bytep> rows;
};

PngJob& jobOf(png_structp png) {
    return *static_cast<PngJob*>(png_get_error_ptr(png));
}

[[noreturn]] void onError(png_structp png, png_const_charp message) {
    jobOf(png).end.message = message ? message : "unknown error";
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}  // benign (e.g. a bad ancillary chunk skipped)

void readBytes(png_structp png, png_bytep out, png_size_t count) {
    PngJob& job = *static_cast<PngJob*>(png_get_io_ptr(png));
    if (count > job.bytes.size() - job.pos) png_error(png, "the file ends inside the image");
    std::memcpy(out, job.bytes.data() + job.pos, count);
    job.pos += count;
}

// The decode proper; false after a libpng error (the reason is in job.end).
bool runPng(png_structp png, png_infop info, PngJob& job) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, &job, readBytes);
    png_set_user_limits(png, static_cast<png_uint_32>(job.limits.maxSide),
                        static_cast<png_uint_32>(job.limits.maxSide));
    if (!job.limits.checkPngCrc) png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
    png_read_info(png, info);
    job.end.headerRead = true;
    int depth = 0, color = 0;
    png_get_IHDR(png, info, &job.width, &job.height, &depth, &color, nullptr, nullptr, nullptr);
    job.end.width = job.width;
    job.end.height = job.height;
    const auto maxSide = static_cast<std::uint32_t>(job.limits.maxSide);
    if (job.width < 1 || job.height < 1 || job.width > maxSide || job.height > maxSide) {
        job.end.sizeRefused = true;
        return false;
    }

    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (depth == 16) png_set_strip_16(png);
    if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA) {
        png_set_gray_to_rgb(png);
    }
    png_set_filler(png, 0xFF, PNG_FILLER_AFTER);  // no effect when alpha is already there
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != 4 * std::size_t{job.width}) {
        png_error(png, "unexpected row layout after conversion to RGBA");
    }

    // Packed RGBA8 with R in the low byte is the bytes R, G, B, A in memory (little-endian x86
    // and ARM), so libpng writes the texels in place.
    job.image.width = static_cast<int>(job.width);
    job.image.height = static_cast<int>(job.height);
    job.image.pixels.assign(std::size_t{job.width} * job.height, 0);
    job.rows.resize(job.height);
    auto* base = reinterpret_cast<png_bytep>(job.image.pixels.data());
    for (std::size_t y = 0; y < job.height; ++y) job.rows[y] = base + 4 * y * job.width;
    png_read_image(png, job.rows.data());
    return true;
}

}  // namespace

Result<DecodedImage> decodePng(std::span<const unsigned char> bytes, const std::string& name,
                               const DecodeLimits& limits) {
    static_assert(std::endian::native == std::endian::little, "texels are stored R first");
    PngJob job;
    job.bytes = bytes;
    job.limits = limits;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, onError, onWarning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        throw std::bad_alloc();
    }
    try {
        job.end.finished = runPng(png, info, job);
    } catch (...) {  // std::bad_alloc from the pixel buffer: free libpng's state first
        png_destroy_read_struct(&png, &info, nullptr);
        throw;
    }
    png_destroy_read_struct(&png, &info, nullptr);
    return decodeResult(job.end, std::move(job.image), name, "PNG", "libpng", limits.maxSide);
}

}  // namespace facet::detail
