#ifndef OMPL_PARC_PARALLEL_OR_RACE_
#define OMPL_PARC_PARALLEL_OR_RACE_

#include <ompl/base/Planner.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief The OR-parallel race of our OR planners (OR-P-ARC, OR-PP-ST-RRT, OR-RRT-C): K independent
        planner instances with their own seeds, run concurrently with OMPL's ParallelPlan until the first
        exact solution; that one wins, the others are stopped, and all are joined before run() returns.

        The owner declares \e instances (K) through declareInstances() and checks worker budgets with
        workersPerInstance(), so every OR planner validates K, W_k and W = K x W_k the same way. Racer k is
        named "<owner>#k", seeded with mixSeed(seed, k) and kept until clear(): a later run() continues the
        same racers. After a run the race reports the winner and, for every racer, how its solve() ended and
        its PlannerData properties, also when nobody won. */
    class OrRace
    {
      public:
        /** \brief Builds racer \e k for \e seed (already mixed); the race names it and sets its problem. */
        using RacerAllocator = std::function<ompl::base::PlannerPtr(unsigned int k, std::uint_fast32_t seed)>;

        /** \brief A race of \e owner's instances; \e owner names the racers and the exceptions. */
        explicit OrRace(const ompl::base::Planner &owner);
        ~OrRace();

        /** \brief Declares \e instances (K, 1 to 64) in \e params, the owner's ParamSet. */
        void declareInstances(ompl::base::ParamSet &params);
        /** \brief K; throws ompl::Exception for 0. Discards the racers. */
        void setInstances(unsigned int instances);
        unsigned int getInstances() const { return instances_; }
        /** \brief W_k for a budget of \e total workers; throws ompl::Exception unless \e total is a positive
            multiple of K. */
        unsigned int workersPerInstance(unsigned int total) const;

        /** \brief Creates the K racers with \e allocate, seeded from \e seed (0: one drawn from OMPL's random
            sequence, see seedOrDraw()), on \e pdef. */
        void createRacers(const RacerAllocator &allocate, unsigned int seed,
                          const ompl::base::ProblemDefinitionPtr &pdef);
        bool hasRacers() const { return !racers_.empty(); }
        /** \brief The racers, in index order (empty before createRacers() and after clear()). */
        const std::vector<ompl::base::PlannerPtr> &getRacers() const { return racers_; }
        /** \brief Discards the racers and the last outcome. */
        void clear();

        /** \brief Races the racers until the first exact solution or \e ptc: EXACT_SOLUTION with a winner,
            otherwise what racer 0 reported (every racer sees the same problem: an invalid start is everyone's,
            otherwise TIMEOUT). */
        ompl::base::PlannerStatus run(const ompl::base::PlannerTerminationCondition &ptc);

        /** \brief Whether run() has raced the current racers. */
        bool hasRun() const { return !statuses_.empty(); }
        /** \brief The index of the winner, -1 if the last run had none. The winner is the racer whose exact
            solution the ProblemDefinition ranks first (usually the only one: the first stops the others). */
        int getWinner() const { return winner_; }
        /** \brief The winner's name, empty if none. */
        std::string getWinnerName() const;
        /** \brief How racer \e k's solve() ended in the last run (CRASH if it threw). */
        ompl::base::PlannerStatus getStatus(unsigned int k) const { return statuses_.at(k); }
        /** \brief Racer \e k's PlannerData properties now. */
        std::map<std::string, std::string> getProperties(unsigned int k) const;

        /** \brief Adds \e instances, \e winner (the winner's name) and, for each racer k, instancek_status and
            its properties prefixed "instancek_", to \e data. Property names become SQL columns in OMPL's
            benchmark database: the prefixes are plain words and digits. */
        void addProperties(ompl::base::PlannerData &data) const;

      private:
        const ompl::base::Planner &owner_;
        unsigned int instances_{2};
        std::vector<ompl::base::PlannerPtr> racers_;
        std::vector<ompl::base::PlannerStatus> statuses_;
        int winner_{-1};
    };
}  // namespace ompl_parc

#endif
