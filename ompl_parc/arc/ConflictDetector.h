#ifndef OMPL_PARC_CONFLICT_DETECTOR_
#define OMPL_PARC_CONFLICT_DETECTOR_

#include "ompl_parc/arc/Conflict.h"
#include "ompl_parc/collision/BoundingBox.h"
#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotSpaceInformation.h"
#include "ompl_parc/robots/DiscRobot.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

namespace ompl_parc
{
    /** \brief Finds robot-robot conflicts in a plan, remembering per robot pair how far it is known to be
        conflict-free (the validated frontier) so that later scans resume there.

        Only the pairs that may meet are tracked, so that memory and work grow with the team and its encounters,
        not with the team's square (20 000 robots have 2e8 pairs; well-separated ones meet a few neighbours each).
        discoverPairs() finds them with a broad phase over time: each robot's path is cut into reach segments of L
        timesteps ([kL, (k+1)L), L a power of two times H chosen at the first discovery so that the plan spans
        about REACH_SEGMENTS of them) and each segment gets the box around the robot's bodies there (after its
        arrival a robot keeps the box of its final body). Two robots whose boxes are disjoint in every segment never
        meet: their pair is conflict-free to its end and is not tracked. A robot invalidated or restarted is
        discovered again from the segment of its change on (the rest of its path, and so its untracked pairs' proof,
        is unchanged). Tracked pairs keep their index until reset().

        A tracked pair (i, j) needs checking at timesteps 0..max(arrival i, arrival j); after that neither moves.
        Robots hold their goal after arriving. When a robot's path is patched from timestep t on,
        invalidate(robot, t) pulls the frontier of each of its pairs back to at most t. scan() examines a
        subset of pairs over a range of timesteps and is the building block of both the sequential
        earliest-conflict search (ARC) and the per-worker scans of P-ARC; it only reads the plan and the
        frontiers of its own pairs, so disjoint pair subsets can be scanned concurrently (discovery cannot: the
        coordinator runs it before the scans).

        Pairs of discs need no further broad phase: their scan works on the plan's straight pieces (DiscPairScan),
        at a cost per piece. For the other kinds, the scan's broad phase is over time too: each robot's path is cut
        into segments of H timesteps ([kH, (k+1)H)), and each segment gets a swept bound, the axis-aligned box
        around the robot's bodies at all its timesteps. A pair whose two boxes of
        a segment are disjoint cannot collide anywhere in it, so the scan advances that pair's frontier
        past the segment without per-timestep checks; the conflicts found are exactly those of the full
        scan. Swept bounds are computed lazily, per robot under that robot's mutex, by the first scan that
        needs them, so concurrent scans of disjoint pair subsets (P-ARC's workers) may share robots;
        invalidate() (called by the coordinator between scans, as for the frontiers) discards the bounds
        of the segments from the changed timestep on.

        Every loop that can run long polls StopSignal: a scan, or a discovery, interrupted by the planning's stop
        leaves what it has not checked unchecked (frontiers never pass an unchecked timestep). */
    class ConflictDetector
    {
      public:
        /** \brief Detector for the team of \e si with swept bounds over \e segmentLength timesteps (0:
            no broad phase in the scan, every timestep of every tracked pair is checked). */
        explicit ConflictDetector(const MultiRobotSpaceInformation &si,
                                  std::size_t segmentLength = DEFAULT_SEGMENT_LENGTH);

        /** \brief Default H: long enough to make the box test rare, short enough for tight boxes. */
        static constexpr std::size_t DEFAULT_SEGMENT_LENGTH = 64;

        /** \brief About how many reach segments the plan of a discovery after reset() spans: few enough that a
            robot's boxes stay small (a few KB), enough that robots crossing the same place at different times
            stay apart. */
        static constexpr std::size_t REACH_SEGMENTS = 32;

        /** \brief Change H (0 disables the scan's broad phase); drops all swept bounds. Not during a scan. */
        void setSegmentLength(std::size_t segmentLength);
        std::size_t getSegmentLength() const { return segmentLength_; }

        /** \brief Forget every plan scanned so far: no tracked pair (every robot to be discovered from timestep 0),
            no known conflict, no swept bounds. Keeps the memory (a new query on the same team faults in no fresh
            pages). Not during a scan. */
        void reset();

