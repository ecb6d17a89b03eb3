// Steps 1 to 4 (assignment section 3, "Image formation: from 3D to 2D"). Write each function,
// delete its `return notStarted(...)` line, then run `make lab-check`.

#include <vector>

#include <glm/geometric.hpp>

#include "lab/steps.hpp"

namespace lab {

// Step 1. Return the 4×4 matrix that takes a world point (x, y, z, 1) to camera coordinates.
// The camera looks down its own +Z axis:
//   z = normalize(lookAt − eye)        the camera's Z axis points from the eye to the look-at point
//   x = normalize(up × z)              (glm::cross, glm::normalize)
//   y = z × x                          the "up" hint is only a hint: y is computed
// The matrix's rows are x, y, z (a rotation R) and its translation is −R·eye, so the eye itself
// goes to the origin. GLM indexes m[column][row]: row 0 is m[0][0], m[1][0], m[2][0], m[3][0].
glm::dmat4 setLookAt(const glm::dvec3& eye, const glm::dvec3& lookAt, const glm::dvec3& up) {
    (void)eye;
    (void)lookAt;
    (void)up;
    return notStarted(Step::SetLookAt, glm::dmat4(1.0));
}

// Step 2. Return the 3×4 projection matrix that takes camera coordinates (X, Y, Z, 1) to the
// homogeneous point (X, Y, Z) of the image plane: dividing by the third coordinate projects,
// and the third coordinate is the depth Z, which the depth buffer needs later.
// glm::dmat4x3 has 4 columns of 3 rows: m[column][row].
glm::dmat4x3 setProjection() {
    return notStarted(Step::SetProjection, glm::dmat4x3(0.0));
}

// Step 3. Return the calibration matrix K that takes the image plane (at Z = f, f in pixels) to
// pixel coordinates, the optical axis through the image centre:
//       | f  0  w/2 |
//   K = | 0  f  h/2 |
//       | 0  0   1  |
// Careful: GLM's constructor and m[column][row] list columns, so w/2 is m[2][0].
glm::dmat3 setCalibration(double focal, int width, int height) {
    (void)focal;
    (void)width;
    (void)height;
    return notStarted(Step::SetCalibration, glm::dmat3(1.0));
}

// Step 4. For each world point p, compute h = K · P · worldToCamera · (p, 1) with the three
// matrices of `t`, and return (h.x / h.z, h.y / h.z, h.z): the continuous pixel coordinates and
// the depth. Keep z (do not divide it by itself to 1): the depth buffer needs it.
std::vector<glm::dvec3> projectPoints(const Transformation& t,
                                      const std::vector<glm::dvec3>& points) {
    (void)t;
    (void)points;
    return notStarted(Step::ProjectPoints, std::vector<glm::dvec3>{});
}

}  // namespace lab
