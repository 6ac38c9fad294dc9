/* ompl_parc_demo: solve a built-in multi-robot scenario or a scenario file with one of our planners (or OMPL's
   RRTConnect over the composite space), re-check the result with the independent validator and optionally
   draw it (SVG for 2D problems; for 3D ones --geometry writes the shapes scripts/draw_panda_cage.py draws).
   Ctrl-C stops the planner through its termination condition: the summary says "Interrupted", --out is written only
   if the plan is complete and validated. Exit 0: solved and validated (or --no-validate); 1: not solved in time (or
   invalid); 2: bad input; 130: interrupted. */
#include "Interruption.h"
#include "ProgressLine.h"
#include "ToolSupport.h"

#include "ompl_parc/io/GeometryFile.h"
#include "ompl_parc/io/HtmlWriter.h"
#include "ompl_parc/io/PictureFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/io/TrajectoryFile.h"
#include "ompl_parc/meshes/BoxFit.h"
#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/planners/ArcPlannerBase.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/quality/PlanSmoother.h"
#include "ompl_parc/quality/SmoothingStep.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/ParseNumber.h"
#include "ompl_parc/util/StopSignal.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/base/PlannerData.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>

namespace po = boost::program_options;
using namespace ompl_parc;

namespace
{
    /** \brief The planner's PlannerData property \e name ("" if it has none). */
    std::string propertyOf(const ompl::base::Planner &planner, const std::string &name)
    {
        ompl::base::PlannerData data(planner.getSpaceInformation());
        planner.getPlannerData(data);
        const auto found = data.properties.find(name);
        return found == data.properties.end() ? std::string() : found->second;
    }

    /** \brief Which OR-P-ARC instance the statistics lines describe, and how every instance ended. */
    /** For the ARC family, ", profile P" and whether the robots chose it (the profile sets the repair windows). */
    std::string profileNote(const ompl::base::Planner &planner, const MultiRobotSpaceInformation &si)
    {
        if (!planner.params().hasParam("profile"))
            return "";
        const std::string set = planner.params().getParam("profile")->getValue();
        if (set != "auto")
            return ", profile " + set;
        return ", profile " + ArcSettings::profileFor(si) + " (from the robots; --param profile=... to choose)";
    }

    void printRace(const ORPARC &orparc)
    {
        const int reported = orparc.getReportedInstance();
        if (reported < 0)
            return;
        const std::string &name = orparc.getRacer(reported).getName();
        std::cout << "race       "
                  << (orparc.getRacerStatus(reported) == ompl::base::PlannerStatus::EXACT_SOLUTION
                          ? "winner " + name
                          : "no winner, " + name + " went furthest")
                  << " of " << orparc.getRacerCount() << " instances (statistics below are its own)\n";
        if (orparc.getObjective() != "first")
            std::cout << "anytime    " << propertyOf(orparc, "anytime_rounds INTEGER") << " races, "
                      << propertyOf(orparc, "improvements INTEGER") << " better plans by " << orparc.getObjective()
                      << " (statistics: the last race's)\n";
        for (std::size_t k = 0; k < orparc.getRacerCount(); ++k)
        {
            const auto &s = orparc.getRacer(k).getStatistics();
            std::cout << "instance   " << orparc.getRacer(k).getName() << ": " << orparc.getRacerStatus(k).asString()
                      << ", stages " << s.initialWall + s.detectionWall + s.resolutionWall << " s, " << s.conflicts
                      << " conflicts resolved, " << orparc.getRacer(k).getParallelStatistics().repairAttempts
                      << " repair attempts\n";
        }
    }

