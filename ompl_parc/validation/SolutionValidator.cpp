#include "ompl_parc/validation/SolutionValidator.h"

#include "ompl_parc/parallel/WorkerPool.h"
#include "ompl_parc/validation/BoxOverlaps.h"
#include "ompl_parc/validation/FclBodies.h"
#include "ompl_parc/validation/LinearMotion.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace
{
    using ompl_parc::LinearMotion;

    /** Timesteps per block of the broad phase: long enough to amortise sorting the team, short enough that a
        robot's box stays tight. */
    constexpr std::size_t BLOCK = 64;
    /** Blocks per round: bounds the memory of the boxes and lets an early violation end the check. */
    constexpr std::size_t ROUND = 256;

    /** \brief The seam to the plan: the one place that reads its configurations. Robot \e robot's motion as
        breakpoints, holding its last state from its arrival to \e makespan: the plan's own breakpoints (between
        consecutive ones a robot moves on a straight line, uniformly in time), read back through getConfig() at
        those timesteps; pieces that continue each other's line merge. */
    LinearMotion readMotion(const ompl_parc::MultiRobotPlan &plan, std::size_t robot, std::size_t makespan)
    {
        LinearMotion motion(plan.getDimension(robot));
        const std::size_t arrival = plan.getArrival(robot);
        std::vector<std::size_t> times;
        plan.getPath(robot).appendBreakpoints(times);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        std::vector<double> q(plan.getDimension(robot));
        ompl_parc::TimedPath::Cursor cursor(plan.getPath(robot));  // increasing times: no search per breakpoint
        for (std::size_t t : times)
        {
            if (t > arrival)
                break;
            cursor.get(t, q.data());
            motion.addBreakpoint(t, q.data());
        }
        if (makespan > arrival)
            motion.addBreakpoint(makespan, q.data());
        return motion;
    }

    /** What a violation is, in the order the old per-sample check reported them at one time. */
    enum class Kind
    {
        BOUNDS,
        OBSTACLE,
        SELF,
        PAIR
    };

    /** A violation: robot \e a out of bounds, robot \e a hitting obstacle \e b, robot \e a in self-collision
        (links \e b and \e c), robots \e a < \e b colliding; at a timestep or at a sample between timesteps. */
    struct Event
    {
        double time;
        bool substep;
        Kind kind;
        std::size_t a, b, c;

        bool operator<(const Event &other) const
        {
            return std::tie(time, substep, kind, a, b, c) <
                   std::tie(other.time, other.substep, other.kind, other.a, other.b, other.c);
        }
    };

    /** A test the broad phase could not rule out: \e kind between robot \e a and robot or obstacle \e b
        (unused for SELF) over one block. */
    struct Candidate
    {
        std::size_t block;
        Kind kind;
        std::size_t a, b;
    };

    using Box = ompl_parc::AxisBox;

    /** The collision part of the check: the broad phase over blocks of time and the narrow phase over what
        it leaves, on a WorkerPool. */
    class TimeSweep
    {
      public:
        TimeSweep(const ompl_parc::MultiRobotSpaceInformation &si, const ompl_parc::ValidationOptions &options,
                  const std::vector<ompl_parc::DisplacementBound> &displacement,
                  const std::vector<LinearMotion> &motions, std::size_t makespan)
            : si_(si),
              options_(options),
              displacement_(displacement),
              motions_(motions),
              makespan_(makespan),
              n_(motions.size()),
              pool_(options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency()))
        {
            std::vector<ompl_parc::CollisionBody> templates(n_);
            for (std::size_t i = 0; i < n_; ++i)
            {
                si.getRobot(i)->computeBody(motions[i].getFirst(), templates[i]);
                // States merged into pieces may be MERGE_TOLERANCE off the piece: pad every radius by the move.
                const std::vector<double> merge(motions[i].getDimension(), 2. * LinearMotion::MERGE_TOLERANCE);
                pad_.push_back(displacement[i](merge.data()));
                // Growth a sample may take before it exceeds the timestep radius (then the samples at the
                // interval's ends are needed, too).
                double margin = std::numeric_limits<double>::infinity();
                for (double r : templates[i].radius_)
                    margin = std::min(margin, std::max(r - options.contactTolerance, MIN_RADIUS) -
                                                  std::max(r - options.substepSlack, MIN_RADIUS));
                margin_.push_back(margin);
                capsules_.push_back(templates[i].size());
                // Per piece, the displacement bound of one timestep on it.
                const LinearMotion &motion = motions[i];
                std::vector<double> dq(motion.getDimension());
                steps_.emplace_back(motion.getPieceCount());
                capsuleSteps_.emplace_back(motion.getPieceCount(), std::vector<double>(templates[i].size()));
                for (std::size_t p = 0; p < motion.getPieceCount(); ++p)
                {
                    const auto duration = static_cast<double>(motion.getEndTime(p) - motion.getStartTime(p));
                    for (unsigned int d = 0; d < motion.getDimension(); ++d)
                        dq[d] = motion.getEnd(p)[d] - motion.getStart(p)[d];
                    steps_[i][p] = displacement[i](dq.data()) / duration;
                    for (std::size_t k = 0; k < templates[i].size(); ++k)
                        capsuleSteps_[i][p][k] = displacement[i].capsuleBound(k, dq.data()) / duration;
                }
                sphere_.push_back(displacement[i].isTranslation() && templates[i].size() == 1 &&
                                          templates[i].ax_[0] == templates[i].bx_[0] &&
                                          templates[i].ay_[0] == templates[i].by_[0] &&
                                          templates[i].az_[0] == templates[i].bz_[0]
                                      ? templates[i].radius_[0]
                                      : -1.);
            }
            for (unsigned int w = 0; w < pool_.getWorkerCount(); ++w)
                workers_.push_back(std::make_unique<Worker>(si, templates));
            listEventfulBlocks();
            for (std::size_t o = 0; o < workers_[0]->fcl.getObstacleCount(); ++o)
            {
                const auto &b = workers_[0]->fcl.getObstacleBox(o);
                obstacleBoxes_.push_back(
                    Box{{b.min().x(), b.min().y(), b.min().z()}, {b.max().x(), b.max().y(), b.max().z()}});
            }
        }

        /** The earliest collision at a time before \e limit, if any; counts narrow-phase configurations. */
        std::optional<Event> run(double limit, std::size_t &checked)
        {
            const std::size_t blocks = eventful_.size();
            std::optional<Event> best;
            for (std::size_t first = 0;
                 first < blocks && !best && static_cast<double>(blockStart(eventful_[first])) <= limit; first += ROUND)
            {
                const std::size_t count = std::min(ROUND, blocks - first);
                std::vector<Candidate> candidates = collectCandidates(&eventful_[first], count);
                std::atomic<std::size_t> next{0};
                pool_.run(
                    [&](unsigned int w)
                    {
                        Worker &worker = *workers_[w];
                        for (std::size_t k = next++; k < candidates.size(); k = next++)
                        {
                            const auto event = check(candidates[k], worker);
                            if (event && (!worker.best || *event < *worker.best))
                                worker.best = event;
                        }
                    });
                for (auto &worker : workers_)
                {
                    if (worker->best && (!best || *worker->best < *best))
                        best = worker->best;
                    checked += worker->checked;
                    worker->checked = 0;
                }
            }
            return best;
        }

      private:
        static constexpr double MIN_RADIUS = ompl_parc::FclBodies::MIN_RADIUS;
        static constexpr double INF = std::numeric_limits<double>::infinity();

        struct Worker
        {
            Worker(const ompl_parc::MultiRobotSpaceInformation &si,
                   const std::vector<ompl_parc::CollisionBody> &templates)
                : fcl(si, templates)
            {
            }
            ompl_parc::FclBodies fcl;
            ompl_parc::CollisionBody body;
            std::vector<double> q;
            /** One block's robot boxes and activity (collectCandidates()). */
            std::vector<Box> blockBoxes;
            std::vector<char> blockActive;
            /** The grid of the robot-robot broad phase (its scratch reused block after block). */
            ompl_parc::BoxOverlaps overlaps;
            /** Scratch of mayTouch(): per capsule of the candidate's robots, its box over one interval, and whether
                the narrow phase needs it; the growth of each capsule between timesteps. */
            std::vector<Box> boxesA, boxesB;
            std::vector<char> maskA, maskB;
            ompl_parc::CollisionBody bodyA, bodyB;
            std::vector<double> growA, growB;
            /** Scratch: the growth per capsule of the placement at hand (the pad at a timestep; for intervalClear(),
                the interval's largest growth plus the whole step). */
            std::vector<double> grow;
            std::size_t checked{0};
            std::optional<Event> best;
        };

        std::size_t blockStart(std::size_t block) const { return block * BLOCK; }
        std::size_t blockEnd(std::size_t block) const { return std::min(makespan_, (block + 1) * BLOCK); }

        /** The blocks in which some robot moves (or moved in the interval before), and block 0: in every other
            block no robot is active, so it has nothing to test (everything there was tested at the timestep
            before it). Skipping them makes the check's time follow the pieces, not the makespan: a robot that
            waits for a million timesteps costs one piece. */
        void listEventfulBlocks()
        {
            // Per moving piece its blocks (and the next one) as an interval; merged, so that the cost follows the
            // pieces and the blocks listed, not pieces times their blocks (Mobile Cross 4096: 168 million).
            const std::size_t blocks = (std::max<std::size_t>(makespan_, 1) + BLOCK - 1) / BLOCK;
            std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, 0}};
            for (const LinearMotion &motion : motions_)
                for (std::size_t p = 0; p < motion.getPieceCount(); ++p)
                    if (!motion.isStill(p))
                        spans.emplace_back(motion.getStartTime(p) / BLOCK,
                                           std::min(motion.getEndTime(p) / BLOCK + 1, blocks - 1));
            std::sort(spans.begin(), spans.end());
            eventful_.clear();
            for (const auto &[first, last] : spans)
                for (std::size_t k = eventful_.empty() ? first : std::max(first, eventful_.back() + 1); k <= last; ++k)
                    eventful_.push_back(k);
        }

        void computeBox(std::size_t i, std::size_t block, Worker &worker, Box &box, char &active) const
        {
            const LinearMotion &motion = motions_[i];
            const auto &robot = *si_.getRobot(i);
            const std::size_t b0 = blockStart(block), b1 = blockEnd(block);
            box.lo.fill(std::numeric_limits<double>::infinity());
            box.hi.fill(-std::numeric_limits<double>::infinity());
            worker.q.resize(motion.getDimension());
            double grow = 0.;
            active = block == 0;
            const auto add = [&](std::size_t piece, std::size_t t)
            {
                motion.interpolate(piece, static_cast<double>(t), worker.q.data());
                if (sphere_[i] >= 0.)  // a disc: its sphere's box, without a body
                {
                    const double centre[3] = {worker.q[0], worker.q[1], 0.};
                    for (int d = 0; d < 3; ++d)
                    {
                        box.lo[d] = std::min(box.lo[d], centre[d] - sphere_[i]);
                        box.hi[d] = std::max(box.hi[d], centre[d] + sphere_[i]);
                    }
                    return;
                }
                robot.computeCapsules(worker.q.data(), worker.body);
                worker.body.expandBox(box.lo, box.hi);
            };
            if (motion.getPieceCount() == 0)  // a plan of one timestep
                add(0, 0);
            // The pieces over [b0 - 1, b1]: the interval before the block only decides whether the robot is active.
            for (std::size_t p = motion.findPiece(b0 == 0 ? 0.5 : b0 - 0.5);
                 p < motion.getPieceCount() && motion.getStartTime(p) < b1; ++p)
            {
                const bool still = motion.isStill(p);
                active = active || !still;
                if (motion.getEndTime(p) <= b0)
                    continue;
                const std::size_t ta = std::max(b0, motion.getStartTime(p)), tb = std::min(b1, motion.getEndTime(p));
                if (still || displacement_[i].isTranslation())
                {
                    // A translation's swept body over a straight piece is the hull of its end bodies.
                    add(p, ta);
                    add(p, tb);
                }
                else
                {
                    // Between timesteps every body point stays within half a step's displacement of one end.
                    for (std::size_t t = ta; t <= tb; ++t)
                        add(p, t);
                    grow = std::max(grow, 0.5 * steps_[i][p]);
                }
            }
            for (int d = 0; d < 3; ++d)
            {
                box.lo[d] -= grow + pad_[i];
                box.hi[d] += grow + pad_[i];
            }
        }

        /** Tests the boxes leave for the round's blocks: robot-obstacle, self and robot-robot (BoxOverlaps), each
            only if a robot in it is active. Per block, first each robot's box around its body at every instant of
            the block and whether it moves in the block or in the interval before (if not, every test of its was
            done before), in the worker's own buffer (the round's boxes of thousands of robots would not stay in
            cache between two passes). */
        std::vector<Candidate> collectCandidates(const std::size_t *blocks, std::size_t count)
        {
            std::vector<std::vector<Candidate>> found(pool_.getWorkerCount());
            pool_.run(
                [&](unsigned int w)
                {
                    Worker &worker = *workers_[w];
                    for (std::size_t k = w; k < count; k += pool_.getWorkerCount())
                    {
                        worker.blockBoxes.assign(n_, Box());
                        worker.blockActive.assign(n_, 0);
                        for (std::size_t i = 0; i < n_; ++i)
                            computeBox(i, blocks[k], worker, worker.blockBoxes[i], worker.blockActive[i]);
                        const Box *boxes = worker.blockBoxes.data();
                        const char *active = worker.blockActive.data();
                        for (std::size_t i = 0; i < n_; ++i)
                        {
                            if (!active[i])
                                continue;
                            for (std::size_t o = 0; o < obstacleBoxes_.size(); ++o)
                                if (boxes[i].overlaps(obstacleBoxes_[o]))
                                    found[w].push_back({blocks[k], Kind::OBSTACLE, i, o});
                            if (!si_.getRobot(i)->getSelfCollisionPairs().empty())
                                found[w].push_back({blocks[k], Kind::SELF, i, i});
                        }
                        worker.overlaps.find(boxes, active, n_,
                                             [&](std::size_t i, std::size_t j) {
                                                 found[w].push_back({blocks[k], Kind::PAIR, i, j});
                                             });
                    }
                });
            std::vector<Candidate> all;
            for (const auto &f : found)
                all.insert(all.end(), f.begin(), f.end());
            return all;
        }

        /** The earliest violation of one candidate in its block: its pieces' spans in turn (a disc's swept test
            may clear one whole), then the last timestep of the plan. */
        std::optional<Event> check(const Candidate &c, Worker &worker) const
        {
            const std::size_t b0 = blockStart(c.block), b1 = blockEnd(c.block);
            const bool pair = c.kind == Kind::PAIR;
            for (std::size_t ta = b0; ta < b1;)
            {
                const double middle = static_cast<double>(ta) + 0.5;
                const std::size_t pa = motions_[c.a].findPiece(middle);
                const std::size_t pb = pair ? motions_[c.b].findPiece(middle) : 0;
                std::size_t tb = std::min(b1, motions_[c.a].getEndTime(pa));
                if (pair)
                    tb = std::min(tb, motions_[c.b].getEndTime(pb));
                if (!sweptClear(c, ta, tb, pa, pb, worker))
                    if (auto event = checkSpan(c, ta, tb, pa, pb, worker))
                        return event;
                ta = tb;
            }
            if (b1 == makespan_)
            {
                const auto end = static_cast<double>(b1);
                selectAll(c, worker);
                return checkSample(c, end, false, motions_[c.a].findPiece(end), pair ? motions_[c.b].findPiece(end) : 0,
                                   worker);
            }
            return std::nullopt;
        }

        /** A disc on a straight piece: true if its whole swept motion over [ta, tb] clears the obstacle or the
            other disc (full radii: more than any check below uses). */
        bool sweptClear(const Candidate &c, std::size_t ta, std::size_t tb, std::size_t pa, std::size_t pb,
                        Worker &worker) const
        {
            if (c.kind == Kind::SELF || sphere_[c.a] < 0. || (c.kind == Kind::PAIR && sphere_[c.b] < 0.))
                return false;
            const auto centre = [&](std::size_t robot, std::size_t piece, std::size_t t)
            {
                double q[2];
                motions_[robot].interpolate(piece, static_cast<double>(t), q);
                return Eigen::Vector3d(q[0], q[1], 0.);
            };
            if (c.kind == Kind::OBSTACLE)
                return !worker.fcl.sweptSphereHitsObstacle(centre(c.a, pa, ta), centre(c.a, pa, tb),
                                                           sphere_[c.a] + pad_[c.a], c.b);
            // Both move linearly over [ta, tb]: their difference runs along a segment; its closest approach to 0.
            const Eigen::Vector3d e0 = centre(c.a, pa, ta) - centre(c.b, pb, ta);
            const Eigen::Vector3d de = centre(c.a, pa, tb) - centre(c.b, pb, tb) - e0;
            const double s = de.squaredNorm() > 0. ? std::clamp(-e0.dot(de) / de.squaredNorm(), 0., 1.) : 0.;
            return (e0 + s * de).norm() > sphere_[c.a] + sphere_[c.b] + pad_[c.a] + pad_[c.b] + 1e-12;
        }

        /** Timesteps ta .. tb - 1 and the intervals after them, on pieces \e pa (and \e pb). */
        std::optional<Event> checkSpan(const Candidate &c, std::size_t ta, std::size_t tb, std::size_t pa,
                                       std::size_t pb, Worker &worker) const
        {
            const bool pair = c.kind == Kind::PAIR;
            const LinearMotion &ma = motions_[c.a];
            const bool still = (ma.getPieceCount() == 0 || ma.isStill(pa)) &&
                               (!pair || motions_[c.b].getPieceCount() == 0 || motions_[c.b].isStill(pb));
            if (still)  // nothing moves: one timestep stands for the whole span
            {
                selectAll(c, worker);
                return checkSample(c, static_cast<double>(ta), false, pa, pb, worker);
            }
            const double da = steps_[c.a][pa], db = pair ? steps_[c.b][pb] : 0.;
            // Displacement of one body relative to the other over a timestep. Two links of one arm move relative
            // to each other only by the joints between them, which da bounds: each side takes half the growth.
            const double total = pair ? da + db : da;
            // The growths (ga + gb, or twice ga for self) add up to total/2m at most: within half the slack.
            const auto m = static_cast<unsigned int>(
                std::max<double>(options_.substeps, std::ceil(total / options_.substepSlack)));
            const double ga = da / ((c.kind == Kind::SELF ? 4. : 2.) * m), gb = db / (2. * m);
            const bool ends = ga > margin_[c.a] || (pair && gb > margin_[c.b]);
            // Between timesteps each capsule grows by its own displacement to the nearest sample (at most ga, gb);
            // for self-collision every capsule takes half the relative displacement's share.
            fillGrowth(c.a, pa, c.kind == Kind::SELF ? ga : -1., 2. * m, worker.growA);
            if (pair)
                fillGrowth(c.b, pb, -1., 2. * m, worker.growB);
            for (std::size_t t = ta; t < tb; ++t)
            {
                if (!mayTouch(c, t, pa, pb, worker))
                    continue;
                // A capsule that does not move on the piece (an arm's base) against an obstacle: its test at the
                // span's first timestep stands for the span, every later sample being that configuration, tested
                // with radii no larger.
                if (c.kind == Kind::OBSTACLE && t > ta && !dropStill(c.a, pa, worker.maskA))
                    continue;
                if (intervalClear(c, pa, pb, worker))
                    continue;
                if (auto event = checkSample(c, static_cast<double>(t), false, pa, pb, worker))
                    return event;
                for (unsigned int j = ends ? 0 : 1; j <= (ends ? m : m - 1); ++j)
                {
                    const double u = static_cast<double>(t) + static_cast<double>(j) / m;
                    if (auto event = checkSample(c, u, true, pa, pb, worker))
                        return event;
                }
            }
            return std::nullopt;
        }

        /** One FCL test for the interval [t, t + 1] mayTouch() just boxed: the selected capsules at t (the bodies it
            left in worker.bodyA, bodyB), each with the largest radius any sample of the interval gives it, grown by
            its displacement bound of the whole step. Every capsule of every sample in the interval lies inside
            these, so if they touch nothing, no sample can (most intervals whose boxes meet, in arm teams: one test
            instead of one per sample). */
        bool intervalClear(const Candidate &c, std::size_t pa, std::size_t pb, Worker &worker) const
        {
            const auto place = [&](std::size_t robot, std::size_t piece, const ompl_parc::CollisionBody &body,
                                   const std::vector<double> &grow, const std::vector<char> &mask)
            {
                worker.grow.resize(body.size());
                for (std::size_t k = 0; k < body.size(); ++k)
                    worker.grow[k] = std::max(pad_[robot], grow[k]) + capsuleSteps_[robot][piece][k];
                worker.fcl.place(robot, body, options_.contactTolerance, worker.grow, mask);
                ++worker.checked;
            };
            place(c.a, pa, worker.bodyA, worker.growA, worker.maskA);
            switch (c.kind)
            {
                case Kind::OBSTACLE:
                    return !worker.fcl.hitsObstacle(c.a, c.b, worker.maskA);
                case Kind::SELF:
                {
                    std::pair<std::size_t, std::size_t> links;
                    return !worker.fcl.selfCollides(c.a, links, worker.maskA);
                }
                case Kind::PAIR:
                    place(c.b, pb, worker.bodyB, worker.growB, worker.maskB);
                    return !worker.fcl.robotsCollide(c.a, c.b, worker.maskA, worker.maskB);
                case Kind::BOUNDS:
                    break;
            }
            return false;
        }

        /** \e grow: per capsule of \e robot, \e uniform if not negative, else its displacement bound of one
            timestep on \e piece over \e divisor; plus the pad. */
        void fillGrowth(std::size_t robot, std::size_t piece, double uniform, double divisor,
                        std::vector<double> &grow) const
        {
            const std::vector<double> &steps = capsuleSteps_[robot][piece];
            grow.resize(steps.size());
            for (std::size_t k = 0; k < steps.size(); ++k)
                grow[k] = (uniform >= 0. ? uniform : steps[k] / divisor) + pad_[robot];
        }

        /** Clears the capsules of \e mask that do not move on \e piece; false if none is left. */
        bool dropStill(std::size_t robot, std::size_t piece, std::vector<char> &mask) const
        {
            bool any = false;
            for (std::size_t k = 0; k < mask.size(); ++k)
            {
                mask[k] = mask[k] && capsuleSteps_[robot][piece][k] > 0.;
                any = any || mask[k];
            }
            return any;
        }

        /** Every capsule of the candidate's robots selected: for the samples no mayTouch() ran for. */
        void selectAll(const Candidate &c, Worker &worker) const
        {
            worker.maskA.assign(capsules_[c.a], 1);
            if (c.kind == Kind::PAIR)
                worker.maskB.assign(capsules_[c.b], 1);
        }

        /** The broad phase of one timestep and the interval after it, capsule by capsule: per capsule a box around
            it at t and t + 1 grown by half its displacement bound of a step and the pad (every point of a capsule
            stays within half a step's displacement of where it is at one end), against the other robot's capsules,
            the obstacle's box, or for self-collision the capsule's pairs. Selects in worker.maskA (maskB) the
            capsules whose boxes meet; false if there are none. */
        bool mayTouch(const Candidate &c, std::size_t t, std::size_t pa, std::size_t pb, Worker &worker) const
        {
            sweptCapsuleBoxes(c.a, pa, t, worker, worker.boxesA, worker.bodyA);
            const std::vector<Box> &a = worker.boxesA;
            std::vector<char> &maskA = worker.maskA;
            maskA.assign(a.size(), 0);
            bool any = false;
            switch (c.kind)
            {
                case Kind::PAIR:
                {
                    sweptCapsuleBoxes(c.b, pb, t, worker, worker.boxesB, worker.bodyB);
                    const std::vector<Box> &b = worker.boxesB;
                    worker.maskB.assign(b.size(), 0);
                    for (std::size_t p = 0; p < a.size(); ++p)
                        for (std::size_t q = 0; q < b.size(); ++q)
                            if (a[p].overlaps(b[q]))
                                maskA[p] = worker.maskB[q] = 1;
                    break;
                }
                case Kind::OBSTACLE:
                    for (std::size_t p = 0; p < a.size(); ++p)
                        maskA[p] = a[p].overlaps(obstacleBoxes_[c.b]);
                    break;
                case Kind::SELF:
                    for (const auto &pair : si_.getRobot(c.a)->getSelfCollisionPairs())
                        if (a[pair.first].overlaps(a[pair.second]))
                            maskA[pair.first] = maskA[pair.second] = 1;
                    break;
                case Kind::BOUNDS:
                    break;
            }
            for (char selected : maskA)
                any = any || selected != 0;
            return any;
        }

        /** Per capsule of \e robot on \e piece, the box of mayTouch() over [t, t + 1]; \e body: the body at t. */
        void sweptCapsuleBoxes(std::size_t robot, std::size_t piece, std::size_t t, Worker &worker,
                               std::vector<Box> &boxes, ompl_parc::CollisionBody &body) const
        {
            worker.q.resize(motions_[robot].getDimension());
            for (std::size_t u = t + 2; u-- > t;)  // t + 1, then t: the body at t stays
            {
                motions_[robot].interpolate(piece, static_cast<double>(u), worker.q.data());
                si_.getRobot(robot)->computeCapsules(worker.q.data(), body);
                if (u == t + 1)
                    boxes.assign(body.size(), Box{{INF, INF, INF}, {-INF, -INF, -INF}});
                for (std::size_t k = 0; k < body.size(); ++k)
                {
                    const double r = body.radius_[k];
                    const std::array<double, 3> ends[2] = {{body.ax_[k], body.ay_[k], body.az_[k]},
                                                           {body.bx_[k], body.by_[k], body.bz_[k]}};
                    for (const auto &end : ends)
                        for (int d = 0; d < 3; ++d)
                        {
                            boxes[k].lo[d] = std::min(boxes[k].lo[d], end[d] - r);
                            boxes[k].hi[d] = std::max(boxes[k].hi[d], end[d] + r);
                        }
                }
            }
            for (std::size_t k = 0; k < boxes.size(); ++k)
            {
                const double grow = 0.5 * capsuleSteps_[robot][piece][k] + pad_[robot];
                for (int d = 0; d < 3; ++d)
                {
                    boxes[k].lo[d] -= grow;
                    boxes[k].hi[d] += grow;
                }
            }
        }

        /** FCL at time \e u on the capsules worker.maskA (maskB) selects: radii shrunk by the contact tolerance and
            grown by the pad at a timestep, shrunk by the slack and grown by worker.growA (growB) between
            timesteps. */
        std::optional<Event> checkSample(const Candidate &c, double u, bool substep, std::size_t pa, std::size_t pb,
                                         Worker &worker) const
        {
            const double shrink = substep ? options_.substepSlack : options_.contactTolerance;
            const auto place = [&](std::size_t robot, std::size_t piece, const std::vector<double> &grow,
                                   const std::vector<char> &mask)
            {
                worker.q.resize(motions_[robot].getDimension());
                motions_[robot].interpolate(piece, u, worker.q.data());
                si_.getRobot(robot)->computeCapsules(worker.q.data(), worker.body);
                if (!substep)
                    worker.grow.assign(worker.body.size(), pad_[robot]);
                worker.fcl.place(robot, worker.body, shrink, substep ? grow : worker.grow, mask);
                ++worker.checked;
            };
            place(c.a, pa, worker.growA, worker.maskA);
            std::pair<std::size_t, std::size_t> links{0, 0};
            bool hit = false;
            switch (c.kind)
            {
                case Kind::OBSTACLE:
                    hit = worker.fcl.hitsObstacle(c.a, c.b, worker.maskA);
                    break;
                case Kind::SELF:
                    hit = worker.fcl.selfCollides(c.a, links, worker.maskA);
                    break;
                case Kind::PAIR:
                    place(c.b, pb, worker.growB, worker.maskB);
                    hit = worker.fcl.robotsCollide(c.a, c.b, worker.maskA, worker.maskB);
                    break;
                case Kind::BOUNDS:
                    break;
            }
            if (!hit)
                return std::nullopt;
            if (c.kind == Kind::SELF)
                return Event{u, substep, c.kind, c.a, links.first, links.second};
            return Event{u, substep, c.kind, c.a, c.b, 0};
        }

        const ompl_parc::MultiRobotSpaceInformation &si_;
        const ompl_parc::ValidationOptions &options_;
        const std::vector<ompl_parc::DisplacementBound> &displacement_;
        const std::vector<LinearMotion> &motions_;
        const std::size_t makespan_, n_;
        ompl_parc::WorkerPool pool_;
        std::vector<std::unique_ptr<Worker>> workers_;
        /** Per robot: radius pad for merged pieces, growth a sample may take (see constructor), the radius of a
            disc (negative for other robots). */
        std::vector<double> pad_, margin_, sphere_;
        /** Per robot and piece, the displacement bound of one timestep. */
        std::vector<std::vector<double>> steps_;
        /** Per robot, its body's capsule count. */
        std::vector<std::size_t> capsules_;
        /** Per robot, piece and capsule, the capsule's displacement bound of one timestep (at most steps_'s). */
        std::vector<std::vector<std::vector<double>>> capsuleSteps_;
        std::vector<Box> obstacleBoxes_;
        /** The blocks to check, in increasing order (listEventfulBlocks()). */
        std::vector<std::size_t> eventful_;
    };

    /** The earliest timestep a robot is out of bounds: bounds are boxes, so a piece with both ends inside
        stays inside. */
    std::optional<Event> firstOutOfBounds(const ompl_parc::MultiRobotSpaceInformation &si,
                                          const std::vector<LinearMotion> &motions)
    {
        std::optional<Event> best;
        for (std::size_t i = 0; i < motions.size(); ++i)
        {
            const auto &bounds = si.getRobot(i)->getBounds();
            const LinearMotion &motion = motions[i];
            std::vector<double> q(motion.getDimension());
            const auto outside = [&](const double *x)
            {
                for (unsigned int d = 0; d < motion.getDimension(); ++d)
                    if (!(x[d] >= bounds.low[d] && x[d] <= bounds.high[d]))
                        return static_cast<std::size_t>(d);
                return std::numeric_limits<std::size_t>::max();
            };
            const std::size_t pieces = std::max<std::size_t>(motion.getPieceCount(), 1);
            for (std::size_t p = 0; p < pieces && !best; ++p)
            {
                const bool inside = outside(motion.getStart(p)) == std::numeric_limits<std::size_t>::max() &&
                                    (motion.getPieceCount() == 0 ||
                                     outside(motion.getEnd(p)) == std::numeric_limits<std::size_t>::max());
                if (inside)
                    continue;
                const std::size_t t1 = motion.getPieceCount() == 0 ? 0 : motion.getEndTime(p);
                for (std::size_t t = motion.getPieceCount() == 0 ? 0 : motion.getStartTime(p); t <= t1; ++t)
                {
                    motion.interpolate(p, static_cast<double>(t), q.data());
                    const std::size_t d = outside(q.data());
                    if (d != std::numeric_limits<std::size_t>::max())
                    {
                        const Event event{static_cast<double>(t), false, Kind::BOUNDS, i, d, 0};
                        if (!best || event < *best)
                            best = event;
                        break;
                    }
                }
            }
        }
        return best;
    }

    std::string describe(const ompl_parc::MultiRobotSpaceInformation &si, const Event &e)
    {
        std::ostringstream out;
        out << "t=" << std::setprecision(12) << e.time << (e.substep ? " (sub-step)" : "") << ": ";
        const auto name = [&](std::size_t i) { return si.getRobot(i)->getName(); };
        switch (e.kind)
        {
            case Kind::BOUNDS:
                out << "robot '" << name(e.a) << "' is out of bounds in coordinate " << e.b;
                break;
            case Kind::OBSTACLE:
                out << "robot '" << name(e.a) << "' hits obstacle '" << si.getEnvironment()->getObstacles()[e.b].name
                    << "'";
                break;
            case Kind::SELF:
                out << "robot '" << name(e.a) << "' is in self-collision (links " << e.b << " and " << e.c << ")";
                break;
            case Kind::PAIR:
                out << "robots '" << name(e.a) << "' and '" << name(e.b) << "' collide";
                break;
        }
        return out.str();
    }
}  // namespace

