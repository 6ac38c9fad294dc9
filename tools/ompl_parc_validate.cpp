/* ompl_parc_validate: re-check a solution file against a problem with the independent validator.
   Exit 0: valid; 1: invalid (the first violation is printed); 2: bad input (one-line reason); 130: interrupted
   (Ctrl-C ends the check at once with the line "ompl_parc_validate: interrupted": it has nothing to report half-way).
*/
#include "Interruption.h"
#include "ToolSupport.h"

#include "ompl_parc/io/PictureFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/util/ParseNumber.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/Time.h>

#include <iostream>

namespace po = boost::program_options;
using namespace ompl_parc;

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_validate",
        [&]
        {
            po::options_description options("Usage: ompl_parc_validate [options] SOLUTION.json\nOptions");
            tools::addProblemOptions(options);
            options.add_options()("substeps", po::value<std::string>()->default_value("4"),
                                  "fewest samples per timestep interval (more where the motion needs them: every "
                                  "instant between timesteps is checked whatever this is)")(
                "threads", po::value<std::string>()->default_value("0"), "threads of the check (0: one per core)")(
                "picture", po::value<std::string>(),
                "draw the plan, valid or not: an interactive 3D page for a .html name, else an animated SVG")(
                "solution", po::value<std::string>(), "solution file");
            po::positional_options_description positional;
            positional.add("solution", 1);
            const auto vm = tools::parse(argc, argv, options, positional);
            const tools::Interruption interruption("ompl_parc_validate", tools::Interruption::FirstSignal::EXIT);
            if (!vm.count("solution"))
                throw std::invalid_argument("no solution file given (see --help)");
            const MultiRobotProblem problem = tools::problemFromOptions(vm);
            const ompl::time::point start = ompl::time::now();
            const MultiRobotPlan plan =
                SolutionFile::read(vm["solution"].as<std::string>(), *problem.getSpaceInformation());
            const double readTime = ompl::time::seconds(ompl::time::now() - start);
            ValidationOptions validation;
            // More samples per timestep than 1024 only make the check slower (the continuous check is exact).
            validation.substeps =
                static_cast<unsigned int>(parseInteger(vm["substeps"].as<std::string>(), "--substeps", 1, 1024));
            validation.threads =
                static_cast<unsigned int>(parseInteger(vm["threads"].as<std::string>(), "--threads", 0, 1024));
            const ompl::time::point checkStart = ompl::time::now();
            const ValidationReport report = SolutionValidator(problem, validation).validate(plan);
            const double checkTime = ompl::time::seconds(ompl::time::now() - checkStart);
            if (vm.count("picture"))
            {
                PictureFile::write(vm["picture"].as<std::string>(), problem, &plan);
                std::cout << "picture: " << vm["picture"].as<std::string>() << std::endl;
            }
            if (!report.valid)
            {
                std::cout << "invalid: " << report.message << std::endl;
                return static_cast<int>(tools::EXIT_FAILED);
            }
            std::cout << "valid: " << plan.getRobotCount() << " robots, makespan " << plan.getMakespan()
                      << " timesteps, sum of costs " << plan.getSumOfCosts() << ", " << report.configurationsChecked
                      << " configurations checked (file read in " << readTime << " s, checked in " << checkTime << " s)"
                      << std::endl;
            return static_cast<int>(tools::EXIT_SOLVED);
        });
}
