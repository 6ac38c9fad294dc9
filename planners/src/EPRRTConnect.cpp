#include "ompl_parc/planners/EPRRTConnect.h"

#include "ompl_parc/util/PlannerSeed.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/datastructures/NearestNeighborsGNATNoThreadSafety.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/tools/config/SelfConfig.h>
#include <ompl/util/Exception.h>

#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct ompl_parc::EPRRTConnect::Motion
{
    ob::State *state{nullptr};
    const Motion *parent{nullptr};
};

/** \brief A tree: its nearest-neighbour structure, guarded by one mutex for queries and insertions. */
struct ompl_parc::EPRRTConnect::Tree
{
    std::mutex mutex;
    ompl::NearestNeighborsGNATNoThreadSafety<Motion *> nn;
    bool isStart{true};
};

ompl_parc::EPRRTConnect::EPRRTConnect(const ob::SpaceInformationPtr &si)
    : ob::Planner(si, "EPRRTConnect"),
      mrsi_(MultiRobotSpaceInformation::get(si, "EPRRTConnect")),
      startTree_(std::make_unique<Tree>()),
      goalTree_(std::make_unique<Tree>())
{
    specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
    specs_.directed = true;
    goalTree_->isStart = false;
    declareParam<unsigned int>("workers", this, &EPRRTConnect::setWorkers, &EPRRTConnect::getWorkers, "1:1:64");
    declareParam<double>("range", this, &EPRRTConnect::setRange, &EPRRTConnect::getRange, "0.:1.:10000.");
    declareParam<unsigned int>("seed", this, &EPRRTConnect::setSeed, &EPRRTConnect::getSeed);
}

ompl_parc::EPRRTConnect::~EPRRTConnect()
{
    freeTree(*startTree_);
    freeTree(*goalTree_);
}

void ompl_parc::EPRRTConnect::setWorkers(unsigned int workers)
{
    if (workers == 0)
        throw ompl::Exception(getName(), "workers must be at least 1");
    workers_ = workers;
}

void ompl_parc::EPRRTConnect::setRange(double range)
{
    if (!(range >= 0.))
        throw ompl::Exception(getName(), "range must be non-negative");
    range_ = range;
}

void ompl_parc::EPRRTConnect::setup()
{
    Planner::setup();
    ompl::tools::SelfConfig(si_, getName()).configurePlannerRange(range_);
    const auto distance = [this](const Motion *a, const Motion *b) { return si_->distance(a->state, b->state); };
    startTree_->nn.setDistanceFunction(distance);
    goalTree_->nn.setDistanceFunction(distance);
}

void ompl_parc::EPRRTConnect::freeTree(Tree &tree)
{
    std::vector<Motion *> motions;
    tree.nn.list(motions);
    for (Motion *motion : motions)
    {
        si_->freeState(motion->state);
        delete motion;
    }
    tree.nn.clear();
}

void ompl_parc::EPRRTConnect::clear()
{
    Planner::clear();
    freeTree(*startTree_);
    freeTree(*goalTree_);
    connection_[0] = connection_[1] = nullptr;
}

ompl_parc::EPRRTConnect::Growth ompl_parc::EPRRTConnect::grow(Tree &tree, const ob::State *target, ob::State *scratch,
                                                              Motion *&added)
{
    Motion query{const_cast<ob::State *>(target), nullptr};
    Motion *near = nullptr;
    {
        std::lock_guard<std::mutex> lock(tree.mutex);
        near = tree.nn.nearest(&query);
    }
    const ob::State *to = target;
    const double d = si_->distance(near->state, target);
    const bool reach = d <= range_;
    if (!reach)
    {
        si_->getStateSpace()->interpolate(near->state, target, range_ / d, scratch);
        to = scratch;
    }
    // Check motions in the direction the robots travel: away from the start root, toward the goal root.
    const bool valid = tree.isStart ? si_->checkMotion(near->state, to) : si_->checkMotion(to, near->state);
    if (!valid)
        return Growth::TRAPPED;
    added = new Motion{si_->cloneState(to), near};
    {
        std::lock_guard<std::mutex> lock(tree.mutex);
        tree.nn.add(added);
    }
    return reach ? Growth::REACHED : Growth::ADVANCED;
}

