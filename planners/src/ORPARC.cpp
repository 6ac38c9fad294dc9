#include "ompl_parc/planners/ORPARC.h"

#include "ompl_parc/planners/subproblem/WholeTeamSolver.h"
#include "ompl_parc/planners/subproblem/PrioritizedSTRRTSolver.h"
#include "ompl_parc/quality/PlanObjective.h"
#include "ompl_parc/quality/PlanQuality.h"
#include "ompl_parc/util/InnerPlannerLog.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/PlannerData.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace ob = ompl::base;

ompl_parc::ORPARC::ORPARC(const ob::SpaceInformationPtr &si)
    : ob::Planner(si, "ORPARC"), prototype_(std::make_shared<PARC>(si)), race_(*this)
{
    specs_ = prototype_->getSpecs();
    specs_.multithreaded = true;
    // The prototype's GenericParams themselves: setting "window" on ORPARC sets the prototype's window.
    params().include(prototype_->params());
    race_.declareInstances(params());
    smoothing_.setReplanner([] { return PrioritizedSTRRTSolver::makeReplanner(); });
    smoothing_.setTeamSolver(&WholeTeamSolver::make);
    smoothing_.setTeamReplanShare(0.5);
    declareParam<unsigned int>("total_workers", this, &ORPARC::setTotalWorkers, &ORPARC::getTotalWorkers, "1:1:64");
    declareParam<bool>("diversify", this, &ORPARC::setDiversify, &ORPARC::getDiversify, "0,1");
    declareParam<std::string>("objective", this, &ORPARC::setObjective, &ORPARC::getObjective,
                              "first,makespan,sum_of_costs");
    for (const auto &[name, property] : progress_.properties())
        addPlannerProgressProperty(name, property);
}

ompl_parc::ORPARC::~ORPARC() = default;

void ompl_parc::ORPARC::setTotalWorkers(unsigned int total)
{
    prototype_->setWorkers(race_.workersPerInstance(total));
}

void ompl_parc::ORPARC::setObjective(const std::string &objective)
{
    objective_ = toString(parsePlanObjective(objective));
}

void ompl_parc::ORPARC::setup()
{
    Planner::setup();
    if (pdef_ && !race_.hasRacers())
        createRacers(prototype_->getSeed());
}

void ompl_parc::ORPARC::clear()
{
    Planner::clear();
    race_.clear();
    result_.reset();
    resultSmoothing_.reset();
    smoothing_.clear();
    progress_.reset();
}

void ompl_parc::ORPARC::setProblemDefinition(const ob::ProblemDefinitionPtr &pdef)
{
    Planner::setProblemDefinition(pdef);
    race_.clear();
    result_.reset();
    resultSmoothing_.reset();
}

std::shared_ptr<ompl_parc::PARC> ompl_parc::ORPARC::makeRacer(unsigned int k, std::uint_fast32_t seed)
{
    // The profile first: it sets the fields no other parameter was set for (ArcSettings::explicitFields),
    // and the prototype's values of all other parameters then make each racer equal to the prototype.
    std::map<std::string, std::string> values;
    prototype_->params().getParams(values);
    const std::string profile = values.at("profile");
    values.erase("profile");
    auto racer = std::make_shared<PARC>(si_);
    racer->params().setParam("profile", profile);
    racer->params().setParams(values, true);
    racer->setSeed(static_cast<unsigned int>(seed));
    if (diversify_ && k % 2 == 1)
    {
        const ArcSettings eager = racer->getSettings().eager();
        racer->setSampleCap(eager.sampleCap);
        racer->setMinWindowGrowth(eager.minWindowGrowth);
    }
    racer->setSmoothing(0.);
    racer->reportProgressInto(progress_);
    return racer;
}

void ompl_parc::ORPARC::createRacers(unsigned int seed)
{
    race_.createRacers([this](unsigned int k, std::uint_fast32_t mixed) { return makeRacer(k, mixed); }, seed, pdef_);
}

