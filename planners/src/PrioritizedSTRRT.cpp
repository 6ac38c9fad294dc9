#include "ompl_parc/planners/PrioritizedSTRRT.h"

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/PlannerSeed.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ob = ompl::base;
namespace og = ompl::geometric;

ompl_parc::PrioritizedSTRRT::PrioritizedSTRRT(const ob::SpaceInformationPtr &si)
    : ob::Planner(si, "PrioritizedSTRRT"), mrsi_(MultiRobotSpaceInformation::get(si, "PrioritizedSTRRT"))
{
    specs_.directed = true;
    declareParam<double>("range", this, &PrioritizedSTRRT::setRange, &PrioritizedSTRRT::getRange, "0.:1.:10000.");
    declareParam<std::string>("priority_order", this, &PrioritizedSTRRT::setPriorityOrder,
                              &PrioritizedSTRRT::getPriorityOrder);
    declareParam<unsigned int>("seed", this, &PrioritizedSTRRT::setSeed, &PrioritizedSTRRT::getSeed);
    declareParam<bool>("promote", this, &PrioritizedSTRRT::setPromote, &PrioritizedSTRRT::getPromote, "0,1");
    declareParam<bool>("unblock", this, &PrioritizedSTRRT::setUnblock, &PrioritizedSTRRT::getUnblock, "0,1");
    declareParam<bool>("lattice", this, &PrioritizedSTRRT::setLattice, &PrioritizedSTRRT::getLattice, "0,1");
    declareParam<double>("lattice_step", this, &PrioritizedSTRRT::setLatticeStep, &PrioritizedSTRRT::getLatticeStep,
                         "0.:0.01:1000.");
    declareParam<unsigned int>("sample_cap", this, &PrioritizedSTRRT::setSampleCap, &PrioritizedSTRRT::getSampleCap,
                               "0:1000:100000000");
    smoothing_.declareParameter(*this);
    smoothing_.setReplanner([] { return PrioritizedSTRRTSolver::makeReplanner(); });
    declareParam<std::string>("rewiring", this, &PrioritizedSTRRT::setRewiring, &PrioritizedSTRRT::getRewiring);
    declareParam<unsigned int>("batch_size", this, &PrioritizedSTRRT::setBatchSize, &PrioritizedSTRRT::getBatchSize,
                               "1:1:1000000");
    declareParam<double>("initial_time_bound_factor", this, &PrioritizedSTRRT::setInitialTimeBoundFactor,
                         &PrioritizedSTRRT::getInitialTimeBoundFactor, "1.0:0.1:100.");
    declareParam<double>("time_bound_factor_increase", this, &PrioritizedSTRRT::setTimeBoundFactorIncrease,
                         &PrioritizedSTRRT::getTimeBoundFactorIncrease, "1.01:0.01:100.");
}

void ompl_parc::PrioritizedSTRRT::updateSettings(const PrioritizedSTRRTSettings &settings)
{
    PrioritizedSTRRTSolver check(settings);
    settings_ = settings;
}

void ompl_parc::PrioritizedSTRRT::setPriorityOrder(const std::string &order)
{
    if (order != "given" && order != "shuffled")
        throw ompl::Exception(getName(), "priority order must be 'given' or 'shuffled', not '" + order + "'");
    settings_.shuffle = order == "shuffled";
}

void ompl_parc::PrioritizedSTRRT::setLatticeStep(double step)
{
    if (!(step >= 0.) || !std::isfinite(step))
        throw ompl::Exception(getName(), "lattice_step must be 0 (automatic) or positive and finite");
    settings_.latticeStep = step;
}

void ompl_parc::PrioritizedSTRRT::setRewiring(const std::string &rewiring)
{
    auto settings = settings_;
    settings.rewiring = rewiring;
    updateSettings(settings);
}

void ompl_parc::PrioritizedSTRRT::setBatchSize(unsigned int size)
{
    auto settings = settings_;
    settings.batchSize = size;
    updateSettings(settings);
}

void ompl_parc::PrioritizedSTRRT::setInitialTimeBoundFactor(double factor)
{
    auto settings = settings_;
    settings.initialTimeBoundFactor = factor;
    updateSettings(settings);
}

void ompl_parc::PrioritizedSTRRT::setTimeBoundFactorIncrease(double factor)
{
    auto settings = settings_;
    settings.timeBoundFactorIncrease = factor;
    updateSettings(settings);
}