void ompl_parc::EPRRTConnect::connect(Motion *startSide, Motion *goalSide)
{
    std::lock_guard<std::mutex> lock(connectionMutex_);
    if (connection_[0] == nullptr)
    {
        connection_[0] = startSide;
        connection_[1] = goalSide;
    }
    stop_ = true;
}

void ompl_parc::EPRRTConnect::work(unsigned int worker, std::uint_fast32_t seed,
                                   const ob::PlannerTerminationCondition &ptc)
{
    // The worker's own sample stream: a seeded copy of the team's spaces, used for sampling only.
    const auto seeded = std::make_shared<MultiRobotSpaceInformation>(
        mrsi_->getRobots(), mrsi_->getResolution(), std::vector<ob::RealVectorBounds>{}, mixSeed(seed, worker));
    const auto sampler = seeded->allocStateSampler();
    ob::State *sample = si_->allocState(), *scratch = si_->allocState(), *connectScratch = si_->allocState();
    bool fromStart = worker % 2 == 0;
    while (!stop_ && !ptc())
    {
        Tree &tree = fromStart ? *startTree_ : *goalTree_;
        Tree &other = fromStart ? *goalTree_ : *startTree_;
        fromStart = !fromStart;
        sampler->sampleUniform(sample);
        Motion *added = nullptr;
        if (grow(tree, sample, scratch, added) == Growth::TRAPPED)
            continue;
        // Connect the other tree toward the new motion, as RRT-Connect does.
        Growth growth = Growth::ADVANCED;
        Motion *reached = nullptr;
        while (growth == Growth::ADVANCED && !stop_ && !ptc())
            growth = grow(other, added->state, connectScratch, reached);
        if (growth == Growth::REACHED)
            tree.isStart ? connect(added, reached) : connect(reached, added);
    }
    si_->freeState(sample);
    si_->freeState(scratch);
    si_->freeState(connectScratch);
}

ob::PlannerStatus ompl_parc::EPRRTConnect::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    auto *goal = dynamic_cast<ob::GoalSampleableRegion *>(pdef_->getGoal().get());
    if (goal == nullptr)
        return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    while (const ob::State *start = pis_.nextStart())
        startTree_->nn.add(new Motion{si_->cloneState(start), nullptr});
    if (startTree_->nn.size() == 0)
        return ob::PlannerStatus::INVALID_START;
    if (goalTree_->nn.size() == 0)
        if (const ob::State *g = pis_.nextGoal(ptc))
            goalTree_->nn.add(new Motion{si_->cloneState(g), nullptr});
    if (goalTree_->nn.size() == 0)
        return ob::PlannerStatus::INVALID_GOAL;

    const std::uint_fast32_t seed = seedOrDraw(seed_);
    stop_ = false;
    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(workers_);
    for (unsigned int w = 0; w < workers_; ++w)
        threads.emplace_back(
            [&, w]
            {
                try
                {
                    const StopSignal::Scope scope(ptc);
                    work(w, seed, ptc);
                }
                catch (...)
                {
                    errors[w] = std::current_exception();
                    stop_ = true;  // a failing worker stops the others
                }
            });
    for (auto &thread : threads)
        thread.join();
    for (const auto &error : errors)
        if (error)
            std::rethrow_exception(error);
    if (connection_[0] == nullptr)
        return ob::PlannerStatus::TIMEOUT;

    auto path = std::make_shared<og::PathGeometric>(si_);
    std::vector<const Motion *> startSide;
    for (const Motion *m = connection_[0]; m != nullptr; m = m->parent)
        startSide.push_back(m);
    for (auto it = startSide.rbegin(); it != startSide.rend(); ++it)
        path->append((*it)->state);
    for (const Motion *m = connection_[1]; m != nullptr; m = m->parent)
        path->append(m->state);
    pdef_->addSolutionPath(path, false, 0., getName());
    return ob::PlannerStatus::EXACT_SOLUTION;
}

void ompl_parc::EPRRTConnect::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    data.properties["workers INTEGER"] = std::to_string(workers_);
    data.properties["start tree states INTEGER"] = std::to_string(startTree_->nn.size());
    data.properties["goal tree states INTEGER"] = std::to_string(goalTree_->nn.size());
}
