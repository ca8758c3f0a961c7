// A short lesson on why more cones per cluster cull more and what they cost, told with one mesh's
// granularity report: what one cone loses to the partition, how 2, 4 and 8 cones narrow the cones,
// the culled share against the record's bytes, and per-triangle culling as the ceiling. Every number
// is read from the GranularityReport it is made from (measureGranularity, runGranularity); the
// window's lesson dock and `conescope-cli granularity --write-lesson` show the same text.
#pragma once

#include <string>
#include <vector>

#include "Granularity.h"
#include "LessonData.h"

namespace conescope {

struct GranularityLesson {
    std::string meshName;
    std::vector<LessonStep> steps;  // kGranularityLessonStepCount of them
};

constexpr int kGranularityLessonStepCount = 4;

// The lesson on `report`. Throws std::invalid_argument when the report lacks the displayed record's
// row, the K-cone rows, their cone widths or the per-triangle row.
GranularityLesson makeGranularityLesson(const GranularityReport& report);

// The lesson as Markdown: a title naming the mesh, then each step as a section.
std::string granularityLessonMarkdown(const GranularityLesson& lesson);

}  // namespace conescope
