#version 330 core
// The OpenGL twin's fragment stage: the course's shaders (spec §6–§8) on the varyings of
// twin.vert. #defines from the renderer, besides those of twin.vert:
//   DEPTH_SHADER  write a marker (alpha 0); the renderer maps depth to viridis after readback
//   COMBINE       texel × (lit) colour instead of the bare texel
//   TEXTURE_LOD0  lines and points sample level 0, as the engine does (no derivatives there)

#ifdef VARY_COLOR
INTERP in vec3 vColor;
#endif
#ifdef TEXTURE
INTERP in vec2 vUv;
uniform sampler2D tex;  // the filter and repeat wrap are the texture's own state
#endif
#ifdef PHONG
INTERP in vec3 vNormal;
INTERP in vec3 vPosition;
#endif

uniform vec3 baseColor;  // the colour without a colour varying: white, red for normals

out vec4 fragColor;

void main() {
#ifdef DEPTH_SHADER
    // The colour needs the depth range of the finished frame: a post-process.
    fragColor = vec4(0.0);
#else
    vec3 rgb = baseColor;
#ifdef VARY_COLOR
    rgb = vColor;
#endif
#ifdef PHONG
    // Interpolated normals are shorter than 1 between vertices: renormalise.
    rgb = shade(rgb, lightIntensity(vPosition, normalizeOrZero(vNormal)));
#endif
#ifdef TEXTURE
#ifdef TEXTURE_LOD0
    vec3 texel = textureLod(tex, vUv, 0.0).rgb;
#else
    vec3 texel = texture(tex, vUv).rgb;
#endif
#ifdef COMBINE
    rgb = texel * rgb;
#else
    rgb = texel;
#endif
#endif
    fragColor = vec4(rgb, 1.0);
#endif
}
