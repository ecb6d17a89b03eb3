// spec §6 in GLSL for the OpenGL twin, the same rules as facet::lightIntensity (float
// version, lighting.hpp), shared by the vertex stage (Gouraud) and the fragment stage (Phong):
//   I = Ia·Ka + Id · ( Kd · max(0, n·l) + Ks · max(0, n·h)^s ),  nothing but Ia·Ka where n·l ≤ 0.
// The renderer inserts this file after the #defines of both stages.

uniform vec4 light;       // FastLighting::light: w ≥ 0, largest |component| 1
uniform vec4 lightTerms;  // Ia·Ka, Id·Kd, Id·Ks, s
uniform vec3 eye;         // camera centre, world space

// An undefined direction is zero, never NaN: it then adds no diffuse or specular term.
vec3 normalizeOrZero(vec3 v) {
    float length2 = dot(v, v);
    return length2 > 0.0 ? v * (1.0 / sqrt(length2)) : vec3(0.0);
}

// nh^s with lighting.hpp's rules, which GLSL's pow() leaves undefined (0^0, x = 0) or gets
// wrong (1^inf is NaN through exp2(s·log2 x)): 0^0 = 1, 1^s = 1 for any s, 0^s = 0 for s > 0.
float specularPower(float nh, float s) {
    if (s == 0.0 || nh >= 1.0) return 1.0;
    if (nh <= 0.0) return 0.0;
    return pow(nh, s);
}

// I at point p (world space) with normal n (unit or zero).
float lightIntensity(vec3 p, vec3 n) {
    // w ≥ 0: xyz − w·p points at a point light, and is the direction of a directional one.
    vec3 l = normalizeOrZero(light.xyz - light.w * p);
    vec3 v = normalizeOrZero(eye - p);
    vec3 h = normalizeOrZero(l + v);
    float nl = dot(n, l);
    float nh = clamp(dot(n, h), 0.0, 1.0);
    float lit = lightTerms.y * nl + lightTerms.z * specularPower(nh, lightTerms.w);
    return lightTerms.x + (nl > 0.0 ? lit : 0.0);
}

// The lit colour clamp(rgb · I, 0, 1).
vec3 shade(vec3 rgb, float intensity) {
    return clamp(rgb * intensity, 0.0, 1.0);
}
