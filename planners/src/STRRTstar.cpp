#include "ompl_parc/planners/STRRTstar.h"

#include "ompl_parc/planners/SpaceTimeNearestNeighbors.h"

#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Exception.h>
#include <ompl/util/GeometricEquations.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ob = ompl::base;
namespace og = ompl::geometric;

ompl_parc::STRRTstar::STRRTstar(const ob::SpaceInformationPtr &si) : ob::Planner(si, "STRRTstar")
{
    space_ = dynamic_cast<spacetime::SpaceTimeStateSpace *>(si->getStateSpace().get());
    if (space_ == nullptr)
        throw ompl::Exception(getName(), "needs a SpaceTimeStateSpace (a robot space x time), got '" +
                                             si->getStateSpace()->getName() + "'");
    specs_.optimizingPaths = true;
    specs_.directed = true;
    specs_.canReportIntermediateSolutions = true;
    declareParam<double>("range", this, &STRRTstar::setRange, &STRRTstar::getRange, "0.:1.:10000.");
    declareParam<std::string>("rewiring", this, &STRRTstar::setRewiringState, &STRRTstar::getRewiringState);
    declareParam<double>("rewire_factor", this, &STRRTstar::setRewireFactor, &STRRTstar::getRewireFactor,
                         "1.0:0.01:2.0");
    declareParam<unsigned int>("batch_size", this, &STRRTstar::setBatchSize, &STRRTstar::getBatchSize, "1:1:1000000");
    declareParam<double>("initial_time_bound_factor", this, &STRRTstar::setInitialTimeBoundFactor,
                         &STRRTstar::getInitialTimeBoundFactor, "1.0:0.1:100.");
    declareParam<double>("time_bound_factor_increase", this, &STRRTstar::setTimeBoundFactorIncrease,
                         &STRRTstar::getTimeBoundFactorIncrease, "1.01:0.01:100.");
    declareParam<bool>("sample_uniform_for_unbounded_time", this, &STRRTstar::setSampleUniformForUnboundedTime,
                       &STRRTstar::getSampleUniformForUnboundedTime, "0,1");
    declareParam<double>("minimum_goal_time", this, &STRRTstar::setMinimumGoalTime, &STRRTstar::getMinimumGoalTime);
    declareParam<bool>("stop_at_first_solution", this, &STRRTstar::setStopAtFirstSolution,
                       &STRRTstar::getStopAtFirstSolution, "0,1");
}

ompl_parc::STRRTstar::~STRRTstar()
{
    freeMemory();
}

std::string ompl_parc::STRRTstar::getRewiringState() const
{
    switch (rewireState_)
    {
        case RewireState::OFF:
            return "off";
        case RewireState::RADIUS:
            return "radius";
        case RewireState::KNEAREST:
            return "knearest";
    }
    return "";
}

void ompl_parc::STRRTstar::setRewiringState(const std::string &state)
{
    if (state == "off")
        setRewiringToOff();
    else if (state == "radius")
        setRewiringToRadius();
    else if (state == "knearest")
        setRewiringToKNearest();
    else
        throw ompl::Exception(getName(), "rewiring must be 'off', 'radius' or 'knearest', not '" + state + "'");
}

void ompl_parc::STRRTstar::setBatchSize(unsigned int size)
{
    if (size == 0)
        throw ompl::Exception(getName(), "the batch size must be positive");
    initialBatchSize_ = size;
}

void ompl_parc::STRRTstar::setInitialTimeBoundFactor(double factor)
{
    if (!(factor >= 1.))
        throw ompl::Exception(getName(), "the initial time bound factor must be at least 1");
    initialTimeBoundFactor_ = factor;
}

void ompl_parc::STRRTstar::setTimeBoundFactorIncrease(double factor)
{
    if (!(factor > 1.))
        throw ompl::Exception(getName(), "the time bound factor increase must exceed 1");
    timeBoundFactorIncrease_ = factor;
}

void ompl_parc::STRRTstar::setup()
{
    Planner::setup();
    space_->updateEpsilon();
    if (maxDistance_ <= 0.)
        maxDistance_ = 0.2 * space_->getSpaceComponent()->getMaximumExtent();
    const auto distance = [this](const Motion *a, const Motion *b) { return si_->distance(a->state, b->state); };
    // Space-time distances are not a metric (they can be infinite), so only linear search is exact; over a
    // RealVectorStateSpace (every robot's) the same search on flat buffers, without a virtual call per element.
    const bool flat = SpaceTimeNearestNeighbors<Motion *>::supports(*space_);
    for (Tree *tree : {&tStart_, &tGoal_})
    {
        if (!*tree && flat)
            tree->reset(new SpaceTimeNearestNeighbors<Motion *>(*space_, [](Motion *const &m) { return m->state; }));
        else if (!*tree)
            tree->reset(new ompl::NearestNeighborsLinear<Motion *>());
        (*tree)->setDistanceFunction(distance);
    }
    spaceSampler_ = space_->getSpaceComponent()->allocStateSampler();
}

