#ifndef OMPL_PARC_CONFLICT_BATCH_
#define OMPL_PARC_CONFLICT_BATCH_

#include "ompl_parc/arc/Conflict.h"

#include <vector>

namespace ompl_parc
{
    /** \brief A conflict of a batch with its robot set R(c) (the conflict's robots grown by the repair cache). */
    struct BatchEntry
    {
        Conflict conflict;
        std::vector<std::size_t> team;
    };

    /** \brief P-ARC's batch of robot-disjoint conflicts to repair concurrently, built from conflicts offered
        in temporal order (paper §III-B).

        Strict mode accepts only \b independent conflicts: c is accepted iff no earlier offered conflict
        shares a robot with R(c). Optimistic mode (the default) also accepts \b optimistically independent
        ones: c is accepted iff R(c) is disjoint from the batch and every earlier conflict c' that shares
        robots with R(c) is explained, i.e. each robot of R(c') outside the shared set was already in the
        batch when c' occurred (the batch repair will desynchronise it, likely removing c'). A deferred
        conflict is remembered with its unexplained robots, so the definition applies recursively.

        skipPair() tells the detectors which pairs need no more checks in this batch: optimistic, pairs with a
        robot in the batch (their conflicts could never be accepted and never block a later one); strict,
        pairs whose two robots are both already involved in an offered conflict. */
    class ConflictBatch
    {
      public:
        /** \brief \e capacity: the batch is full at this many conflicts (W in the paper; W x batch_per_worker in
            P-ARC, 1 for ARC); \e robots: team size. */
        ConflictBatch(bool optimistic, std::size_t capacity, std::size_t robots);

        /** \brief Offer the next conflict in temporal order with its robot set; true if accepted. */
        bool offer(const Conflict &conflict, std::vector<std::size_t> team);

        bool full() const { return entries_.size() >= capacity_; }
        const std::vector<BatchEntry> &getEntries() const { return entries_; }
        bool skipPair(std::size_t i, std::size_t j) const;

      private:
        bool optimistic_;
        std::size_t capacity_;
        std::vector<BatchEntry> entries_;
        /** \brief Robots in the batch; robots involved in any offered conflict (strict mode). */
        std::vector<char> inBatch_, involved_;
        /** \brief Deferred conflicts' robots that were not in the batch when they occurred (optimistic). */
        std::vector<std::vector<std::size_t>> unexplained_;
    };
}  // namespace ompl_parc

#endif
