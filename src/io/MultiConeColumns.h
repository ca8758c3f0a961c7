// The K-cone record's keys, one list for `lod` (each level, the cut, a view) and `stats`: the JSON's
// "multi_cone" object and the CSV's "multi_cone_" columns.
#pragma once

#include <vector>

#include "core/MultiConeCulling.h"
#include "io/ColumnTable.h"

namespace conescope {

const std::vector<NamedColumn<MultiConeCulling>>& multiConeColumns();

}  // namespace conescope
