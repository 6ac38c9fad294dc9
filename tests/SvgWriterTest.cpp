#include "TestProblems.h"

#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
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
        attribute given twice. A hand-written scanner: std::regex recurses per character and overflows the
        stack on the long attribute values of animations (seen under ASan). */
    ::testing::AssertionResult wellFormed(const std::string &svg)
    {
        const auto isName = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == ':' || c == '-'; };
        std::vector<std::string> open;
        std::size_t roots = 0, i = 0;
        const auto fail = [&](const std::string &what) { return ::testing::AssertionFailure() << what << " at " << i; };
        while ((i = svg.find_first_of("<>", i)) != std::string::npos)
        {
            if (svg[i] == '>')
                return fail("stray '>'");
            if (svg.compare(i, 5, "<?xml") == 0)
            {
                i = svg.find("?>", i);
                if (i == std::string::npos)
                    return fail("unterminated XML declaration");
                i += 2;
                continue;
            }
            ++i;
            const bool closing = i < svg.size() && svg[i] == '/';
            i += closing ? 1 : 0;
            const std::size_t nameStart = i;
            while (i < svg.size() && std::isalpha(static_cast<unsigned char>(svg[i])))
                ++i;
            const std::string element = svg.substr(nameStart, i - nameStart);
            if (element.empty())
                return fail("tag without a name");
            std::set<std::string> names;
            while (true)
            {
                const std::size_t space = i;
                while (i < svg.size() && std::isspace(static_cast<unsigned char>(svg[i])))
                    ++i;
                if (i >= svg.size() || !isName(svg[i]) || i == space)
                    break;
                const std::size_t attributeStart = i;
                while (i < svg.size() && isName(svg[i]))
                    ++i;
                const std::string attribute = svg.substr(attributeStart, i - attributeStart);
                if (svg.compare(i, 2, "=\"") != 0)
                    return fail("attribute " + attribute + " without a quoted value");
                const std::size_t end = svg.find('"', i + 2);
                if (end == std::string::npos || svg.find('<', i + 2) < end)
                    return fail("unterminated value of " + attribute);
                if (!names.insert(attribute).second)
                    return fail("attribute " + attribute + " repeated");
                i = end + 1;
            }
            const bool empty = i < svg.size() && svg[i] == '/';
            i += empty ? 1 : 0;
            if (i >= svg.size() || svg[i] != '>')
                return fail("malformed <" + element + ">");
            ++i;
            if (closing)
            {
                if (open.empty() || open.back() != element)
                    return fail("unexpected </" + element + ">");
                open.pop_back();
            }
            else if (!empty)
            {
                roots += open.empty() ? 1 : 0;
                open.push_back(element);
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

TEST(SvgWriter, TheWellFormednessCheckRejectsBrokenDocuments)
{
    EXPECT_TRUE(wellFormed("<?xml version=\"1.0\"?><svg a=\"1\"><g b=\"x y\"/><text>hi</text></svg>"));
    EXPECT_FALSE(wellFormed("<svg><g></svg>"));
    EXPECT_FALSE(wellFormed("<svg fill=\"a\" fill=\"b\"></svg>"));
    EXPECT_FALSE(wellFormed("<svg></svg><svg></svg>"));
    EXPECT_FALSE(wellFormed("<svg a=\"1></svg>"));
    EXPECT_FALSE(wellFormed("<svg> > </svg>"));
}

TEST(SvgWriter, ATopViewOfA3DProblemSaysSo)
{
    const MultiRobotProblem panda = scenarios::createScenario("panda_cage", 2);
    const MultiRobotProblem discs = scenarios::createScenario("mobile_cross", 4);
    EXPECT_FALSE(SvgWriter::isPlanar(panda));
    EXPECT_TRUE(SvgWriter::isPlanar(discs));
    EXPECT_TRUE(SvgWriter::isPlanar(scenarios::createScenario("planar_cross", 4)));
    EXPECT_NE(SvgWriter::toSvg(panda, nullptr).find("3D problem: top view only"), std::string::npos);
    EXPECT_EQ(SvgWriter::toSvg(discs, nullptr).find("class=\"note\""), std::string::npos);
}