ompl_parc::SolutionValidator::SolutionValidator(MultiRobotProblem problem, ValidationOptions options)
    : problem_(std::move(problem)), options_(options)
{
    // Every instant between timesteps is checked whatever the options: substeps is only the fewest samples.
    if (options_.substeps == 0)
        options_.substeps = 1;
    if (options_.substepSlack < 0.)
        options_.substepSlack = 0.5 / problem_.getSpaceInformation()->getResolution();
    if (!(options_.substepSlack > 0.) || !std::isfinite(options_.substepSlack))
        throw std::invalid_argument(
            "SolutionValidator: the check between timesteps needs a positive, finite "
            "substepSlack");
    if (!(options_.contactTolerance >= 0.) || !std::isfinite(options_.contactTolerance) ||
        !(options_.endpointTolerance >= 0.) || !std::isfinite(options_.endpointTolerance))
        throw std::invalid_argument(
            "SolutionValidator: contactTolerance and endpointTolerance must be finite and "
            "not negative");
    const auto &si = *problem_.getSpaceInformation();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
        displacement_.emplace_back(*si.getRobot(i));
}

std::string ompl_parc::SolutionValidator::checkStructure(const MultiRobotPlan &plan) const
{
    if (std::string mismatch = plan.checkTeam(*problem_.getSpaceInformation()); !mismatch.empty())
        return mismatch;
    if (plan.getMakespan() > MultiRobotPlan::MAX_TIMESTEP)
        return "plan's makespan " + std::to_string(plan.getMakespan()) + " is beyond the largest timestep accepted (" +
               std::to_string(MultiRobotPlan::MAX_TIMESTEP) + ")";
    return "";
}

