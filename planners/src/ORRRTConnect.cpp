#include "ompl_parc/planners/ORRRTConnect.h"

#include "ompl_parc/planners/EPRRTConnect.h"

#include <ompl/base/PlannerData.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Exception.h>

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
    : ob::Planner(si, "ORRRTConnect"), mrsi_(MultiRobotSpaceInformation::get(si, "ORRRTConnect")), race_(*this)
{
    specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
    specs_.directed = true;
    specs_.multithreaded = true;
    race_.declareInstances(params());
    declareParam<unsigned int>("workers", this, &ORRRTConnect::setWorkers, &ORRRTConnect::getWorkers, "1:1:64");
    declareParam<unsigned int>("total_workers", this, &ORRRTConnect::setTotalWorkers, &ORRRTConnect::getTotalWorkers,
                               "1:1:64");
    declareParam<double>("range", this, &ORRRTConnect::setRange, &ORRRTConnect::getRange, "0.:1.:10000.");
    declareParam<unsigned int>("seed", this, &ORRRTConnect::setSeed, &ORRRTConnect::getSeed);
}

void ompl_parc::ORRRTConnect::setWorkers(unsigned int workers)
{
    if (workers == 0)
        throw ompl::Exception(getName(), "workers must be at least 1");
    workers_ = workers;
}

void ompl_parc::ORRRTConnect::setTotalWorkers(unsigned int total)
{
    workers_ = race_.workersPerInstance(total);
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
    race_.clear();
}

ob::PlannerStatus ompl_parc::ORRRTConnect::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    race_.createRacers(
        [this](unsigned int, std::uint_fast32_t seed) -> ob::PlannerPtr
        {
            if (workers_ == 1)
            {
                auto rrtc = std::make_shared<SeededRRTConnect>(mrsi_, seed);
                rrtc->setRange(range_);
                return rrtc;
            }
            auto ep = std::make_shared<EPRRTConnect>(si_);
            ep->setWorkers(workers_);
            ep->setRange(range_);
            ep->setSeed(seed);
            return ep;
        },
        seed_, pdef_);
    return race_.run(ptc);
}

void ompl_parc::ORRRTConnect::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    data.properties["workers INTEGER"] = std::to_string(workers_);
    race_.addProperties(data);
}
