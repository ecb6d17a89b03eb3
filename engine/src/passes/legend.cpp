#include "facet/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>

#include "facet/colormap.hpp"

namespace facet {
namespace {

/// 3×5 glyphs, one row per 3-bit number (bit 2 = left column), top row first. Lower-case
/// letters are drawn as capitals, except 'e', which numbers in exponent form use.
struct Glyph {
    char c;
    std::uint8_t rows[5];
};
constexpr Glyph kFont[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'+', {0, 2, 7, 2, 0}}, {'e', {0, 7, 7, 4, 7}}, {'/', {1, 1, 2, 4, 4}}, {':', {0, 2, 0, 2, 0}},
    {'(', {1, 2, 2, 2, 1}}, {')', {4, 2, 2, 2, 4}}, {'A', {2, 5, 7, 5, 5}}, {'B', {6, 5, 6, 5, 6}},
    {'C', {3, 4, 4, 4, 3}}, {'D', {6, 5, 5, 5, 6}}, {'E', {7, 4, 6, 4, 7}}, {'F', {7, 4, 6, 4, 4}},
    {'G', {3, 4, 5, 5, 3}}, {'H', {5, 5, 7, 5, 5}}, {'I', {7, 2, 2, 2, 7}}, {'J', {1, 1, 1, 5, 2}},
    {'K', {5, 5, 6, 5, 5}}, {'L', {4, 4, 4, 4, 7}}, {'M', {5, 7, 7, 5, 5}}, {'N', {6, 5, 5, 5, 5}},
    {'O', {2, 5, 5, 5, 2}}, {'P', {6, 5, 6, 4, 4}}, {'Q', {2, 5, 5, 6, 3}}, {'R', {6, 5, 6, 5, 5}},
    {'S', {3, 4, 2, 1, 6}}, {'T', {7, 2, 2, 2, 2}}, {'U', {5, 5, 5, 5, 7}}, {'V', {5, 5, 5, 5, 2}},
    {'W', {5, 5, 7, 7, 5}}, {'X', {5, 5, 2, 5, 5}}, {'Y', {5, 5, 2, 2, 2}}, {'Z', {7, 1, 2, 4, 7}},
};
constexpr int kGlyphW = 3, kGlyphH = 5, kAdvance = 4;

const Glyph* findGlyph(char c) {
    for (const Glyph& g : kFont)
        if (g.c == c) return &g;
    if (c >= 'a' && c <= 'z') return findGlyph(static_cast<char>(c - 'a' + 'A'));
    return nullptr;
}

void fillRect(Framebuffer& f, int x0, int y0, int w, int h, std::uint32_t rgba) {
    for (int y = std::max(0, y0); y < std::min(f.height, y0 + h); ++y)
        for (int x = std::max(0, x0); x < std::min(f.width, x0 + w); ++x)
            f.color[f.index(x, y)] = rgba;
}

std::uint32_t packUnit(const glm::dvec3& c) {
    return packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
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

constexpr std::uint32_t kWhite = packRgba(255, 255, 255);
constexpr std::uint32_t kBlack = packRgba(0, 0, 0);

bool tooSmall(const Framebuffer& frame) {
    return frame.width < 64 || frame.height < 32;
}

/// A tick's text without owning it: the depth legend draws from stack buffers, so a frame
/// allocates nothing.
struct TickText {
    double t;
    std::string_view text;
};

void drawBar(Framebuffer& frame, std::string_view title, int bands, std::span<const TickText> ticks,
             int scale) {
    if (tooSmall(frame)) return;
    scale = std::max(1, scale);
    const int margin = 4 * scale, barH = 6 * scale, textH = kGlyphH * scale;
    const int titleW = textWidth(title, scale);
    const int barW = std::min(frame.width - 2 * margin, std::max(128 * scale, titleW));
    const int titleH = title.empty() ? 0 : textH + margin;

    // A dark box behind bar and labels keeps them readable on any background.
    const int boxH = titleH + barH + textH + 3 * margin;
    const int x0 = margin, y0 = frame.height - margin - boxH;
    fillRect(frame, x0, y0, barW + 2 * margin, boxH, kBlack);
    const int barX = x0 + margin;
    if (!title.empty()) drawText(frame, barX, y0 + margin, title, scale, kWhite);
    const int barY = y0 + margin + titleH;
    for (int i = 0; i < barW; ++i) {
        double t = barW > 1 ? static_cast<double>(i) / (barW - 1) : 0.0;
        if (bands > 1) {
            const int k = std::min(bands - 1, i * bands / barW);
            t = static_cast<double>(k) / (bands - 1);
        }
        fillRect(frame, barX + i, barY, 1, barH, packUnit(viridis(t)));
    }
    const int textY = barY + barH + margin;
    // From the right: the last tick (the top of the scale) always shows; one that would touch
    // the label to its right is left out ("10000100000" read as one number).
    int rightmost = barX + barW + 2 * scale;  // the left edge of the label drawn last
    for (std::size_t i = ticks.size(); i-- > 0;) {
        const TickText& tick = ticks[i];
        const int w = textWidth(tick.text, scale);
        const int centre = barX + static_cast<int>(std::lround(std::clamp(tick.t, 0.0, 1.0) *
                                                               static_cast<double>(barW - 1)));
        const int x = std::max(barX, std::min(centre - w / 2, barX + barW - w));
        if (x + w + 2 * scale > rightmost) continue;
        drawText(frame, x, textY, tick.text, scale, kWhite);
        rightmost = x;
    }
}

}  // namespace

int legendScale(int height) {
    return height >= 900 ? 3 : height >= 400 ? 2 : 1;
}

void drawLegend(Framebuffer& frame, const LegendBar& bar, int scale) {
    std::vector<TickText> ticks;
    for (const LegendTick& tick : bar.ticks) ticks.push_back({tick.t, tick.text});
    drawBar(frame, bar.title, bar.bands, ticks, scale);
}

void drawLegend(Framebuffer& frame, std::string_view title,
                const std::vector<LegendSwatch>& swatches, int scale) {
    if (tooSmall(frame)) return;
    scale = std::max(1, scale);
    const int margin = 4 * scale, textH = kGlyphH * scale, rowH = textH + margin;
    int w = textWidth(title, scale);
    for (const LegendSwatch& s : swatches)
        w = std::max(w, textH + margin + textWidth(s.text, scale));
    const int rows = static_cast<int>(swatches.size()) + (title.empty() ? 0 : 1);
    const int boxH = rows * rowH + margin;
    const int x0 = margin, y0 = frame.height - margin - boxH;
    fillRect(frame, x0, y0, w + 2 * margin, boxH, kBlack);
    int y = y0 + margin;
    if (!title.empty()) {
        drawText(frame, x0 + margin, y, title, scale, kWhite);
        y += rowH;
    }
    for (const LegendSwatch& s : swatches) {
        // A grey rim shows a black swatch against the black box.
        fillRect(frame, x0 + margin, y, textH, textH, packRgba(160, 160, 160));
        fillRect(frame, x0 + margin + scale, y + scale, textH - 2 * scale, textH - 2 * scale,
                 s.rgba);
        drawText(frame, x0 + 2 * margin + textH, y, s.text, scale, kWhite);
        y += rowH;
    }
}

void drawDepthLegend(Framebuffer& frame, float depthNear, float depthFar) {
    if (!std::isfinite(depthNear) || !std::isfinite(depthFar)) return;
    char nearText[32], farText[32];
    std::snprintf(nearText, sizeof nearText, "%.4g", static_cast<double>(depthNear));
    std::snprintf(farText, sizeof farText, "%.4g", static_cast<double>(depthFar));
    const TickText ticks[] = {{0.0, nearText}, {1.0, farText}};
    drawBar(frame, "", 0, ticks, frame.height >= 400 ? 2 : 1);
}

}  // namespace facet