ompl_parc::ValidationReport ompl_parc::SolutionValidator::validate(const MultiRobotPlan &plan) const
{
    ValidationReport report;
    report.message = checkStructure(plan);
    if (!report.message.empty())
        return report;
    const auto &si = *problem_.getSpaceInformation();
    const std::size_t n = plan.getRobotCount(), makespan = plan.getMakespan();
    std::vector<LinearMotion> motions;
    for (std::size_t i = 0; i < n; ++i)
        motions.push_back(readMotion(plan, i, makespan));

    for (std::size_t i = 0; i < n; ++i)
        for (unsigned int d = 0; d < motions[i].getDimension(); ++d)
        {
            if (std::abs(motions[i].getFirst()[d] - problem_.getStart(i)[d]) > options_.endpointTolerance)
            {
                report.message = "robot '" + si.getRobot(i)->getName() + "' does not start at its start";
                return report;
            }
            if (std::abs(motions[i].getLast()[d] - problem_.getGoal(i)[d]) > options_.endpointTolerance)
            {
                report.message = "robot '" + si.getRobot(i)->getName() + "' does not end at its goal";
                return report;
            }
        }

    // A piece moves the same in every timestep.
    const double maxStep = 1. / plan.getResolution() * (1. + 1e-9) + 1e-12;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t p = 0; p < motions[i].getPieceCount(); ++p)
        {
            double d2 = 0.;
            for (unsigned int d = 0; d < motions[i].getDimension(); ++d)
                d2 += std::pow(motions[i].getEnd(p)[d] - motions[i].getStart(p)[d], 2);
            const double step =
                std::sqrt(d2) / static_cast<double>(motions[i].getEndTime(p) - motions[i].getStartTime(p));
            if (step > maxStep)
            {
                report.time = static_cast<double>(motions[i].getStartTime(p));
                report.message = "t=" + std::to_string(motions[i].getStartTime(p)) + ": robot '" +
                                 si.getRobot(i)->getName() + "' moves " + std::to_string(step) +
                                 " in one timestep (limit " + std::to_string(1. / plan.getResolution()) + ")";
                return report;
            }
        }

    auto first = firstOutOfBounds(si, motions);
    TimeSweep sweep(si, options_, displacement_, motions, makespan);
    const auto collision =
        sweep.run(first ? first->time : std::numeric_limits<double>::infinity(), report.configurationsChecked);
    if (collision && (!first || *collision < *first))
        first = collision;
    if (first)
    {
        report.message = describe(si, *first);
        report.time = first->time;
    }
    report.valid = !first;
    return report;
}
