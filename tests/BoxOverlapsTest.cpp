/* The validator's robot-robot broad phase: exactly the overlapping pairs (with an active box), each once, whatever
   the layout: scattered, lined up across an axis, with huge and with identical boxes. */
#include "ompl_parc/validation/BoxOverlaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace ompl_parc;

namespace
{
    using Pairs = std::multiset<std::pair<std::size_t, std::size_t>>;

    Pairs everyPair(const std::vector<AxisBox> &boxes, const std::vector<char> &active)
    {
        Pairs pairs;
        for (std::size_t i = 0; i < boxes.size(); ++i)
            for (std::size_t j = i + 1; j < boxes.size(); ++j)
                if ((active[i] || active[j]) && boxes[i].overlaps(boxes[j]))
                    pairs.emplace(i, j);
        return pairs;
    }

    Pairs gridPairs(BoxOverlaps &grid, const std::vector<AxisBox> &boxes, const std::vector<char> &active)
    {
        Pairs pairs;
        grid.find(boxes.data(), active.data(), boxes.size(),
                  [&](std::size_t i, std::size_t j) { pairs.emplace(i, j); });
        return pairs;
    }

    AxisBox boxAt(double x, double y, double z, double sx, double sy, double sz)
    {
        return AxisBox{{x, y, z}, {x + sx, y + sy, z + sz}};
    }
}  // namespace

TEST(BoxOverlaps, FindsExactlyTheOverlappingPairsOnceWhateverTheLayout)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0., 1.);
    BoxOverlaps grid;  // one instance for every layout: its scratch is reused
    std::size_t layouts = 0, pairsSeen = 0;
    for (const std::size_t n : {3u, 15u, 16u, 200u, 1500u})
        for (int layout = 0; layout < 5; ++layout)
        {
            std::vector<AxisBox> boxes;
            std::vector<char> active;
            for (std::size_t i = 0; i < n; ++i)
            {
                const double size = 0.2 + 0.8 * unit(rng);
                switch (layout)
                {
                    case 0:  // scattered, 3D
                        boxes.push_back(boxAt(30. * unit(rng), 30. * unit(rng), 30. * unit(rng), size, size, size));
                        break;
                    case 1:  // a column and a row (a cross of robots), flat: a sweep along x or y alone is quadratic
                        boxes.push_back(i % 2 == 0 ? boxAt(0.3 * unit(rng), 0.9 * i, 0., size, size, 0.1)
                                                   : boxAt(0.9 * i, 0.3 * unit(rng), 0., size, size, 0.1));
                        break;
                    case 2:  // a few huge boxes among small ones
                        boxes.push_back(i % 50 == 7 ? boxAt(10. * unit(rng), 10. * unit(rng), 0., 40., 25., 1.)
                                                    : boxAt(60. * unit(rng), 60. * unit(rng), 0., size, size, size));
                        break;
                    case 3:  // identical boxes and points, boxes that touch at a face
                        boxes.push_back(i % 3 == 0   ? boxAt(1., 1., 1., 0.5, 0.5, 0.5)
                                        : i % 3 == 1 ? boxAt(1.5, 1., 1., 0., 0., 0.)
                                                     : boxAt(static_cast<double>(i), 0., 0., 1., 1., 1.));
                        break;
                    default:  // far apart in one corner and one far outlier: a coarse grid
                        boxes.push_back(i == 0
                                            ? boxAt(1e7, 1e7, 1e7, 1., 1., 1.)
                                            : boxAt(5. * unit(rng), 5. * unit(rng), 5. * unit(rng), size, size, size));
                        break;
                }
                active.push_back(unit(rng) < 0.7 ? 1 : 0);
            }
            const Pairs expected = everyPair(boxes, active);
            EXPECT_EQ(gridPairs(grid, boxes, active), expected) << n << " boxes, layout " << layout;
            ++layouts;
            pairsSeen += expected.size();
        }
    EXPECT_EQ(layouts, 25u);
    EXPECT_GT(pairsSeen, 1000u);  // the layouts do overlap
}

TEST(BoxOverlaps, InactiveBoxesMeetOnlyActiveOnes)
{
    std::vector<AxisBox> boxes(40, boxAt(0., 0., 0., 1., 1., 1.));
    std::vector<char> active(40, 0);
    BoxOverlaps grid;
    EXPECT_TRUE(gridPairs(grid, boxes, active).empty());
    active[5] = 1;
    const Pairs pairs = gridPairs(grid, boxes, active);
    EXPECT_EQ(pairs.size(), 39u);
    for (const auto &[i, j] : pairs)
        EXPECT_TRUE(i == 5 || j == 5);
}
