// The twin's frame: choose the shader variant, upload the streams it reads, draw the main pass
// and the normals, read back, then the post-processes the engine also runs after drawing
// (depth colours, legend).

#include "gl_renderer.hpp"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "facet/advanced/fast_lighting.hpp"
#include "facet/camera.hpp"
#include "facet/legend.hpp"
#include "facet/mesh.hpp"
#include "facet/multisample.hpp"
#include "facet/normals.hpp"
#include "facet/render.hpp"
#include "gl_depth_colors.hpp"
#include "gl_lines.hpp"
#include "gl_program.hpp"
#include "gl_state.hpp"
#include "gl_streams.hpp"
#include "gl_target.hpp"
#include "gl_texture.hpp"
#include "gl_variant.hpp"

namespace facet {
namespace gl {

/// Everything the renderer keeps between frames.
struct RendererState {
    ShaderSources sources;
    bool clipControl = false;                 ///< glClipControl available (exact depth)
    std::map<std::string, Program> programs;  ///< built variants, by their #defines
    RenderTarget target;
    VertexStreams mesh;     ///< the scene's vertices
    VertexStreams normals;  ///< the normals display's segments
    TextureCache texture;
    WireframeIndices wireframe;
    std::vector<glm::vec3> vertexNormals;  ///< the uploaded mesh's, when lit or displayed
    std::vector<glm::vec3> segments;       ///< normals display: two world points per vertex
    std::vector<float> rangeDepth;         ///< Depth shader with normals: depth before the normals
    std::string device;                    ///< GL_RENDERER
    // What the last upload() sent, so draw() can refuse a scene it did not send; holding the
    // sources keeps their addresses from being reused by others while they are resident.
    std::shared_ptr<const Mesh> residentMesh;
    std::shared_ptr<const Texture> residentTexture;
    std::string residentKey;
    int drawnWidth = 0, drawnHeight = 0;  ///< the last draw()'s frame; 0: nothing to read
};

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/// A vector of glm vectors as the floats GL reads.
template <class V>
std::span<const float> floats(const std::vector<V>& v) {
    static_assert(sizeof(V) == V::length() * sizeof(float), "tightly packed floats");
    return {reinterpret_cast<const float*>(v.data()), v.size() * V::length()};
}

/// The program of a variant, built on first use.
Result<GLuint> programFor(RendererState& s, const std::string& defines) {
    auto it = s.programs.find(defines);
    if (it == s.programs.end()) {
        Result<Program> built = buildProgram(s.sources, defines);
        if (!built) return built.error();
        it = s.programs.emplace(defines, std::move(built).value()).first;
    }
    return it->second.get();
}

/// Uniforms every variant of a frame shares.
struct FrameUniforms {
    glm::mat4 clipFromWorld;
    glm::vec2 viewport;
    float nearPlane;
    int pointSize;
    FastLighting lighting;
    glm::vec3 eye;
};

/// Binds `program` and sets its uniforms; those a variant does not use are ignored by GL.
void useProgram(GLuint program, const FrameUniforms& u, const glm::vec3& baseColor) {
    glUseProgram(program);
    auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    glUniformMatrix4fv(at("clipFromWorld"), 1, GL_FALSE, glm::value_ptr(u.clipFromWorld));
    glUniform2f(at("viewport"), u.viewport.x, u.viewport.y);
    glUniform1f(at("nearPlane"), u.nearPlane);
    glUniform1i(at("pointSize"), u.pointSize);
    const FastLighting& l = u.lighting;
    glUniform4f(at("light"), l.light.x, l.light.y, l.light.z, l.light.w);
    glUniform4f(at("lightTerms"), l.ambientTerm, l.diffuse, l.specular, l.shininess);
    glUniform3f(at("eye"), u.eye.x, u.eye.y, u.eye.z);
    glUniform3f(at("baseColor"), baseColor.r, baseColor.g, baseColor.b);
    glUniform1i(at("tex"), 0);
}

/// LESS on Z is GREATER on the stored nearPlane / Z (twin.vert); Simple tests nothing and, as
/// GL writes depth only while testing, leaves the depth empty like the engine.
void setDepthTest(bool tested) {
    if (tested) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
}

/// Fills the mesh streams the variant reads; returns the bytes sent.
std::size_t uploadMesh(RendererState& s, const Mesh& mesh, const Variant& v,
                       const std::vector<glm::vec3>& normals) {
    VertexStreams& m = s.mesh;
    std::size_t bytes = m.upload(Attribute::Position, floats(mesh.positions), 3);
    if (v.color && mesh.hasColors())
        bytes += m.upload(Attribute::Color, floats(mesh.colors), 3);
    else
        m.constant(Attribute::Color, glm::vec4(1.0f));  // no colours: white
    if (v.texture && mesh.hasUvs())
        bytes += m.upload(Attribute::Uv, floats(mesh.uvs), 2);
    else
        m.constant(Attribute::Uv, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    if (v.gouraud || v.phong)
        bytes += m.upload(Attribute::Normal, floats(normals), 3);
    else
        m.constant(Attribute::Normal, glm::vec4(0.0f));
    m.setDivisor(v.mode == DrawMode::Vertices ? 1 : 0);
    if (v.mode == DrawMode::Solid) bytes += m.uploadIndices(mesh.indices);
    if (v.mode == DrawMode::Wireframe) {
        s.wireframe.build(mesh);
        bytes += m.uploadIndices(s.wireframe.indices);
    }
    return bytes;
}

/// What upload() sends for these settings beyond the mesh and texture: the variant, the
/// texture filter (which levels go up) and the normals display's segments.
std::string residentKey(const std::string& defines, const RenderSettings& settings) {
    return defines + "|filter " + std::to_string(static_cast<int>(settings.filter)) + "|normals " +
           (settings.showNormals ? std::to_string(settings.normalLength) : std::string("off"));
}

/// The normals display (spec §8): a red segment from each vertex with a normal; their
/// positions, sent with the mesh. Returns the bytes sent.
std::size_t uploadNormals(RendererState& s, const Scene& scene, const RenderSettings& settings,
                          GlStats& stats) {
    const Mesh& mesh = *scene.mesh;
    const float length = settings.normalLength > 0.0 ? static_cast<float>(settings.normalLength)
                                                     : normalDisplayLength(mesh);
    normalSegments(mesh, s.vertexNormals, length, s.segments);
    stats.normalsDrawn = s.segments.size() / 2;
    if (s.segments.empty()) return 0;
    return s.normals.upload(Attribute::Position, floats(s.segments), 3);
}

/// Draws the normals display after the main pass; under the depth test except with Simple, as
/// in the engine.
Status drawNormals(RendererState& s, const RenderSettings& settings, const FrameUniforms& u) {
    if (s.segments.empty()) return {};
    const Variant lines{.mode = DrawMode::Wireframe};
    const Result<GLuint> program = programFor(s, definesFor(lines, s.clipControl));
    if (!program) return program.error();
    setDepthTest(settings.shader != ShaderKind::Simple);
    glDisable(GL_CULL_FACE);
    useProgram(program.value(), u, glm::vec3(1.0f, 0.0f, 0.0f));
    s.normals.bind();
    drawLines(false, s.segments.size(), s.segments.size());
    return {};
}

}  // namespace
}  // namespace gl

Result<GlRenderer> GlRenderer::create() {
    if (glGetString(GL_VERSION) == nullptr)
        return Error{{"OpenGL twin", 0}, "no current OpenGL context"};
    if (epoxy_gl_version() < 33 || !epoxy_is_desktop_gl())
        return Error{{"OpenGL twin", 0},
                     "needs desktop OpenGL 3.3 core, the context has " +
                         std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION)))};
    Result<gl::ShaderSources> sources = gl::loadShaderSources();
    if (!sources) return sources.error();
    auto state = std::make_unique<gl::RendererState>();
    state->sources = std::move(sources).value();
    state->clipControl = epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_clip_control");
    if (const GLubyte* device = glGetString(GL_RENDERER))
        state->device = reinterpret_cast<const char*>(device);
    return GlRenderer(std::move(state));
}

