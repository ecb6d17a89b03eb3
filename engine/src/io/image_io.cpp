// PNG writing through libpng (the decoder's library): 8-bit RGB, written row by row straight
// from the packed RGBA frame (libpng drops the alpha byte), with zlib's fastest level and the
// Sub filter. stb_image_write compressed at level 8 with a filter chosen per row, from a full
// RGB copy: a 16384x16384 frame spent most of its 46 s there. Rendered frames are mostly flat
// runs, which Sub turns into zeros that even level 1 packs well (docs/cli.md has the numbers).
// libpng reports errors by longjmp, so what it touches lives in a PngWriteJob owned by the
// caller of the one function that calls setjmp.

#include "facet/image_io.hpp"

#include <png.h>

#include <algorithm>
#include <bit>
#include <csetjmp>
#include <cstdio>
#include <new>
#include <string>

namespace facet {

namespace {

/// Rows between two progress reports: a caller is not called back per row of a huge frame.
constexpr std::uint32_t kRowsPerReport = 64;

struct PngWriteJob {
    const std::uint32_t* rgba = nullptr;
    int width = 0, height = 0;
    std::string* bytes = nullptr;  // the encoded file when encoding to memory
    const LoadControl* control = nullptr;
    std::string message;  // libpng's reason for stopping, or ours
};

PngWriteJob& jobOf(png_structp png) {
    return *static_cast<PngWriteJob*>(png_get_error_ptr(png));
}

[[noreturn]] void onError(png_structp png, png_const_charp message) {
    jobOf(png).message = message ? message : "unknown error";
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    static_cast<PngWriteJob*>(png_get_io_ptr(png))
        ->bytes->append(reinterpret_cast<const char*>(data), size);
}

void flushNothing(png_structp) {}

void onRow(png_structp png, png_uint_32 row, int) {
    const PngWriteJob& job = jobOf(png);
    if (!job.control || (row % kRowsPerReport != 0 && row != png_uint_32(job.height))) return;
    if (job.control->cancel && job.control->cancel->load(std::memory_order_relaxed))
        png_error(png, "writing cancelled");
    if (job.control->progress)
        job.control->progress(static_cast<float>(row) / static_cast<float>(job.height));
}

// The encode proper, to `file` or (null) to job.bytes; false after a libpng error.
bool runPng(png_structp png, png_infop info, PngWriteJob& job, std::FILE* file) {
    if (setjmp(png_jmpbuf(png))) return false;
    if (file)
        png_init_io(png, file);
    else
        png_set_write_fn(png, &job, appendBytes, flushNothing);
    png_set_write_status_fn(png, onRow);
    png_set_compression_level(png, 1);  // Z_BEST_SPEED
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_IHDR(png, info, static_cast<png_uint_32>(job.width),
                 static_cast<png_uint_32>(job.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    png_set_filler(png, 0, PNG_FILLER_AFTER);  // the rows are R, G, B, A: A is dropped
    for (int y = 0; y < job.height; ++y) {
        // libpng reads the row only; its API has no const.
        auto* row = reinterpret_cast<png_bytep>(
            const_cast<std::uint32_t*>(job.rgba + static_cast<std::size_t>(y) * job.width));
        png_write_row(png, row);
    }
    png_write_end(png, nullptr);
    return true;
}

/// Encodes the frame to `file`, or to `bytes` when `file` is null; the reason on failure.
std::string encode(const std::uint32_t* rgba, int width, int height, std::FILE* file,
                   std::string* bytes, const LoadControl* control) {
    // Packed RGBA8 with R in the low byte is the bytes R, G, B, A in memory.
    static_assert(std::endian::native == std::endian::little, "pixels are stored R first");
    PngWriteJob job{rgba, width, height, bytes, control, {}};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, onError, onWarning);
    if (!png) throw std::bad_alloc();
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw std::bad_alloc();
    }
    bool done = false;
    try {
        done = runPng(png, info, job, file);
    } catch (...) {  // std::bad_alloc from the byte string: free libpng's state first
        png_destroy_write_struct(&png, &info);
        throw;
    }
    png_destroy_write_struct(&png, &info);
    return done ? std::string() : job.message;
}

}  // namespace

Result<std::string> encodePng(const Framebuffer& frame, const LoadControl* control) {
    if (frame.width <= 0 || frame.height <= 0) return Error{{}, "cannot write an empty image"};
    std::string bytes;
    if (const std::string why =
            encode(frame.color.data(), frame.width, frame.height, nullptr, &bytes, control);
        !why.empty())
        return Error{{}, "cannot encode the PNG (libpng: " + why + ")"};
    return bytes;
}

Status writePng(const std::uint32_t* rgba, int width, int height, const std::string& path,
                const LoadControl* control) {
    if (width <= 0 || height <= 0) return Error{{path, 0}, "cannot write an empty image"};
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return Error{{path, 0}, "cannot write PNG (is the folder there and writable?)"};
    std::string why;
    try {
        why = encode(rgba, width, height, file, nullptr, control);
    } catch (...) {
        std::fclose(file);
        throw;
    }
    if (std::fclose(file) != 0 && why.empty()) why = "the file could not be completed";
    if (!why.empty()) {
        std::remove(path.c_str());  // no half-written image left under the name
        return Error{{path, 0}, "cannot write PNG (libpng: " + why + ")"};
    }
    return {};
}

Status writePng(const Framebuffer& frame, const std::string& path, const LoadControl* control) {
    return writePng(frame.color.data(), frame.width, frame.height, path, control);
}

}  // namespace facet
