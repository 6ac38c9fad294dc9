#include "ompl_parc/planners/subproblem/SequentialRRTConnectSolver.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/planners/subproblem/MoveScheduler.h"
#include "ompl_parc/planners/subproblem/TeamPatch.h"
#include "ompl_parc/robots/RakeMotionValidator.h"
#include "ompl_parc/robots/UrdfArmLanes.h"
#include "ompl_parc/util/OmplCompat.h"
#include "ompl_parc/util/SeededPathSimplifier.h"
#include "ompl_parc/util/SeededRealVectorSampler.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <unordered_set>
#include <utility>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    using Config = std::vector<double>;

    /** Robot \e robot's configurations among the team's robots standing still: valid alone (static obstacles,
        itself) and touching none of them. The standing bodies are computed once per move, and each configuration
        costs one body of the moving robot (the team's own check would compute the whole team's). */
    class StandingTeam
    {
      public:
        StandingTeam(const ompl_parc::MultiRobotSpaceInformation &team, std::size_t robot,
                     const std::vector<const Config *> &configs)
            : robot_(*team.getRobot(robot)), lanes_(robot_.getLanes())
        {
            const std::size_t width = ompl_parc::UrdfArmLanes::width();
            for (std::size_t j = 0; j < configs.size(); ++j)
                if (j != robot)
                {
                    const ompl_parc::Robot &other = *team.getRobot(j);
                    standing_.emplace_back();
                    other.computeBody(configs[j]->data(), standing_.back());
                    standingLanes_.push_back(other.getLanes());
                    if (standingLanes_.back() == nullptr)
                        continue;
                    // The standing configuration in every lane, so that it meets each lane of a moving batch.
                    Config repeated;
                    for (std::size_t l = 0; l < width; ++l)
                        repeated.insert(repeated.end(), configs[j]->begin(), configs[j]->end());
                    placed_.emplace_back();
                    standingLanes_.back()->place(repeated.data(), width, placed_.back());
                }
            if (lanes_ == nullptr || placed_.size() != standing_.size())
                placed_.clear();  // lanes only when every robot has them
        }

        bool valid(const double *q) const
        {
            if (robot_.checkValidity(q, body_) != ompl_parc::Robot::Validity::VALID)
                return false;
            return std::none_of(standing_.begin(), standing_.end(),
                                [this](const ompl_parc::CollisionBody &other)
                                { return ompl_parc::bodiesCollide(body_, other); });
        }

        /** \brief All \e count configurations \e q (flat) valid. Where every robot has lanes: the robot alone as its
            batch check decides (Robot::allValid(), as in the team's own check), then the standing robots compared a
            lane batch at a time and tested exactly only where the lanes cannot tell, which answers as valid() does
            (MultiRobotValidityChecker::allValid()); otherwise valid() on each configuration. */
        bool allValid(const double *q, std::size_t count) const
        {
            const unsigned int dim = robot_.getDimension();
            if (placed_.empty())
            {
                for (std::size_t c = 0; c < count; ++c)
                    if (!valid(q + c * dim))
                        return false;
                return true;
            }
            if (!robot_.allValid(q, count))
                return false;
            const std::size_t width = ompl_parc::UrdfArmLanes::width();
            for (std::size_t first = 0; first < count; first += width)
            {
                const std::size_t lanes = std::min(width, count - first);
                lanes_->place(q + first * dim, lanes, moving_);
                for (std::size_t k = 0; k < placed_.size(); ++k)
                {
                    unsigned int touching = 0;
                    const unsigned int near =
                        ompl_parc::UrdfArmLanes::nearLanes(*lanes_, moving_, *standingLanes_[k], placed_[k], touching);
                    if (touching != 0)
                        return false;
                    for (std::size_t l = 0; l < lanes; ++l)
                        if (((near >> l) & 1u) != 0)
                        {
                            robot_.computeBody(q + (first + l) * dim, body_);
                            if (ompl_parc::bodiesCollide(body_, standing_[k]))
                                return false;
                        }
                }
            }
            return true;
        }

      private:
        const ompl_parc::Robot &robot_;
        const ompl_parc::UrdfArmLanes *lanes_;
        std::vector<ompl_parc::CollisionBody> standing_;
        std::vector<const ompl_parc::UrdfArmLanes *> standingLanes_;
        std::vector<ompl_parc::UrdfArmLanes::Placed> placed_;  // the standing robots in lanes (all robots have them)
        mutable ompl_parc::CollisionBody body_;                // scratch: a move is planned by one thread
        mutable ompl_parc::UrdfArmLanes::Placed moving_;
    };

    /** One robot's move with the set of robots moved before it fixed: its own RRTConnect, kept between the rounds
        of a search so that a round with a larger cap goes on growing the trees of the round before. Its path is
        shortened, where asked, among the same standing robots (drawn from \e seed). */
    class Move
    {
      public:
        Move(const ompl_parc::MultiRobotSpaceInformation &team, std::size_t robot,
             const std::vector<const Config *> &configs, const Config &goal, bool simplify, std::uint_fast32_t seed)
            : standing_(team, robot, configs), simplify_(simplify), seed_(seed),
              // The robot's space in the team's (local bounds, seeded sampler, one check per timestep), its motions
              // sampled at every timestep by the rake, as the team's would be.
              si_(std::make_shared<ob::SpaceInformation>(
                  team.getCompositeSpace()->getSubspace(static_cast<unsigned int>(robot))))
        {
            const unsigned int dim = team.getRobot(robot)->getDimension();
            const StandingTeam &standing = standing_;
            si_->setStateValidityChecker(
                [&standing](const ob::State *state)
                { return standing.valid(state->as<ob::RealVectorStateSpace::StateType>()->values); });
            si_->setMotionValidator(std::make_shared<ompl_parc::RakeMotionValidator>(
                si_.get(), [&standing](const double *q, std::size_t count) { return standing.allValid(q, count); },
                si_->getStateValidityChecker().get()));
            si_->setup();

            const Config &start = *configs[robot];
            if (!standing.valid(start.data()) || !standing.valid(goal.data()))
                return;  // never solvable: a robot moved before stands on its start or goal
            if (start == goal)
            {
                path_.push_back(start);  // a robot whose window ends where it starts stays
                return;
            }
            ob::ScopedState<> from(si_), to(si_);
            for (unsigned int d = 0; d < dim; ++d)
            {
                from[d] = start[d];
                to[d] = goal[d];
            }
            pdef_ = std::make_shared<ob::ProblemDefinition>(si_);
            pdef_->setStartAndGoalStates(from, to, 1e-9);
            planner_ = std::make_unique<og::RRTConnect>(si_);
            planner_->setProblemDefinition(pdef_);
            planner_->setup();
        }
        // Its space's checkers refer to standing_: a move stays where it was made.
        Move(const Move &) = delete;
        Move &operator=(const Move &) = delete;

        /** The move's path from its start to its goal; empty while none is found. */
        const std::vector<Config> &path() const { return path_; }

        /** Go on planning until the move has had \e cap iterations in all, or \e ptc; true once it is solved. */
        bool grow(unsigned int cap, const ob::PlannerTerminationCondition &ptc)
        {
            if (!path_.empty() || !planner_ || spent_ >= cap)
                return !path_.empty();
            unsigned int *spent = &spent_;
            const ob::PlannerTerminationCondition capped = ob::plannerOrTerminationCondition(
                ptc, ob::PlannerTerminationCondition([spent, cap] { return ++*spent > cap; }));
            if (planner_->solve(capped) != ob::PlannerStatus::EXACT_SOLUTION)
                return false;
            auto &solution = *pdef_->getSolutionPath()->as<og::PathGeometric>();
            if (simplify_)
            {
                // As the team's patches are (team_patch::lay): one pass of vertex reduction and of shortcutting.
                ompl_parc::SeededPathSimplifier simplifier(si_, seed_);
                simplifier.reduceVertices(solution);
                ompl_parc::compat::shortcutPath(simplifier, solution, 128, 32);
            }
            for (const ob::State *state : solution.getStates())
            {
                const double *values = state->as<ob::RealVectorStateSpace::StateType>()->values;
                path_.emplace_back(values, values + si_->getStateDimension());
            }
            planner_.reset();  // its trees are no longer needed
            return true;
        }

      private:
        StandingTeam standing_;
        bool simplify_;
        std::uint_fast32_t seed_;
        ob::SpaceInformationPtr si_;
        ob::ProblemDefinitionPtr pdef_;
        std::unique_ptr<og::RRTConnect> planner_;  // null: solved, or never solvable
        unsigned int spent_{0};
        std::vector<Config> path_;
    };

    /** The depth-first search over the sets of robots already moved (bit k: team robot k stands at its goal), in
        rounds of growing move caps; a call cut by its condition leaves the round to the next call. */
    class OrderSearch : public ompl_parc::SubproblemSolver::Memory
    {
      public:
        /** Whether a call has begun the search (its team space and seed are then fixed). */
        bool started() const { return team_ != nullptr; }

        void start(std::shared_ptr<ompl_parc::MultiRobotSpaceInformation> team, std::size_t robots,
                   std::uint_fast32_t seed, bool simplify)
        {
            team_ = std::move(team);
            seed_ = seed;
            simplify_ = simplify;
            rng_.seed(seed);
            order_.resize(robots);
            for (std::size_t k = 0; k < robots; ++k)
                order_[k] = k;
        }

        const std::shared_ptr<ompl_parc::MultiRobotSpaceInformation> &team() const { return team_; }

        /** The team's robots in the order they move, each with its move's path (owned by the search); empty once ptc
            or the sample cap stopped the search. */
        std::vector<ompl_parc::MoveScheduler::Move> run(const ompl_parc::Subproblem &subproblem,
                                                        const ob::PlannerTerminationCondition &ptc)
        {
            subproblem_ = &subproblem;
            ptc_ = subproblem.cappedTermination(ptc);
            while (!ptc_)
            {
                moveCap_ =
                    ompl_parc::Subproblem::doubledCap(ompl_parc::SequentialRRTConnectSolver::FIRST_MOVE_CAP, round_);
                if (!inRound_)
                {
                    dead_.clear();
                    std::shuffle(order_.begin(), order_.end(), rng_);
                    inRound_ = true;
                }
                moves_.clear();
                if (enter(0))
                    return moves_;
                if (ptc_)
                    break;  // cut: the next call goes on with this round
                inRound_ = false;
                ++round_;
                if (!subproblem.global)
                    break;  // a window gets one cheap round (below)
                if (subproblem.sampleCap != 0 && moveCap_ >= subproblem.sampleCap)
                    break;  // the last round a move's cap could grow in under this sample cap
            }
            return {};
        }

      private:
        bool enter(std::uint32_t moved)
        {
            const std::size_t n = subproblem_->robots.size();
            if (moved == (std::uint32_t{1} << n) - 1)
                return true;
            if (dead_.count(moved) != 0)
                return false;
            for (std::size_t k : order_)
            {
                if ((moved >> k) & 1u || ptc_)
                    continue;
                Move &move = this->move(moved, k);
                if (!move.grow(moveCap_, ptc_))
                    continue;
                moves_.emplace_back(k, &move.path());
                if (enter(moved | (std::uint32_t{1} << k)))
                    return true;
                moves_.pop_back();
            }
            if (!ptc_)
                dead_.insert(moved);
            return false;
        }

        /** Robot \e k's move with the robots of \e moved at their goals and the others at their starts. */
        Move &move(std::uint32_t moved, std::size_t k)
        {
            auto &slot = movesByKey_[{moved, k}];
            if (!slot)
            {
                std::vector<const Config *> configs;
                for (std::size_t j = 0; j < subproblem_->robots.size(); ++j)
                    configs.push_back((moved >> j) & 1u ? &subproblem_->goals[j] : &subproblem_->starts[j]);
                slot = std::make_unique<Move>(*team_, k, configs, subproblem_->goals[k], simplify_,
                                              ompl_parc::mixSeed(seed_, (std::uint64_t{moved} << 5) | k));
            }
            return *slot;
        }

        std::shared_ptr<ompl_parc::MultiRobotSpaceInformation> team_;
        const ompl_parc::Subproblem *subproblem_{nullptr};  // of the call running
        ob::PlannerTerminationCondition ptc_{ob::plannerAlwaysTerminatingCondition()};
        std::mt19937 rng_;
        std::uint_fast32_t seed_{0};
        bool simplify_{false};
        unsigned int round_{0};
        bool inRound_{false};
        unsigned int moveCap_{0};
        std::vector<std::size_t> order_;
        std::map<std::pair<std::uint32_t, std::size_t>, std::unique_ptr<Move>> movesByKey_;
        std::unordered_set<std::uint32_t> dead_;
        std::vector<ompl_parc::MoveScheduler::Move> moves_;
    };
}  // namespace

