// The texture decoders against hostile and ordinary files: PNG (libpng) decodes exactly as
// stb_image did before, JPEG (libjpeg-turbo) within the measured IDCT/colour-conversion difference;
// the fuzz findings stay fixed; a progressive JPEG of endless scans is stopped.
//
// Data (tests/data): tex_png_*.png and tex_jpeg_*.jpg are small images made with ImageMagick
// (palette, tRNS, 16-bit, Adam7, grey+alpha; 4:2:0, 4:2:2 at odd sizes, progressive, grey,
// CMYK); tex_huffman_overflow.jpg is tex_jpeg_420 with a DHT whose 16 counts are 17 each (272
// codes, more than the 256 a table holds: stb_image 2.27 writes past its size[257]).

#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "facet/image_io.hpp"
#include "facet/limits.hpp"
#include "facet/texture.hpp"
#include "io/image_decode.hpp"

// stb_image's PNG and JPEG decoders, here only as the reference the engine used to ship.
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include "io/stb_image_quiet.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;
using namespace facet;

namespace {

using facet::test::sharedData;
using facet::test::testData;

std::vector<unsigned char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// How far the engine's level 0 is from stb_image's RGBA decode of the same file.
struct Difference {
    bool sameSize = false;
    int maxChannel = 0;            // largest channel difference, in 8-bit steps
    double differingPixels = 0.0;  // share of pixels with any channel different
};

Difference againstStb(const std::string& path) {
    const Result<Texture> texture = loadTexture(path);
    EXPECT_TRUE(texture.ok()) << texture.error().what();
    if (!texture) return {};
    const std::vector<unsigned char> bytes = readBytes(path);
    int w = 0, h = 0, n = 0;
    stbi_uc* ref =
        stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &n, 4);
    EXPECT_NE(ref, nullptr) << path << ": " << stbi_failure_reason();
    if (!ref) return {};
    Difference d;
    const MipLevel& level = texture->level(0);
    d.sameSize = level.width == w && level.height == h;
    std::size_t differing = 0;
    for (std::size_t i = 0; d.sameSize && i < level.texels.size(); ++i) {
        int pixelMax = 0;
        for (int k = 0; k < 4; ++k) {
            const int mine = static_cast<int>((level.texels[i] >> (8 * k)) & 0xFFu);
            pixelMax =
                std::max(pixelMax, std::abs(mine - ref[4 * i + static_cast<std::size_t>(k)]));
        }
        d.maxChannel = std::max(d.maxChannel, pixelMax);
        differing += pixelMax > 0;
    }
    stbi_image_free(ref);
    d.differingPixels = static_cast<double>(differing) / static_cast<double>(w * h);
    return d;
}

}  // namespace

// libpng with the transforms of png_decode.cpp gives stb_image's pixels exactly, for every PNG
// flavour, so PNG-textured images are byte-identical to before.
TEST(ImageDecode, PngMatchesStbExactly) {
    for (const char* name : {"tex_4x4.png", "tex_gray_3x2.png", "texture_checker.png",
                             "tex_png_16bit.png", "tex_png_interlaced.png", "tex_png_palette.png",
                             "tex_png_trns.png", "tex_png_gray_alpha.png"}) {
        const Difference d = againstStb(testData(name));
        EXPECT_TRUE(d.sameSize) << name;
        EXPECT_EQ(d.maxChannel, 0) << name;
    }
    REQUIRE_SHARED_DATA(sharedData("models"));
    const Difference spot = againstStb(sharedData("models/spot_texture.png"));
    EXPECT_TRUE(spot.sameSize);
    EXPECT_EQ(spot.maxChannel, 0);
}

// libjpeg-turbo (JDCT_ISLOW, fancy upsampling: the closest of its settings) rounds its IDCT and
// YCbCr conversion differently from stb_image: measured on the course's images, brick.jpg has
// 10.4% of pixels off by at most 3 steps, world_map.jpg 2.5% by at most 2 (docs/fuzzing.md).
TEST(ImageDecode, JpegWithinMeasuredDifferenceOfStb) {
    for (const char* name : {"tex_jpeg_progressive.jpg", "tex_jpeg_gray.jpg",
                             "tex_jpeg_422_odd.jpg", "tex_jpeg_cmyk.jpg"}) {
        const Difference d = againstStb(testData(name));
        EXPECT_TRUE(d.sameSize) << name;
        EXPECT_LE(d.maxChannel, 3) << name;
    }
    REQUIRE_SHARED_DATA(sharedData("course"));
    const Difference brick = againstStb(sharedData("course/brick.jpg"));
    EXPECT_TRUE(brick.sameSize);
    EXPECT_LE(brick.maxChannel, 3);
    EXPECT_LT(brick.differingPixels, 0.11);
    const Difference world = againstStb(sharedData("course/world_map.jpg"));
    EXPECT_TRUE(world.sameSize);
    EXPECT_LE(world.maxChannel, 2);
    EXPECT_LT(world.differingPixels, 0.03);
}

