#include "io/CrossSectionIO.h"

#include "core/Settings.h"

namespace conescope {

namespace {

double inDegrees(double radians) { return glm::degrees(radians); }

nlohmann::json anglesJson(const std::vector<double>& radians) {
    nlohmann::json angles = nlohmann::json::array();
    for (double a : radians) angles.push_back(inDegrees(a));
    return angles;
}

std::string ruleName(CullRegionRule rule) {
    switch (rule) {
        case CullRegionRule::None: return "none";
        case CullRegionRule::Round: return "round";
        case CullRegionRule::Octagon: return "octagon";
        case CullRegionRule::Asked: return "asked";
    }
    return "none";
}

}  // namespace

nlohmann::json crossSectionToJson(const CrossSection& section, const std::vector<CrossSectionLabel>& labels,
                                  const std::vector<std::string>& leftOut, int width, int height) {
    nlohmann::json region = nlohmann::json::array();
    for (const AngleRange& range : section.cullRegion) region.push_back({inDegrees(range[0]), inDegrees(range[1])});
    nlohmann::json texts = nlohmann::json::array();
    for (const CrossSectionLabel& label : labels)
        texts.push_back({{"text", label.text}, {"box", {label.box[0], label.box[1], label.box[2], label.box[3]}}});
    nlohmann::json document = {
        {"cluster", section.cluster},
        {"test", toString(section.test)},
        {"orthographic", section.orthographic},
        {"view_name", section.viewName},
        {"half_angle_deg", section.cone ? nlohmann::json(inDegrees(section.alpha)) : nlohmann::json(nullptr)},
        {"angle_b_deg", section.cone ? nlohmann::json(inDegrees(section.angleB)) : nlohmann::json(nullptr)},
        {"normals_deg", anglesJson(section.normalAngles)},
        {"v_deg", inDegrees(section.viewAngle)},
        {"culls", section.culls},
        {"cull_region_rule", ruleName(section.rule)},
        {"cull_region_deg", region},
        {"title", section.title},
        {"caption", section.caption},
        {"labels", texts},
        {"labels_left_out", leftOut},
        {"width", width},
        {"height", height},
    };
    if (!section.pointAngles.empty()) {
        document["points_deg"] = anglesJson(section.pointAngles);
        document["lowest_point"] = section.tightestPoint;
    }
    if (section.rule == CullRegionRule::Round) {
        document["region_half_angle_deg"] = inDegrees(section.regionHalfAngle);
        document["narrowing_deg"] = inDegrees(section.narrowing);
    }
    if (section.rule == CullRegionRule::Octagon && section.hasRegion()) {
        document["bounding_edges"] = {section.boundingEdges[0], section.boundingEdges[1]};
        document["bounding_edges_deg"] = {inDegrees(section.boundingEdgeAngles[0]), inDegrees(section.boundingEdgeAngles[1])};
    }
    if (section.place.shown) {
        const CrossSectionPlace& place = section.place;
        document["place"] = {{"to", place.toApex ? "apex" : "centre"},
                             {"eye", {place.eye.x, place.eye.y}},
                             {"distance", place.distance},
                             {"radius", place.radius},
                             {"spread_deg", inDegrees(place.spread)}};
    }
    return document;
}

}  // namespace conescope
