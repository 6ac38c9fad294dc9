#ifndef OMPL_PARC_MULTI_ROBOT_VALIDITY_CHECKER_
#define OMPL_PARC_MULTI_ROBOT_VALIDITY_CHECKER_

#include "ompl_parc/robots/Robot.h"

#include <ompl/base/StateValidityChecker.h>

#include <vector>

namespace ompl_parc
{
    /** \brief Validity of a composite state (one real vector component per robot of \e team, in order):
        every robot valid alone, and every robot pair apart.

        Bodies are computed once per robot per call (thread-local buffers, so the checker is safe to share
        between planner threads); the pairs of a small team are all tested (with the bounding-sphere early-out),
        those of a team of SWEEP_FROM robots or more through a CollidingPairSweep over the bodies' boxes. */
    class MultiRobotValidityChecker : public ompl::base::StateValidityChecker
    {
      public:
        MultiRobotValidityChecker(ompl::base::SpaceInformation *si, std::vector<RobotPtr> team);
        bool isValid(const ompl::base::State *state) const override;

        /** \brief True if all \e count composite configurations \e configs (flat: the robots' values in team
            order, per configuration) are valid: each robot checks its own batch with Robot::allValid() (SIMD
            lanes where its kind has them), then the robot pairs, configuration by configuration. A team whose
            robots all have lanes (Robot::getLanes(): arms) goes a lane batch at a time instead: each robot alone
            in lanes, whose kinematics also place it in the world, then each pair compared in single precision
            (UrdfArmLanes::nearLanes()) and tested exactly, in double precision, only for the configurations the
            lanes cannot tell: the answer of the exact test of every pair, without the two arms' kinematics in
            double and their bounds at every configuration, which cost several times the lanes. The batch check
            of the team's RakeMotionValidator. */
        bool allValid(const double *configs, std::size_t count) const;

        /** \brief Robot::sweepValid() of a team of one (the initial stage's single-robot planning); std::nullopt for
            larger teams, whose robot pairs are checked at the samples. */
        std::optional<bool> sweepValid(const double *from, const double *to) const;

        /** \brief The team size from which the robot pairs are found by a sweep over boxes instead of testing
            them all (ompl_parc_bench_collision's `teamPairs`: below it the sweep's sort costs more than it saves). */
        static constexpr std::size_t SWEEP_FROM = 24;

      private:
        /** \brief True if two of the team's \e bodies overlap. */
        bool anyPairCollides(const std::vector<CollisionBody> &bodies) const;

        /** \brief allValid() for a team whose robots all have lanes (lanes_ full): a lane batch at a time, each robot
            alone (as its Robot::allValid() decides), then the pairs. */
        bool lanesValid(const double *configs, std::size_t count) const;

        std::vector<RobotPtr> team_;
        /** \brief Where each robot's values start in a composite configuration (the last entry: its size). */
        std::vector<std::size_t> offsets_;
        /** \brief Each robot's lanes, when every robot of the team has them (else empty). */
        std::vector<const UrdfArmLanes *> lanes_;
    };
}  // namespace ompl_parc

#endif
