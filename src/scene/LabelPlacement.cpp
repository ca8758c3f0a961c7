#include "scene/LabelPlacement.h"

#include <algorithm>
#include <cmath>

namespace conescope {

namespace {

constexpr double pi = 3.14159265358979323846;

}  // namespace

LabelPlacer::LabelPlacer(int width, int height, const PixelBox& bounds, double padding, double leaderGap)
    : width_(std::max(width, 1)),
      height_(std::max(height, 1)),
      bounds_(bounds),
      padding_(padding),
      leaderGap_(leaderGap),
      blocked_(size_t(width_) * size_t(height_), 0),
      labelled_(size_t(width_) * size_t(height_), 0) {}

void LabelPlacer::mark(int x, int y) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    blocked_[size_t(y) * size_t(width_) + size_t(x)] = 1;
}

void LabelPlacer::markDisc(const glm::dvec2& centre, double radius) {
    const int x0 = int(std::floor(centre.x - radius)), x1 = int(std::ceil(centre.x + radius));
    const int y0 = int(std::floor(centre.y - radius)), y1 = int(std::ceil(centre.y + radius));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (glm::length(glm::dvec2(x + 0.5, y + 0.5) - centre) <= radius + 0.71) mark(x, y);
    stale_ = true;
}

void LabelPlacer::blockLine(const std::vector<glm::dvec2>& points, double width) {
    const double radius = 0.5 * std::max(width, 1.0);
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const glm::dvec2 a = points[i], b = points[i + 1];
        const int steps = std::max(1, int(std::ceil(glm::length(b - a) * 2.0)));
        for (int s = 0; s <= steps; ++s) markDisc(a + (b - a) * (double(s) / steps), radius);
    }
    if (points.size() == 1) markDisc(points[0], radius);
}

void LabelPlacer::blockTriangles(const std::vector<glm::dvec2>& corners) {
    for (size_t t = 0; t + 2 < corners.size(); t += 3) {
        const glm::dvec2 a = corners[t], b = corners[t + 1], c = corners[t + 2];
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const int x0 = int(std::floor(std::min({a.x, b.x, c.x}))), x1 = int(std::ceil(std::max({a.x, b.x, c.x})));
        const int y0 = int(std::floor(std::min({a.y, b.y, c.y}))), y1 = int(std::ceil(std::max({a.y, b.y, c.y})));
        if (area != 0.0) {
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const glm::dvec2 p(x + 0.5, y + 0.5);
                    const double u = ((b.x - p.x) * (c.y - p.y) - (c.x - p.x) * (b.y - p.y)) / area;
                    const double v = ((c.x - p.x) * (a.y - p.y) - (a.x - p.x) * (c.y - p.y)) / area;
                    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) mark(x, y);
                }
        }
        // The edges as well: the rasteriser may cover a pixel whose centre is just outside.
        blockLine({a, b, c, a}, 1.0);
    }
    stale_ = true;
}

void LabelPlacer::blockBox(const PixelBox& box) {
    for (int y = int(std::floor(box.y0)); y < int(std::ceil(box.y1)); ++y)
        for (int x = int(std::floor(box.x0)); x < int(std::ceil(box.x1)); ++x) mark(x, y);
    stale_ = true;
}

void LabelPlacer::refresh() const {
    if (!stale_) return;
    const size_t stride = size_t(width_) + 1;
    sums_.assign(stride * (size_t(height_) + 1), 0);
    for (int y = 0; y < height_; ++y) {
        int32_t row = 0;
        for (int x = 0; x < width_; ++x) {
            row += blocked_[size_t(y) * size_t(width_) + size_t(x)];
            sums_[(size_t(y) + 1) * stride + size_t(x) + 1] = sums_[size_t(y) * stride + size_t(x) + 1] + row;
        }
    }
    stale_ = false;
}

