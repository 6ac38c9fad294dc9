/* ompl_parc_demo: solve a built-in multi-robot scenario and re-check the result with the independent
   validator. Until ARC lands, the planner is OMPL's own RRTConnect over the composite space.
   Exit 0: solved and validated; 1: not solved in time (or invalid); 2: bad input. */
#include "ToolSupport.h"

#include "ompl_parc/SolutionFile.h"
#include "ompl_parc/SolutionValidator.h"

#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <iomanip>
#include <iostream>

namespace og = ompl::geometric;
namespace po = boost::program_options;
using namespace ompl_parc;

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_demo",
        [&]
        {
            po::options_description options("Usage: ompl_parc_demo [options]\nOptions");
            tools::addProblemOptions(options);
            options.add_options()("seed", po::value<std::uint32_t>()->default_value(1), "random seed")(
                "time-limit", po::value<double>()->default_value(30.), "planning time limit in seconds")(
                "out", po::value<std::string>(), "write the solution to this JSON file")("help,h", "show this help");
            const auto vm = tools::parse(argc, argv, options);
            if (vm.count("help"))
            {
                std::cout << options << std::endl;
                return static_cast<int>(tools::EXIT_SOLVED);
            }
            const double timeLimit = vm["time-limit"].as<double>();
            if (!(timeLimit > 0.))
                throw std::invalid_argument("--time-limit must be positive");
            ompl::RNG::setSeed(vm["seed"].as<std::uint32_t>());

            const MultiRobotProblem problem = tools::problemFromOptions(vm);
            const auto &si = problem.getSpaceInformation();
            auto pdef = problem.createProblemDefinition();
            auto planner = std::make_shared<og::RRTConnect>(si);
            planner->setProblemDefinition(pdef);
            planner->setup();

            std::cout << "scenario   " << problem.getName() << ", " << si->getRobotCount() << " robots\n"
                      << "planner    " << planner->getName() << " over the composite space\n";
            const ompl::time::point start = ompl::time::now();
            const auto status = planner->solve(ompl::base::timedPlannerTerminationCondition(timeLimit));
            const double planTime = ompl::time::seconds(ompl::time::now() - start);
            std::cout << "status     " << status.asString() << " after " << std::fixed << std::setprecision(3)
                      << planTime << " s\n";
            if (status != ompl::base::PlannerStatus::EXACT_SOLUTION)
                return static_cast<int>(tools::EXIT_FAILED);

            auto &path = *pdef->getSolutionPath()->as<og::PathGeometric>();
            og::PathSimplifier(si).simplify(path, 1.0);
            const MultiRobotPlan plan = MultiRobotPlan::fromPathGeometric(*si, path);
            const ValidationReport report = SolutionValidator(problem).validate(plan);
            std::cout << "makespan   " << plan.getMakespan() << " timesteps ("
                      << plan.getMakespan() / si->getResolution() << " s at vmax 1)\n"
                      << "sum costs  " << plan.getSumOfCosts() << " timesteps\n"
                      << "validated  " << (report.valid ? "yes" : "NO: " + report.message) << std::endl;
            if (vm.count("out"))
            {
                SolutionFile::write(vm["out"].as<std::string>(), plan, *si);
                std::cout << "solution   " << vm["out"].as<std::string>() << std::endl;
            }
            return static_cast<int>(report.valid ? tools::EXIT_SOLVED : tools::EXIT_FAILED);
        });
}
