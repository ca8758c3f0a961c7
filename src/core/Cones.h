// Cones of normals: an axis V1 and a half-angle alpha such that every unit face normal n of the
// cluster has n.V1 >= cos(alpha). In seed 000's terms B = asin(min n.V1) = 90deg - alpha, and the
// cluster is back-facing from every view vector v with v.V1 > cos(B) = sin(alpha).
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace conescope {

struct ConeOfNormals {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cosHalfAngle = -1.0;  // min over normals of n.axis (minus a rounding margin)
    double sinHalfAngle = 1.0;   // = cos(B), the threshold of every view test
    bool cullable = false;       // false when no cone narrower than a hemisphere holds the normals

    double halfAngle() const;    // alpha in radians; pi/2 or more when not cullable
};

// Builds the cone with this axis that holds all normals: cos(alpha) = min n.axis, rounded down.
// Every method ends here, so a cone is valid whatever the accuracy of the axis search.
ConeOfNormals coneAroundAxis(const glm::dvec3& axis, const glm::dvec3* normals, size_t count);

// Seed 000: V1 = normalised mean of the normals, B = asin(min n.V1).
ConeOfNormals averageCone(const glm::dvec3* normals, size_t count);

// Seed 000's note: smallest sphere around the normals' tips, V1 towards its centre c, half-angle
// taken as asin(r/|c|) exactly as written there (the cone tangent to that sphere).
ConeOfNormals seedSphereCone(const glm::dvec3* normals, size_t count);

// The exact smallest cone (spherical cap) holding all normals: Welzl's algorithm on the sphere.
ConeOfNormals minimalCone(const glm::dvec3* normals, size_t count);

}  // namespace conescope
