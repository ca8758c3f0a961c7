// The reduction's nearest clusters by centre from a grid: the same answers, in the same order, as a
// scan over every live cluster (k smallest squared distances, ties by id), as clusters move and
// leave, on clouds of many shapes (a ball, a plane, a line, repeated points).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "core/optimizer/NearestCentres.h"

namespace conescope {
namespace {

std::vector<uint32_t> scan(const std::vector<glm::dvec3>& centres, const std::vector<bool>& live, uint32_t c, size_t limit) {
    std::vector<std::pair<double, uint32_t>> all;
    for (uint32_t o = 0; o < centres.size(); ++o)
        if (o != c && live[o]) {
            const glm::dvec3 d = centres[o] - centres[c];
            all.emplace_back(glm::dot(d, d), o);
        }
    std::sort(all.begin(), all.end());
    std::vector<uint32_t> out;
    for (size_t i = 0; i < std::min(limit, all.size()); ++i) out.push_back(all[i].second);
    return out;
}

std::vector<glm::dvec3> cloud(std::mt19937_64& random, int shape, size_t count) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> grid(0, 3);
    std::vector<glm::dvec3> points;
    for (size_t i = 0; i < count; ++i) {
        switch (shape) {
            case 0: points.emplace_back(u(random), u(random), u(random)); break;               // a box
            case 1: points.emplace_back(u(random), 0.25 * u(random), 0.0); break;              // a plane
            case 2: points.emplace_back(100.0 * u(random), 0.0, 0.0); break;                   // a line
            default: points.emplace_back(double(grid(random)), double(grid(random)), 0.5); break;  // many ties
        }
    }
    return points;
}

TEST(NearestCentres, AnswersAsAScanOfEveryLiveCluster) {
    std::mt19937_64 random(7);
    for (int shape = 0; shape < 4; ++shape)
        for (size_t count : {1, 2, 7, 60, 400}) {
            SCOPED_TRACE("shape " + std::to_string(shape) + ", " + std::to_string(count) + " centres");
            std::vector<glm::dvec3> centres = cloud(random, shape, count);
            std::vector<bool> live(count, true);
            if (count > 2) live[1] = false;
            optimizer::NearestCentres nearby(centres, live);
            std::vector<uint32_t> out;
            for (int step = 0; step < 200; ++step) {
                const uint32_t c = uint32_t(random() % count);
                if (live[c]) {
                    for (size_t limit : {1, 6, 24, 96}) {
                        nearby.nearest(c, limit, out);
                        ASSERT_EQ(out, scan(centres, live, c, limit)) << "cluster " << c << ", limit " << limit;
                    }
                }
                // Clusters merge (one leaves, the other moves to the weighted mean) or move a little.
                const uint32_t other = uint32_t(random() % count);
                if (step % 3 == 0 && other != c && live[other] && live[c]) {
                    centres[c] = 0.5 * (centres[c] + centres[other]);
                    nearby.move(c, centres[c]);
                    nearby.remove(other);
                    live[other] = false;
                } else if (live[c]) {
                    centres[c] = glm::clamp(centres[c] + 0.05 * glm::dvec3(random() % 3, random() % 3, 0.0) - 0.05, -1.0, 1.0);
                    nearby.move(c, centres[c]);
                }
            }
        }
}

}  // namespace
}  // namespace conescope
