// report.html of a batch: one self-contained page (inline CSS, script and SVG; nothing from the
// network) drawn from the rows of results.csv: the totals, plots (efficiency against triangles,
// against the comparison's A when there is one, the loss breakdown), the error rows and a sortable
// table of the meshes, worst first, each linking to its statistics JSON.
#pragma once

#include <string>
#include <vector>

#include "io/BatchTable.h"

namespace conescope {

struct BatchReportInfo {
    std::string title;      // the output folder's name
    size_t meshes = 0;      // the meshes of the run (rows may be fewer when it was stopped)
    std::string compare;    // the comparison's A, "K=V,...", or empty
};

std::string batchReportHtml(const std::vector<BatchRow>& rows, const BatchReportInfo& info);

// The page around the data: the data goes where `@DATA@` is (BatchReportPage.cpp).
const std::string& batchReportPage();

}  // namespace conescope