void ompl_parc::STRRTstar::freeMemory()
{
    for (auto &motion : motions_)
        si_->freeState(motion->state);
    motions_.clear();
    if (scratch_ != nullptr)
        si_->freeState(scratch_);
    scratch_ = nullptr;
}

void ompl_parc::STRRTstar::clear()
{
    Planner::clear();
    freeMemory();
    if (tStart_)
        tStart_->clear();
    if (tGoal_)
        tGoal_->clear();
    startMotion_ = nullptr;
    goalMotions_.clear();
    newBatchGoalMotions_.clear();
    bestPath_.clear();
    iterations_ = solutions_ = 0;
}

ompl_parc::STRRTstar::Motion *ompl_parc::STRRTstar::newMotion(const ob::State *state, Motion *parent)
{
    motions_.push_back(std::make_unique<Motion>());
    Motion *motion = motions_.back().get();
    motion->state = si_->cloneState(state);
    motion->parent = parent;
    motion->root = parent != nullptr ? parent->root : motion;
    if (parent != nullptr)
        parent->children.push_back(motion);
    return motion;
}

bool ompl_parc::STRRTstar::motionValid(const ob::State *from, const ob::State *to) const
{
    return spacetime::SpaceTimeStateSpace::getStateTime(to) > spacetime::SpaceTimeStateSpace::getStateTime(from) &&
           si_->checkMotion(from, to);
}

ompl_parc::STRRTstar::Motion *ompl_parc::STRRTstar::growSingle(Tree &tree, bool startTree, Motion *near,
                                                               const ob::State *target, bool &reached)
{
    // The start tree grows forward in time, the goal tree backward.
    if (startTree != (timeOf(near) < spacetime::SpaceTimeStateSpace::getStateTime(target)))
        return nullptr;
    const ob::State *step = target;
    const double d = si_->distance(near->state, target);
    reached = d <= maxDistance_;
    if (!reached)
    {
        // An infinite distance (too fast) interpolates to the near state itself: no progress.
        si_->getStateSpace()->interpolate(near->state, target, maxDistance_ / d, scratch_);
        if (si_->equalStates(near->state, scratch_))
            return nullptr;
        step = scratch_;
    }
    const bool valid =
        startTree ? motionValid(near->state, step) : si_->isValid(step) && motionValid(step, near->state);
    if (!valid)
        return nullptr;
    Motion *motion = newMotion(step, near);
    tree->add(motion);
    return motion;
}

void ompl_parc::STRRTstar::getNeighbors(const Tree &tree, const ob::State *state, std::vector<Motion *> &nbh) const
{
    nbh.clear();
    if (rewireState_ == RewireState::OFF)
        return;
    query_.state = const_cast<ob::State *>(state);
    const double n = static_cast<double>(tree->size()) + 1.;
    const double dim = static_cast<double>(si_->getStateDimension());
    if (rewireState_ == RewireState::KNEAREST)
    {
        const double kRRT =
            rewireFactor_ * (boost::math::constants::e<double>() + boost::math::constants::e<double>() / dim);
        tree->nearestK(&query_, static_cast<std::size_t>(std::ceil(kRRT * std::log(n))), nbh);
        return;
    }
    // The RRT* radius for the space-time volume searched so far (the space's measure x the time horizon).
    const double measure = space_->getSpaceComponent()->getMeasure() * currentHorizon();
    const double rRRT =
        rewireFactor_ *
        std::pow(2. * (1. + 1. / dim) * (measure / ompl::unitNBallMeasure(si_->getStateDimension())), 1. / dim);
    const double radius = rRRT * std::pow(std::log(n) / n, 1. / dim);
    tree->nearestR(&query_, std::isfinite(radius) ? std::min(maxDistance_, radius) : maxDistance_, nbh);
}

namespace
{
    void setStateTime(ob::State *state, double time)
    {
        state->as<ob::CompoundState>()->as<ob::TimeStateSpace::StateType>(1)->position = time;
    }
}  // namespace

