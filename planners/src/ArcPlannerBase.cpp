#include "ompl_parc/planners/ArcPlannerBase.h"

#include "ompl_parc/planners/subproblem/CompositeRRTConnectSolver.h"
#include "ompl_parc/planners/subproblem/LatticeMapfSolver.h"
#include "ompl_parc/planners/subproblem/WholeTeamSolver.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/planners/subproblem/SequentialRRTConnectSolver.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/PlannerSeed.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/util/Exception.h>

#include <algorithm>

namespace ob = ompl::base;

namespace
{
    /** The subproblem solvers of \e settings, in the order they are tried. */
    std::vector<ompl_parc::SubproblemSolverPtr> makeHierarchy(const ompl_parc::ArcSettings &settings)
    {
        using ompl_parc::ArcSettings;
        const auto prioritized = std::make_shared<ompl_parc::PrioritizedSTRRTSolver>();
        // Composite RRT-Connect, then (sequential) the same space searched one robot at a time.
        std::vector<ompl_parc::SubproblemSolverPtr> rrtConnect{
            std::make_shared<ompl_parc::CompositeRRTConnectSolver>(0., settings.shortenPatches)};
        if (settings.sequential)
            rrtConnect.push_back(std::make_shared<ompl_parc::SequentialRRTConnectSolver>(settings.shortenPatches));
        switch (settings.solvers)
        {
            case ArcSettings::Solvers::COMPOSITE:
                return rrtConnect;
            case ArcSettings::Solvers::PRIORITIZED:
                return {prioritized};
            case ArcSettings::Solvers::COMPOSITE_FIRST:
            case ArcSettings::Solvers::HIERARCHY:
                break;
        }
        std::vector<ompl_parc::SubproblemSolverPtr> hierarchy;
        if (settings.solvers == ArcSettings::Solvers::HIERARCHY)
            hierarchy.push_back(prioritized);
        hierarchy.insert(hierarchy.end(), rrtConnect.begin(), rrtConnect.end());
        // After composite RRT-Connect: on a window it fails, MAPF's patch is found at once where prioritised
        // planning can take the call's whole time cap (docs/results.md: the order measured).
        if (settings.latticeMapf)
            hierarchy.push_back(std::make_shared<ompl_parc::LatticeMapfSolver>());
        if (settings.solvers == ArcSettings::Solvers::COMPOSITE_FIRST)
            hierarchy.push_back(prioritized);
        return hierarchy;
    }
}  // namespace