// Fuzz finding (stb_image 2.27): Huffman counts adding up to more than 256. libjpeg-turbo
// refuses the table; the error names the file and says the image is damaged.
TEST(ImageDecode, HuffmanTableOverflowIsAnError) {
    const Result<Texture> t = loadTexture(testData("tex_huffman_overflow.jpg"));
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().loc.file, testData("tex_huffman_overflow.jpg"));
    EXPECT_NE(t.error().message.find("JPEG"), std::string::npos) << t.error().what();
    EXPECT_NE(t.error().message.find("libjpeg"), std::string::npos) << t.error().what();
}

// A progressive JPEG whose last scan is repeated 600 times: each repeat is a pass over the
// image, so the decoder stops after kMaxJpegScans instead of working on.
TEST(ImageDecode, EndlessProgressiveScansAreStopped) {
    const std::vector<unsigned char> bytes = readBytes(testData("tex_jpeg_progressive.jpg"));
    ASSERT_GT(bytes.size(), 4u);
    std::size_t lastScan = 0;
    for (std::size_t i = 0; i + 1 < bytes.size(); ++i) {
        if (bytes[i] == 0xFF && bytes[i + 1] == 0xDA) lastScan = i;
    }
    ASSERT_GT(lastScan, 0u);
    ASSERT_EQ(bytes[bytes.size() - 2], 0xFF);
    ASSERT_EQ(bytes.back(), 0xD9);
    std::vector<unsigned char> hostile(bytes.begin(), bytes.end() - 2);
    const std::vector<unsigned char> scan(bytes.begin() + static_cast<std::ptrdiff_t>(lastScan),
                                          bytes.end() - 2);
    for (int i = 0; i < 600; ++i) hostile.insert(hostile.end(), scan.begin(), scan.end());
    hostile.insert(hostile.end(), {0xFF, 0xD9});

    const Result<Texture> t = detail::decodeTexture(hostile, "many_scans.jpg");
    ASSERT_FALSE(t.ok());
    EXPECT_NE(t.error().message.find("more than " + std::to_string(kMaxJpegScans)),
              std::string::npos)
        << t.error().what();
    // The untouched file still decodes.
    EXPECT_TRUE(detail::decodeTexture(bytes, "progressive.jpg").ok());
}

// The size limit is checked from the header for every format, before pixels are allocated.
TEST(ImageDecode, SidesOverTheLimitAreRefusedFromTheHeader) {
    const detail::DecodeLimits small{.maxSide = 4};
    for (const char* name : {"tex_jpeg_progressive.jpg", "tex_png_16bit.png", "tex_5x3.bmp"}) {
        const Result<Texture> t = detail::decodeTexture(readBytes(testData(name)), name, small);
        ASSERT_FALSE(t.ok()) << name;
        EXPECT_NE(t.error().message.find("a texture side must be 1 to 4"), std::string::npos)
            << t.error().what();
    }
}

// Damage after the header: the message says so and names the decoder.
TEST(ImageDecode, DamagedDataGivesClearErrors) {
    std::vector<unsigned char> png = readBytes(testData("tex_png_16bit.png"));
    ASSERT_GT(png.size(), 149u);
    png.resize(149);  // IDAT starts at byte 111 and holds 66 bytes
    const Result<Texture> cut = detail::decodeTexture(png, "cut.png");
    ASSERT_FALSE(cut.ok());
    EXPECT_NE(cut.error().message.find("damaged or truncated (libpng:"), std::string::npos)
        << cut.error().what();

    std::vector<unsigned char> jpeg = readBytes(testData("tex_jpeg_gray.jpg"));
    jpeg.resize(40);  // inside the header's tables
    const Result<Texture> header = detail::decodeTexture(jpeg, "header.jpg");
    ASSERT_FALSE(header.ok());
    EXPECT_NE(header.error().message.find("JPEG image: its header is damaged"), std::string::npos)
        << header.error().what();
}