std::string GlRenderer::differences(const RenderSettings& settings) {
    // The same limits gl_twin_test's tolerances state; rounding (1 LSB) is not worth a line.
    std::string lines;
    if (settings.interp == Interp::Subdivided)
        lines += "subdivided interpolation is drawn perspective-correct (no spans in GLSL)\n";
    if (settings.shader == ShaderKind::Texture && settings.filter == TextureFilter::Trilinear)
        lines += "trilinear: GL picks the mip level per 2x2 pixels, with 8-bit fractions\n";
    if (settings.mode == DrawMode::Wireframe || settings.showNormals)
        lines += "lines follow GL's rules, not Bresenham: a few line pixels differ\n";
    if (settings.view != DebugView::None)
        lines += "debug views are the CPU engine's: the twin draws the shaded image\n";
    if (settings.mode == DrawMode::Solid && settings.supersample > 1)
        lines += "one sample per pixel: the twin does not supersample\n";
    if (settings.mode == DrawMode::Solid && msaaSamples(settings.msaa) > 1) {
        lines +=
            "MSAA: edge pixels are shaded at the centre even outside the triangle (the "
            "engine: at the covered samples' centroid)\n";
        if (settings.shader == ShaderKind::Depth)
            lines += "MSAA depth image: coloured from one sample's depth per pixel\n";
        if (settings.showNormals) lines += "MSAA: the normals display is multisampled too\n";
    }
    if (settings.mode == DrawMode::Solid && settings.subPixelBits != kMaxSubPixelBits)
        lines += "the driver snaps to its own sub-pixel grid, not the chosen bits\n";
    if (!lines.empty()) lines.pop_back();
    return lines;
}

