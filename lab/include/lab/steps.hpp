#pragma once
// The course's steps ("Rendering Pipeline: Do It Yourself"), as the functions a student writes.
//
// Each step lives in a file of lab/steps/ (the student's copy, a stub) and of lab/solution/
// (facet's answer); the build links one set or the other (CMake option FACET_LAB_SOLUTION, or
// FACET_LAB_STEPS_DIR for a handout). Everything else here is given: the types, the barycentric
// matrix C, the simple and painter shaders, and the renderer and checks (lab/src/).
//
// The course's meanings, which the checks hold every step to (spec §4 to §7):
//  - The camera looks down its +Z axis; y grows downwards in the image (with the course's
//    up = (0, -1, 0), world +Y is up on screen).
//  - The focal length f is in pixels; the image plane is at Z = f.
//  - Pixel (i, j) covers [i, i+1) × [j, j+1); the fragment of a pixel sits at its centre
//    (i + ½, j + ½). A projected point keeps its continuous coordinates (no rounding).
//  - Depth is the camera-space Z, kept through the projection; the nearer fragment wins.
//  - Colours are RGB in [0, 1].
//
// GLM matrices are indexed m[column][row], and a matrix literal lists columns, not rows.

#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace lab {

/// The steps in the course's order (assignment sections 3 to 7).
enum class Step : int {
    SetLookAt,              ///< Transformation: world -> camera
    SetProjection,          ///< Transformation: camera -> image plane (homogeneous)
    SetCalibration,         ///< Transformation: image plane -> pixels (K)
    ProjectPoints,          ///< Transformation: the three matrices applied, z kept
    RasterizeFace,          ///< Rasterizer: a triangle's pixels, attributes interpolated
    DepthBuffer,            ///< DepthBuffer: testFragment and writeFragment
    ComputeNormals,         ///< Mesh: vertex normals
    AmbientLight,           ///< AmbientLight::getContribution
    PointLight,             ///< PointLight::getContribution (diffuse and specular)
    TextureSample,          ///< Texture::sample with repetition
    TextureShader,          ///< the texture shader
    PerspectiveRasterizer,  ///< the perspective-correct rasterizer
};

/// Number of steps.
inline constexpr int kStepCount = 12;

/// The course's name of a step, e.g. "setLookAt", "DepthBuffer.testFragment/writeFragment".
std::string_view stepName(Step step);

/// Records that `step` is still the handout's stub: the checks then say "not started" and the
/// renderer lists it. Every stub calls this; a student's own code must not.
void markNotStarted(Step step);

/// markNotStarted(step), then `value`: what a stub returns.
template <class T>
T notStarted(Step step, T value) {
    markNotStarted(step);
    return value;
}

/// True when a stub of `step` ran since the last clearNotStarted().
bool wasNotStarted(Step step);

/// Forgets which stubs ran.
void clearNotStarted();

/// A point on the pixel grid with its attributes (the course's Fragment): a projected vertex,
/// or a pixel a rasterizer produced.
struct Fragment {
    /// Continuous pixel coordinates. A rasterizer's fragment of pixel (i, j) sits at the pixel
    /// centre (i + ½, j + ½).
    glm::dvec2 position{0.0};
    double depth = 0.0;      ///< camera-space Z (positive in front of the camera)
    glm::dvec3 color{1.0};   ///< RGB in [0, 1]
    glm::dvec3 normal{0.0};  ///< world-space normal (unit, or zero for none)
    glm::dvec2 uv{0.0};      ///< texture coordinates (may leave [0, 1]: the texture repeats)
};

/// The pixel a fragment falls in: (floor(x), floor(y)).
glm::ivec2 pixelOf(const Fragment& fragment);

/// The three matrices of the course's Transformation class.
struct Transformation {
    glm::dmat4 worldToCamera{1.0};  ///< setLookAt
    glm::dmat4x3 projection{0.0};   ///< setProjection: 3 rows, 4 columns
    glm::dmat3 calibration{1.0};    ///< setCalibration: K
};

// ---- Section 3: image formation (transformation.cpp) ----------------------------------------

/// Step 1. The 4×4 rigid transform from world to camera coordinates.
glm::dmat4 setLookAt(const glm::dvec3& eye, const glm::dvec3& lookAt, const glm::dvec3& up);

/// Step 2. The 3×4 projection onto the image plane in homogeneous coordinates.
glm::dmat4x3 setProjection();