        /** \brief The team this detector is for (a RepairLoop checks that its problem's team is the same). */
        const MultiRobotSpaceInformation &getSpaceInformation() const { return si_; }

        /** \brief Track the pairs of \e plan that may meet since the last discovery (see the class documentation):
            new pairs get the next indices, with their frontier at the earliest change of their two robots (0 for
            robots never discovered). False if the planning stopped (StopSignal) first: the robots not yet done
            stay to be discovered, and no scan may call the plan conflict-free. Not during a scan. */
        bool discoverPairs(const MultiRobotPlan &plan);

        /** \brief The earliest conflict of \e plan over all pairs, ties broken by (first, second); none if
            the plan is conflict-free, or if the planning stopped (StopSignal) first (the caller checks its
            termination condition). Discovers pairs, and advances the frontiers of the pairs it validates. */
        std::optional<Conflict> findEarliest(const MultiRobotPlan &plan);

        /** \brief Which pairs a scan leaves out: skip(i, j) true means pair (i, j) is not checked. */
        using PairFilter = std::function<bool(std::size_t, std::size_t)>;

        /** \brief Scan \e pairs (indices of tracked pairs, see discoverPairs()) at timesteps [from, to) in time
            order, checking at each timestep every pair whose frontier has reached it. With \e firstTimestepOnly
            (ARC) it stops at the first timestep with a conflict and returns all conflicts there; otherwise (a P-ARC
            worker) each pair is scanned to its own first conflict or to \e to, and all those first conflicts are
            returned in (timestep, pair) order. Pairs \e skip rejects are not checked, nor pairs whose frontier is
            before \e from (they stop at a known conflict). Frontiers of checked pairs advance to their first
            unchecked or conflicting timestep: a frontier never passes an unchecked or conflicting timestep. When
            the planning stops (StopSignal) the scan returns early with what it found.

            Pairs of two discs (DiscRobot) are scanned from the plan's pieces (DiscPairScan), straight to their
            first conflict or their end, also past \e to: their frontiers may end up beyond \e to, and a conflict
            found there is left for the scan whose range holds it. \e resume, if given, receives the earliest
            timestep that a pair this scan considered (not skipped, frontier not before \e from) still needs
            checked, or SIZE_MAX: a later scan of the same pairs may start there instead of at \e to, as nothing
            between needs checking. */
        std::vector<Conflict> scan(const MultiRobotPlan &plan, const std::vector<std::size_t> &pairs, std::size_t from,
                                   std::size_t to, bool firstTimestepOnly, const PairFilter &skip = {},
                                   std::size_t *resume = nullptr);

        /** \brief Robot \e robot's path changed from timestep \e timestep on: pulls back the frontiers of
            its pairs, drops its swept bounds from the segment of \e timestep on, and has the next discoverPairs()
            look for its new pairs from there. Not during a scan. */
        void invalidate(std::size_t robot, std::size_t timestep);

        /** \brief The caller knows that \e robot's pairs are conflict-free before timestep \e timestep (a plan known
            to be conflict-free whose path of \e robot is about to change, or changed back, from \e timestep on):
            sets the frontier of each of its tracked pairs to exactly \e timestep, forgetting known conflicts, drops
            its swept bounds from the segment of \e timestep on, and the pairs the next discoverPairs() finds for it
            start at \e timestep. Unlike invalidate(), it may move frontiers forward: a smoother trying a change of
            one robot's path scans only from the change. Not during a scan. */
        void restart(std::size_t robot, std::size_t timestep);

        /** \brief True if pair \e pair (a tracked pair's index) is known conflict-free to its end in \e plan. */
        bool isSettled(const MultiRobotPlan &plan, std::size_t pair) const
        {
            return frontier_[pair] >
                   std::max(plan.getArrival(pairs_[pair].first), plan.getArrival(pairs_[pair].second));
        }

        std::size_t getRobotCount() const { return robots_; }

        /** \brief First timestep of pair (i, j), i < j, not yet known to be conflict-free; 0 for a pair not
            tracked (nothing is recorded for it: after a complete discovery it never meets). */
        std::size_t getFrontier(std::size_t i, std::size_t j) const;