std::shared_ptr<ompl_parc::PARC> ompl_parc::ORPARC::createInstance(unsigned int k, std::uint_fast32_t raceSeed)
{
    if (!pdef_)
        throw ompl::Exception(getName(), "createInstance() needs the problem definition set first");
    auto racer = makeRacer(k, mixSeed(raceSeed, k));
    racer->setName(getName() + "#" + std::to_string(k));
    racer->setProblemDefinition(pdef_);
    return racer;
}

std::optional<ompl_parc::SmoothingReport> ompl_parc::ORPARC::smoothWinner(MultiRobotPlan &plan,
                                                                          std::uint_fast32_t instanceSeed,
                                                                          const ob::PlannerTerminationCondition &ptc)
{
    smoothing_.setBudget(prototype_->getSmoothing());
    smoothing_.apply(MultiRobotSpaceInformation::get(si_, getName()), plan, ptc, mixSeed(instanceSeed, 0x5300));
    return smoothing_.getReport();
}

ob::PlannerStatus ompl_parc::ORPARC::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    if (!race_.hasRacers())
        createRacers(prototype_->getSeed());
    result_.reset();
    resultSmoothing_.reset();
    smoothing_.clear();
    rounds_ = 1;
    improvements_ = 0;
    firstSolutionTime_ = -1.;
    progress_.startSolve();
    const InnerPlannerLog::Session session;
    OMPL_INFORM("%s: racing %u P-ARC instances of %u worker(s) each", getName().c_str(), getInstances(), getWorkers());
    ob::PlannerStatus status = race_.run(ptc);
    if (race_.getWinner() >= 0)
        takeWinner(ptc);
    if (objective_ == "first" || (status != ob::PlannerStatus::EXACT_SOLUTION && status != ob::PlannerStatus::TIMEOUT))
        return finish(status);  // an invalid start or goal, or a crash, is every race's
    // Anytime: more rounds with fresh seeds until the termination condition; the best plan is the solution.
    const unsigned int seed = prototype_->getSeed();
    const auto mrsi = MultiRobotSpaceInformation::get(si_, getName());
    const auto optimal = [&]
    {
        const PlanQuality quality = PlanQuality::measure(*mrsi, *result_);
        return objectiveOf(*result_) ==
               (objective_ == "sum_of_costs" ? quality.sumOfCostsBound : quality.makespanBound);
    };
    for (; !ptc() && !(result_ && optimal()); ++rounds_)
    {
        pdef_->clearSolutionPaths();  // the race's winner is the ProblemDefinition's first solution
        race_.clear();
        createRacers(seed == 0 ? 0 : static_cast<unsigned int>(mixSeed(seed, rounds_)));
        const ob::PlannerStatus round = race_.run(ptc);
        if (round == ob::PlannerStatus::EXACT_SOLUTION)
            takeWinner(ptc);
        else if (round != ob::PlannerStatus::TIMEOUT)
            break;
    }
    pdef_->clearSolutionPaths();
    if (!result_)
        return finish(status);
    pdef_->addSolutionPath(result_->toPathGeometric(mrsi), false, 0., getName());
    OMPL_INFORM("%s: %zu races, %zu better plans; the best has %s %zu", getName().c_str(), rounds_, improvements_,
                objective_.c_str(), objectiveOf(*result_));
    return finish(ob::PlannerStatus::EXACT_SOLUTION);
}

ob::PlannerStatus ompl_parc::ORPARC::finish(ob::PlannerStatus status)
{
    if (status == ob::PlannerStatus::EXACT_SOLUTION)
    {
        progress_.setMakespan(getPlan().getMakespan());
        progress_.reachStage(ArcProgress::Stage::SOLVED);
    }
    else
        OMPL_INFORM("%s: no solution: %s", getName().c_str(), getStatusMessage().c_str());
    return status;
}