ob::PlannerStatus ompl_parc::PrioritizedSTRRT::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    const auto *goal = dynamic_cast<const ob::GoalState *>(pdef_->getGoal().get());
    if (goal == nullptr)
    {
        OMPL_ERROR("%s: the goal must be a GoalState (one configuration per robot)", getName().c_str());
        return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    }
    if (const std::string coarse = mrsi_->checkPlanningResolution(); !coarse.empty())
    {
        OMPL_ERROR("%s: %s", getName().c_str(), coarse.c_str());
        return ob::PlannerStatus::ABORT;
    }
    if (pdef_->getStartStateCount() == 0)
    {
        OMPL_ERROR("%s: no start state", getName().c_str());
        return ob::PlannerStatus::INVALID_START;
    }
    const ob::State *start = pdef_->getStartState(0);
    if (const std::string why = mrsi_->explainInvalid(start); !why.empty())
    {
        OMPL_ERROR("%s: invalid start: %s", getName().c_str(), why.c_str());
        return ob::PlannerStatus::INVALID_START;
    }
    if (const std::string why = mrsi_->explainInvalid(goal->getState()); !why.empty())
    {
        OMPL_ERROR("%s: invalid goal: %s", getName().c_str(), why.c_str());
        return ob::PlannerStatus::INVALID_GOAL;
    }

    // The whole problem as one subproblem: every robot, global starts and goals, whole spaces.
    Subproblem whole;
    for (std::size_t i = 0; i < mrsi_->getRobotCount(); ++i)
    {
        const unsigned int d = mrsi_->getRobot(i)->getDimension();
        whole.robots.push_back(i);
        const double *s = mrsi_->getRobotValues(start, i), *g = mrsi_->getRobotValues(goal->getState(), i);
        whole.starts.emplace_back(s, s + d);
        whole.goals.emplace_back(g, g + d);
    }
    lastSeed_ = static_cast<unsigned int>(seedOrDraw(seed_));
    Patch patch;
    const StopSignal::Scope scope(ptc);
    const InnerPlannerLog::Session session;
    {
        const InnerPlannerLog::Scope inner;
        // With the lattice, rounds after the first shuffle the base order (which breaks the blocking order's ties
        // and cycles): the lattice plans an order the same way every time, so only another order can change that.
        auto reshuffled = settings_;
        reshuffled.shuffle = settings_.shuffle || settings_.lattice;
        const PrioritizedSTRRTSolver first(settings_), later(reshuffled);
        solved_ = false;
        // Round r: each robot's ST-RRT capped at sample_cap x 2^r iterations (no cap and one round for 0); a round
        // that failed for good (nothing another draw could change) ends them.
        bool retry = true;
        for (rounds_ = 0; !solved_ && !ptc && retry && (sampleCap_ > 0 || rounds_ == 0);)
        {
            whole.sampleCap = Subproblem::doubledCap(sampleCap_, rounds_);
            solved_ = rounds_ == 0 ? first.solve(*mrsi_, whole, ptc, lastSeed_, patch, retry)
                                   : later.solve(*mrsi_, whole, ptc, mixSeed(lastSeed_, rounds_), patch, retry);
            ++rounds_;
        }
    }
    if (!solved_)
        return ob::PlannerStatus::TIMEOUT;

    plan_ = MultiRobotPlan(*mrsi_);
    for (std::size_t i = 0; i < mrsi_->getRobotCount(); ++i)
        plan_.setPath(i, patch.paths[i]);
    publishPlan(ptc, mixSeed(lastSeed_, 0x5300));
    return ob::PlannerStatus::EXACT_SOLUTION;
}

void ompl_parc::PrioritizedSTRRT::publishPlan(const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed)
{
    if (smoothing_.getBudget() > 0.)
    {
        smoothing_.apply(mrsi_, plan_, ptc, seed);
        pdef_->clearSolutionPaths();  // the unsmoothed solution, if an OR race's winner put it there
    }
    pdef_->addSolutionPath(plan_.toPathGeometric(mrsi_), false, 0., getName());
}

void ompl_parc::PrioritizedSTRRT::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    data.properties["seed INTEGER"] = std::to_string(lastSeed_);
    data.properties["priority_order STRING"] = getPriorityOrder();
    data.properties["solved BOOLEAN"] = solved_ ? "1" : "0";
    data.properties["rounds INTEGER"] = std::to_string(rounds_);
    SmoothingStep::addProperties(*mrsi_, plan_, smoothing_.getReport(), data);
}
