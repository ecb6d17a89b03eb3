#include "sweep_extreme.hpp"

#include "facet/evaluation/frame_times.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/draw.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/settings.hpp"

namespace facet::app {
namespace {

using Clock = std::chrono::steady_clock;

/// The near distance of every case (the near-plane families cross it).
constexpr float kNear = 0.01f;

/// One draw: what the fast path gets, and what must come out of it, as the input the reference
/// draws (the same vertices, unless the case says some triangles must vanish).
struct Case {
    std::string family;
    std::string label;
    double param = 0.0;
    std::vector<glm::vec4> clip;
    std::vector<std::uint32_t> indices;
    /// What the reference draws when `expectInput` is false (possibly nothing at all).
    std::vector<glm::vec4> expectedClip;
    std::vector<std::uint32_t> expectedIndices;
    bool expectInput = true;  ///< the reference draws the input itself
};

/// A screen-space point (pixels) at depth w, as clip coordinates.
glm::vec4 atPixel(double x, double y, double w = 1.0) {
    return {static_cast<float>(x * w), static_cast<float>(y * w), static_cast<float>(w),
            static_cast<float>(w)};
}

/// A label like "L=3.16e+03": short, no comma (it is a CSV cell).
std::string label(const char* name, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s=%.3g", name, v);
    return buf;
}

/// 10^(k/perDecade) for k from lo·perDecade to hi·perDecade.
std::vector<double> logLadder(int loExp, int hiExp, int perDecade) {
    std::vector<double> v;
    for (int k = loExp * perDecade; k <= hiExp * perDecade; ++k)
        v.push_back(std::pow(10.0, static_cast<double>(k) / perDecade));
    return v;
}

/// A triangle of edge length `edge` around `centre`, its w varying so perspective matters.
std::vector<glm::vec4> equilateral(glm::dvec2 centre, double edge) {
    std::vector<glm::vec4> clip;
    const double r = edge / std::sqrt(3.0);
    for (int k = 0; k < 3; ++k) {
        const double a = 0.3 + 2.0 * std::numbers::pi * k / 3.0;
        clip.push_back(atPixel(centre.x + r * std::cos(a), centre.y + r * std::sin(a),
                               1.0 + 0.5 * std::sin(3.0 * a + 0.7 * k)));
    }
    return clip;
}

std::vector<Case> buildCases(bool quick, int w, int h) {
    std::vector<Case> cases;
    const std::vector<std::uint32_t> tri = {0, 1, 2};
    const int perDecade = quick ? 1 : 2;
    // A generic point (no pixel centre, no symmetry) and a pixel centre.
    const glm::dvec2 generic(0.49 * w + 0.137, 0.47 * h + 0.311);
    const glm::dvec2 pixelCentre(std::floor(w / 3.0) + 0.5, std::floor(h / 3.0) + 0.5);
    for (double edge : logLadder(-4, 6, perDecade)) {
        cases.push_back({"size", label("L", edge), edge, equilateral(generic, edge), tri, {}, {}});
        cases.push_back({"size_pixel_centre",
                         label("L", edge),
                         edge,
                         equilateral(pixelCentre, edge),
                         tri,
                         {},
                         {}});
    }
    // Slivers: the edge functions' cross products near zero, the worst case for setup rounding.
    for (const double length : {1e3, 1e6}) {
        for (double aspect : logLadder(0, 6, perDecade)) {
            const double angle = 0.37;
            const glm::dvec2 dir(std::cos(angle), std::sin(angle));
            const glm::dvec2 normal(-dir.y, dir.x);
            const glm::dvec2 a = generic - 0.5 * length * dir, b = generic + 0.5 * length * dir;
            const glm::dvec2 c = generic + (length / aspect) * normal;
            cases.push_back(
                {length < 1e4 ? "sliver" : "sliver_long",
                 label("A", aspect),
                 aspect,
                 {atPixel(a.x, a.y, 1.0), atPixel(b.x, b.y, 1.5), atPixel(c.x, c.y, 0.8)},
                 tri,
                 {},
                 {}});
        }
    }
    // Far vertices: at 1e7 px a float's spacing is a whole pixel. A thin wedge through the
    // image from far outside the guard band, and a triangle with one far vertex at w = 3.
    const glm::dvec2 mid(0.5 * w + 0.1, 0.5 * h + 0.2);
    for (double m : logLadder(2, 7, perDecade)) {
        cases.push_back({"far_wedge",
                         label("M", m),
                         m,
                         {atPixel(mid.x - m, mid.y - 0.5 * m), atPixel(mid.x + m, mid.y + 0.5 * m),
                          atPixel(mid.x + m, mid.y + 0.5 * m + 9.0)},
                         tri,
                         {},
                         {}});
        cases.push_back({"far_vertex",
                         label("M", m),
                         m,
                         {atPixel(0.16 * w, 0.12 * h, 1.0), atPixel(0.84 * w, 0.9 * h, 2.0),
                          atPixel(mid.x - m, mid.y + m, 3.0)},
                         tri,
                         {},
                         {}});
    }
    // Through the near plane (0.01): one vertex's w from in front, onto the plane, behind it.
    const std::vector<double> ws =
        quick ? std::vector<double>{1.0, 0.0101, 0.01, 0.0099, 1e-4, 0.0, -1e-4, -1.0}
              : std::vector<double>{2.0,  1.0,  0.1, 0.02,  0.0101, 0.01,  0.0099, 0.005,
                                    1e-4, 1e-7, 0.0, -1e-7, -1e-4,  -0.01, -1.0,   -100.0};
    const glm::vec4 p0 = atPixel(0.15 * w, 0.2 * h, 2.0), p1 = atPixel(0.8 * w, 0.25 * h, 1.0);
    for (double wv : ws) {
        cases.push_back({"near_vertex",
                         label("w", wv),
                         wv,
                         {p0, p1, atPixel(0.45 * w + 0.3, 0.85 * h + 0.1, wv)},
                         tri,
                         {},
                         {}});
        // Clip x, y fixed: the projected pixel runs off to ±infinity as w goes to 0.
        const auto fw = static_cast<float>(wv);
        cases.push_back({"near_fixed_clip",
                         label("w", wv),
                         wv,
                         {p0, p1,
                          glm::vec4(static_cast<float>(0.45 * w + 0.3),
                                    static_cast<float>(0.85 * h + 0.1), fw, fw)},
                         tri,
                         {},
                         {}});
    }
    // Non-finite clip coordinates: the triangle has no position and must vanish, sparing a good
    // triangle drawn after it. z is never read (depth is 1/(interpolated 1/w)), so a NaN z
    // draws as a finite one would.
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf = std::numeric_limits<float>::infinity();
    struct Bad {
        const char* name;
        glm::vec4 v;
    };
    const glm::vec4 base = atPixel(0.3 * w, 0.6 * h, 1.0);
    const std::vector<Bad> bads = {
        {"x=nan", {nan, base.y, base.z, base.w}},   {"y=nan", {base.x, nan, base.z, base.w}},
        {"z=nan", {base.x, base.y, nan, base.w}},   {"w=nan", {base.x, base.y, base.z, nan}},
        {"x=+inf", {inf, base.y, base.z, base.w}},  {"x=-inf", {-inf, base.y, base.z, base.w}},
        {"y=+inf", {base.x, inf, base.z, base.w}},  {"w=+inf", {base.x, base.y, base.z, inf}},
        {"w=-inf", {base.x, base.y, base.z, -inf}}, {"all=+inf", {inf, inf, inf, inf}},
        {"xy=-inf", {-inf, -inf, inf, inf}},        {"all=nan", {nan, nan, nan, nan}},
    };
    const glm::vec4 b1 = atPixel(0.9 * w, 0.1 * h, 1.5), b2 = atPixel(0.7 * w, 0.95 * h, 0.7);
    const std::vector<glm::vec4> good = {atPixel(0.06 * w, 0.08 * h, 1.0),
                                         atPixel(0.95 * w, 0.2 * h, 2.0),
                                         atPixel(0.3 * w, 0.92 * h, 0.5)};
    for (std::size_t k = 0; k < bads.size(); ++k) {
        const bool zOnly = std::string(bads[k].name) == "z=nan";
        std::vector<glm::vec4> fixedZ = {bads[k].v, b1, b2};
        fixedZ[0].z = fixedZ[0].w;
        const auto param = static_cast<double>(k);
        // Alone: nothing may draw (but the NaN-z triangle, which draws as with a finite z).
        cases.push_back({"nonfinite",
                         bads[k].name,
                         param,
                         {bads[k].v, b1, b2},
                         tri,
                         zOnly ? fixedZ : std::vector<glm::vec4>{},
                         zOnly ? tri : std::vector<std::uint32_t>{},
                         false});
        // Then a good triangle in the same draw: it draws exactly as alone.
        std::vector<glm::vec4> mixed = {bads[k].v, b1, b2, good[0], good[1], good[2]};
        std::vector<glm::vec4> expected = zOnly ? fixedZ : std::vector<glm::vec4>{b1, b1, b1};
        expected.insert(expected.end(), good.begin(), good.end());
        cases.push_back({"nonfinite_mixed",
                         bads[k].name,
                         param,
                         mixed,
                         {0, 1, 2, 3, 4, 5},
                         expected,
                         zOnly ? std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}
                               : std::vector<std::uint32_t>{3, 4, 5},
                         false});
    }
    return cases;
}

/// Vertex colours: red, green, blue around each triangle, so interpolation errors show.
std::vector<glm::vec3> cornerColors(std::size_t n) {
    std::vector<glm::vec3> c;
    for (std::size_t i = 0; i < n; ++i)
        c.emplace_back(i % 3 == 0 ? 1.0f : 0.0f, i % 3 == 1 ? 1.0f : 0.0f,
                       i % 3 == 2 ? 1.0f : 0.0f);
    return c;
}

ExtremePoint measure(const Case& c, int step, int w, int h, int frames, Renderer& renderer,
                     Framebuffer& fb) {
    ExtremePoint p;
    p.family = c.family;
    p.label = c.label;
    p.step = step;
    p.param = c.param;
    p.width = w;
    p.height = h;
    RenderSettings s;
    s.interp = Interp::Perspective;
    // One thread: the triangle's own cost, not the thread pool's hand-off.
    s.threads = 1;
    const std::vector<glm::vec3> colors = cornerColors(c.clip.size());
    const DrawInput input{
        .clip = c.clip, .colors = colors, .indices = c.indices, .nearPlane = kNear};
    const std::uint32_t background = rgbaFromHex(s.background);
    fb.resize(w, h);
    // A warm-up draw, then the timed ones, each on a cleared frame so every draw does the same
    // work (the depth test would reject a second pass).
    std::vector<double> us;
    RenderStats stats;
    for (int f = 0; f <= std::max(1, frames); ++f) {
        fb.clear(background);
        const Clock::time_point t0 = Clock::now();
        if (Result<RenderStats> r = facet::draw(renderer, input, s, fb)) stats = r.value();
        const double t = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
        if (f > 0) us.push_back(t);
    }
    const FrameTimes times = summarize(std::move(us));
    p.frames = times.frames;
    p.fastUs = times.median;
    p.fastUsMin = times.min;
    p.fastUsMax = times.max;
    p.fragments = stats.fragments;
    p.clipped = stats.trianglesClipped;
    // The reference sees exactly the floats the fast path sees (or what must remain of them),
    // so any difference is the rasterizer's, not the input's rounding.
    const std::vector<glm::vec4>& eClip = c.expectInput ? c.clip : c.expectedClip;
    const std::vector<std::uint32_t>& eIdx = c.expectInput ? c.indices : c.expectedIndices;
    const std::vector<glm::dvec4> clipD(eClip.begin(), eClip.end());
    std::vector<glm::dvec3> colorsD;
    for (const glm::vec3& col : cornerColors(eClip.size())) colorsD.emplace_back(col);
    const Clock::time_point t0 = Clock::now();
    const reference::Image ref = reference::draw(
        {.clip = clipD, .colors = colorsD, .indices = eIdx, .nearPlane = kNear}, s, w, h);
    p.refMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    p.diff = compareWithReference(fb, ref, s.shader, s.background);
    for (std::size_t i = 0; i < ref.depth.size(); ++i)
        p.mustDraw = p.mustDraw || (!ref.ambiguous[i] && std::isfinite(ref.depth[i]));
    p.exactColor = true;
    return p;
}

}  // namespace