ompl_parc::ArcPlannerBase::ArcPlannerBase(const ob::SpaceInformationPtr &si, const std::string &name)
    : ob::Planner(si, name), mrsi_(MultiRobotSpaceInformation::get(si, name))
{
    specs_.approximateSolutions = false;
    specs_.optimizingPaths = false;
    specs_.multithreaded = false;
    declareParam<std::string>("profile", this, &ArcPlannerBase::setProfile, &ArcPlannerBase::getProfile,
                              "auto,mobile,planar,panda");
    setProfile("auto");
    smoothing_.declareParameter(*this);
    smoothing_.setReplanner([] { return PrioritizedSTRRTSolver::makeReplanner(); });
    smoothing_.setTeamSolver(&WholeTeamSolver::make);
    smoothing_.setTeamReplanShare(0.5);
#define OMPL_PARC_ARC_KNOB(Name, member, parameter, Type, Parameter, range, ...)                                       \
    declareParam<Parameter>(parameter, this, &ArcPlannerBase::set##Name, &ArcPlannerBase::get##Name, range);
#include "ompl_parc/arc/ArcKnobs.def"
    declareParam<unsigned int>("seed", this, &ArcPlannerBase::setSeed, &ArcPlannerBase::getSeed);
    declareParam<std::string>("objective", this, &ArcPlannerBase::setObjective, &ArcPlannerBase::getObjective,
                              "first,makespan,sum_of_costs");
    for (const auto &[name, property] : progress_.properties())
        addPlannerProgressProperty(name, property);
}

ompl_parc::ArcPlannerBase::~ArcPlannerBase() = default;

void ompl_parc::ArcPlannerBase::setProfile(const std::string &profile)
{
    options_.settings.applyProfile(profile == "auto" ? ArcSettings::profileFor(*mrsi_) : profile);
    profile_ = profile;
}

// The knobs' setters and getters (ArcKnobs.def). The value is read (an enumerator by its name) and checked before
// anything changes, so a refused value leaves the settings as they were.
#define OMPL_PARC_ARC_KNOB(Name, member, parameter, Type, Parameter, range, valid, otherwise, ...)                     \
    void ompl_parc::ArcPlannerBase::set##Name(ParameterArgument<Parameter> parameterValue)                             \
    {                                                                                                                  \
        const auto value = ArcSettings::fromParameter(parameterValue, &options_.settings.member);                      \
        if (!(valid))                                                                                                  \
            throw ompl::Exception(getName(), std::string(parameter) + " " + (otherwise));                              \
        options_.settings.member = value;                                                                              \
        options_.settings.setExplicit(ArcSettings::Knob::member);                                                      \
    }                                                                                                                  \
                                                                                                                       \
    Parameter ompl_parc::ArcPlannerBase::get##Name() const                                                             \
    {                                                                                                                  \
        return ArcSettings::toParameter(getSettings().member);                                                         \
    }
#include "ompl_parc/arc/ArcKnobs.def"

void ompl_parc::ArcPlannerBase::setSeed(unsigned int seed)
{
    seed_ = seed;
}

// The parallel knobs' setters and getters (ParcKnobs.def), checked before anything changes.
#define OMPL_PARC_PARALLEL_KNOB(Name, member, parameter, Parameter, range, check)                                     \
    void ompl_parc::ArcPlannerBase::set##Name(Parameter value)                                                         \
    {                                                                                                                  \
        [[maybe_unused]] const std::string &who = getName();                                                           \
        check;                                                                                                         \
        options_.member = value;                                                                                       \
    }                                                                                                                  \
                                                                                                                       \
    Parameter ompl_parc::ArcPlannerBase::get##Name() const                                                             \
    {                                                                                                                  \
        return static_cast<Parameter>(options_.member);                                                                \
    }
#include "ompl_parc/arc/ParcKnobs.def"

const ompl_parc::MultiRobotPlan &ompl_parc::ArcPlannerBase::getPlan() const
{
    static const MultiRobotPlan none;
    if (smoothed_)
        return *smoothed_;
    return loop_ ? loop_->getPlan() : none;
}

const ompl_parc::ArcStatistics &ompl_parc::ArcPlannerBase::getStatistics() const
{
    static const ArcStatistics none;
    return loop_ ? loop_->getStatistics() : none;
}

void ompl_parc::ArcPlannerBase::setup()
{
    // First: if it throws, the planner is not marked set up and the next solve() tries again.
    if (!workspace_)
        workspace_ = std::make_unique<RepairWorkspace>(*mrsi_, options_.workers);
    ob::Planner::setup();
}

void ompl_parc::ArcPlannerBase::clear()
{
    ob::Planner::clear();
    loop_.reset();
    problem_.reset();
    statusMessage_.clear();
    smoothed_.reset();
    smoothing_.clear();
    progress_.reset();
}

std::optional<ob::PlannerStatus> ompl_parc::ArcPlannerBase::readProblem()
{
    const ob::State *start = pdef_->getStartStateCount() > 0 ? pdef_->getStartState(0) : nullptr;
    const auto *goal = dynamic_cast<const ob::GoalState *>(pdef_->getGoal().get());
    if (const std::string coarse = mrsi_->checkPlanningResolution(); !coarse.empty())
    {
        statusMessage_ = coarse;
        OMPL_ERROR("%s: %s", getName().c_str(), coarse.c_str());
        return ob::PlannerStatus(ob::PlannerStatus::ABORT);
    }
    if (start == nullptr)
    {
        statusMessage_ = "no start state";
        return ob::PlannerStatus(ob::PlannerStatus::INVALID_START);
    }
    if (goal == nullptr)
    {
        statusMessage_ = "the goal must be an ompl::base::GoalState (one composite goal state)";
        return ob::PlannerStatus(ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE);
    }
    std::vector<std::vector<double>> starts, goals;
    for (std::size_t i = 0; i < mrsi_->getRobotCount(); ++i)
    {
        const unsigned int d = mrsi_->getRobot(i)->getDimension();
        const double *s = mrsi_->getRobotValues(start, i), *g = mrsi_->getRobotValues(goal->getState(), i);
        starts.emplace_back(s, s + d);
        goals.emplace_back(g, g + d);
    }
    auto problem = std::make_unique<MultiRobotProblem>(mrsi_, starts, goals);
    // Report the first problem found, as the matching status (start before goal).
    const std::string reason = problem->checkEndpoints();
    if (!reason.empty())
    {
        statusMessage_ = reason;
        OMPL_ERROR("%s: %s", getName().c_str(), reason.c_str());
        return ob::PlannerStatus(reason.rfind("start", 0) == 0 ? ob::PlannerStatus::INVALID_START
                                                               : ob::PlannerStatus::INVALID_GOAL);
    }
    auto loop = std::make_unique<RepairLoop>(*problem, seedOrDraw(seed_), *workspace_);
    problem_ = std::move(problem);  // only with its loop: a later solve() reads the problem again otherwise
    loop_ = std::move(loop);
    return std::nullopt;
}

ob::PlannerStatus ompl_parc::ArcPlannerBase::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    statusMessage_.clear();
    smoothed_.reset();
    smoothing_.clear();
    improvement_.reset();
    firstSolutionTime_ = -1.;
    solveStarted_ = ompl::time::now();
    if (reportTo_ == &progress_)
        progress_.startSolve();
    try
    {
        const StopSignal::Scope scope(ptc);
        const InnerPlannerLog::Session session;
        const ob::PlannerStatus status = solveStages(ptc);
        if (status == ob::PlannerStatus::TIMEOUT)
            OMPL_INFORM("%s: %s (%zu of %zu robots planned, %u conflicts resolved)", getName().c_str(),
                        statusMessage_.c_str(), loop_ ? loop_->getPlannedCount() : 0, mrsi_->getRobotCount(),
                        getStatistics().repairs);
        return status;
    }
    catch (const std::exception &e)
    {
        // A failing stage (e.g. a worker task that threw; all workers are joined by then) ends the solve
        // with its reason instead of unwinding through the caller's planning loop.
        statusMessage_ = e.what();
        OMPL_ERROR("%s: %s", getName().c_str(), e.what());
        return ob::PlannerStatus(ob::PlannerStatus::CRASH);
    }
}

