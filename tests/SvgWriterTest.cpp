#include "TestProblems.h"

#include "ompl_parc/SvgWriter.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>

using namespace ompl_parc;

namespace
{
    std::size_t count(const std::string &text, const std::string &part)
    {
        std::size_t n = 0;
        for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size()))
            ++n;
        return n;
    }

    /** Well-formed enough for a viewer: one root, every start tag closed in order, quotes balanced, no
        attribute given twice. */
    ::testing::AssertionResult wellFormed(const std::string &svg)
    {
        std::vector<std::string> open;
        std::size_t roots = 0;
        const std::regex tag(R"(<(/?)([a-zA-Z]+)((?:\s+[a-zA-Z:-]+="[^"<]*")*)\s*(/?)>|<\?xml[^>]*\?>)");
        std::size_t last = 0;
        for (std::sregex_iterator it(svg.begin(), svg.end(), tag), end; it != end; ++it)
        {
            const auto &m = *it;
            if (svg.substr(last, m.position() - last).find_first_of("<>") != std::string::npos)
                return ::testing::AssertionFailure() << "stray '<' or '>' at " << last;
            last = m.position() + m.length();
            if (m[2].length() == 0)
                continue;  // the XML declaration
            const std::string attributes = m[3];
            const std::regex name(R"(([a-zA-Z:-]+)=")");
            std::set<std::string> names;
            for (std::sregex_iterator at(attributes.begin(), attributes.end(), name), none; at != none; ++at)
                if (!names.insert((*at)[1]).second)
                    return ::testing::AssertionFailure() << "attribute " << (*at)[1] << " repeated at " << m.position();
            if (m[1] == "/")
            {
                if (open.empty() || open.back() != m[2])
                    return ::testing::AssertionFailure() << "unexpected </" << m[2] << "> at " << m.position();
                open.pop_back();
            }
            else if (m[4] != "/")
            {
                roots += open.empty() ? 1 : 0;
                open.push_back(m[2]);
            }
        }
        if (!open.empty() || roots != 1)
            return ::testing::AssertionFailure() << open.size() << " unclosed elements, " << roots << " roots";
        return ::testing::AssertionSuccess();
    }

    /** Every robot on a straight line from start to goal: not collision-free, but a plan to draw. */
    MultiRobotPlan straightPlan(const MultiRobotProblem &problem)
    {
        MultiRobotPlan plan(*problem.getSpaceInformation());
        for (std::size_t i = 0; i < problem.getRobotCount(); ++i)
            plan.setRobotPath(i, test::straightLine(problem.getStart(i), problem.getGoal(i), 128.));
        return plan;
    }
}  // namespace

TEST(SvgWriter, AnimatesDiscsAsCircles)
{
    const auto problem = scenarios::createMobileCross(4);
    const auto plan = straightPlan(problem);
    ASSERT_GT(plan.getMakespan(), 1000u);  // long enough to need subsampling
    SvgOptions options;
    options.maxKeyframes = 50;
    const std::string svg = SvgWriter::toSvg(problem, &plan, options);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(count(svg, "<g class=\"robot\""), 4u);
    EXPECT_EQ(count(svg, "<animate attributeName=\"cx\""), 4u);
    EXPECT_EQ(count(svg, "<animate attributeName=\"cy\""), 4u);
    EXPECT_EQ(count(svg, "class=\"trace\""), 4u);
    // 50 keyframes: 49 separators in each values list.
    const auto values = svg.find("values=\"", svg.find("attributeName=\"cx\""));
    EXPECT_EQ(std::count(svg.begin() + values, svg.begin() + svg.find('"', values + 8), ';'), 49);
}

TEST(SvgWriter, DrawsArmsAsPolylinesAndObstacles)
{
    const auto problem = scenarios::createPlanarCross(4);
    const auto plan = straightPlan(problem);
    const std::string svg = SvgWriter::toSvg(problem, &plan);
    EXPECT_TRUE(wellFormed(svg));
    EXPECT_EQ(count(svg, "<g class=\"robot\""), 4u);
    EXPECT_EQ(count(svg, "class=\"obstacle\""), 4u);  // backboards and walls
    EXPECT_EQ(count(svg, "<animate attributeName=\"points\""), 4u);
    EXPECT_EQ(count(svg, "<polyline points="), 3u * 4u);  // start, goal and moving arm of each robot
}

TEST(SvgWriter, StaticSnapshotHasNoAnimation)
{
    const auto problem = scenarios::createMobileCircle(8);
    const auto plan = straightPlan(problem);
    SvgOptions options;
    options.animate = false;
    const std::string withPlan = SvgWriter::toSvg(problem, &plan, options);
    EXPECT_TRUE(wellFormed(withPlan));
    EXPECT_EQ(count(withPlan, "<animate"), 0u);
    EXPECT_EQ(count(withPlan, "class=\"trace\""), 8u);
    EXPECT_EQ(count(withPlan, "class=\"start\""), 8u);
    EXPECT_EQ(count(withPlan, "class=\"goal\""), 8u);
    // Without a plan: the problem alone.
    const std::string alone = SvgWriter::toSvg(problem, nullptr);
    EXPECT_TRUE(wellFormed(alone));
    EXPECT_EQ(count(alone, "class=\"trace\""), 0u);
    EXPECT_EQ(count(alone, "<g class=\"robot\""), 8u);
}
