// The picked cluster's page: its size, cone and bounds, and for the current eye every number the
// chosen test compared (from core explainCull), laid out as the seed's argument in steps. Only
// formatting: the numbers come in ready.
#pragma once

#include <QString>

#include "core/Culling.h"

namespace conescope {

struct ClusterReportInput {
    uint32_t cluster = 0;
    const ClusterBounds* bounds = nullptr;
    Eye eye;
    CullTest test = CullTest::Vertices;
    CullExplanation explanation;
};

QString clusterReportHtml(const ClusterReportInput& input);

// The page shown before anything is picked.
QString emptyClusterReportHtml();

}  // namespace conescope