bool LabelPlacer::free(const PixelBox& box, const PixelBox& bounds) const {
    if (box.x0 < bounds.x0 || box.y0 < bounds.y0 || box.x1 > bounds.x1 || box.y1 > bounds.y1) return false;
    refresh();
    const int x0 = std::clamp(int(std::floor(box.x0 - padding_)), 0, width_), x1 = std::clamp(int(std::ceil(box.x1 + padding_)), 0, width_);
    const int y0 = std::clamp(int(std::floor(box.y0 - padding_)), 0, height_), y1 = std::clamp(int(std::ceil(box.y1 + padding_)), 0, height_);
    const size_t stride = size_t(width_) + 1;
    auto at = [&](int x, int y) { return sums_[size_t(y) * stride + size_t(x)]; };
    return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0) == 0;
}

bool LabelPlacer::leaderClear(const glm::dvec2& from, const glm::dvec2& to) const {
    const int steps = std::max(1, int(std::ceil(glm::length(to - from) * 2.0)));
    for (int s = 0; s <= steps; ++s) {
        const glm::dvec2 p = from + (to - from) * (double(s) / steps);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = int(std::floor(p.x)) + dx, y = int(std::floor(p.y)) + dy;
                if (x >= 0 && y >= 0 && x < width_ && y < height_ && labelled_[size_t(y) * size_t(width_) + size_t(x)]) return false;
            }
    }
    return true;
}

std::optional<LabelSpot> LabelPlacer::place(const glm::dvec2& anchor, const glm::dvec2& toward, const glm::dvec2& size, double reach,
                                            const std::optional<PixelBox>& within) {
    PixelBox bounds = bounds_;
    if (within)
        bounds = {std::max(bounds.x0, within->x0), std::max(bounds.y0, within->y0), std::min(bounds.x1, within->x1), std::min(bounds.y1, within->y1)};
    // 24 sides, the preferred one first, then the ones nearest to it.
    const double preferred = glm::length(toward) > 0.0 ? std::atan2(toward.y, toward.x) : pi / 2.0;
    std::vector<glm::dvec2> sides;
    for (int k = 0; k < 24; ++k) {
        const int turn = (k + 1) / 2 * (k % 2 ? 1 : -1);
        const double angle = preferred + turn * pi / 12.0;
        sides.emplace_back(std::cos(angle), std::sin(angle));
    }
    std::vector<double> gaps;
    for (double gap = 1.0; gap <= reach; gap = gap < 8.0 ? gap + 2.0 : gap * 1.25) gaps.push_back(gap);
    for (double gap : gaps) {
        for (const glm::dvec2& side : sides) {
            // The box touches the circle of radius `gap` around the anchor on this side.
            const double big = std::max(std::abs(side.x), std::abs(side.y));
            const glm::dvec2 centre = anchor + side * gap + glm::dvec2(0.5 * size.x * side.x / big, 0.5 * size.y * side.y / big);
            const PixelBox box{centre.x - 0.5 * size.x, centre.y - 0.5 * size.y, centre.x + 0.5 * size.x, centre.y + 0.5 * size.y};
            if (!free(box, bounds)) continue;
            LabelSpot spot;
            spot.box = box;
            const glm::dvec2 nearest(std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1));
            if (glm::length(nearest - anchor) > leaderGap_) {
                // Start the leader a little off the named point, end it just short of the box.
                const glm::dvec2 along = glm::normalize(nearest - anchor);
                spot.leader = true;
                spot.leaderFrom = anchor + 2.0 * along;
                spot.leaderTo = nearest - 2.0 * along;
                if (!leaderClear(spot.leaderFrom, spot.leaderTo)) continue;
            }
            blockBox(box);
            for (int y = int(std::floor(box.y0)); y < int(std::ceil(box.y1)); ++y)
                for (int x = int(std::floor(box.x0)); x < int(std::ceil(box.x1)); ++x)
                    if (x >= 0 && y >= 0 && x < width_ && y < height_) labelled_[size_t(y) * size_t(width_) + size_t(x)] = 1;
            if (spot.leader) blockLine({spot.leaderFrom, spot.leaderTo}, 1.0);
            return spot;
        }
    }
    return std::nullopt;
}

}  // namespace conescope
