#include "TestProblems.h"

#include "ompl_parc/robots/DiscRobot.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

ompl::base::PlannerStatus ompl_parc::test::solveWith(ompl::base::Planner &planner, const MultiRobotProblem &problem,
                                                     double limit)
{
    planner.setProblemDefinition(problem.createProblemDefinition());
    planner.setup();
    return planner.solve(ompl::base::timedPlannerTerminationCondition(limit));
}

ompl_parc::MultiRobotProblem ompl_parc::test::discPair(const std::shared_ptr<Environment> &env,
                                                       std::vector<std::vector<double>> starts,
                                                       std::vector<std::vector<double>> goals, double resolution,
                                                       const std::string &name)
{
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(-10.);
    bounds.setHigh(10.);
    std::vector<RobotPtr> team = {std::make_shared<DiscRobot>("a", env, 0.5, bounds),
                                  std::make_shared<DiscRobot>("b", env, 0.5, bounds)};
    return MultiRobotProblem(std::make_shared<MultiRobotSpaceInformation>(team, resolution), std::move(starts),
                             std::move(goals), name);
}

ompl_parc::MultiRobotProblem ompl_parc::test::twoDiscs(std::vector<double> startA, std::vector<double> goalA,
                                                       std::vector<double> startB, std::vector<double> goalB, bool wall,
                                                       double resolution)
{
    auto env = std::make_shared<Environment>();
    if (wall)
        env->addBox2D("wall", 0., 0., 0.2, 4.);
    return discPair(env, {std::move(startA), std::move(startB)}, {std::move(goalA), std::move(goalB)}, resolution,
                    "two_discs");
}

ompl_parc::MultiRobotProblem ompl_parc::test::corridorSwap(double resolution)
{
    auto env = std::make_shared<Environment>();
    env->addBox2D("above", 0., 5.3, 20., 9.4);
    env->addBox2D("below", 0., -5.3, 20., 9.4);
    return discPair(env, {{-5., 0.}, {5., 0.}}, {{5., 0.}, {-5., 0.}}, resolution, "corridor_swap");
}

std::vector<double> ompl_parc::test::straightLine(const std::vector<double> &a, const std::vector<double> &b,
                                                  double resolution)
{
    double d2 = 0.;
    for (std::size_t k = 0; k < a.size(); ++k)
        d2 += (b[k] - a[k]) * (b[k] - a[k]);
    const auto steps = static_cast<std::size_t>(std::ceil(std::sqrt(d2) * resolution));
    std::vector<double> flat(a);
    for (std::size_t s = 1; s <= steps; ++s)
        for (std::size_t k = 0; k < a.size(); ++k)
            flat.push_back(s == steps ? b[k]
                                      : a[k] + (b[k] - a[k]) * static_cast<double>(s) / static_cast<double>(steps));
    return flat;
}

ompl_parc::Subproblem ompl_parc::test::wholeProblem(const MultiRobotProblem &problem)
{
    Subproblem sub;
    for (std::size_t i = 0; i < problem.getRobotCount(); ++i)
    {
        sub.robots.push_back(i);
        sub.starts.push_back(problem.getStart(i));
        sub.goals.push_back(problem.getGoal(i));
    }
    sub.global = true;
    return sub;
}

ompl_parc::ValidationReport ompl_parc::test::validatePatch(const MultiRobotProblem &problem, const Subproblem &sub,
                                                           const Patch &patch)
{
    std::vector<RobotPtr> team;
    for (std::size_t r : sub.robots)
        team.push_back(problem.getSpaceInformation()->getRobot(r));
    MultiRobotProblem local(
        std::make_shared<MultiRobotSpaceInformation>(team, problem.getSpaceInformation()->getResolution()), sub.starts,
        sub.goals);
    MultiRobotPlan plan(*local.getSpaceInformation());
    for (std::size_t k = 0; k < team.size(); ++k)
        plan.setPath(k, patch.paths[k]);
    return SolutionValidator(local).validate(plan);
}