std::vector<ExtremePoint> sweepExtreme(const SweepOptions& options) {
    const int w = options.quick ? 64 : 256, h = options.quick ? 48 : 192;
    std::vector<Case> cases = buildCases(options.quick, w, h);
    // Grouped by family (in the order they first appear), in sweep order within each: the CSV
    // reads as one block per family and `step` counts within it.
    std::vector<std::string> order;
    for (const Case& c : cases)
        if (std::find(order.begin(), order.end(), c.family) == order.end())
            order.push_back(c.family);
    auto rank = [&](const Case& c) {
        return std::find(order.begin(), order.end(), c.family) - order.begin();
    };
    std::stable_sort(cases.begin(), cases.end(),
                     [&](const Case& a, const Case& b) { return rank(a) < rank(b); });
    std::vector<ExtremePoint> points;
    Renderer renderer;
    Framebuffer fb;
    int step = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        step = i > 0 && cases[i - 1].family == cases[i].family ? step + 1 : 0;
        options.report("extreme: " + cases[i].family + " " + cases[i].label);
        points.push_back(measure(cases[i], step, w, h, options.frames, renderer, fb));
    }
    return points;
}

SweepTable extremeTable(const std::vector<ExtremePoint>& points) {
    SweepTable t;
    t.name = "extreme";
    t.title = "Extreme triangles: fast path (one thread) against the reference";
    if (!points.empty())
        t.title += ", " + std::to_string(points[0].width) + "x" + std::to_string(points[0].height);
    t.columns = {"family",  "label",       "step",        "param",  "width",     "height",
                 "fast_us", "fast_us_min", "fast_us_max", "ref_ms", "fragments", "clipped"};
    for (std::string& c : referenceDiffColumns()) t.columns.push_back(std::move(c));
    t.columns.insert(t.columns.end(), {"must_draw", "exact_color"});
    for (const ExtremePoint& p : points) {
        std::vector<std::string> row{p.family,
                                     p.label,
                                     cell(p.step),
                                     cell(p.param),
                                     cell(p.width),
                                     cell(p.height),
                                     cell(p.fastUs),
                                     cell(p.fastUsMin),
                                     cell(p.fastUsMax),
                                     cell(p.refMs),
                                     cell(static_cast<double>(p.fragments)),
                                     cell(static_cast<double>(p.clipped))};
        for (std::string& c : referenceDiffCells(p.diff)) row.push_back(std::move(c));
        row.insert(row.end(), {cell(p.mustDraw ? 1.0 : 0.0), cell(p.exactColor ? 1.0 : 0.0)});
        t.add(std::move(row));
    }
    return t;
}

}  // namespace facet::app
