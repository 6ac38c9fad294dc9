#include "TestProblems.h"

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/io/HtmlWriter.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <boost/archive/iterators/binary_from_base64.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <cmath>
#include <cstring>

using namespace ompl_parc;
using nlohmann::json;

namespace
{
    /** The scene the page carries. */
    json sceneOf(const std::string &page)
    {
        const std::string open = "<script id=\"scene\" type=\"application/json\">";
        const auto from = page.find(open) + open.size();
        return json::parse(page.substr(from, page.find("</script>", from) - from));
    }

    std::vector<float> floatsOf(const std::string &base64)
    {
        using namespace boost::archive::iterators;
        using Decoder = transform_width<binary_from_base64<std::string::const_iterator>, 8, 6>;
        const std::string trimmed = base64.substr(0, base64.find('='));
        std::string bytes(Decoder(trimmed.begin()), Decoder(trimmed.end()));
        std::vector<float> out(bytes.size() / sizeof(float));
        std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
        return out;
    }

    /** The largest distance between a capsule end point as the page interpolates it at timestep \e t and as the
        robot's kinematics put it. */
    double pageError(const Robot &robot, const MultiRobotPlan &plan, std::size_t i, const json &entry, std::size_t t)
    {
        const auto frames = floatsOf(entry["frames"]);
        const auto &times = entry["times"];
        const std::size_t capsules = entry["radii"].size();
        const double now = static_cast<double>(t) / plan.getResolution();
        std::size_t k = 0;
        while (k + 1 < times.size() && times[k + 1].get<double>() <= now)
            ++k;
        const std::size_t k1 = std::min(k + 1, times.size() - 1);
        const double f =
            k1 > k ? std::clamp((now - times[k].get<double>()) / (times[k1].get<double>() - times[k].get<double>()), 0.,
                                1.)
                   : 0.;
        CollisionBody body;
        robot.computeBody(test::config(plan, i, t).data(), body);
        double worst = 0.;
        for (std::size_t c = 0; c < capsules; ++c)
        {
            const double truth[6] = {body.ax_[c], body.ay_[c], body.az_[c], body.bx_[c], body.by_[c], body.bz_[c]};
            for (int end = 0; end < 2; ++end)
            {
                double squared = 0.;
                for (int d = 0; d < 3; ++d)
                {
                    const std::size_t j = (k * capsules + c) * 6 + end * 3 + d,
                                      j1 = (k1 * capsules + c) * 6 + end * 3 + d;
                    const double x = frames[j] + f * (frames[j1] - frames[j]) - truth[end * 3 + d];
                    squared += x * x;
                }
                worst = std::max(worst, std::sqrt(squared));
            }
        }
        return worst;
    }
}  // namespace

/* The page is self-contained (three.js and its controls inlined, no address outside it) and carries the plan: both
   robots' keyframes (a disc: its path's breakpoints alone), the duration, and the closest approach of the pair. */
TEST(HtmlWriter, APageCarriesThePlanAndEverythingItNeeds)
{
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 1.5}, {-5., 1.5});
    MultiRobotPlan plan(*problem.getSpaceInformation());
    for (std::size_t i = 0; i < 2; ++i)
    {
        TimedPath path(2, problem.getStart(i).data());
        path.appendMotion(problem.getStart(i).data(), problem.getGoal(i).data(), 1280);
        plan.setPath(i, std::move(path));
    }
    const std::string page = HtmlWriter::toHtml(problem, &plan);
    EXPECT_NE(page.find("REVISION=\"111\""), std::string::npos) << "three.js (Debian's libjs-three) inlined";
    EXPECT_NE(page.find("OrbitControls"), std::string::npos);
    EXPECT_EQ(page.find("src=\"http"), std::string::npos);
    const json scene = sceneOf(page);
    EXPECT_TRUE(scene["planar"].get<bool>());
    EXPECT_DOUBLE_EQ(scene["duration"].get<double>(), plan.getMakespan() / plan.getResolution());
    ASSERT_EQ(scene["robots"].size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
    {
        const json &robot = scene["robots"][i];
        EXPECT_EQ(robot["times"].size(), 2u) << "a straight motion needs its two ends only";
        EXPECT_EQ(floatsOf(robot["frames"]).size(), 2u * 6u);
        for (std::size_t t = 0; t <= plan.getMakespan(); t += 7)
            EXPECT_LT(pageError(*problem.getSpaceInformation()->getRobot(i), plan, i, robot, t), 1e-5);
    }
    ASSERT_EQ(scene["closest"].size(), 1u);
    EXPECT_NEAR(scene["closest"][0]["clearance"].get<double>(), 0.5, 1e-3);

    // Without a plan: starts and goals only.
    const json problemOnly = sceneOf(HtmlWriter::toHtml(problem, nullptr));
    EXPECT_FALSE(problemOnly["robots"][0].contains("frames"));
    EXPECT_TRUE(problemOnly["closest"].empty());
}

/* A Panda's links sweep arcs: between keyframes the page's interpolated capsules stay within a few tenths of the
   thinnest capsule's radius of the true ones at every timestep of an ARC plan of Panda Cage 4 (checked by the
   validator too). */
TEST(HtmlWriter, ArmKeyframesFollowTheKinematics)
{
    const auto problem = scenarios::createPandaCage(4, 0);
    ARC planner(problem.getSpaceInformation());
    planner.setSeed(1);
    ASSERT_EQ(test::solveWith(planner, problem, 100.), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const auto &plan = planner.getPlan();
    ASSERT_TRUE(SolutionValidator(problem).validate(plan).valid);
    const json scene = sceneOf(HtmlWriter::toHtml(problem, &plan));
    EXPECT_FALSE(scene["planar"].get<bool>());
    for (std::size_t i = 0; i < 4; ++i)
    {
        const json &robot = scene["robots"][i];
        double thinnest = 1e9, worst = 0.;
        for (const auto &r : robot["radii"])
            thinnest = std::min(thinnest, r.get<double>());
        for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
            worst = std::max(worst, pageError(*problem.getSpaceInformation()->getRobot(i), plan, i, robot, t));
        EXPECT_LT(worst, 0.3 * thinnest) << "robot " << i << ", " << robot["times"].size() << " keyframes";
    }
}

/* Bad input: a plan of another team, a path that cannot be written; and which names make a page. */
TEST(HtmlWriter, BadInputGetsAClearError)
{
    const auto problem = test::twoDiscs({-5., 0.}, {5., 0.}, {5., 1.5}, {-5., 1.5});
    const auto other = scenarios::createMobileCircle(4);
    const auto plan = test::straightLinePlan(other);
    try
    {
        HtmlWriter::toHtml(problem, &plan);
        FAIL() << "a plan of 4 robots was drawn for 2";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("the plan has 4 robots, the problem 2"), std::string::npos) << e.what();
    }
    try
    {
        HtmlWriter::write("/nonexistent-folder/plan.html", problem, nullptr);
        FAIL() << "wrote into a folder that does not exist";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("cannot write '/nonexistent-folder/plan.html'"), std::string::npos);
    }
    EXPECT_TRUE(HtmlWriter::isPagePath("plan.html"));
    EXPECT_TRUE(HtmlWriter::isPagePath("PLAN.HTM"));
    EXPECT_FALSE(HtmlWriter::isPagePath("plan.svg"));
    EXPECT_FALSE(HtmlWriter::isPagePath("html"));
}