bool ompl_parc::test::pathFollowsPlan(const MultiRobotSpaceInformation &si, const ompl::geometric::PathGeometric &path,
                                      const MultiRobotPlan &plan)
{
    const auto times = plan.getBreakpoints();
    if (path.getStateCount() != times.size())
        return false;
    for (std::size_t k = 0; k < times.size(); ++k)
        for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        {
            const auto q = config(plan, i, times[k]);
            if (!std::equal(q.begin(), q.end(), si.getRobotValues(path.getState(k), i)))
                return false;
        }
    return true;
}

std::vector<double> ompl_parc::test::config(const MultiRobotPlan &plan, std::size_t robot, std::size_t t)
{
    std::vector<double> q(plan.getDimension(robot));
    plan.getConfig(robot, t, q.data());
    return q;
}

ompl_parc::MultiRobotPlan ompl_parc::test::randomWalkPlan(const MultiRobotSpaceInformation &si, std::mt19937 &rng,
                                                          double maxStep)
{
    MultiRobotPlan plan(si);
    std::uniform_real_distribution<double> where(-3.5, 3.5), step(-maxStep, maxStep);
    std::uniform_int_distribution<int> length(50, 400);
    for (std::size_t r = 0; r < si.getRobotCount(); ++r)
    {
        std::vector<double> q = {where(rng), where(rng)}, flat = q;
        for (int t = length(rng); t > 0; --t)
        {
            q[0] += step(rng);
            q[1] += step(rng);
            flat.insert(flat.end(), q.begin(), q.end());
        }
        plan.setRobotPath(r, flat);
    }
    return plan;
}

std::vector<ompl_parc::Conflict> ompl_parc::test::allConflicts(const MultiRobotSpaceInformation &si,
                                                               const MultiRobotPlan &plan)
{
    std::vector<Conflict> all;
    for (std::size_t t = 0; t <= plan.getMakespan(); ++t)
        for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
            for (std::size_t j = i + 1; j < plan.getRobotCount(); ++j)
                if (si.robotsCollide(i, config(plan, i, t).data(), j, config(plan, j, t).data()))
                    all.push_back({i, j, t});
    return all;
}

ompl_parc::MultiRobotProblem ompl_parc::test::problemOfPlan(const MultiRobotSpaceInformationPtr &si,
                                                            const MultiRobotPlan &plan)
{
    std::vector<std::vector<double>> starts, goals;
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        starts.emplace_back(plan.getDimension(i));
        goals.emplace_back(plan.getDimension(i));
        plan.getConfig(i, 0, starts.back().data());
        plan.getConfig(i, plan.getArrival(i), goals.back().data());
    }
    return MultiRobotProblem(si, starts, goals);
}

void ompl_parc::test::followFrom(MultiRobotPlan &plan, std::size_t a, std::size_t b, std::size_t t)
{
    auto path = plan.getRobotPath(a);
    path.resize(plan.getDimension(a) * t);
    for (std::size_t s = t; s <= std::max(t, plan.getArrival(b)); ++s)
    {
        const auto q = config(plan, b, s);
        path.insert(path.end(), q.begin(), q.end());
    }
    plan.setRobotPath(a, path);
}

ompl_parc::MultiRobotPlan ompl_parc::test::straightLinePlan(const MultiRobotProblem &problem)
{
    const auto &si = *problem.getSpaceInformation();
    MultiRobotPlan plan(si);
    for (std::size_t r = 0; r < si.getRobotCount(); ++r)
        plan.setRobotPath(r, straightLine(problem.getStart(r), problem.getGoal(r), si.getResolution()));
    return plan;
}

