#include "ompl_parc/parallel/OrRace.h"

#include "ompl_parc/util/PlannerSeed.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/PlannerData.h>
#include <ompl/tools/multiplan/ParallelPlan.h>
#include <ompl/util/Exception.h>

namespace ob = ompl::base;

namespace
{
    /** \brief What ParallelPlan runs for one racer: the racer itself, recording how its solve() ended
        (ParallelPlan keeps only whether it succeeded). CRASH stays recorded if the racer throws. */
    class RecordingRacer : public ob::Planner
    {
      public:
        RecordingRacer(ob::PlannerPtr racer, ob::PlannerStatus &status)
            : ob::Planner(racer->getSpaceInformation(), racer->getName()), racer_(std::move(racer)), status_(status)
        {
        }

        ob::PlannerStatus solve(const ob::PlannerTerminationCondition &ptc) override
        {
            status_ = ob::PlannerStatus::CRASH;
            const ompl_parc::StopSignal::Scope scope(ptc);
            status_ = racer_->solve(ptc);
            return status_;
        }

      private:
        ob::PlannerPtr racer_;
        ob::PlannerStatus &status_;
    };
}  // namespace

ompl_parc::OrRace::OrRace(const ob::Planner &owner) : owner_(owner) {}

ompl_parc::OrRace::~OrRace() = default;

void ompl_parc::OrRace::declareInstances(ob::ParamSet &params)
{
    params.declareParam<unsigned int>(
        "instances", [this](unsigned int instances) { setInstances(instances); }, [this] { return instances_; });
    params["instances"].setRangeSuggestion("1:1:64");
}

void ompl_parc::OrRace::setInstances(unsigned int instances)
{
    if (instances == 0)
        throw ompl::Exception(owner_.getName(), "instances must be at least 1");
    instances_ = instances;
    clear();
}

unsigned int ompl_parc::OrRace::workersPerInstance(unsigned int total) const
{
    if (total == 0 || total % instances_ != 0)
        throw ompl::Exception(owner_.getName(), "total_workers (" + std::to_string(total) +
                                                    ") must be a positive multiple of instances (" +
                                                    std::to_string(instances_) + ")");
    return total / instances_;
}

void ompl_parc::OrRace::createRacers(const RacerAllocator &allocate, unsigned int seed,
                                     const ob::ProblemDefinitionPtr &pdef)
{
    clear();
    const std::uint_fast32_t raceSeed = seedOrDraw(seed);
    for (unsigned int k = 0; k < instances_; ++k)
    {
        ob::PlannerPtr racer = allocate(k, mixSeed(raceSeed, k));
        racer->setName(owner_.getName() + "#" + std::to_string(k));
        racer->setProblemDefinition(pdef);
        racers_.push_back(std::move(racer));
    }
}

void ompl_parc::OrRace::clear()
{
    racers_.clear();
    statuses_.clear();
    winner_ = -1;
}

ob::PlannerStatus ompl_parc::OrRace::run(const ob::PlannerTerminationCondition &ptc)
{
    if (racers_.empty())
        throw ompl::Exception(owner_.getName(), "OrRace::run() before createRacers()");
    const ob::ProblemDefinitionPtr &pdef = racers_.front()->getProblemDefinition();
    statuses_.assign(racers_.size(), ob::PlannerStatus(ob::PlannerStatus::UNKNOWN));
    winner_ = -1;
    ompl::tools::ParallelPlan race(pdef);
    for (std::size_t k = 0; k < racers_.size(); ++k)
        race.addPlanner(std::make_shared<RecordingRacer>(racers_[k], statuses_[k]));
    // ParallelPlan terminates the condition it is given once a racer wins: give it its own.
    const ob::PlannerTerminationCondition raceStop([&ptc] { return ptc(); });
    race.solve(raceStop, 1, racers_.size(), false);

    for (const auto &solution : pdef->getSolutions())
        for (std::size_t k = 0; k < racers_.size() && winner_ < 0; ++k)
            if (!solution.approximate_ && solution.plannerName_ == racers_[k]->getName())
                winner_ = static_cast<int>(k);
    return winner_ >= 0 ? ob::PlannerStatus(ob::PlannerStatus::EXACT_SOLUTION) : statuses_.front();
}

std::string ompl_parc::OrRace::getWinnerName() const
{
    return winner_ >= 0 ? racers_[winner_]->getName() : std::string();
}

std::map<std::string, std::string> ompl_parc::OrRace::getProperties(unsigned int k) const
{
    ob::PlannerData data(racers_.at(k)->getSpaceInformation());
    racers_[k]->getPlannerData(data);
    return data.properties;
}

void ompl_parc::OrRace::addProperties(ob::PlannerData &data) const
{
    auto &p = data.properties;
    p["instances INTEGER"] = std::to_string(instances_);
    p["winner STRING"] = getWinnerName();
    for (unsigned int k = 0; k < statuses_.size(); ++k)
    {
        const std::string prefix = "instance" + std::to_string(k) + "_";
        p[prefix + "status STRING"] = statuses_[k].asString();
        for (const auto &[name, value] : getProperties(k))
            p[prefix + name] = value;
    }
}
