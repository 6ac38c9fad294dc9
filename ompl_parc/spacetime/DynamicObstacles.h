#ifndef OMPL_PARC_DYNAMIC_OBSTACLES_
#define OMPL_PARC_DYNAMIC_OBSTACLES_

#include "ompl_parc/collision/BodyTrack.h"
#include "ompl_parc/model/TimedPath.h"
#include "ompl_parc/robots/Robot.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace ompl_parc
{
    /** \brief What one robot must avoid when it is planned after others (prioritised planning): the static
        environment and the other robots' timed paths.

        Each other robot's path is a sequence of configurations at integer timesteps, held after its end (a
        robot that has arrived stays at its goal). Their collision bodies are computed once here, per
        timestep (flat, BodyTrack), because space-time planning asks for them at the same timesteps over and over. */
    class DynamicObstacles
    {
      public:
        /** \brief Obstacles for \e robot on a grid of \e resolution timesteps per unit of time. */
        DynamicObstacles(RobotPtr robot, double resolution);

        const RobotPtr &getRobot() const { return robot_; }
        double getResolution() const { return resolution_; }

        /** \brief The most timesteps of a path whose bodies are kept (a 2^22-timestep path holds hundreds of
            megabytes of bodies; at resolution 1e8 one unit of motion is 1e8 timesteps). */
        static constexpr std::size_t MAX_TIMESTEPS = std::size_t{1} << 22;

        /** \brief Whether computeTrack() and addPath() take \e path (its arrival is below MAX_TIMESTEPS). */
        static bool fits(const TimedPath &path) { return path.getArrival() < MAX_TIMESTEPS; }

        /** \brief The bodies of robot \e other following \e path (not empty, fits()) at timesteps 0..arrival.
            Throws ompl::Exception for a path that does not fit. */
        static std::shared_ptr<const BodyTrack> computeTrack(const Robot &other, const TimedPath &path);

        /** \brief Add robot \e other following \e path: addTrack(computeTrack(other, path)); throws
            ompl::Exception as computeTrack() does. */
        void addPath(const Robot &other, const TimedPath &path);

        /** \brief Add an obstacle whose bodies computeTrack() gave. Prioritised planning shares one track per
            planned robot among the obstacles of every robot planned after it, instead of computing (and
            allocating: a fresh page costs a fault) the same bodies once per later robot. Throws ompl::Exception
            for a missing or empty track. */
        void addTrack(std::shared_ptr<const BodyTrack> track);

        std::size_t getPathCount() const { return tracks_.size(); }

        /** \brief True if the robot at \e q is valid (bounds, self, environment) and touches no other robot
            at timestep \e timestep. */
        bool isClear(const double *q, std::size_t timestep) const;

        /** \brief True if the robot is clear (isClear()) at every timestep \e first + s, s = 1..\e steps, moving
            straight from \e from (a valid configuration: the motion's start, checked before) to \e to as a timed
            path lays it (TimedPath::interpolate(from, to, s, steps)). Keeps up to \e steps + 1 bodies per thread
            between calls, so \e steps should stay modest (LatticeSearch: at most a few thousand).
            The same answer as isClear() at each of those timesteps, or stricter where the robot can sweep the
            motion at once (Robot::sweepValid); faster for robots with a box over configurations
            (Robot::expandBoxOver): an obstacle is checked only in blocks of timesteps whose box meets the motion's. */
        bool isMotionClear(const double *from, const double *to, std::size_t first, std::size_t steps) const;

        /** \brief True if the robot may move straight from \e from (valid) to \e to among the static obstacles: its
            sweep where it has one (Robot::sweepValid), else its configurations at the \e steps timesteps the motion
            is laid on. */
        bool isStaticMotionValid(const double *from, const double *to, std::size_t steps) const;

        /** \brief The last timestep at which an obstacle still moves (0 if none): from then on nothing changes. */
        std::size_t getLastMove() const { return lastMove_; }

        /** \brief The earliest timestep from which the robot can stay at \e q forever untouched; none if
            \e q is invalid or a robot that has arrived blocks it for good. */
        std::optional<std::size_t> earliestHold(const double *q) const;

      private:
        RobotPtr robot_;
        double resolution_;
        /** \brief tracks_[o]: obstacle o's bodies at timesteps 0..arrival; its last body is held afterwards. */
        std::vector<std::shared_ptr<const BodyTrack>> tracks_;
        std::size_t lastMove_{0};
    };

    using DynamicObstaclesPtr = std::shared_ptr<const DynamicObstacles>;

    /** \brief The space-time SpaceInformation of the obstacles' robot: a SpaceTimeStateSpace (vMax 1) over
        \e space (the robot's space, possibly with local bounds and a seeded sampler), with a
        SpaceTimeValidityChecker and a SpaceTimeMotionValidator among \e obstacles; set up. */
    ompl::base::SpaceInformationPtr createSpaceTimeSpaceInformation(const ompl::base::StateSpacePtr &space,
                                                                    const DynamicObstaclesPtr &obstacles);
}  // namespace ompl_parc

#endif