        /** \brief The index of the tracked pair (i, j), i < j, if it is tracked. */
        std::optional<std::size_t> findPair(std::size_t i, std::size_t j) const;

        /** \brief How many pairs are tracked: their indices are 0 .. getPairCount() - 1. */
        std::size_t getPairCount() const { return pairs_.size(); }
        const std::pair<std::size_t, std::size_t> &getPair(std::size_t index) const { return pairs_[index]; }

        /** \brief The indices of robot \e robot's tracked pairs. */
        const std::vector<std::size_t> &getPairsOf(std::size_t robot) const { return robotPairs_[robot]; }

      private:
        /** \brief One robot's swept bounds: \e segments[k] is valid for k < \e valid; \e finalBox (the
            body at arrival, used past the last segment) and the segment count while \e current. */
        struct SweptBounds
        {
            std::vector<BoundingBox> segments;
            BoundingBox finalBox;
            std::size_t valid{0};
            bool current{false};
        };

        /** \brief Robot \e robot's swept bounds, computed up to segment \e last if missing (thread safe). */
        const SweptBounds &sweptBounds(const MultiRobotPlan &plan, std::size_t robot, std::size_t last,
                                       CollisionBody &scratch);

        /** \brief The box around robot \e robot's bodies at timesteps [from, to) of \e plan (from the pieces for
            kinds that bound their body from a box of configurations, else body by body); \e work is scratch. */
        BoundingBox boxOver(const MultiRobotPlan &plan, std::size_t robot, std::size_t from, std::size_t to,
                            CollisionBody &scratch, std::vector<double> &work) const;

        /** \brief Robot \e robot's bounds at segment \e segment (the final box past its last segment). */
        static const BoundingBox &boxAt(const SweptBounds &bounds, std::size_t segment)
        {
            return segment < bounds.segments.size() ? bounds.segments[segment] : bounds.finalBox;
        }

        /** \brief Recompute robot \e robot's reach segments from segment \e first on, and its hull. */
        void computeReach(const MultiRobotPlan &plan, std::size_t robot, std::size_t first, CollisionBody &scratch,
                          std::vector<double> &work);

        /** \brief Track pair (i, j) unless it is (see discoverPairs() for its frontier). */
        void trackPair(std::size_t i, std::size_t j);

        /** \brief Discovery by one sweep along x per reach segment over the whole team (many robots changed). */
        bool sweepAll(std::size_t firstSegment);

        /** \brief Discovery by testing each of the robots \e changed against every robot (a few changed). */
        bool testEach(const std::vector<std::size_t> &changed);

        /** \brief Pair key for the index map. */
        std::uint64_t key(std::size_t i, std::size_t j) const { return static_cast<std::uint64_t>(i) * robots_ + j; }

        const MultiRobotSpaceInformation &si_;
        std::size_t segmentLength_;
        std::vector<SweptBounds> swept_;
        /** \brief Per robot, the DiscRobot it is, or null: pairs of two discs are scanned piece by piece. */
        std::vector<const DiscRobot *> discs_;
        std::unique_ptr<std::mutex[]> sweptMutex_;
        std::size_t robots_;

        /** \brief Reach segment length L (0: chosen at the next discovery) and, per robot, its reach boxes (as
            SweptBounds, all valid) and their hull (the box test before the segments'). */
        std::size_t reachLength_{0};
        std::vector<SweptBounds> reach_;
        std::vector<BoundingBox> hull_;
        /** \brief Per robot, the first timestep from which its pairs are to be discovered (NONE: discovered). */
        std::vector<std::size_t> changedFrom_;
        static constexpr std::size_t NONE = std::numeric_limits<std::size_t>::max();

        std::vector<std::size_t> frontier_;
        /** \brief Per pair, 1 if its frontier is a conflict a scan found (reported again without a check until an
            invalidation reaches it); char, not bool, so that workers write their own pairs' entries safely. */
        std::vector<char> knownConflict_;
        std::vector<std::pair<std::size_t, std::size_t>> pairs_;
        std::unordered_map<std::uint64_t, std::size_t> pairIndex_;
        std::vector<std::vector<std::size_t>> robotPairs_;
        /** \brief Every pair index, for findEarliest(). */
        std::vector<std::size_t> allPairs_;
    };
}  // namespace ompl_parc

#endif
