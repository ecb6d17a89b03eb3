// Solution of steps 1 to 4 (assignment section 3): the camera's matrices and the projection.

#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>

#include "lab/steps.hpp"

namespace lab {

glm::dmat4 setLookAt(const glm::dvec3& eye, const glm::dvec3& lookAt, const glm::dvec3& up) {
    // The camera looks down +Z: z points from the eye to the look-at point; x is perpendicular
    // to the up hint and z; y completes the frame (pointing down the image for up = (0, -1, 0)).
    const glm::dvec3 z = glm::normalize(lookAt - eye);
    const glm::dvec3 x = glm::normalize(glm::cross(up, z));
    const glm::dvec3 y = glm::cross(z, x);
    // Rows x, y, z (GLM indexes m[column][row]), then the eye moved to the origin: -R·eye.
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = x[c];
        m[c][1] = y[c];
        m[c][2] = z[c];
    }
    m[3][0] = -glm::dot(x, eye);
    m[3][1] = -glm::dot(y, eye);
    m[3][2] = -glm::dot(z, eye);
    return m;
}

glm::dmat4x3 setProjection() {
    // [I | 0]: (X, Y, Z, 1) -> (X, Y, Z), the homogeneous point of the image plane at Z = 1;
    // dividing by the third coordinate later projects it, and keeping that coordinate keeps Z.
    glm::dmat4x3 p(0.0);
    p[0][0] = 1.0;
    p[1][1] = 1.0;
    p[2][2] = 1.0;
    return p;
}

glm::dmat3 setCalibration(double focal, int width, int height) {
    // K = [[f, 0, w/2], [0, f, h/2], [0, 0, 1]]: scale by the focal length in pixels, then move
    // the optical axis to the image centre. GLM's constructor lists columns.
    return glm::dmat3(focal, 0.0, 0.0,  //
                      0.0, focal, 0.0,  //
                      0.5 * width, 0.5 * height, 1.0);
}

std::vector<glm::dvec3> projectPoints(const Transformation& t,
                                      const std::vector<glm::dvec3>& points) {
    std::vector<glm::dvec3> out;
    out.reserve(points.size());
    const glm::dmat4x3 kp = t.calibration * t.projection;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 h = kp * (t.worldToCamera * glm::dvec4(p, 1.0));
        // Divide x and y by the homogeneous coordinate (the depth Z) but keep Z itself.
        out.emplace_back(h.x / h.z, h.y / h.z, h.z);
    }
    return out;
}

}  // namespace lab