    /** How tightly the primitives planning checks fit the meshes: per URDF with meshes (once for all the robots
        that share it) and per mesh obstacle, the fitted volume over the mesh's (1 is exact). */
    void printMeshFits(const MultiRobotSpaceInformation &si)
    {
        std::map<std::string, std::vector<std::string>> robotsOf;
        std::vector<const UrdfArm *> arms;
        for (unsigned int r = 0; r < si.getRobotCount(); ++r)
            if (const auto *arm = dynamic_cast<const UrdfArm *>(si.getRobot(r).get()); arm && !arm->getMeshes().empty())
            {
                auto &names = robotsOf[arm->getUrdfXml()];
                if (names.empty())
                    arms.push_back(arm);
                names.push_back(arm->getName());
            }
        std::cout << std::setprecision(3);
        for (const UrdfArm *arm : arms)
        {
            // An open mesh bounds no volume to compare with: it is counted, not rated.
            std::vector<std::pair<double, std::string>> ratios;
            std::size_t capsules = 0, open = 0;
            for (const auto &mesh : arm->getMeshes())
            {
                if (mesh.fit.getVolumeRatio() > 0.)
                    ratios.emplace_back(mesh.fit.getVolumeRatio(), mesh.link);
                else
                    ++open;
                capsules += mesh.fit.getCapsules().size();
            }
            std::sort(ratios.begin(), ratios.end());
            const std::size_t sharing = robotsOf[arm->getUrdfXml()].size();
            std::cout << "meshes     robot " << arm->getName()
                      << (sharing > 1 ? " (and " + std::to_string(sharing - 1) + " more of its URDF)" : "") << ": "
                      << arm->getMeshes().size() << " meshes in " << capsules << " capsules";
            if (!ratios.empty())
                std::cout << ", fitted / mesh volume median " << ratios[ratios.size() / 2].first << ", worst "
                          << ratios.back().first << " (" << ratios.back().second << ")";
            if (open > 0)
                std::cout << ", " << open << " open (no volume to compare)";
            std::cout << "\n";
        }
        const auto &environment = *si.getRobot(0)->getEnvironment();
        for (std::size_t k = 0; k < environment.getObstacles().size(); ++k)
            if (const auto &fit = environment.getBoxFit(k))
            {
                std::cout << "meshes     obstacle " << environment.getObstacles()[k].name << ": "
                          << fit->getBoxes().size() << " boxes, ";
                if (fit->getVolumeRatio() > 0.)
                    std::cout << "fitted / mesh volume " << fit->getVolumeRatio() << "\n";
                else
                    std::cout << "open mesh (no volume to compare)\n";
            }
        std::cout << std::defaultfloat;
    }

