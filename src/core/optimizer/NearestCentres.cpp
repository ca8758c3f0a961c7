#include "NearestCentres.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace conescope::optimizer {

namespace {

constexpr uint32_t kNoCell = std::numeric_limits<uint32_t>::max();
// About this many centres per cell of the box's longest side cubed (more for flat or thin sets of
// centres, whose cells are mostly empty).
constexpr double kCentresPerCell = 2.0;
// The grid has at most this many cells per live centre (a box much longer than wide).
constexpr size_t kCellsPerCentreAtMost = 8;
// Where a query asks for at least a quarter of the live centres, all of them are scanned.
constexpr size_t kScanAtLeast = 4;

}  // namespace

NearestCentres::NearestCentres(const std::vector<glm::dvec3>& centres, const std::vector<bool>& live)
    : centres_(centres), cellOfCluster_(centres.size(), kNoCell), placeInLive_(centres.size(), kNoCell) {
    for (size_t c = 0; c < centres.size(); ++c)
        if (live[c]) placeInLive_[c] = uint32_t(live_.size()), live_.push_back(uint32_t(c));
    glm::dvec3 high(-std::numeric_limits<double>::infinity());
    low_ = glm::dvec3(std::numeric_limits<double>::infinity());
    size_t count = 0;
    for (size_t c = 0; c < centres.size(); ++c)
        if (live[c]) low_ = glm::min(low_, centres[c]), high = glm::max(high, centres[c]), ++count;
    if (count == 0) return;
    const glm::dvec3 extent = high - low_;
    const double longest = std::max({extent.x, extent.y, extent.z});
    // Cells of equal sides: as many along the longest side as the cube root of count / kCentresPerCell.
    double along = std::max(1.0, std::cbrt(double(count) / kCentresPerCell));
    for (;;) {
        cell_ = longest > 0.0 ? longest / along : 1.0;
        size_t total = 1;
        for (int axis = 0; axis < 3; ++axis) {
            dims_[axis] = std::max<size_t>(1, size_t(std::floor(extent[axis] / cell_)) + 1);
            total *= dims_[axis];
        }
        if (total <= kCellsPerCentreAtMost * count + 8 || along <= 1.0) break;
        along = std::max(1.0, along / 2.0);
    }
    cells_.resize(dims_[0] * dims_[1] * dims_[2]);
    for (size_t c = 0; c < centres.size(); ++c)
        if (live[c]) {
            const size_t index = indexOf(centres[c]);
            cellOfCluster_[c] = uint32_t(index);
            cells_[index].push_back(uint32_t(c));
        }
}

size_t NearestCentres::cellOf(const glm::dvec3& p, int axis) const {
    const double at = std::floor((p[axis] - low_[axis]) / cell_);
    return at <= 0.0 ? 0 : std::min(dims_[axis] - 1, size_t(at));
}

size_t NearestCentres::indexOf(const glm::dvec3& p) const {
    return (cellOf(p, 2) * dims_[1] + cellOf(p, 1)) * dims_[0] + cellOf(p, 0);
}

void NearestCentres::nearest(uint32_t c, size_t limit, std::vector<uint32_t>& out) { nearestTo(centres_[c], limit, out, c); }

void NearestCentres::nearestTo(const glm::dvec3& p, size_t limit, std::vector<uint32_t>& out, uint32_t c) {
    out.clear();
    found_.clear();
    if (limit == 0 || cells_.empty()) return;
    if (kScanAtLeast * limit >= live_.size()) {  // most of them asked for: the scan itself
        for (uint32_t other : live_)
            if (other != c) {
                const glm::dvec3 d = centres_[other] - p;
                found_.emplace_back(glm::dot(d, d), other);
            }
        const size_t kept = std::min(limit, found_.size());
        std::partial_sort(found_.begin(), found_.begin() + long(kept), found_.end());
        for (size_t i = 0; i < kept; ++i) out.push_back(found_[i].second);
        return;
    }
    const long at[3] = {long(cellOf(p, 0)), long(cellOf(p, 1)), long(cellOf(p, 2))};
    const long most = long(std::max({dims_[0], dims_[1], dims_[2]}));
    // Ring r: the cells r steps away from p's (in the largest coordinate). Once `limit` centres are
    // found nearer than any point outside the rings so far, no farther ring can give a nearer one,
    // nor a tie.
    for (long r = 0; r <= most; ++r) {
        for (long z = at[2] - r; z <= at[2] + r; ++z) {
            if (z < 0 || z >= long(dims_[2])) continue;
            for (long y = at[1] - r; y <= at[1] + r; ++y) {
                if (y < 0 || y >= long(dims_[1])) continue;
                const bool shellZY = std::abs(z - at[2]) == r || std::abs(y - at[1]) == r;
                for (long x = at[0] - r; x <= at[0] + r; x += (shellZY || r == 0) ? 1 : 2 * r) {
                    if (x < 0 || x >= long(dims_[0])) continue;
                    for (uint32_t other : cells_[(size_t(z) * dims_[1] + size_t(y)) * dims_[0] + size_t(x)]) {
                        if (other == c) continue;
                        const glm::dvec3 d = centres_[other] - p;
                        found_.emplace_back(glm::dot(d, d), other);
                    }
                }
            }
        }
        if (found_.size() >= limit) {
            // Every centre not seen yet lies outside the cube of cells r steps around p's.
            double reach = std::numeric_limits<double>::infinity();
            for (int axis = 0; axis < 3; ++axis) {
                if (at[axis] - r > 0) reach = std::min(reach, p[axis] - (low_[axis] + double(at[axis] - r) * cell_));
                if (at[axis] + r + 1 < long(dims_[axis])) reach = std::min(reach, low_[axis] + double(at[axis] + r + 1) * cell_ - p[axis]);
            }
            std::nth_element(found_.begin(), found_.begin() + long(limit - 1), found_.end());
            if (reach == std::numeric_limits<double>::infinity() || (reach > 0.0 && found_[limit - 1].first < reach * reach)) break;
        }
    }
    const size_t kept = std::min(limit, found_.size());
    std::partial_sort(found_.begin(), found_.begin() + long(kept), found_.end());
    for (size_t i = 0; i < kept; ++i) out.push_back(found_[i].second);
}

void NearestCentres::move(uint32_t c, const glm::dvec3& centre) {
    centres_[c] = centre;
    if (cellOfCluster_[c] == kNoCell) return;
    const size_t index = indexOf(centre);
    if (index == cellOfCluster_[c]) return;
    std::vector<uint32_t>& cell = cells_[cellOfCluster_[c]];
    cell.erase(std::find(cell.begin(), cell.end(), c));
    cellOfCluster_[c] = uint32_t(index);
    cells_[index].push_back(c);
}

void NearestCentres::remove(uint32_t c) {
    if (cellOfCluster_[c] == kNoCell) return;
    const uint32_t place = placeInLive_[c];
    live_[place] = live_.back();
    placeInLive_[live_[place]] = place;
    live_.pop_back();
    placeInLive_[c] = kNoCell;
    std::vector<uint32_t>& cell = cells_[cellOfCluster_[c]];
    cell.erase(std::find(cell.begin(), cell.end(), c));  // keeps the cell's order: no answer depends on it
    cellOfCluster_[c] = kNoCell;
}

}  // namespace conescope::optimizer
