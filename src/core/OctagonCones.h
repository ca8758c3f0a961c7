// An eight-sided cone of normals: eight unit edge directions around a cluster's cone axis such
// that every face normal of the cluster is a non-negative combination of them.
//
// Seen in the plane that touches the unit sphere at the axis (the gnomonic projection n / (n.axis):
// great circles become lines, so convex cones become convex polygons), it is the octagon of sides
// at 45 degree steps around the normals' projections, turned to the least area. Where
// the normals spread more one way than the other (a cylinder's lie along an arc) it is much
// tighter than the round cap, which has to be as wide as the longest spread in every direction.
//
// Its test (CullTest::Octagon) is the apex test with this cone: the cluster is culled when every
// edge g has g.(apex - eye) > 0, for then every normal n has n.(eye - apex) < 0, and the apex lies
// behind every face plane, so n.(eye - q) < 0 for every face. The eyes it culls from fill an
// eight-sided pyramid behind the apex: the polar cone of the octagon, whose faces are
// perpendicular to the edges.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "Cones.h"

namespace conescope {

struct OctagonCone {
    std::array<glm::dvec3, 8> edges{};  // unit, in order around the axis (repeats where a side is missing)
    bool cullable = false;              // false when the round cone is not: the test never culls
};

// The octagon around the normals, projected about `cone`'s axis; zero normals (degenerate faces) are
// left out. Not cullable when the cone is not.
OctagonCone octagonCone(const ConeOfNormals& cone, const glm::dvec3* normals, size_t count);

// Whether `view` (from the eye to the apex, or an orthographic view direction) sees every normal
// of the octagon from behind: g.view > kCullMargin |view| + slack for each edge g (slack: the
// apex's rounding, apexRoundingSlack in CullTest.h, for a view from an eye).
bool octagonSeesBack(const OctagonCone& octagon, const glm::dvec3& view, double slack = 0.0);

// The tightest edge: min over edges of g.view / |view| (unit view), what octagonSeesBack compares
// with kCullMargin; -1 for a cone that is not cullable or a zero view.
double octagonTightest(const OctagonCone& octagon, const glm::dvec3& view);

// The share of view directions (eye at infinity) from which the octagon test culls: the area of its
// pyramid's cross-section on the unit sphere over 4 pi, which is (2 pi - the octagon's perimeter on
// the sphere) / 4 pi, as (1 - sin alpha) / 2 is for a round cone. 0 when not cullable.
double octagonCullShare(const OctagonCone& octagon);

// The same for the normals themselves: the share of view directions from which every one faces
// away, (2 pi - the perimeter of their convex hull on the sphere) / 4 pi, exactly. The hull is
// found in the gnomonic plane about the axis of `holding` (a cone that holds them all, such as the
// cluster's bounds), or else of their minimal cone. 0 when no open hemisphere holds them (they then
// face every direction somewhere) or there are none.
double normalsCullShare(const glm::dvec3* normals, size_t count, const ConeOfNormals* holding = nullptr);

// octagonCone(cone, normals, count) and normalsCullShare(the nonzero normals, &cone) at once, from
// one hull of the normals (computing each alone finds it twice).
struct OctagonAndShare {
    OctagonCone octagon;
    double normalsShare = 0.0;
};
OctagonAndShare octagonAndNormalsShare(const ConeOfNormals& cone, const glm::dvec3* normals, size_t count);

// The octagon as the sample lays it out: in the gnomonic plane about `axis` (its basis the one
// octagonCone projects with), four strips with sides at `turn` + k 45 degrees, strip k holding every
// projected normal p with low[k] <= d_k.p <= high[k]. What the compact octagon stores, rounded outward.
struct OctagonStrips {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double turn = 0.0;  // radians
    std::array<double, 4> low{}, high{};
};
// The strips of these normals (zero normals left out) at this turn, padded against rounding as
// octagonCone pads its own; empty when some normal is not in front of the axis.
std::optional<OctagonStrips> octagonStripsOf(const glm::dvec3& axis, double turn, const glm::dvec3* normals, size_t count);
// The octagon the strips bound: its corners lifted to unit edges. Not cullable when they bound no octagon.
OctagonCone octagonFromStrips(const OctagonStrips& strips);

// The eight edges of the pyramid of eyes it culls from (unit directions from the apex, in order):
// each is perpendicular to two neighbouring edges of the octagon, on the side away from the others.
std::array<glm::dvec3, 8> octagonPyramidEdges(const OctagonCone& octagon);

}  // namespace conescope