void ompl_parc::ORPARC::takeWinner(const ob::PlannerTerminationCondition &ptc)
{
    const PARC &winner = getRacer(race_.getWinner());
    const auto mrsi = MultiRobotSpaceInformation::get(si_, getName());
    if (firstSolutionTime_ < 0.)
        firstSolutionTime_ = progress_.getElapsed();
    OMPL_INFORM("%s: instance %d won the race (makespan %zu)", getName().c_str(), race_.getWinner(),
                winner.getPlan().getMakespan());
    if (objective_ == "first" && prototype_->getSmoothing() <= 0.)
        return;  // the winner's own plan and solution path are the answer
    if (objective_ == "first")
        progress_.reachStage(ArcProgress::Stage::SMOOTHING);
    MultiRobotPlan plan = winner.getPlan();
    std::optional<SmoothingReport> report = smoothWinner(plan, winner.getSeed(), ptc);
    if (result_ && objectiveOf(plan) >= objectiveOf(*result_))
        return;
    result_ = std::move(plan);
    resultSmoothing_ = std::move(report);
    ++improvements_;
    const auto path = result_->toPathGeometric(mrsi);
    if (objective_ == "first")
    {
        pdef_->clearSolutionPaths();
        pdef_->addSolutionPath(path, false, 0., getName());
    }
    else if (const auto &report = pdef_->getIntermediateSolutionCallback())
    {
        const std::vector<const ob::State *> states(path->getStates().begin(), path->getStates().end());
        report(this, states, ob::Cost(static_cast<double>(objectiveOf(*result_))));
    }
}

std::size_t ompl_parc::ORPARC::objectiveOf(const MultiRobotPlan &plan) const
{
    return objective_ == "sum_of_costs" ? plan.getSumOfCosts() : plan.getMakespan();
}

const ompl_parc::PARC &ompl_parc::ORPARC::getRacer(std::size_t k) const
{
    return static_cast<const PARC &>(*race_.getRacers().at(k));
}

int ompl_parc::ORPARC::getReportedInstance() const
{
    if (race_.getWinner() >= 0 || !race_.hasRun())
        return race_.getWinner();
    const auto progress = [this](std::size_t k)
    {
        const ArcStatistics &s = getRacer(k).getStatistics();
        return std::make_tuple(s.conflicts, s.solverCalls);
    };
    std::size_t furthest = 0;
    for (std::size_t k = 1; k < getRacerCount(); ++k)
        if (progress(k) > progress(furthest))
            furthest = k;
    return static_cast<int>(furthest);
}

const ompl_parc::PARC &ompl_parc::ORPARC::reported() const
{
    const int k = getReportedInstance();
    return k >= 0 ? getRacer(k) : *prototype_;
}

const ompl_parc::MultiRobotPlan &ompl_parc::ORPARC::getPlan() const
{
    if (result_)
        return *result_;
    return race_.getWinner() >= 0 ? getRacer(race_.getWinner()).getPlan() : prototype_->getPlan();
}

const ompl_parc::ArcStatistics &ompl_parc::ORPARC::getStatistics() const
{
    return reported().getStatistics();
}

const ompl_parc::ParcStatistics &ompl_parc::ORPARC::getParallelStatistics() const
{
    return reported().getParallelStatistics();
}

const std::string &ompl_parc::ORPARC::getStatusMessage() const
{
    return reported().getStatusMessage();
}

void ompl_parc::ORPARC::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    reported().getPlannerData(data);
    if (result_)
        SmoothingStep::addProperties(*MultiRobotSpaceInformation::get(si_, getName()), *result_, resultSmoothing_,
                                     data);
    if (objective_ != "first")
    {
        data.properties["anytime_rounds INTEGER"] = std::to_string(rounds_);
        data.properties["improvements INTEGER"] = std::to_string(improvements_);
        if (firstSolutionTime_ >= 0.)
            data.properties["first_solution_time REAL"] = std::to_string(firstSolutionTime_);
    }
    data.properties["reported_instance INTEGER"] = std::to_string(getReportedInstance());
    race_.addProperties(data);
}