const std::string& GlRenderer::device() const {
    return state_->device;
}

GlRenderer::GlRenderer(std::unique_ptr<gl::RendererState> state) : state_(std::move(state)) {}
GlRenderer::GlRenderer(GlRenderer&& other) noexcept = default;
GlRenderer& GlRenderer::operator=(GlRenderer&& other) noexcept = default;
GlRenderer::~GlRenderer() = default;

Result<GlStats> GlRenderer::render(const Scene& scene, const RenderSettings& settings,
                                   Framebuffer& frame) {
    GlStats stats;
    if (Status st = upload(scene, settings, stats); !st) return st.error();
    if (Status st = draw(scene, settings, stats); !st) return st.error();
    if (Status st = readBack(scene, settings, frame, stats); !st) return st.error();
    return stats;
}

Status GlRenderer::upload(const Scene& scene, const RenderSettings& settings, GlStats& stats) {
    using namespace gl;
    RendererState& s = *state_;
    const auto t0 = Clock::now();
    const Mesh& mesh = *scene.mesh;
    const Variant v = variantFor(settings, mesh);
    const StateGuard guard(s.clipControl);
    // Forget the last upload first: a failure below leaves nothing draw() would take for it.
    s.residentMesh.reset();
    s.residentKey.clear();
    s.drawnWidth = s.drawnHeight = 0;
    const std::string defines = definesFor(v, s.clipControl);
    // The first frame of a variant builds its program; an application does so once, too.
    const Result<GLuint> program = programFor(s, defines);
    if (!program) return program.error();
    s.vertexNormals.clear();
    if (v.gouraud || v.phong || settings.showNormals) s.vertexNormals = computeVertexNormals(mesh);
    stats.uploadBytes += uploadMesh(s, mesh, v, s.vertexNormals);
    s.segments.clear();
    if (settings.showNormals) stats.uploadBytes += uploadNormals(s, scene, settings, stats);
    if (v.texture) stats.uploadBytes += s.texture.bind(scene.texture, settings.filter);
    s.residentMesh = scene.mesh;
    s.residentTexture = v.texture ? scene.texture : nullptr;
    s.residentKey = residentKey(defines, settings);
    stats.uploadMs += msBetween(t0, Clock::now());
    return {};
}