ob::PlannerStatus ompl_parc::ArcPlannerBase::solveStages(const ob::PlannerTerminationCondition &ptc)
{
    if (!problem_)
        if (auto bad = readProblem())
            return *bad;
    RepairLoopOptions options = options_;
    options.hierarchy = makeHierarchy(options.settings);
    options.progress = reportTo_;
    loop_->configure(std::move(options));
    const ArcStatistics &s = loop_->getStatistics();
    if (!loop_->isInitialised())
    {
        OMPL_INFORM("%s: planning %zu robots alone with %u worker(s)", getName().c_str(), mrsi_->getRobotCount(),
                    options_.workers);
        if (!loop_->planInitial(ptc))
        {
            statusMessage_ = "time ran out while planning the robots' individual paths";
            return ob::PlannerStatus(ob::PlannerStatus::TIMEOUT);
        }
        OMPL_INFORM("%s: initial stage done in %.3f s, makespan %zu; resolving conflicts", getName().c_str(),
                    s.initialWall, loop_->getPlan().getMakespan());
    }
    if (!loop_->resolve(ptc))
    {
        statusMessage_ = "time ran out while resolving conflicts";
        return ob::PlannerStatus(ob::PlannerStatus::TIMEOUT);
    }
    OMPL_INFORM(
        "%s: conflict-free after %u conflicts (%u solver calls, %u window expansions): detection %.3f s, "
        "resolution %.3f s, makespan %zu",
        getName().c_str(), s.conflicts, s.solverCalls, s.expansions, s.detectionWall, s.resolutionWall,
        loop_->getPlan().getMakespan());
    if (smoothing_.getBudget() > 0.)
    {
        reportTo_->reachStage(ArcProgress::Stage::SMOOTHING);
        smoothed_ = loop_->getPlan();
        smoothing_.apply(mrsi_, *smoothed_, ptc, mixSeed(loop_->getSeed(), 0x5300));
    }
    if (objective_ != PlanObjective::FIRST)
        improve(ptc);
    if (smoothed_)
        pdef_->addSolutionPath(smoothed_->toPathGeometric(mrsi_), false, 0., getName());
    else
        pdef_->addSolutionPath(loop_->buildSolutionPath(), false, 0., getName());
    if (reportTo_ == &progress_)
    {
        progress_.setMakespan(getPlan().getMakespan());
        progress_.reachStage(ArcProgress::Stage::SOLVED);
    }
    return ob::PlannerStatus(ob::PlannerStatus::EXACT_SOLUTION);
}