    void printStatistics(const ompl::base::Planner &planner, double planTime)
    {
        const ArcStatistics *s = nullptr;
        const ParcStatistics *parallel = nullptr;
        if (const auto *orparc = dynamic_cast<const ORPARC *>(&planner))
        {
            printRace(*orparc);
            s = &orparc->getStatistics();
            parallel = &orparc->getParallelStatistics();
        }
        else if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner))
        {
            s = &arc->getStatistics();
            if (const auto *parc = dynamic_cast<const PARC *>(arc))
                parallel = &parc->getParallelStatistics();
        }
        if (s == nullptr)
            return;
        // The anytime phase has a line of its own (as smoothing, which planTime leaves out).
        double after = 0.;
        if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner); arc && arc->getImprovementReport())
            after = arc->getImprovementReport()->seconds;
        std::cout << "stages     initial " << s->initialWall << " s, detection " << s->detectionWall
                  << " s, resolution " << s->resolutionWall << " s, other "
                  << planTime - s->initialWall - s->detectionWall - s->resolutionWall - after
                  << " s (wall; other: reading the problem, building the solution path)\n"
                  << "conflicts  " << s->conflicts << " resolved, " << s->solverCalls << " solver calls, "
                  << s->expansions << " window expansions, " << s->teamGrowths << " robot-set growths, "
                  << s->globalRepairs << " global repairs, longest solver call " << s->longestSolverCall << " s\n";
        // Where the plan's length comes from: the initial plan, then what each solver's repairs added.
        std::cout << "length     initial plan makespan " << s->initialMakespan << ", sum of costs "
                  << s->initialSumOfCosts << "; repairs added";
        for (const auto &[solver, wins] : s->solverWins)
            std::cout << ", " << solver << " (" << wins << "): " << s->solverDelays.at(solver) << " to arrivals, "
                      << s->solverMakespanAdded.at(solver) << " to the makespan";
        std::cout << (s->solverWins.empty() ? " nothing" : "") << "; global repairs " << s->globalDelay
                  << " of those delays\n";
        if (parallel != nullptr)
            std::cout << "parallel   " << parallel->batches << " batches, " << parallel->repairAttempts
                      << " repair attempts (" << parallel->cancelledAttempts << " cancelled)\n";
        if (const auto *arc = dynamic_cast<const ArcPlannerBase *>(&planner); arc && arc->getImprovementReport())
            std::cout << "anytime    first solution after " << propertyOf(planner, "first_solution_time REAL")
                      << " s, then " << arc->getImprovementReport()->seconds << " s in "
                      << arc->getImprovementReport()->rounds << " rounds, " << arc->getImprovementReport()->improvements
                      << " better plans by " << arc->getObjective() << "\n";
    }

    /** \brief The smoothing line: what the planner's own smoothing did (from its properties), or, for a planner
        without one (OMPL's), smoothing \e plan here (from \e seed) for up to \e budget seconds within \e ptc; a plan
        with a conflict (OMPL's path laid on the grid) is left as it is, for the validator to report. */
    void printSmoothing(const ompl::base::Planner &planner, bool plannerSmooths, double budget, std::uint32_t seed,
                        const ompl::base::PlannerTerminationCondition &ptc, MultiRobotPlan &plan)
    {
        if (!(budget > 0.))
            return;
        SmoothingReport report;
        if (plannerSmooths)
        {
            ompl::base::PlannerData data(planner.getSpaceInformation());
            planner.getPlannerData(data);
            if (const auto written = SmoothingStep::reportOf(data.properties))
                report = *written;
        }
        else
        {
            const auto si = MultiRobotSpaceInformation::get(planner.getSpaceInformation(), "ompl_parc_demo");
            PlanSmoother smoother(si, seed);
            smoother.setReplanner(PrioritizedSTRRTSolver::makeReplanner());
            try
            {
                report = smoother.smooth(plan, ompl::base::plannerOrTerminationCondition(
                                                   ptc, ompl::base::timedPlannerTerminationCondition(budget)));
            }
            catch (const ompl::Exception &e)  // a composite path laid on the grid may touch between its states
            {
                std::cout << "smoothing  skipped: " << e.what() << "\n";
                return;
            }
        }
        const std::size_t teamKept = (report.teamReplanKept ? 1 : 0) + (report.teamSolveKept ? 1 : 0);
        std::ostringstream solve;
        if (report.teamSolveTried)
            solve << "whole-team solve "
                  << (report.teamSolveKept ? "kept" : report.teamSolved ? "not kept" : "not solved") << " ("
                  << report.teamSolveSeconds << " s), ";
        const char *team =
            report.teamReplanned ? (report.teamReplanKept ? "team replanned, " : "team replan not kept, ") : "";
        std::cout << "smoothing  " << report.seconds << " s (--smooth " << budget << "): " << solve.str() << team
                  << report.kept() - teamKept << " of " << report.attempts
                  << " shortcuts and replans kept; before it, makespan " << report.makespanBefore << ", sum of costs "
                  << report.sumOfCostsBefore << "\n";
    }
}  // namespace

