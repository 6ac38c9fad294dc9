#ifndef OMPL_PARC_DEMOS_MPI_RACE_
#define OMPL_PARC_DEMOS_MPI_RACE_

#include "MpiSession.h"

#include <ompl/base/Planner.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace ompl_parc::tools
{
    /** \brief An OR race over MPI ranks: every rank solves its own planner instance; the first exact solution wins
        and stops the others, a rank that fails ends the race for all.

        Rank 0 is the referee. Each rank's planner runs in a thread of its own while the rank's main thread (the only
        one that calls MPI) polls every millisecond. When a planner returns, its rank announces how (a "claim":
        status, reason, when, a report) without waiting (MPI_Isend). Rank 0 takes the first exact claim as the winner,
        or the first claim of a rank that crashed (threw) as a failure, or waits until every rank has claimed; then it
        tells every rank the outcome ("end"). A rank that receives it stops its planner through the planner's
        termination condition, joins it, and claims if it had not. Every rank thus exchanges two small messages with
        rank 0; the winner's plan is not part of the race (the caller sends it). */
    class MpiRace
    {
      public:
        /** \brief How one rank's solve ended, as rank 0 heard it. */
        struct Claim
        {
            ompl::base::PlannerStatus status{ompl::base::PlannerStatus::UNKNOWN};
            /** \brief Why it ended so (the exception's message for a crash; else the status in words). */
            std::string reason;
            /** \brief Seconds from the common start of the race to the return of the rank's solve. */
            double returnedAfter{0.};
            /** \brief What the rank's \e describe function said after its solve (JSON). */
            std::string report;
        };

        /** \brief A rank's solve under the race's termination condition. */
        using Solve = std::function<ompl::base::PlannerStatus(const ompl::base::PlannerTerminationCondition &)>;
        /** \brief A rank's report after its solve, as JSON text. */
        using Describe = std::function<std::string()>;

        explicit MpiRace(const MpiSession &session) : session_(session) {}

        /** \brief Races (a collective call: every rank calls it): \e solve runs on a thread of its own under a
            termination condition that fires after \e timeLimit seconds or when the race ends; an exception from it
            counts as a CRASH with its message. \e describe, called after the solve returned, makes the rank's report.
            Returns once this rank's solve has returned and everybody knows the outcome. */
        void run(const Solve &solve, const Describe &describe, double timeLimit);

        /** \brief The winning rank, -1 if nobody won (known on every rank). */
        int getWinner() const { return winner_; }
        /** \brief The first rank whose solve crashed before anybody won, -1 if none (known on every rank). */
        int getFailedRank() const { return failed_; }
        /** \brief Seconds since the common start of the race. */
        double getElapsed() const;
        /** \brief On rank 0, every rank's claim, in rank order (empty elsewhere). */
        const std::vector<Claim> &getClaims() const { return claims_; }

      private:
        /** \brief Rank 0's side: referee until the outcome is known, tell everyone, collect the remaining claims. */
        void referee(const std::function<bool()> &returned, const std::function<std::string()> &claim,
                     const std::function<void()> &stop);
        /** \brief Another rank's side: claim when the solve returns, stop when the outcome arrives. */
        void play(const std::function<bool()> &returned, const std::function<std::string()> &claim,
                  const std::function<void()> &stop);

        const MpiSession &session_;
        int winner_{-1}, failed_{-1};
        std::vector<Claim> claims_;
        std::chrono::steady_clock::time_point start_;
    };
}  // namespace ompl_parc::tools

#endif