double ompl_parc::STRRTstar::referenceDuration(const ob::State *goal) const
{
    return std::max(
        {space_->timeToCoverDistance(startMotion_->state, goal), minimumGoalTime_ - startTime_, durationFloor_});
}

double ompl_parc::STRRTstar::currentHorizon() const
{
    return timeBounded_ ? upperTimeBound_ - startTime_ : newBatchFactor_ * minimumDuration_;
}

ompl_parc::STRRTstar::Motion *ompl_parc::STRRTstar::extend(Tree &tree, bool startTree, const ob::State *target)
{
    bool reached = false;
    std::vector<Motion *> nbh;
    getNeighbors(tree, target, nbh);
    if (nbh.empty())
    {
        query_.state = const_cast<ob::State *>(target);
        return growSingle(tree, startTree, tree->nearest(&query_), target, reached);
    }
    // The start tree tries the closest vertices first, the goal tree those leading to the earliest goal.
    if (startTree)
        std::sort(nbh.begin(), nbh.end(),
                  [this, target](const Motion *a, const Motion *b)
                  { return si_->distance(a->state, target) < si_->distance(b->state, target); });
    else
        std::sort(nbh.begin(), nbh.end(),
                  [](const Motion *a, const Motion *b) { return timeOf(a->root) < timeOf(b->root); });
    for (Motion *near : nbh)
        if (Motion *motion = growSingle(tree, startTree, near, target, reached))
            return motion;
    return nullptr;
}

ompl_parc::STRRTstar::Motion *ompl_parc::STRRTstar::connect(Tree &tree, bool startTree, const ob::State *target,
                                                            const ob::PlannerTerminationCondition &ptc)
{
    bool reached = false;
    while (!ptc)
    {
        query_.state = const_cast<ob::State *>(target);
        Motion *motion = growSingle(tree, startTree, tree->nearest(&query_), target, reached);
        if (motion == nullptr)
            return nullptr;
        if (reached)
            return motion;
    }
    return nullptr;
}

void ompl_parc::STRRTstar::rewireGoalTree(Motion *added)
{
    std::vector<Motion *> nbh;
    getNeighbors(tGoal_, added->state, nbh);
    for (Motion *n : nbh)
    {
        // n may lead through the new vertex (later in time) to an earlier goal than its own.
        if (n == added || !(timeOf(n) < timeOf(added)) || !(timeOf(added->root) < timeOf(n->root)) ||
            !motionValid(n->state, added->state))
            continue;
        auto &siblings = n->parent->children;
        siblings.erase(std::find(siblings.begin(), siblings.end(), n));
        n->parent = added;
        added->children.push_back(n);
        std::vector<Motion *> subtree{n};
        while (!subtree.empty())
        {
            Motion *m = subtree.back();
            subtree.pop_back();
            m->root = added->root;
            subtree.insert(subtree.end(), m->children.begin(), m->children.end());
        }
    }
}

bool ompl_parc::STRRTstar::sampleConditional(ob::State *state, bool oldBatch)
{
    const auto &goals =
        (oldBatch && !goalMotions_.empty()) || newBatchGoalMotions_.empty() ? goalMotions_ : newBatchGoalMotions_;
    if (goals.empty())
        return false;
    ob::State *spaceState = state->as<ob::CompoundState>()->components[0];
    constexpr unsigned int ATTEMPTS = 10;
    for (unsigned int attempt = 0; attempt < ATTEMPTS; ++attempt)
    {
        spaceSampler_->sampleUniform(spaceState);
        const Motion *goal = goals[rng_.uniformInt(0, static_cast<int>(goals.size()) - 1)];
        // Reachable from the start at vMax, and the goal still reachable from there in time.
        const double earliest = startTime_ + space_->timeToCoverDistance(startMotion_->state, state);
        const double latest = timeOf(goal) - space_->timeToCoverDistance(state, goal->state);
        if (earliest > latest)
            continue;
        setStateTime(state, earliest == latest ? earliest : rng_.uniformReal(earliest, latest));
        return true;
    }
    return false;
}

