// results.csv of a batch: one row per mesh, one line per row. An `ok` row holds the totals of the
// mesh's displayed (first) cone and test exactly as `stats --format csv` writes them (made by that
// writer), the mesh's sizes, the settings and, when asked, a comparison's totals; an `error` row the
// message. docs/statistics-schema.md lists the columns; new ones go at the end.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/Comparison.h"
#include "core/Granularity.h"
#include "core/lod/LodCut.h"
#include "core/Statistics.h"

namespace conescope {

// Column name -> cell text, unquoted; a column left out is an empty cell. No cell holds a line break.
using BatchRow = std::map<std::string, std::string>;

// Every column of results.csv, in order.
const std::vector<std::string>& batchColumns();

// The run's cells: its displayed result's totals row (as writeStatisticsCsv writes it), vertices,
// faces, triangles and its warnings (joined by " | ").
void addRunCells(BatchRow& row, const RunStatistics& run, const std::vector<std::string>& warnings);

// setting_KEY for every schema field, as its command-line text (settingText).
void addSettingCells(BatchRow& row, const Settings& settings);

// A's totals as a_COLUMN (those a run's mesh does not fix), and what only each side culled. The row's
// own totals are B's: the batch's settings.
void addComparisonCells(BatchRow& row, const ComparedRuns& runs);

// With `batch --granularity`: the displayed result's `culled_share` and, for each finer record of
// the granularity report (cones-2 ... triangle, as cones_2 ... triangle), RECORD_efficiency,
// RECORD_culled_share, RECORD_bytes_per_cluster and RECORD_tests_per_view.
void addGranularityCells(BatchRow& row, const GranularityReport& report);

// With `batch --lod`: lod_levels, lod_false_culls (every level's and the cut's), per level L below
// kLodLevelColumns lod_level_L_triangles and lod_level_L_efficiency, and the cut's lod_cut_triangles
// (mean per view), lod_cut_efficiency and lod_cut_false_culls.
constexpr size_t kLodLevelColumns = 8;
void addLodCells(BatchRow& row, const LodStatistics& lod);

// The header line and a row's line, each ending in '\n'; cells with a comma or a quote are quoted.
std::string batchCsvHeader();
std::string batchCsvLine(const BatchRow& row);

// A CSV line's cells (quotes as batchCsvLine writes them). Throws std::invalid_argument when a quote
// is left open.
std::vector<std::string> splitCsvLine(const std::string& line);

// What a results.csv holds: its complete rows (a last line without its newline, cut by a kill, is
// left out). `sameColumns` is false when its header is another version's: its rows are then empty.
// Lines that are no row of the header (edited by hand, say) are counted and left out.
struct BatchTable {
    bool sameColumns = true;
    std::vector<BatchRow> rows;
    size_t unreadableRows = 0;
};
// An absent file is an empty table. Throws std::runtime_error naming the file when it cannot be read.
BatchTable readBatchCsv(const std::string& path);

// The whole file: the header and the rows in this order.
std::string batchCsvText(const std::vector<BatchRow>& rows);

}  // namespace conescope