// A truncated or corrupt JPEG is an error, as a truncated PNG is: libjpeg only warns and makes up
// the missing rows (a grey wall with exit 0 before). Real photographs, damaged on disk here.
TEST(ImageDecode, TruncatedOrCorruptJpegIsAnErrorNamingTheFile) {
    const std::string brick = sharedData("course/brick.jpg");
    REQUIRE_SHARED_DATA(brick);
    const std::vector<unsigned char> whole = readBytes(brick);
    ASSERT_GT(whole.size(), 4000u);
    ASSERT_TRUE(loadTexture(brick).ok());
    const fs::path dir =
        fs::temp_directory_path() / ("facet_jpeg_damage_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto write = [&dir](const std::string& name, const std::vector<unsigned char>& bytes) {
        const fs::path path = dir / name;
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        return path.string();
    };
    for (const double kept : {0.5, 0.9, 0.999}) {
        std::vector<unsigned char> cut = whole;
        cut.resize(static_cast<std::size_t>(kept * static_cast<double>(whole.size())));
        const std::string path = write("cut.jpg", cut);
        const Result<Texture> t = loadTexture(path);
        ASSERT_FALSE(t.ok()) << kept;
        EXPECT_EQ(t.error().loc.file, path);
        EXPECT_NE(t.error().what().find("damaged or truncated (libjpeg: Premature end of JPEG"),
                  std::string::npos)
            << t.error().what();
    }
    // An end-of-image marker written over the middle of the entropy-coded data.
    std::vector<unsigned char> corrupt = whole;
    for (std::size_t i = whole.size() / 2; i < whole.size() / 2 + 16; i += 2) {
        corrupt[i] = 0xFF;
        corrupt[i + 1] = 0xD9;
    }
    const Result<Texture> c = loadTexture(write("corrupt.jpg", corrupt));
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().what().find("Corrupt JPEG data"), std::string::npos) << c.error().what();
    fs::remove_all(dir);
}

// The PNG writer (libpng, fastest level, Sub filter) loses nothing: what it writes decodes to
// the frame's pixels, alpha dropped; its progress rises to 1; a cancel leaves no file behind.
TEST(ImageDecode, WrittenPngDecodesToTheFramesPixels) {
    Framebuffer frame;
    ASSERT_TRUE(frame.resize(301, 203));
    std::uint32_t state = 12345u;
    for (std::size_t i = 0; i < frame.color.size(); ++i) {
        state = state * 1664525u + 1013904223u;  // noise and flat runs, as in a render
        frame.color[i] = (i / 301) % 3 == 0 ? 0xFF5C5C5Cu : (state | 0xFF000000u);
    }
    frame.color[7] &= 0x00FFFFFFu;  // a zero alpha is written opaque: PNGs are RGB
    const fs::path dir =
        fs::temp_directory_path() / ("facet_png_write_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "frame.png").string();
    std::vector<float> reports;
    LoadControl control;
    control.progress = [&reports](float f) { reports.push_back(f); };
    ASSERT_TRUE(writePng(frame, path, &control));
    ASSERT_FALSE(reports.empty());
    EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
    EXPECT_EQ(reports.back(), 1.0f);
    const Result<Texture> back = loadTexture(path);
    ASSERT_TRUE(back.ok()) << back.error().what();
    std::vector<std::uint32_t> opaque = frame.color;
    for (std::uint32_t& p : opaque) p |= 0xFF000000u;
    EXPECT_EQ(back->level(0).texels, opaque);
    const Result<std::string> bytes = encodePng(frame);
    ASSERT_TRUE(bytes.ok());
    const std::vector<unsigned char> file = readBytes(path);
    EXPECT_TRUE(bytes.value() == std::string(file.begin(), file.end()));  // no dump of bytes

    std::atomic<bool> cancel{true};
    LoadControl stop;
    stop.cancel = &cancel;
    const Status cancelled = writePng(frame, (dir / "cancelled.png").string(), &stop);
    ASSERT_FALSE(cancelled);
    EXPECT_NE(cancelled.error().what().find("cancelled"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "cancelled.png"));
    fs::remove_all(dir);
}

// Fuzz finding (a timeout): a 134-byte run-length TGA claiming 3855x3855 pixels; stb_image reads
// zeros past the end and filled all 15 million. Refused from the header: no BMP or TGA packs
// more than 64 pixels into a byte.
TEST(ImageDecode, TgaClaimingMorePixelsThanItsBytesIsRefused) {
    const Result<Texture> t = loadTexture(testData("tex_tga_empty_claim.tga"));
    ASSERT_FALSE(t.ok());
    EXPECT_NE(t.error().message.find("image claims 3855x3855 pixels, more than a 134-byte BMP or "
                                     "TGA file can hold"),
              std::string::npos)
        << t.error().what();
    // A real run-length TGA (8x8 in 50 bytes) still loads.
    const Result<Texture> rle = loadTexture(testData("tex_tga_rle.tga"));
    ASSERT_TRUE(rle.ok()) << rle.error().what();
    EXPECT_EQ(rle->width(), 8);
}
