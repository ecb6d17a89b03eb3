#include "facet/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "facet/colormap.hpp"

namespace facet {
namespace {

/// 3×5 glyphs, one row per 3-bit number (bit 2 = left column), top row first.
struct Glyph {
    char c;
    std::uint8_t rows[5];
};
constexpr Glyph kFont[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'+', {0, 2, 7, 2, 0}}, {'e', {0, 7, 7, 4, 7}},
};
constexpr int kGlyphW = 3, kGlyphH = 5, kAdvance = 4;

const Glyph* findGlyph(char c) {
    for (const Glyph& g : kFont)
        if (g.c == c) return &g;
    return nullptr;
}

void fillRect(Framebuffer& f, int x0, int y0, int w, int h, std::uint32_t rgba) {
    for (int y = std::max(0, y0); y < std::min(f.height, y0 + h); ++y)
        for (int x = std::max(0, x0); x < std::min(f.width, x0 + w); ++x)
            f.color[f.index(x, y)] = rgba;
}

std::uint32_t packUnit(const glm::dvec3& c) {
    auto byte = [](double v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return packRgba(byte(c.r), byte(c.g), byte(c.b));
}

/// Width in pixels drawText() uses for `text` at `scale`.
int textWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (static_cast<int>(text.size()) * kAdvance - 1) * scale;
}

/// Draws `text` with its top-left corner at (x, y), `scale` frame pixels per font pixel, in
/// `rgba`; characters the font lacks are left blank and pixels outside the frame are skipped.
void drawText(Framebuffer& frame, int x, int y, std::string_view text, int scale,
              std::uint32_t rgba) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const Glyph* g = findGlyph(text[i]);
        if (!g) continue;
        const int gx = x + static_cast<int>(i) * kAdvance * scale;
        for (int row = 0; row < kGlyphH; ++row)
            for (int col = 0; col < kGlyphW; ++col)
                if (g->rows[row] & (4 >> col))
                    fillRect(frame, gx + col * scale, y + row * scale, scale, scale, rgba);
    }
}

}  // namespace

void drawDepthLegend(Framebuffer& frame, float depthNear, float depthFar) {
    if (frame.width < 64 || frame.height < 32) return;
    if (!std::isfinite(depthNear) || !std::isfinite(depthFar)) return;
    const int scale = frame.height >= 400 ? 2 : 1;
    const int margin = 4 * scale, barH = 6 * scale, textH = kGlyphH * scale;
    const int barW = std::min(frame.width - 2 * margin, 128 * scale);
    char nearText[32], farText[32];
    std::snprintf(nearText, sizeof nearText, "%.4g", static_cast<double>(depthNear));
    std::snprintf(farText, sizeof farText, "%.4g", static_cast<double>(depthFar));

    // A dark box behind bar and labels keeps them readable on any background.
    const int boxH = barH + textH + 3 * margin;
    const int x0 = margin, y0 = frame.height - margin - boxH;
    fillRect(frame, x0, y0, barW + 2 * margin, boxH, packRgba(0, 0, 0));
    const int barX = x0 + margin, barY = y0 + margin;
    for (int i = 0; i < barW; ++i) {
        const double t = barW > 1 ? static_cast<double>(i) / (barW - 1) : 0.0;
        fillRect(frame, barX + i, barY, 1, barH, packUnit(viridis(t)));
    }
    const int textY = barY + barH + margin;
    const std::uint32_t white = packRgba(255, 255, 255);
    drawText(frame, barX, textY, nearText, scale, white);
    drawText(frame, barX + barW - textWidth(farText, scale), textY, farText, scale, white);
}

}  // namespace facet