ompl_parc::SequentialRRTConnectSolver::SequentialRRTConnectSolver(bool simplify) : simplify_(simplify) {}

std::unique_ptr<ompl_parc::SubproblemSolver::Memory> ompl_parc::SequentialRRTConnectSolver::makeMemory() const
{
    return std::make_unique<OrderSearch>();
}

bool ompl_parc::SequentialRRTConnectSolver::solve(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                                  const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                                  Patch &patch) const
{
    OrderSearch search;
    return resume(si, subproblem, ptc, seed, patch, &search);
}

bool ompl_parc::SequentialRRTConnectSolver::resume(const MultiRobotSpaceInformation &si, const Subproblem &subproblem,
                                                   const ob::PlannerTerminationCondition &ptc, std::uint_fast32_t seed,
                                                   Patch &patch, Memory *memory) const
{
    auto *search = dynamic_cast<OrderSearch *>(memory);
    if (search == nullptr)
        return solve(si, subproblem, ptc, seed, patch);
    if (subproblem.robots.size() > MAX_TEAM)
        return false;
    if (!search->started())
    {
        auto local = subproblem.createSpaceInformation(si, seed);
        if (!local)
            return false;
        search->start(std::move(local), subproblem.robots.size(), seed, simplify_);
    }
    const auto &local = search->team();
    ob::ScopedState<> start(local), goal(local);
    if (!team_patch::fillEndpoints(*local, subproblem, start.get(), goal.get()))
        return false;

    const auto moves = search->run(subproblem, ptc);
    if (moves.empty())
        return false;
    // One robot moving per segment: each segment is a motion its move checked as the team's would be.
    og::PathGeometric path(local, start.get());
    ob::ScopedState<> at(start);
    for (const auto &[robot, states] : moves)
        for (std::size_t s = 1; s < states->size(); ++s)
        {
            std::copy((*states)[s].begin(), (*states)[s].end(), local->getRobotValues(at.get(), robot));
            path.append(at.get());
        }
    // The moves overlapped in time where the robots stay apart (the path above where they cannot).
    MoveScheduler(local).schedule(moves, start.get(), path, ptc);
    team_patch::lay(local, path, seed, simplify_, patch);
    return true;
}