Status GlRenderer::draw(const Scene& scene, const RenderSettings& settings, GlStats& stats) {
    using namespace gl;
    RendererState& s = *state_;
    const auto t0 = Clock::now();
    const Camera& cam = scene.camera;
    const Mesh& mesh = *scene.mesh;
    const Variant v = variantFor(settings, mesh);
    const std::string defines = definesFor(v, s.clipControl);
    if (s.residentMesh != scene.mesh || (v.texture && s.residentTexture != scene.texture) ||
        s.residentKey != residentKey(defines, settings))
        return Error{{"OpenGL twin", 0},
                     "draw() of a mesh, texture or variant the last upload() did not send"};
    const StateGuard guard(s.clipControl);
    // Multisampling as the engine does it: triangles only (Solid mode).
    const int samples = settings.mode == DrawMode::Solid ? msaaSamples(settings.msaa) : 1;
    if (Status st = s.target.resize(cam.width, cam.height, samples); !st) return st.error();
    const Result<GLuint> program = programFor(s, defines);
    if (!program) return program.error();
    const float nearPlane = static_cast<float>(resolveNearPlane(settings, mesh));
    // The matrix is built in double and used in float, as the engine does.
    const FrameUniforms u{glm::mat4(clipFromWorld(cam)),
                          glm::vec2(static_cast<float>(cam.width), static_cast<float>(cam.height)),
                          nearPlane,
                          settings.pointSize,
                          prepareLighting(scene.lighting),
                          glm::vec3(cam.eye)};

    s.target.bind();
    if (s.clipControl) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    const std::uint32_t bg = settings.background;
    glClearColor(static_cast<float>((bg >> 16) & 0xFF) / 255.0f,
                 static_cast<float>((bg >> 8) & 0xFF) / 255.0f,
                 static_cast<float>(bg & 0xFF) / 255.0f, 1.0f);
    glClearDepth(0.0);  // stored depth is nearPlane / Z: 0 is infinitely far
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    setDepthTest(settings.shader != ShaderKind::Simple);
    if (settings.mode == DrawMode::Solid && settings.cullBackFaces) {
        // Window coordinates are pixel coordinates (y down), where the engine's front faces
        // (CCW from outside in the world) have a negative signed area: clockwise to GL.
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CW);
        glCullFace(GL_BACK);
    }
    if (v.texture) s.texture.bind(scene.texture, settings.filter);  // resident: binds only
    useProgram(program.value(), u, glm::vec3(1.0f));
    s.mesh.bind();
    switch (settings.mode) {
        case DrawMode::Solid:
            stats.trianglesIn = mesh.indices.size() / 3;
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(stats.trianglesIn * 3),
                           GL_UNSIGNED_INT, nullptr);
            break;
        case DrawMode::Wireframe:
            stats.linesDrawn = s.wireframe.edgeIndices / 2;
            drawLines(true, s.wireframe.edgeIndices,
                      s.wireframe.indices.size() - s.wireframe.edgeIndices);
            break;
        case DrawMode::Vertices:
            // Six corners (two triangles) per instance, one instance per vertex.
            stats.pointsDrawn = mesh.vertexCount();
            glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(stats.pointsDrawn));
            break;
    }
    if (settings.showNormals) {
        // The engine colours depth before it draws the normals: take the range now.
        if (v.depthShader) {
            s.target.resolve();
            s.target.readDepth(s.rangeDepth, nearPlane);
            s.target.bind();
        }
        stats.normalsDrawn = s.segments.size() / 2;
        if (Status st = drawNormals(s, settings, u); !st) return st.error();
    }
    // The draw's time is the CPU clock up to glFinish: on llvmpipe that is exactly the work
    // (its GL_TIME_ELAPSED queries came back as noise: 0.5–3.8 ms for a 12 ms draw, and
    // 9.8e6 ms on the first frame); on a GPU it adds the submission, an honest upper bound.
    s.target.resolve();  // part of the draw's time, as the engine's resolve is
    glFinish();
    s.drawnWidth = cam.width;
    s.drawnHeight = cam.height;
    stats.drawMs += msBetween(t0, Clock::now());
    return {};
}

Status GlRenderer::readBack(const Scene& scene, const RenderSettings& settings, Framebuffer& frame,
                            GlStats& stats) {
    using namespace gl;
    RendererState& s = *state_;
    const auto t0 = Clock::now();
    if (s.drawnWidth != scene.camera.width || s.drawnHeight != scene.camera.height)
        return Error{{"OpenGL twin", 0}, "readBack() without a draw() of this size"};
    const StateGuard guard(s.clipControl);
    frame.resize(scene.camera.width, scene.camera.height);
    const float nearPlane = static_cast<float>(resolveNearPlane(settings, *scene.mesh));
    s.target.readColor(frame);
    s.target.readDepth(frame.depth, nearPlane);
    if (variantFor(settings, *scene.mesh).depthShader) {
        const DepthRange range =
            colorDepth(frame, settings.showNormals ? s.rangeDepth : frame.depth);
        stats.depthNear = range.nearest;
        stats.depthFar = range.farthest;
        if (settings.depthLegend && range.farthest > 0.0f)
            drawDepthLegend(frame, range.nearest, range.farthest);
    }
    stats.readbackMs += msBetween(t0, Clock::now());
    return {};
}

}  // namespace facet
