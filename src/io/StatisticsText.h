// Statistics for a person at a terminal: a few lines on the mesh, the clusters, the efficiency and
// where the rest of the back faces went, and the worst clusters as a table. The JSON and CSV
// (StatisticsIO.h) remain the stable interface; this text is for reading.
#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

#include "core/Statistics.h"

namespace conescope {

// The run's summary: one block per result, each with its `worstClusters` worst clusters by test loss.
void writeStatisticsText(const RunStatistics& run, std::ostream& out, size_t worstClusters = 5);

// The given clusters of one result, in that order, as an aligned table with a header.
void writeClusterTableText(const CullTestStatistics& result, const std::vector<uint32_t>& order, std::ostream& out);

}  // namespace conescope