ompl_parc::STRRTstar::Motion *ompl_parc::STRRTstar::sampleGoal(unsigned int tries, bool oldBatch,
                                                               const ob::PlannerTerminationCondition &ptc)
{
    for (unsigned int i = 0; i < tries && !ptc; ++i)
    {
        goal_->sampleGoal(scratch_);
        const double duration = referenceDuration(scratch_);
        double low = startTime_ + duration, high = 0.;
        if (timeBounded_)
            high = upperTimeBound_;
        else if (oldBatch)
            high = startTime_ + oldBatchFactor_ * duration;
        else
        {
            low = startTime_ + oldBatchFactor_ * duration;
            high = startTime_ + newBatchFactor_ * duration;
        }
        if (low > high)
            continue;
        setStateTime(scratch_, low == high ? low : rng_.uniformReal(low, high));
        if (!si_->satisfiesBounds(scratch_) || !si_->isValid(scratch_))
            continue;
        Motion *motion = newMotion(scratch_, nullptr);
        tGoal_->add(motion);
        (oldBatch ? goalMotions_ : newBatchGoalMotions_).push_back(motion);
        minimumDuration_ = std::min(minimumDuration_, duration);
        ++batchSamples_;
        return motion;
    }
    return nullptr;
}

void ompl_parc::STRRTstar::increaseTimeBound(bool skipEmpty)
{
    oldBatchFactor_ = skipEmpty ? newBatchFactor_ * timeBoundFactorIncrease_ : newBatchFactor_;
    newBatchFactor_ *= timeBoundFactorIncrease_;
    nextFromStart_ = true;
    if (sampleUniformForUnboundedTime_)
        batchSize_ = static_cast<unsigned int>(
            std::ceil(2. * (timeBoundFactorIncrease_ - 1.) * static_cast<double>(tStart_->size() + tGoal_->size())));
    batchSamples_ = 0;
    goalMotions_.insert(goalMotions_.end(), newBatchGoalMotions_.begin(), newBatchGoalMotions_.end());
    newBatchGoalMotions_.clear();
}

bool ompl_parc::STRRTstar::recordSolution(const Motion *startSide, const Motion *goalSide)
{
    const double arrival = timeOf(goalSide->root);
    if (solutions_ > 0 && arrival >= bestTime_)
        return false;
    bestPath_.clear();
    for (const Motion *m = startSide; m != nullptr; m = m->parent)
        bestPath_.push_back(m->state);
    std::reverse(bestPath_.begin(), bestPath_.end());
    for (const Motion *m = goalSide; m != nullptr; m = m->parent)
        bestPath_.push_back(m->state);
    bestTime_ = arrival;
    ++solutions_;
    if (const auto &callback = pdef_->getIntermediateSolutionCallback())
        callback(this, bestPath_, ob::Cost(bestTime_));
    // Only earlier arrivals are of interest from now on.
    timeBounded_ = true;
    upperTimeBound_ = arrival;
    goalMotions_.insert(goalMotions_.end(), newBatchGoalMotions_.begin(), newBatchGoalMotions_.end());
    newBatchGoalMotions_.clear();
    return true;
}

