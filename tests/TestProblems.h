#ifndef OMPL_PARC_TESTS_TEST_PROBLEMS_
#define OMPL_PARC_TESTS_TEST_PROBLEMS_

#include "ompl_parc/arc/Conflict.h"
#include "ompl_parc/arc/Patch.h"
#include "ompl_parc/arc/Subproblem.h"
#include "ompl_parc/collision/Environment.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>

#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace ompl_parc::test
{
    /** \brief Two discs "a" and "b" (radius 0.5) in the 20 x 20 box around the origin among \e env's obstacles. */
    MultiRobotProblem discPair(const std::shared_ptr<Environment> &env, std::vector<std::vector<double>> starts,
                               std::vector<std::vector<double>> goals, double resolution, const std::string &name);

    /** \brief Two discs (radius 0.5) in an empty 20 x 20 box, optionally with a wall box at the origin. */
    MultiRobotProblem twoDiscs(std::vector<double> startA, std::vector<double> goalA, std::vector<double> startB,
                               std::vector<double> goalB, bool wall = false, double resolution = 128.);

    /** \brief Two discs (radius 0.5) swapping ends of a closed corridor 1.2 wide (x from -10 to 10): each alone goes
        straight, together they can never pass, so no solution exists and a planner can only run until it is stopped. */
    MultiRobotProblem corridorSwap(double resolution = 128.);

    /** \brief Give \e planner the problem, set it up and solve with a time limit of \e limit seconds. */
    ompl::base::PlannerStatus solveWith(ompl::base::Planner &planner, const MultiRobotProblem &problem,
                                        double limit = 60.);

    /** \brief Seconds within which a planner must return after its termination condition fires. Typical is
        a few milliseconds; the bound is 250 ms (1.5 s in sanitizer builds, which run several times slower)
        because ctest runs two tests at once on a 2-core machine and a parallel planner's threads then wait
        for a core: a tighter bound would make the tests flaky, not stricter. */
    constexpr double promptReturn()
    {
#ifdef OMPL_PARC_SANITIZED
        return 1.5;
#else
        return 0.25;
#endif
    }

    /** \brief Random-walk plans of different lengths (50-400 timesteps) for a team of discs, all started in
        a 7 x 7 square, moving up to \e maxStep per coordinate and timestep: conflicts at all sorts of times. */
    MultiRobotPlan randomWalkPlan(const MultiRobotSpaceInformation &si, std::mt19937 &rng, double maxStep);

    /** \brief The problem of the team of \e si whose starts and goals are where \e plan starts and ends. */
    MultiRobotProblem problemOfPlan(const MultiRobotSpaceInformationPtr &si, const MultiRobotPlan &plan);

    /** \brief All conflicts of \e plan by brute force over every timestep and pair, in (t, i, j) order. */
    std::vector<Conflict> allConflicts(const MultiRobotSpaceInformation &si, const MultiRobotPlan &plan);

    /** \brief Straight-line timestep plan of one robot from \e a to \e b (at most 1/resolution per step). */
    std::vector<double> straightLine(const std::vector<double> &a, const std::vector<double> &b, double resolution);

    /** \brief The plan of \e problem in which every robot goes straight from its start to its goal. */
    MultiRobotPlan straightLinePlan(const MultiRobotProblem &problem);

    /** \brief The whole of \e problem as a subproblem of all its robots (ARC's global problem of every robot). */
    Subproblem wholeProblem(const MultiRobotProblem &problem);

    /** \brief A subproblem's patch as a plan of its own team, re-checked by the independent validator. */
    ValidationReport validatePatch(const MultiRobotProblem &problem, const Subproblem &sub, const Patch &patch);

    /** \brief True if \e path is \e plan as handed to OMPL: one composite state per breakpoint of the plan
        (MultiRobotPlan::getBreakpoints()), each exactly the plan's configurations there. */
    bool pathFollowsPlan(const MultiRobotSpaceInformation &si, const ompl::geometric::PathGeometric &path,
                         const MultiRobotPlan &plan);

    /** \brief Robot \e robot's configuration at timestep \e t as a vector. */
    std::vector<double> config(const MultiRobotPlan &plan, std::size_t robot, std::size_t t);

    /** \brief A configuration of \e robot drawn uniformly within its bounds. */
    std::vector<double> randomConfig(const Robot &robot, std::mt19937 &rng);

    /** \brief A URDF arm with every joint kind UrdfArm reads, chain "base" .. "finger1": a column turning about z
        (joint "turn"), a carriage sliding along \e slideAxis of the column (prismatic "slide", -0.2 .. 0.3 m), a
        forearm bending about y ("bend"), a hand fixed to it, a finger sliding along y of the hand (prismatic
        "finger_joint1", 0 .. 0.05 m, the tip link) and a second finger off the chain sliding along -y that mimics
        it (\e mimic: the `<mimic>` element; its own limit is 0 .. \e finger2Upper). */
    std::string gripperArmUrdf(const std::string &slideAxis = "1 0 0",
                               const std::string &mimic = "<mimic joint=\"finger_joint1\"/>",
                               const std::string &finger2Upper = "0.05");

    /** \brief A six-joint arm whose links are covered by spheres, as VAMP and cuRobo model arms, chain "link0" ..
        "link6": each link 0.3 m long with six spheres along it and two beside it, so several spheres per frame (the
        lanes' per-frame spheres skip most sphere pairs). */
    std::string sphereArmUrdf();

    /** \brief Replace robot \e a's path from timestep \e t on by robot \e b's (so that a and b collide from t on,
        up to b's arrival): the change an invalidation of (a, t) must account for. */
    void followFrom(MultiRobotPlan &plan, std::size_t a, std::size_t b, std::size_t t);

    /** \brief The message of the exception \e f throws, or "" if it throws none. */
    std::string messageOf(const std::function<void()> &f);
}  // namespace ompl_parc::test

#endif
