#ifndef OMPL_PARC_ROBOT_
#define OMPL_PARC_ROBOT_

#include "ompl_parc/collision/CollisionBody.h"
#include "ompl_parc/collision/Environment.h"
#include "ompl_parc/robots/MotionLimits.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorBounds.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ompl_parc
{
    class UrdfArmLanes;

    /** \brief One robot of a team: its own configuration space, validity against the static world, and
        the collision body used for robot-robot checks.

        Every robot lives in a bounded real vector space (a workspace box for mobile robots, joint limits
        for arms), so a configuration is a flat array of getDimension() doubles. Plans, conflict scans
        and the validator work on such arrays; OMPL planners work on the robot's own SpaceInformation,
        whose validity checker is isValid(). Subclasses provide the kinematics in computeCapsules(). */
    class Robot
    {
      public:
        /** \brief Why a configuration is invalid, for error messages. */
        enum class Validity
        {
            VALID,
            OUT_OF_BOUNDS,
            SELF_COLLISION,
            ENVIRONMENT_COLLISION
        };

        /** \brief \e bounds are the configuration bounds; throws ompl::Exception if they are empty. */
        Robot(std::string name, EnvironmentPtr environment, const ompl::base::RealVectorBounds &bounds);
        virtual ~Robot() = default;
        Robot(const Robot &) = delete;
        Robot &operator=(const Robot &) = delete;

        const std::string &getName() const { return name_; }

        /** \brief A short kind name ("disc", "planar_arm", ...), written into solution files. */
        virtual std::string getKind() const = 0;

        /** \brief The shape of the robot at configuration \e q (world frame), with the bounds the collision tests
            read (CollisionBody::updateBound()). */
        void computeBody(const double *q, CollisionBody &body) const
        {
            computeCapsules(q, body);
            body.updateBound();
        }

        /** \brief The capsules of computeBody() without their bounds: for the SolutionValidator, which tests with
            its own broad phase and FCL shapes and would spend a fifth of its time on bounds it never reads. */
        virtual void computeCapsules(const double *q, CollisionBody &body) const = 0;

        const ompl::base::SpaceInformationPtr &getSpaceInformation() const { return si_; }
        const ompl::base::StateSpacePtr &getStateSpace() const { return si_->getStateSpace(); }
        const EnvironmentPtr &getEnvironment() const { return environment_; }
        unsigned int getDimension() const { return dimension_; }
        const ompl::base::RealVectorBounds &getBounds() const { return bounds_; }

        /** \brief Pairs of capsule indices of the body that must not touch (non-adjacent links). */
        const std::vector<std::pair<std::size_t, std::size_t>> &getSelfCollisionPairs() const
        {
            return selfCollisionPairs_;
        }

        /** \brief True if all \e count configurations \e configs (flat, getDimension() doubles each) are within the
            bounds (NaN never is). */
        bool withinBounds(const double *configs, std::size_t count) const;

        /** \brief Checks bounds, self-collision and the environment, in that order. */
        Validity checkValidity(const double *q) const;
        /** \brief checkValidity(), leaving the body at \e q in \e body (unless \e q is out of bounds), for callers
            that test it against other robots next. */
        Validity checkValidity(const double *q, CollisionBody &body) const;
        bool isValid(const double *q) const { return checkValidity(q) == Validity::VALID; }
        bool isValid(const ompl::base::State *state) const;

        /** \brief True if all \e count configurations \e configs (flat, getDimension() doubles each) are valid:
            the samples of a motion, checked together. Kinds with a kernel that checks several configurations at
            once (UrdfArm) override it; the default checks them one by one, in order, stopping at the first
            invalid one. */
        virtual bool allValid(const double *configs, std::size_t count) const;

        /** \brief Whether the straight motion from \e from (valid) to \e to is valid at every point of it, for kinds
            that can tell at once, without samples (a translating disc sweeps a capsule: DiscRobot); std::nullopt
            for the others, whose motions are checked sample by sample. Stricter than any sampling. */
        virtual std::optional<bool> sweepValid(const double *from, const double *to) const;

        /** \brief The kind's kernel that checks several configurations at once in SIMD lanes, for the team checks
            that compare two robots a lane batch at a time (MultiRobotValidityChecker::allValid()); null for kinds
            without one (the default). A kind that has one decides allValid() as it does: the bounds, then
            UrdfArmLanes::anyCollides(). */
        virtual const UrdfArmLanes *getLanes() const { return nullptr; }

        /** \brief For kinds whose body's bounding box follows from a box of configurations (a translating disc:
            the configuration box grown by the radius): expand [\e boxLo, \e boxHi] to contain the body at every
            configuration in [\e lo, \e hi] and return true; false (box untouched) for the others. Lets swept
            bounds over many timesteps come from a plan's pieces instead of one body per timestep. */
        virtual bool expandBoxOver(const double *lo, const double *hi, std::array<double, 3> &boxLo,
                                   std::array<double, 3> &boxHi) const;

        /** \brief True if the two bodies (of this robot) overlap in any listed self-collision pair. */
        bool selfCollides(const CollisionBody &body) const;

        /** \brief The distance between configurations \e a and \e b in the robot's state space: the metric the
            timestep grid, the plans' bounds and the straight initial paths use. */
        double distance(const double *a, const double *b) const;

        void stateToConfig(const ompl::base::State *state, double *q) const;
        void configToState(const double *q, ompl::base::State *state) const;

        /** \brief Motions are checked every 1/\e stepsPerUnit of distance (the plans' timestep length).
            Throws like checkTimesteps(). */
        void setResolution(double stepsPerUnit);

        /** \brief Throws ompl::Exception naming robot \e name if \e bounds are not finite or if crossing them
            once (the diagonal) at \e resolution timesteps per unit takes more timesteps than a plan may hold
            (MultiRobotPlan::MAX_TIMESTEP): such a team could only get plans nobody can check, and OMPL's motion
            checks would underflow. */
        static void checkTimesteps(const std::string &name, const ompl::base::RealVectorBounds &bounds,
                                   double resolution);

        static std::string toString(Validity validity);

        /** \brief The velocity and acceleration limits a trajectory of this robot must respect
            (TimeParameterization): the ones set (setMotionLimits(), a scenario file's "limits"), else the kind's
            defaults (defaultMotionLimits()). */
        MotionLimits getMotionLimits() const { return motionLimits_ ? *motionLimits_ : defaultMotionLimits(); }
        /** \brief True if limits were set rather than taken from the kind's defaults (scenario files write them). */
        bool hasOwnMotionLimits() const { return motionLimits_.has_value(); }
        /** \brief Throws ompl::Exception naming the robot if \e limits do not fit it (MotionLimits::check()). */
        void setMotionLimits(MotionLimits limits);

        /** \brief A name per configuration coordinate, for trajectory files (a JointTrajectory's joint names):
            "q0", "q1", ... unless the kind knows better (a URDF arm's joint names, a disc's "x", "y"). */
        virtual std::vector<std::string> getCoordinateNames() const;

      protected:
        /** \brief The kind's limits when none are set: 1 unit/s and 3 units/s^2 per coordinate. */
        virtual MotionLimits defaultMotionLimits() const;

        std::vector<std::pair<std::size_t, std::size_t>> selfCollisionPairs_;

      private:
        std::string name_;
        EnvironmentPtr environment_;
        ompl::base::RealVectorBounds bounds_;
        unsigned int dimension_;
        ompl::base::SpaceInformationPtr si_;
        std::optional<MotionLimits> motionLimits_;
    };

    using RobotPtr = std::shared_ptr<Robot>;
}  // namespace ompl_parc

#endif
