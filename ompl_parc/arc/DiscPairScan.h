#ifndef OMPL_PARC_DISC_PAIR_SCAN_
#define OMPL_PARC_DISC_PAIR_SCAN_

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/model/TimedPath.h"
#include "ompl_parc/robots/DiscRobot.h"

#include <optional>

namespace ompl_parc
{
    /** \brief The earliest timestep at which two translating discs collide along their timed paths, found from
        the paths' pieces instead of one body per timestep.

        Between the timesteps where either path changes piece, both discs move on straight lines at constant
        velocity, so their distance is a quadratic in time: one closest-approach computation per stretch tells
        whether, and around which timesteps, the discs can come within the sum of their radii plus a margin far
        above the rounding of this model. Only those timesteps are checked exactly, with the same bodies and
        test the per-timestep scan uses (DiscRobot::computeBody, bodiesCollide), in increasing order: the answer
        is exactly the per-timestep scan's, at a cost per piece rather than per timestep. A conflict scan of
        Mobile Cross 256 looks at ~170 000 timesteps per pair and a few pieces. */
    class DiscPairScan
    {
      public:
        /** \brief The pair (\e a on \e pathA, \e b on \e pathB), with two scratch bodies for the exact checks. */
        DiscPairScan(const DiscRobot &a, const TimedPath &pathA, const DiscRobot &b, const TimedPath &pathB,
                     CollisionBody &bodyA, CollisionBody &bodyB);

        /** \brief The first timestep in [\e from, \e last] at which the discs collide, if any. The exact checks
            poll StopSignal (a stretch where the discs stay close may span millions of timesteps at a fine
            resolution): when the planning stops, none is returned and getStoppedAt() says where. */
        std::optional<std::size_t> firstContact(std::size_t from, std::size_t last);

        /** \brief After a firstContact() that stopped early: the first timestep it did not check (the ones
            before it are clear); none after a complete one. */
        std::optional<std::size_t> getStoppedAt() const { return stoppedAt_; }

      private:
        /** \brief A disc's straight motion: position (exactly the path's) at timestep \e time, velocity per
            timestep, and the last timestep it holds (the end of the piece, or of its linear part). */
        struct Motion
        {
            double x, y, vx, vy;
            std::size_t time, end;
        };
        /** \brief The motion of \e path from timestep \e t on, found by \e cursor (on \e path; t only grows). */
        static Motion motionAt(const TimedPath &path, TimedPath::Cursor &cursor, std::size_t t);

        /** \brief The exact per-timestep test. */
        bool collidesAt(std::size_t t);

        const DiscRobot &a_, &b_;
        const TimedPath &pathA_, &pathB_;
        CollisionBody &bodyA_, &bodyB_;
        /** \brief One reader per path, for the motions and the exact checks alike: both only move forward. */
        TimedPath::Cursor cursorA_, cursorB_;
        std::optional<std::size_t> stoppedAt_;
    };
}  // namespace ompl_parc

#endif