int main(int argc, char **argv)
{
    return tools::runTool(
        "ompl_parc_demo",
        [&]
        {
            po::options_description options("Usage: ompl_parc_demo [options]\nOptions");
            tools::addProblemOptions(options);
            std::string plannerHelp = "planner:";
            for (const auto &n : PlannerRegistry::names())
                plannerHelp += " " + n;
            options.add_options()("planner", po::value<std::string>()->default_value("arc"), plannerHelp.c_str())(
                "param", po::value<std::vector<std::string>>()->composing(),
                "planner parameter key=value (repeatable; declared names, e.g. window=100)")(
                "seed", po::value<std::string>()->default_value("1"), "random seed")(
                "time-limit", po::value<std::string>()->default_value("30"), "planning time limit in seconds")(
                "workers", po::value<std::string>(), "worker threads of a parallel planner (its 'workers' parameter)")(
                "smooth", po::value<std::string>()->default_value("1"),
                "seconds of time-aware shortcutting after the solution (the planner's 'smooth' parameter); 0: off")(
                "out", po::value<std::string>(), "write the solution to this JSON file")(
                "trajectory", po::value<std::string>(),
                "write trajectories within the robots' velocity and acceleration limits (JointTrajectory fields) and "
                "the temporal plan graph to this JSON file (see ompl_parc_execute)")(
                "no-validate", "skip the independent validation of the solution (timing and memory runs)")(
                "picture", po::value<std::string>(),
                "draw the solution (or, unsolved, the problem): an interactive 3D page for a .html name, else an "
                "animated SVG")(
                "picture-static", "make an SVG --picture a static snapshot: starts, goals and traced paths")(
                "geometry", po::value<std::string>(),
                "write the world-frame shapes of the problem and solution (JSON, for scripts/draw_panda_cage.py)")(
                "verbose", "log the planner's stages (OMPL's INFO level)")(
                "debug", "log every conflict and repair, and the inner planners' messages too (OMPL's DEBUG level)")(
                "quiet", "no live progress line and no log but errors");
            const auto vm = tools::parse(argc, argv, options);
            if (vm.count("picture-static") && vm.count("picture") &&
                HtmlWriter::isPagePath(vm["picture"].as<std::string>()))
                throw std::invalid_argument("--picture-static applies to SVG pictures, not to the 3D page");
            if (vm.count("verbose") + vm.count("debug") + vm.count("quiet") > 1)
                throw std::invalid_argument("give one of --verbose, --debug and --quiet");
            ompl::msg::setLogLevel(vm.count("debug")     ? ompl::msg::LOG_DEBUG
                                   : vm.count("verbose") ? ompl::msg::LOG_INFO
                                   : vm.count("quiet")   ? ompl::msg::LOG_ERROR
                                                         : ompl::msg::LOG_WARN);
            InnerPlannerLog::setShown(vm.count("debug") != 0);
            // Longer than about four months, a limit is no limit, and OMPL's clock overflows near 1e10 s.
            const double timeLimit = parseReal(vm["time-limit"].as<std::string>(), "--time-limit", 0., 1e7);
            if (!(timeLimit > 0.))
                throw std::invalid_argument("--time-limit must be positive");
            const auto seed =
                static_cast<std::uint32_t>(parseInteger(vm["seed"].as<std::string>(), "--seed", 0, UINT32_MAX));
            ompl::RNG::setSeed(seed);
            // From here on a Ctrl-C stops the work and the summary says so (building a large problem takes a while).
            const tools::Interruption interruption("ompl_parc_demo");

            const MultiRobotProblem problem = tools::problemFromOptions(vm);
            if (const std::string coarse = problem.getSpaceInformation()->checkPlanningResolution(); !coarse.empty())
                throw std::invalid_argument(coarse);
            const auto &si = problem.getSpaceInformation();
            auto pdef = problem.createProblemDefinition();
            const auto params =
                vm.count("param") ? vm["param"].as<std::vector<std::string>>() : std::vector<std::string>{};
            auto planner = PlannerRegistry::create(vm["planner"].as<std::string>(), si, params);
            if (vm.count("workers"))
            {
                if (!planner->params().hasParam("workers"))
                    throw std::invalid_argument("--workers needs a parallel planner (parc); '" +
                                                vm["planner"].as<std::string>() + "' has no 'workers' parameter");
                PlannerRegistry::setParameter(*planner, "workers", vm["workers"].as<std::string>());
            }
            // Planners of ours smooth inside solve() (their 'smooth' parameter); OMPL's are smoothed here.
            const double smooth = parseReal(vm["smooth"].as<std::string>(), "--smooth", 0., 3600.);
            const bool plannerSmooths = planner->params().hasParam("smooth");
            if (plannerSmooths)
                PlannerRegistry::setParameter(*planner, "smooth", vm["smooth"].as<std::string>());
            planner->setProblemDefinition(pdef);
            planner->setup();

            std::cout << "scenario   " << problem.getName() << ", " << si->getRobotCount() << " robots\n";
            printMeshFits(*si);
            std::cout << "planner    " << planner->getName() << profileNote(*planner, *si) << "\n";
            std::optional<tools::ProgressLine> progress;
            if (vm.count("quiet") == 0)
                progress.emplace("planning...", PlannerRegistry::progressOf(*planner), si->getRobotCount());
            const ompl::time::point start = ompl::time::now();
            // The scope lets OMPL's own planners (rrtconnect) stop inside a long motion check too, on Ctrl-C as well.
            const auto ptc = ompl::base::plannerOrTerminationCondition(
                ompl::base::timedPlannerTerminationCondition(timeLimit), tools::Interruption::condition());
            const StopSignal::Scope scope(ptc);
            const auto status = planner->solve(ptc);
            const double planTime = ompl::time::seconds(ompl::time::now() - start);
            progress.reset();
            if (tools::Interruption::raised())
                std::cout << "status     Interrupted after " << std::fixed << std::setprecision(3) << planTime
                          << " s (the planner returned: " << status.asString() << ")\n";
            else
                std::cout << "status     " << status.asString() << " after " << std::fixed << std::setprecision(3)
                          << planTime << " s\n";
            // Smoothing is part of solve(); the stage line shows the planning before it.
            printStatistics(*planner, planTime - std::stod("0" + propertyOf(*planner, "smoothing_time REAL")));
            // The pictures of the solution, or of the problem alone if there is none.
            const auto writePictures = [&](const MultiRobotPlan *plan)
            {
                const char *only = plan == nullptr ? " (the problem only)" : "";
                if (vm.count("picture"))
                {
                    const std::string &path = vm["picture"].as<std::string>();
                    SvgOptions svg;
                    svg.animate = vm.count("picture-static") == 0;
                    PictureFile::write(path, problem, plan, svg);
                    const bool topView = !HtmlWriter::isPagePath(path) && !SvgWriter::isPlanar(problem);
                    std::cout << "picture    " << path << only
                              << (topView ? std::string(" -- ") + SvgWriter::TOP_VIEW_NOTE : "") << std::endl;
                }
                if (vm.count("geometry"))
                {
                    GeometryFile::write(vm["geometry"].as<std::string>(), problem, plan);
                    std::cout << "geometry   " << vm["geometry"].as<std::string>() << only << std::endl;
                }
            };
            // An interrupted run ends as any other and exits 130 (a Ctrl-C during the checks below counts too).
            const auto exitCode = [](tools::ExitCode code)
            { return static_cast<int>(tools::Interruption::raised() ? tools::EXIT_INTERRUPTED : code); };
            if (status != ompl::base::PlannerStatus::EXACT_SOLUTION)
            {
                writePictures(nullptr);
                return exitCode(tools::EXIT_FAILED);
            }

            MultiRobotPlan plan = PlannerRegistry::planOf(*planner, si, true);
            printSmoothing(*planner, plannerSmooths, smooth, seed, ptc, plan);
            const PlanQuality quality = PlanQuality::measure(*si, plan);
            const bool validate = vm.count("no-validate") == 0;
            const ompl::time::point checkStart = ompl::time::now();
            const ValidationReport report = validate ? SolutionValidator(problem).validate(plan) : ValidationReport{};
            const double checkTime = ompl::time::seconds(ompl::time::now() - checkStart);
            std::cout << "makespan   " << plan.getMakespan() << " timesteps ("
                      << plan.getMakespan() / si->getResolution() << " s at vmax 1), " << std::setprecision(2)
                      << quality.makespanRatio() << "x the lower bound " << quality.makespanBound << "\n"
                      << "sum costs  " << plan.getSumOfCosts() << " timesteps, " << quality.sumOfCostsRatio()
                      << "x the lower bound " << quality.sumOfCostsBound << std::setprecision(3)
                      << " (bounds: each robot alone on a straight line)\n"
                      << "path bound makespan " << std::setprecision(2) << quality.makespanPathRatio() << "x of "
                      << quality.makespanPathBound << ", sum of costs " << quality.sumOfCostsPathRatio() << "x of "
                      << quality.sumOfCostsPathBound << std::setprecision(3)
                      << " (each robot alone on its shortest path around the obstacles)\n"
                      << "waypoints  " << plan.getPieceCount() << " pieces over the team\n"
                      << "validated  "
                      << (!validate      ? std::string("skipped (--no-validate)")
                          : report.valid ? "yes (" + std::to_string(checkTime) + " s)"
                                         : "NO: " + report.message)
                      << std::endl;
            // After a Ctrl-C the plan is written only as one the validator accepted: nothing half-done lands in a file.
            if (vm.count("out") && tools::Interruption::raised() && !(validate && report.valid))
                std::cout << "solution   not written (interrupted: --out takes a validated plan only)" << std::endl;
            else if (vm.count("out"))
            {
                SolutionFile::write(vm["out"].as<std::string>(), plan, *si);
                std::cout << "solution   " << vm["out"].as<std::string>() << std::endl;
            }
            if (vm.count("trajectory") && report.valid)
            {
                const auto doc = TrajectoryFile::fromPlan(problem, plan);
                TrajectoryFile::write(vm["trajectory"].as<std::string>(), doc);
                std::cout << "trajectory " << vm["trajectory"].as<std::string>() << " (" << std::setprecision(2)
                          << doc.at("duration").get<double>() << " s within the robots' limits)" << std::endl;
            }
            writePictures(&plan);
            return exitCode(report.valid || !validate ? tools::EXIT_SOLVED : tools::EXIT_FAILED);
        });
}
