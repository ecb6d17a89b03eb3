// Steps 8 and 9 (assignment section 6, "Lighting – Gouraud shading"). The whole formula is
//   I = Ia·Ka + Id · (Kd · max(0, n·l) + Ks · max(0, n·h)^s)
// and each light returns its share. Write both, delete their notStarted lines, run
// `make lab-check`, and choose Gouraud lighting.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lab/steps.hpp"

namespace lab {

// Step 8. I_ambient = Ia · Ka (`intensity` is Ia).
double AmbientLight::getContribution(const Material& material) const {
    (void)material;
    return notStarted(Step::AmbientLight, 0.0);
}

// Step 9. I_diffuse + I_specular at `point` with unit normal `normal`, the camera at `eye`:
//  - l: unit vector from the point to the light; position.w == 0 means a light at infinity
//    coming from (x, y, z): l = normalize(x, y, z); else the light is at (x, y, z) / w;
//  - if n·l <= 0 the light is behind the surface: return 0 (no diffuse, and no highlight);
//  - diffuse = Kd · (n·l);
//  - v: unit vector from the point to the eye; h = normalize(l + v), the bisector;
//  - specular = Ks · max(0, n·h)^s (clamp n·h to [0, 1]: rounding may push it past 1);
//  - return Id · (diffuse + specular) (`intensity` is Id).
// A direction that cannot be normalised (zero length) is the zero vector, never NaN.
double PointLight::getContribution(const glm::dvec3& point, const glm::dvec3& normal,
                                   const glm::dvec3& eye, const Material& material) const {
    (void)point;
    (void)normal;
    (void)eye;
    (void)material;
    return notStarted(Step::PointLight, 0.0);
}

}  // namespace lab
