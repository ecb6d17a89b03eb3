// JPEG through libjpeg-turbo. Errors arrive by longjmp, so the decompressor lives in a JpegJob
// owned by the caller of the one function that calls setjmp. Settings: the library's defaults,
// JDCT_ISLOW and fancy upsampling, the closest to stb_image (docs/fuzzing.md, "Texture decoders",
// has the measured difference). Progressive files are stopped after kMaxJpegScans scans, each being
// a pass over the image. A truncated file or corrupt entropy-coded data is an error: libjpeg only
// warns and invents the missing pixels (a grey wall with exit 0), so those warnings end the decode.

#include <cstdio>  // jpeglib.h needs FILE and size_t first

#include <jerror.h>  // the warning codes (JWRN_*)
#include <jpeglib.h>

#include <csetjmp>
#include <new>

#include "io/image_decode.hpp"

namespace facet::detail {
namespace {

struct JpegJob {
    jpeg_error_mgr errors{};
    jpeg_progress_mgr progress{};
    std::jmp_buf jump{};
    jpeg_decompress_struct cinfo{};
    DecodeEnd end;
    DecodeLimits limits;
    DecodedImage image;
    std::vector<unsigned char> row;  // one scanline in the decoder's output layout
};

JpegJob& jobOf(j_common_ptr cinfo) {
    return *static_cast<JpegJob*>(cinfo->client_data);
}

[[noreturn]] void onError(j_common_ptr cinfo) {
    char text[JMSG_LENGTH_MAX] = {};
    cinfo->err->format_message(cinfo, text);
    JpegJob& job = jobOf(cinfo);
    job.end.message = text;
    std::longjmp(job.jump, 1);
}

/// Warnings where libjpeg makes up pixels it could not read; the others (an unknown JFIF
/// revision, a bad ICC marker, a scan repeated) leave the image as the file describes it.
bool inventsPixels(int code) {
    switch (code) {
        case JWRN_JPEG_EOF:        // the file ends before the image does
        case JWRN_HIT_MARKER:      // a data segment ends early
        case JWRN_MUST_RESYNC:     // a restart marker missing: rows lost until the next
        case JWRN_HUFF_BAD_CODE:   // entropy-coded data that decodes to nothing
        case JWRN_NOT_SEQUENTIAL:  // scan parameters a baseline image cannot have
            return true;
        default:
            return false;
    }
}

// Traces (level >= 0) and harmless warnings are silent; damage ends the decode as an error.
void onMessage(j_common_ptr cinfo, int level) {
    if (level >= 0 || !inventsPixels(cinfo->err->msg_code)) return;
    char text[JMSG_LENGTH_MAX] = {};
    cinfo->err->format_message(cinfo, text);
    JpegJob& job = jobOf(cinfo);
    job.end.message = text;
    std::longjmp(job.jump, 1);
}

void onProgress(j_common_ptr cinfo) {
    const auto* d = reinterpret_cast<j_decompress_ptr>(cinfo);
    if (d->input_scan_number > kMaxJpegScans) {
        JpegJob& job = jobOf(cinfo);
        job.end.message = "more than " + std::to_string(kMaxJpegScans) + " progressive scans";
        std::longjmp(job.jump, 1);
    }
}

// Adobe's CMYK JPEGs store inverted inks; stb_image's mix of an ink with black, kept as it was.
unsigned char blinn(unsigned x, unsigned y) {
    const unsigned t = x * y + 128;
    return static_cast<unsigned char>((t + (t >> 8)) >> 8);
}

// The decode proper; false after a libjpeg error (the reason is in job.end).
bool runJpeg(std::span<const unsigned char> bytes, JpegJob& job) {
    if (setjmp(job.jump)) return false;
    jpeg_decompress_struct& d = job.cinfo;
    jpeg_create_decompress(&d);
    d.progress = &job.progress;
    jpeg_mem_src(&d, bytes.data(), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&d, TRUE);
    job.end.headerRead = true;
    job.end.width = d.image_width;
    job.end.height = d.image_height;
    const auto maxSide = static_cast<JDIMENSION>(job.limits.maxSide);
    if (d.image_width < 1 || d.image_height < 1 || d.image_width > maxSide ||
        d.image_height > maxSide) {
        job.end.sizeRefused = true;
        return false;
    }
    job.image.width = static_cast<int>(d.image_width);
    job.image.height = static_cast<int>(d.image_height);
    const bool cmyk = d.jpeg_color_space == JCS_CMYK || d.jpeg_color_space == JCS_YCCK;
    d.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
    d.dct_method = JDCT_ISLOW;
    d.do_fancy_upsampling = TRUE;
    jpeg_start_decompress(&d);
    if (d.output_components != 4 || d.output_width != d.image_width ||
        d.output_height != d.image_height) {
        job.end.message = "unexpected output layout";
        return false;
    }

    const std::size_t w = d.output_width;
    job.image.pixels.assign(w * d.output_height, 0);
    job.row.resize(4 * w);
    while (d.output_scanline < d.output_height) {
        const std::size_t y = d.output_scanline;
        // RGBA rows go straight into the texels (R first in memory); CMYK rows via `row`.
        JSAMPROW target =
            cmyk ? job.row.data() : reinterpret_cast<JSAMPROW>(job.image.pixels.data() + y * w);
        if (jpeg_read_scanlines(&d, &target, 1) != 1) {
            job.end.message = "the decoder stopped before the last row";
            return false;
        }
        if (cmyk) {
            for (std::size_t x = 0; x < w; ++x) {
                const unsigned char* p = &job.row[4 * x];
                job.image.pixels[y * w + x] = std::uint32_t{blinn(p[0], p[3])} |
                                              std::uint32_t{blinn(p[1], p[3])} << 8 |
                                              std::uint32_t{blinn(p[2], p[3])} << 16 | 0xFF000000u;
            }
        }
    }
    jpeg_finish_decompress(&d);
    return true;
}

}  // namespace

Result<DecodedImage> decodeJpeg(std::span<const unsigned char> bytes, const std::string& name,
                                const DecodeLimits& limits) {
    JpegJob job;
    job.limits = limits;
    job.cinfo.err = jpeg_std_error(&job.errors);
    job.cinfo.client_data = &job;  // kept by jpeg_create_decompress
    job.errors.error_exit = onError;
    job.errors.emit_message = onMessage;
    job.progress.progress_monitor = onProgress;
    try {
        job.end.finished = runJpeg(bytes, job);
    } catch (...) {  // std::bad_alloc from the pixel buffer: free libjpeg's state first
        jpeg_destroy_decompress(&job.cinfo);
        throw;
    }
    jpeg_destroy_decompress(&job.cinfo);
    return decodeResult(job.end, std::move(job.image), name, "JPEG", "libjpeg", limits.maxSide);
}

}  // namespace facet::detail
