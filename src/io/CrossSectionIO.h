// What a picture of the cross-section drew, as the export writes it beside the PNG (X.png, X.json):
// every angle in degrees from V1 (negative to the left of it) as drawn, the core's verdict and the
// drawn region of v that culls, and each text with its box in the picture's pixels, so a test (or a
// reader) can hold the picture against the core. Keys in docs/statistics-schema.md.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/CrossSection.h"

namespace conescope {

// `labels`, `leftOut`: what CrossSectionScene drew into a width x height picture.
nlohmann::json crossSectionToJson(const CrossSection& section, const std::vector<CrossSectionLabel>& labels,
                                  const std::vector<std::string>& leftOut, int width, int height);

}  // namespace conescope