/// Step 3. The 3×3 calibration matrix K (focal length and image size in pixels).
glm::dmat3 setCalibration(double focal, int width, int height);

/// Step 4. Each world point's pixel coordinates (x, y) and depth z.
std::vector<glm::dvec3> projectPoints(const Transformation& transformation,
                                      const std::vector<glm::dvec3>& points);

// ---- Section 4: triangle rasterization (rasterizer.cpp) -------------------------------------

/// Given: the course's matrix C (assignment eq. 2): C · (1, x, y) = (α, β, γ), the barycentric
/// coordinates of the point (x, y) with respect to the three fragments' positions. C is the
/// zero matrix for a triangle of zero area.
glm::dmat3 makeBarycentricCoordsMatrix(const Fragment& v1, const Fragment& v2, const Fragment& v3);

/// Step 5. Appends to `out` one fragment per pixel of the width × height image whose centre is
/// inside the triangle, every attribute interpolated linearly in the image and the colour
/// clamped to [0, 1].
void rasterizeFace(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                   int height, std::vector<Fragment>& out);

// ---- Section 5: depth buffering (depth_buffer.cpp) ------------------------------------------

/// The z-buffer: one depth per pixel, +infinity where nothing was drawn.
struct DepthBuffer {
    int width = 0;
    int height = 0;
    std::vector<double> depth;  ///< row-major, row 0 at the top

    /// Given: resizes to width × height and fills with +infinity.
    void clear(int newWidth, int newHeight);

    /// Step 6a. True when the fragment lies in the buffer and is nearer than what is stored.
    bool testFragment(const Fragment& fragment) const;

    /// Step 6b. Stores the fragment's depth at its pixel (nothing outside the buffer).
    void writeFragment(const Fragment& fragment);
};

// ---- Section 6: lighting (mesh.cpp, lights.cpp) ---------------------------------------------

/// Step 7. One unit normal per vertex: the normalised sum of the normals of the triangles
/// around it (zero when it has none).
std::vector<glm::dvec3> computeNormals(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::uint32_t>& indices);

/// The material coefficients of the .scene file.
struct Material {
    double ka = 0.5;  ///< ambient
    double kd = 0.5;  ///< diffuse
    double ks = 0.5;  ///< specular
    double s = 1.0;   ///< shininess exponent
};

/// The ambient light: intensity Ia.
struct AmbientLight {
    double intensity = 1.0;  ///< Ia

    /// Step 8. I_ambient.
    double getContribution(const Material& material) const;
};

/// The point light: homogeneous position (w = 0: a direction the light comes from), Id.
struct PointLight {
    glm::dvec4 position{0.0, 0.0, 0.0, 1.0};  ///< x y z w
    double intensity = 1.0;                   ///< Id

    /// Step 9. I_diffuse + I_specular at `point` with unit normal `normal`, seen from `eye`.
    double getContribution(const glm::dvec3& point, const glm::dvec3& normal, const glm::dvec3& eye,
                           const Material& material) const;
};

// ---- Section 7: texture mapping (texture.cpp, perspective_rasterizer.cpp) -------------------

/// An image to sample: RGB texels in [0, 1], row-major, row 0 at the top (v = 0).
struct Texture {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> texels;

    /// Given: the texel at column x, row y (no bounds check).
    glm::dvec3 at(int x, int y) const;

    /// Step 10. The colour at texture coordinates (u, v), the image repeated beyond [0, 1].
    glm::dvec3 sample(double u, double v) const;
};

/// What the shaders draw into: a colour per pixel and the depth buffer.
struct Canvas {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> color;  ///< row-major, row 0 at the top
    DepthBuffer depth;

    /// Given: resizes to width × height, colour `background`, depth +infinity.
    void clear(int newWidth, int newHeight, const glm::dvec3& background);
};

/// Given: the course's SimpleShader: writes the fragment's colour, no depth test (last wins).
void simpleShade(Canvas& canvas, const Fragment& fragment);

/// Given: the course's PainterShader: the depth test, then colour and depth.
void painterShade(Canvas& canvas, const Fragment& fragment);

/// Step 11. The texture shader: the depth test, then the texel at the fragment's uv as the
/// colour (times the fragment's colour when `combine`), and the depth.
void textureShade(Canvas& canvas, const Fragment& fragment, const Texture& texture, bool combine);

/// Step 12. rasterizeFace's pixels with the attributes interpolated perspective-correctly.
void rasterizeFacePerspective(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                              int height, std::vector<Fragment>& out);

}  // namespace lab