ob::PlannerStatus ompl_parc::STRRTstar::solve(const ob::PlannerTerminationCondition &ptc)
{
    checkValidity();
    goal_ = dynamic_cast<const ob::GoalSampleableRegion *>(pdef_->getGoal().get());
    if (goal_ == nullptr)
    {
        OMPL_ERROR("%s: the goal must be sampleable", getName().c_str());
        return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    }
    while (const ob::State *start = pis_.nextStart())
        if (startMotion_ == nullptr)
        {
            startMotion_ = newMotion(start, nullptr);
            tStart_->add(startMotion_);
        }
    if (startMotion_ == nullptr)
    {
        OMPL_ERROR("%s: no valid start state", getName().c_str());
        return ob::PlannerStatus::INVALID_START;
    }
    if (!goal_->couldSample())
    {
        OMPL_ERROR("%s: the goal region has no states to sample", getName().c_str());
        return ob::PlannerStatus::INVALID_GOAL;
    }
    if (scratch_ == nullptr)
        scratch_ = si_->allocState();

    const ob::TimeStateSpace *time = space_->getTimeComponent();
    startTime_ = timeOf(startMotion_);
    durationFloor_ = 1e-3 * space_->getSpaceComponent()->getMaximumExtent() / space_->getVMax();
    minimumDuration_ = std::numeric_limits<double>::infinity();
    timeBounded_ = time->isBounded() || solutions_ > 0;
    upperTimeBound_ = solutions_ > 0      ? bestTime_
                      : time->isBounded() ? time->getMaxTimeBound()
                                          : std::numeric_limits<double>::infinity();
    batchSize_ = initialBatchSize_;
    batchSamples_ = static_cast<unsigned int>(tStart_->size() + tGoal_->size());
    oldBatchFactor_ = newBatchFactor_ = initialTimeBoundFactor_;
    nextFromStart_ = true;
    bool firstBatch = true, forceGoalSample = true;
    double oldBatchProbability = 1.;
    unsigned int newBatchGoalSamples = 0;
    ob::State *sample = si_->allocState();

    while (!ptc)
    {
        ++iterations_;
        const bool startTree = nextFromStart_;
        nextFromStart_ = !nextFromStart_;
        Tree &tree = startTree ? tStart_ : tGoal_;
        Tree &otherTree = startTree ? tGoal_ : tStart_;

        if (!timeBounded_ && batchSamples_ >= batchSize_)
        {
            if (firstBatch)
                oldBatchProbability = 0.5 / timeBoundFactorIncrease_;
            firstBatch = false;
            increaseTimeBound(false);
            newBatchGoalSamples = 0;
            continue;
        }

        // Goal states: keep about one goal per goalRatio goal-tree vertices of the batch's region.
        constexpr std::size_t GOAL_RATIO = 4;
        const bool oldBatch =
            firstBatch || timeBounded_ || !sampleUniformForUnboundedTime_ || rng_.uniform01() <= oldBatchProbability;
        auto &batchGoals = oldBatch ? goalMotions_ : newBatchGoalMotions_;
        if (batchGoals.empty())
        {
            // Sample in earnest; with unbounded time, a region without a valid goal is skipped.
            const unsigned int tries = timeBounded_ ? std::numeric_limits<unsigned int>::max() : batchSize_;
            if (sampleGoal(tries, oldBatch, ptc) == nullptr)
            {
                if (!timeBounded_)
                    increaseTimeBound(oldBatch);
                continue;
            }
            newBatchGoalSamples += oldBatch ? 0 : 1;
        }
        else if (forceGoalSample ||
                 (oldBatch && goalMotions_.size() < (tGoal_->size() - newBatchGoalSamples) / GOAL_RATIO) ||
                 (!oldBatch && newBatchGoalMotions_.size() < newBatchGoalSamples / GOAL_RATIO))
        {
            forceGoalSample = false;
            if (sampleGoal(1, oldBatch, ptc) != nullptr)
                newBatchGoalSamples += oldBatch ? 0 : 1;
        }

        if (!sampleConditional(sample, oldBatch))
        {
            forceGoalSample = true;
            continue;
        }
        Motion *added = extend(tree, startTree, sample);
        if (added == nullptr)
            continue;
        ++batchSamples_;
        if (!startTree && rewireState_ != RewireState::OFF)
            rewireGoalTree(added);

        const std::size_t before = tStart_->size() + tGoal_->size();
        const Motion *reached = connect(otherTree, !startTree, added->state, ptc);
        batchSamples_ += static_cast<unsigned int>(tStart_->size() + tGoal_->size() - before);
        if (reached == nullptr)
            continue;
        // Both vertices hold the same state: the path uses it once.
        const Motion *startSide = startTree ? added : reached;
        const Motion *goalSide = startTree ? reached : added;
        if (startSide->parent != nullptr)
            startSide = startSide->parent;
        else
            goalSide = goalSide->parent;
        // No arrival beats the least duration (up to the round-off the space's speed test allows).
        if (recordSolution(startSide, goalSide) &&
            (stopAtFirstSolution_ ||
             bestTime_ - startTime_ <= minimumDuration_ * (1. + std::numeric_limits<float>::epsilon())))
            break;
    }
    si_->freeState(sample);

    if (solutions_ == 0)
        return ob::PlannerStatus::TIMEOUT;
    auto path = std::make_shared<og::PathGeometric>(si_);
    for (const ob::State *state : bestPath_)
        path->append(state);
    pdef_->addSolutionPath(path, false, 0., getName());
    return ob::PlannerStatus::EXACT_SOLUTION;
}

void ompl_parc::STRRTstar::getPlannerData(ob::PlannerData &data) const
{
    Planner::getPlannerData(data);
    data.properties["iterations INTEGER"] = std::to_string(iterations_);
    data.properties["solutions INTEGER"] = std::to_string(solutions_);
    data.properties["best time REAL"] = std::to_string(bestTime_);
    for (const auto &motion : motions_)
    {
        if (motion->parent == nullptr)
        {
            if (motion.get() == startMotion_)
                data.addStartVertex(ob::PlannerDataVertex(motion->state, 1));
            else
                data.addGoalVertex(ob::PlannerDataVertex(motion->state, 2));
        }
        else if (motion->root == startMotion_)
            data.addEdge(ob::PlannerDataVertex(motion->parent->state, 1), ob::PlannerDataVertex(motion->state, 1));
        else
            data.addEdge(ob::PlannerDataVertex(motion->state, 2), ob::PlannerDataVertex(motion->parent->state, 2));
    }
}
