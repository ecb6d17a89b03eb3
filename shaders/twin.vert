#version 330 core
// The OpenGL twin's vertex stage: facet's camera (spec §4, camera.hpp) into GL's clip
// space, Gouraud lighting per vertex, and the varyings the fragment stage needs. The renderer
// inserts one variant's #defines after the #version line:
//   POINTS            vertices mode: each instance is one mesh vertex drawn as a square
//   LINES             wireframe and normals: segments between pixel centres
//   INTERP            smooth (perspective-correct), noperspective (affine) or flat (points)
//   VARY_COLOR        a colour varying (vertex colour, lit when GOURAUD)
//   GOURAUD, PHONG    lighting per vertex / per fragment
//   TEXTURE           a uv varying
//   CLIP_ZERO_TO_ONE  glClipControl(GL_ZERO_TO_ONE) is on (see depthNdc)

layout(location = 0) in vec3 position;  // world space (the course has no model matrix)
layout(location = 1) in vec3 color;     // a constant white when the mesh has none
layout(location = 2) in vec2 uv;        // a constant (0, 0) when the mesh has none
layout(location = 3) in vec3 normal;    // unit or zero (normals.hpp)

uniform mat4 clipFromWorld;  // facet::clipFromWorld: clip = (f·X + w/2·Z, f·Y + h/2·Z, Z, Z)
uniform vec2 viewport;       // image width and height in pixels
uniform float nearPlane;     // facet::resolveNearPlane
uniform int pointSize;       // side of the vertex squares

#ifdef VARY_COLOR
INTERP out vec3 vColor;
#endif
#ifdef TEXTURE
INTERP out vec2 vUv;
#endif
#ifdef PHONG
INTERP out vec3 vNormal;
INTERP out vec3 vPosition;
#endif

// Depth is stored reversed, as nearPlane / Z: linear in screen space like 1/w, so GL
// interpolates it exactly as the engine interpolates 1/w, and a float keeps its relative
// precision at every distance (the usual 1 − n/Z loses it far away). The depth test is
// GREATER. With zero-to-one clip control z_clip = n gives z_ndc = n/Z and the clip rule
// z_clip ≤ w is the engine's near plane Z ≥ n. Without it z_clip = 2n − Z clips at the same
// plane and lands on the same window depth, through a subtraction that costs precision.
float depthClip(float w) {
#ifdef CLIP_ZERO_TO_ONE
    return nearPlane;
#else
    return 2.0 * nearPlane - w;
#endif
}

// Pixel space (x right, y down, origin at the image's top-left corner) to GL clip space. Image
// row y becomes window row y: the FBO's first row in memory is the image's top row, so the
// readback needs no flip, and GL's fill rule (which includes edges on the side of the smaller
// window y) is the engine's top-left rule.
vec4 glClip(vec4 c) {
    return vec4(2.0 * c.xy / viewport - c.w, depthClip(c.w), c.w);
}

#ifdef LINES
// Wireframe and normals: the engine's Bresenham line joins the centres of the pixels holding
// its ends (spec §8), so each end is moved there. llvmpipe draws a line as a thin
// parallelogram under the fill rule, which settles a tie (the line exactly between two pixel
// centres) towards the smaller x or y, where Bresenham rounds towards the larger: the nudge of
// two steps of GL's 1/256 px grid turns the ties (one step left 0.14% of the wireframe pixels
// different, two 0.07%, four 0.46%). An end behind the near plane is left for GL to clip.
vec4 lineEnd(vec4 c) {
    if (!(c.w >= nearPlane)) return glClip(c);
    vec2 centre = floor(c.xy / c.w) + 0.5 + 2.0 / 256.0;
    return vec4((2.0 * centre / viewport - 1.0) * c.w, depthClip(c.w), c.w);
}
#endif

#ifdef POINTS
// The engine's vertex square (spec §8): pixels px + lo … px + lo + size − 1 around the
// pixel (px, py) holding the vertex. Two triangles with edges on pixel borders cover exactly
// those pixels; GL points would drop squares whose centre is off-screen.
vec4 pointCorner(vec4 c) {
    if (!(c.w >= nearPlane)) return vec4(2.0, 2.0, 2.0, 1.0);  // outside every clip plane
    const vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
                                    vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
    float lo = float(-((pointSize - 1) / 2));
    vec2 pixel = floor(c.xy / c.w) + lo + corners[gl_VertexID] * float(pointSize);
    // w = 1: the square is flat at the vertex's depth, which reversed is nearPlane / Z.
    float z = depthClip(c.w) / c.w;
    return vec4(2.0 * pixel / viewport - 1.0, z, 1.0);
}
#endif

void main() {
    vec4 c = clipFromWorld * vec4(position, 1.0);
#if defined(POINTS)
    gl_Position = pointCorner(c);
#elif defined(LINES)
    gl_Position = lineEnd(c);
#else
    gl_Position = glClip(c);
#endif
#ifdef VARY_COLOR
#ifdef GOURAUD
    vColor = shade(color, lightIntensity(position, normal));
#else
    vColor = color;
#endif
#endif
#ifdef TEXTURE
    vUv = uv;
#endif
#ifdef PHONG
    vNormal = normal;
    vPosition = position;
#endif
}