std::string ompl_parc::test::gripperArmUrdf(const std::string &slideAxis, const std::string &mimic,
                                            const std::string &finger2Upper)
{
    return R"(<robot name="gripper_arm">
  <link name="base"><collision><geometry><sphere radius="0.08"/></geometry></collision></link>
  <link name="column"><collision><origin xyz="0 0 0.2"/><geometry><cylinder radius="0.04" length="0.3"/></geometry></collision></link>
  <link name="carriage"><collision><geometry><box size="0.08 0.08 0.08"/></geometry></collision></link>
  <link name="forearm"><collision><origin xyz="0 0 0.15"/><geometry><cylinder radius="0.03" length="0.3"/></geometry></collision></link>
  <link name="hand"><collision><geometry><box size="0.04 0.16 0.03"/></geometry></collision></link>
  <link name="finger1"><collision><origin xyz="0 0 0.03"/><geometry><box size="0.02 0.02 0.06"/></geometry></collision></link>
  <link name="finger2"><collision><origin xyz="0 0 0.03"/><geometry><box size="0.02 0.02 0.06"/></geometry></collision></link>
  <joint name="turn" type="revolute"><parent link="base"/><child link="column"/><origin xyz="0 0 0.05"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1.5"/></joint>
  <joint name="slide" type="prismatic"><parent link="column"/><child link="carriage"/><origin xyz="0 0 0.5"/>
    <axis xyz=")" +
           slideAxis +
           R"("/><limit lower="-0.2" upper="0.3" effort="1" velocity="0.5"/></joint>
  <joint name="bend" type="revolute"><parent link="carriage"/><child link="forearm"/><origin xyz="0.05 0 0"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="fixed"><parent link="forearm"/><child link="hand"/><origin xyz="0 0 0.3"/></joint>
  <joint name="finger_joint1" type="prismatic"><parent link="hand"/><child link="finger1"/>
    <origin xyz="0 0.01 0.015"/><axis xyz="0 1 0"/><limit lower="0" upper="0.05" effort="1" velocity="0.2"/></joint>
  <joint name="finger_joint2" type="prismatic"><parent link="hand"/><child link="finger2"/>
    <origin xyz="0 -0.01 0.015"/><axis xyz="0 -1 0"/><limit lower="0" upper=")" +
           finger2Upper + R"(" effort="1" velocity="0.2"/>)" + mimic + R"(</joint>
</robot>)";
}

std::vector<double> ompl_parc::test::randomConfig(const Robot &robot, std::mt19937 &rng)
{
    std::vector<double> q(robot.getDimension());
    for (unsigned int d = 0; d < q.size(); ++d)
        q[d] = std::uniform_real_distribution<double>(robot.getBounds().low[d], robot.getBounds().high[d])(rng);
    return q;
}

std::string ompl_parc::test::messageOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const std::exception &e)
    {
        return e.what();
    }
    return "";
}

std::string ompl_parc::test::sphereArmUrdf()
{
    std::string urdf = R"(<robot name="spheres"><link name="link0"><collision><geometry><sphere radius="0.08"/>)"
                       R"(</geometry></collision></link>)";
    for (int k = 1; k <= 6; ++k)
    {
        urdf += "<link name=\"link" + std::to_string(k) + "\">";
        for (int s = 0; s < 8; ++s)
        {
            const double z = s < 6 ? 0.05 * s : 0.15, x = s == 6 ? 0.05 : (s == 7 ? -0.05 : 0.);
            urdf += "<collision><origin xyz=\"" + std::to_string(x) + " 0 " + std::to_string(z) +
                    "\"/><geometry><sphere radius=\"" + std::to_string(0.035 - 0.002 * k) +
                    "\"/></geometry></collision>";
        }
        urdf += "</link><joint name=\"joint" + std::to_string(k) + "\" type=\"revolute\"><parent link=\"link" +
                std::to_string(k - 1) + "\"/><child link=\"link" + std::to_string(k) + "\"/><origin xyz=\"0 0 " +
                (k == 1 ? "0.1" : "0.3") + "\"/><axis xyz=\"" + (k % 2 == 1 ? "0 0 1" : "0 1 0") +
                "\"/><limit lower=\"-2.9\" upper=\"2.9\" effort=\"1\" velocity=\"1\"/></joint>";
    }
    urdf += "</robot>";
    return urdf;
}
