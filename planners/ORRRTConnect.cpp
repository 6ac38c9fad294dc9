#include "ompl_parc/planners/ORRRTConnect.h"

#include "ompl_parc/planners/EPRRTConnect.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/multiplan/ParallelPlan.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

namespace ob = ompl::base;

namespace
{
    /** \brief OMPL's RRTConnect drawing its samples from a seeded copy of the team's spaces. ParallelPlan needs
        every racer on the ProblemDefinition's SpaceInformation, so the seed goes in through the sampler, which
        RRTConnect allocates lazily and keeps until clear(). */
    class SeededRRTConnect : public ompl::geometric::RRTConnect
    {
      public:
        SeededRRTConnect(const ompl_parc::MultiRobotSpaceInformationPtr &si, std::uint_fast32_t seed)
            : RRTConnect(si),
              seeded_(std::make_shared<ompl_parc::MultiRobotSpaceInformation>(
                  si->getRobots(), si->getResolution(), std::vector<ob::RealVectorBounds>{}, seed))
        {
        }

        ob::PlannerStatus solve(const ob::PlannerTerminationCondition &ptc) override
        {
            if (!sampler_)
                sampler_ = seeded_->allocStateSampler();
            return RRTConnect::solve(ptc);
        }

      private:
        ompl_parc::MultiRobotSpaceInformationPtr seeded_;
    };
}  // namespace

ompl_parc::ORRRTConnect::ORRRTConnect(const ob::SpaceInformationPtr &si)
    : ob::Planner(si, "ORRRTConnect"), mrsi_(MultiRobotSpaceInformation::get(si, "ORRRTConnect"))
{
    specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
    specs_.directed = true;
    specs_.multithreaded = true;
    declareParam<unsigned int>("instances", this, &ORRRTConnect::setInstances, &ORRRTConnect::getInstances, "1:1:64");
    declareParam<unsigned int>("workers", this, &ORRRTConnect::setWorkers, &ORRRTConnect::getWorkers, "1:1:64");
    declareParam<unsigned int>("total_workers", this, &ORRRTConnect::setTotalWorkers, &ORRRTConnect::getTotalWorkers,
                               "1:1:64");
    declareParam<double>("range", this, &ORRRTConnect::setRange, &ORRRTConnect::getRange, "0.:1.:10000.");
    declareParam<unsigned int>("seed", this, &ORRRTConnect::setSeed, &ORRRTConnect::getSeed);
}

void ompl_parc::ORRRTConnect::setInstances(unsigned int instances)
{
    if (instances == 0)
        throw ompl::Exception(getName(), "instances must be at least 1");
    instances_ = instances;
}

void ompl_parc::ORRRTConnect::setWorkers(unsigned int workers)
{
    if (workers == 0)
        throw ompl::Exception(getName(), "workers must be at least 1");
    workers_ = workers;
}

void ompl_parc::ORRRTConnect::setTotalWorkers(unsigned int total)
{
    if (total == 0 || total % instances_ != 0)
        throw ompl::Exception(getName(), "total_workers (" + std::to_string(total) +
                                             ") must be a positive multiple of instances (" +
                                             std::to_string(instances_) + ")");
    workers_ = total / instances_;
}

void ompl_parc::ORRRTConnect::setRange(double range)
{
    if (!(range >= 0.))
        throw ompl::Exception(getName(), "range must be non-negative");
    range_ = range;
}

void ompl_parc::ORRRTConnect::clear()
{
    Planner::clear();
    winner_.clear();
}

ob::PlannerStatus ompl_parc::ORRRTConnect::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    winner_.clear();
    const std::uint_fast32_t seed = seed_ != 0 ? seed_ : ompl::RNG().uniformInt(1, std::numeric_limits<int>::max());
    // Fresh racers per solve: each run starts from empty trees with the current parameters and seed.
    std::vector<ob::PlannerPtr> racers;
    for (unsigned int k = 0; k < instances_; ++k)
    {
        ob::PlannerPtr racer;
        if (workers_ == 1)
        {
            auto rrtc = std::make_shared<SeededRRTConnect>(mrsi_, mixSeed(seed, k));
            rrtc->setRange(range_);
            racer = rrtc;
        }
        else
        {
            auto ep = std::make_shared<EPRRTConnect>(si_);
            ep->setWorkers(workers_);
            ep->setRange(range_);
            ep->setSeed(mixSeed(seed, k));
            racer = ep;
        }
        racer->setName(getName() + "#" + std::to_string(k));
        racer->setProblemDefinition(pdef_);
        racers.push_back(racer);
    }
    ompl::tools::ParallelPlan race(pdef_);
    for (const auto &racer : racers)
        race.addPlanner(racer);
    // ParallelPlan terminates the condition it is given once a racer wins: give it its own.
    const ob::PlannerTerminationCondition raceStop([&ptc] { return ptc(); });
    race.solve(raceStop, 1, racers.size(), false);
    for (const auto &solution : pdef_->getSolutions())
        if (!solution.approximate_)
        {
            winner_ = solution.plannerName_;
            return ob::PlannerStatus::EXACT_SOLUTION;
        }
    return ob::PlannerStatus::TIMEOUT;
}

void ompl_parc::ORRRTConnect::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    data.properties["instances INTEGER"] = std::to_string(instances_);
    data.properties["workers INTEGER"] = std::to_string(workers_);
    data.properties["winner STRING"] = winner_;
}
