// The picked cluster's page: its size, cone and bounds, and for the current eye every number the
// chosen test compared (from core explainCull), laid out as the seed's argument in steps. Only
// formatting: the numbers come in ready.
#pragma once

#include <QString>

#include "core/Culling.h"
#include "core/MultiConeCulling.h"

namespace conescope {

struct ClusterReportInput {
    uint32_t cluster = 0;
    const ClusterBounds* bounds = nullptr;
    Eye eye;
    CullTest test = kDefaultTest;
    CullExplanation explanation;
};

// `appendix`: more HTML after the page (the cluster under A).
QString clusterReportHtml(const ClusterReportInput& input, const QString& appendix = {});

// The same cluster's faces under the pinned configuration A, in short: A's cluster holding them, its
// size, cone and decision from the same eye, after the page of B (the current configuration).
QString pinnedClusterHtml(const ClusterReportInput& a);

// The cluster's K sub-groups from the eye (subGroupVerdicts): triangles, cone, verdict, the oracle.
QString subGroupsHtml(const std::vector<SubGroupVerdict>& verdicts);

// The page shown before anything is picked.
QString emptyClusterReportHtml();

}  // namespace conescope