void ompl_parc::ArcPlannerBase::improve(const ob::PlannerTerminationCondition &ptc)
{
    firstSolutionTime_ = ompl::time::seconds(ompl::time::now() - solveStarted_);
    if (!smoothed_)
        smoothed_ = loop_->getPlan();
    const auto report = [this](const MultiRobotPlan &plan)
    {
        if (const auto &callback = pdef_->getIntermediateSolutionCallback())
        {
            const auto path = plan.toPathGeometric(mrsi_);
            const std::vector<const ob::State *> states(path->getStates().begin(), path->getStates().end());
            callback(this, states, ob::Cost(static_cast<double>(objectiveKey(plan, objective_).first)));
        }
        if (reportTo_ == &progress_)
            progress_.setMakespan(plan.getMakespan());
    };
    report(*smoothed_);
    reportTo_->reachStage(ArcProgress::Stage::SMOOTHING);
    PlanImprover improver(mrsi_, objective_,
                          [](bool shuffle) { return PrioritizedSTRRTSolver::makeReplanner(shuffle); });
    improver.setTeamSolver(&WholeTeamSolver::make);
    improvement_ = improver.improve(*smoothed_, workspace_->getPool(), ptc, mixSeed(loop_->getSeed(), 0xa117), report);
    OMPL_INFORM("%s: %zu anytime rounds, %zu better plans; the best has %s %zu", getName().c_str(),
                improvement_->rounds, improvement_->improvements, getObjective().c_str(),
                objectiveKey(*smoothed_, objective_).first);
}

void ompl_parc::ArcPlannerBase::getPlannerData(ob::PlannerData &data) const
{
    ob::Planner::getPlannerData(data);
    const auto &s = getStatistics();
    auto &p = data.properties;
    p["initial_wall_time REAL"] = std::to_string(s.initialWall);
    p["initial_cpu_time REAL"] = std::to_string(s.initialCpu);
    p["detection_wall_time REAL"] = std::to_string(s.detectionWall);
    p["detection_cpu_time REAL"] = std::to_string(s.detectionCpu);
    p["resolution_wall_time REAL"] = std::to_string(s.resolutionWall);
    p["resolution_cpu_time REAL"] = std::to_string(s.resolutionCpu);
    p["conflicts INTEGER"] = std::to_string(s.conflicts);
    p["repairs INTEGER"] = std::to_string(s.repairs);
    p["solver_calls INTEGER"] = std::to_string(s.solverCalls);
    p["expansions INTEGER"] = std::to_string(s.expansions);
    p["team_growths INTEGER"] = std::to_string(s.teamGrowths);
    p["global_repairs INTEGER"] = std::to_string(s.globalRepairs);
    p["longest_solver_call REAL"] = std::to_string(s.longestSolverCall);
    // Property names become SQL column names in ompl_benchmark_statistics: no '-' (solver names have them).
    for (const auto &[solver, wins] : s.solverWins)
    {
        std::string column = solver;
        std::replace(column.begin(), column.end(), '-', '_');
        p["wins_" + column + " INTEGER"] = std::to_string(wins);
        p["delay_" + column + " INTEGER"] = std::to_string(s.solverDelays.at(solver));
        p["makespan_added_" + column + " INTEGER"] = std::to_string(s.solverMakespanAdded.at(solver));
    }
    p["global_delay INTEGER"] = std::to_string(s.globalDelay);
    p["initial_makespan INTEGER"] = std::to_string(s.initialMakespan);
    p["initial_sum_of_costs INTEGER"] = std::to_string(s.initialSumOfCosts);
    if (loop_ && loop_->isInitialised())
        SmoothingStep::addProperties(*mrsi_, getPlan(), smoothing_.getReport(), data);
    if (improvement_)
    {
        p["first_solution_time REAL"] = std::to_string(firstSolutionTime_);
        p["anytime_rounds INTEGER"] = std::to_string(improvement_->rounds);
        p["improvements INTEGER"] = std::to_string(improvement_->improvements);
    }
}
