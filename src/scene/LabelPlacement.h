// Places a figure's labels so that none overlaps another and none lies on a line: every drawn shape
// is painted into a grid of the picture's pixels, and each label, in order of importance, takes the
// first free spot around the point it names (nearest first, its preferred side first), joined to it
// by a thin leader when it had to move away. Plain geometry in pixels (y up, as VTK's display).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace conescope {

struct PixelBox {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    bool intersects(const PixelBox& other) const { return x0 < other.x1 && other.x0 < x1 && y0 < other.y1 && other.y0 < y1; }
};

// A label's place: its box and, when it sits away from what it names, the leader from there to it.
struct LabelSpot {
    PixelBox box;
    bool leader = false;
    glm::dvec2 leaderFrom{0.0}, leaderTo{0.0};  // the named point, the box's nearest point
};

class LabelPlacer {
public:
    // A picture of width x height pixels; labels stay inside `bounds` and keep `padding` pixels from
    // anything drawn; one farther than `leaderGap` from what it names gets a leader.
    LabelPlacer(int width, int height, const PixelBox& bounds, double padding, double leaderGap);

    // What the labels must keep off: a polyline of this width, filled triangles (3 points each), a box.
    void blockLine(const std::vector<glm::dvec2>& points, double width);
    void blockTriangles(const std::vector<glm::dvec2>& corners);
    void blockBox(const PixelBox& box);

    // The first free spot for a box of `size` near `anchor`, on the side `toward` first, no farther
    // than `reach` pixels and inside `within` if given; the spot (and its leader) is then blocked.
    // Nothing when none is free.
    std::optional<LabelSpot> place(const glm::dvec2& anchor, const glm::dvec2& toward, const glm::dvec2& size, double reach,
                                   const std::optional<PixelBox>& within = std::nullopt);

private:
    bool free(const PixelBox& box, const PixelBox& bounds) const;
    bool leaderClear(const glm::dvec2& from, const glm::dvec2& to) const;
    void mark(int x, int y);
    void markDisc(const glm::dvec2& centre, double radius);
    void refresh() const;

    int width_, height_;
    PixelBox bounds_;
    double padding_, leaderGap_;
    std::vector<uint8_t> blocked_;            // width x height, row 0 at the bottom
    std::vector<uint8_t> labelled_;           // the labels' own boxes: leaders keep off them
    mutable std::vector<int32_t> sums_;       // summed-area table of blocked_, (width + 1) x (height + 1)
    mutable bool stale_ = true;
};

}  // namespace conescope
