#ifndef OMPL_PARC_MULTI_ROBOT_SPACE_INFORMATION_
#define OMPL_PARC_MULTI_ROBOT_SPACE_INFORMATION_

#include "ompl_parc/robots/Robot.h"
#include "ompl_parc/statespaces/CompositeStateSpace.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorBounds.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ompl_parc
{
    class MultiRobotSpaceInformation;
    using MultiRobotSpaceInformationPtr = std::shared_ptr<MultiRobotSpaceInformation>;

    /** \brief SpaceInformation of a robot team over its CompositeStateSpace.

        Its validity checker accepts a composite state only if every robot is valid on its own and no two
        robots touch, so any OMPL planner run on it solves the coupled problem unchanged (the coupled
        baseline). Our planners additionally use the per-robot structure through get() and the robots.

        Each instance gets its own robot spaces (copies of the robots' bounds, or the tighter \e bounds a
        subproblem asks for), so planning tasks never share mutable OMPL state and can run in parallel.
        Every robot space checks motions every 1/resolution (one timestep at vmax = 1); with a non-zero
        \e seed its samplers draw from that seed instead of OMPL's global sequence, so a task's result
        depends only on its seed. */
    class MultiRobotSpaceInformation : public ompl::base::SpaceInformation
    {
      public:
        /** \brief \e bounds (one per robot, or empty for the robots' own) restrict sampling, e.g. to a
            subproblem's local region. Throws ompl::Exception for an empty team, null or duplicate-named
            robots, robots in different Environments, a non-positive resolution or malformed bounds. */
        explicit MultiRobotSpaceInformation(std::vector<RobotPtr> robots, double resolution = 128.,
                                            const std::vector<ompl::base::RealVectorBounds> &bounds = {},
                                            std::uint_fast32_t seed = 0);

        std::size_t getRobotCount() const { return robots_.size(); }
        const RobotPtr &getRobot(std::size_t i) const { return robots_.at(i); }
        const std::vector<RobotPtr> &getRobots() const { return robots_; }
        /** \brief The static world, shared by the whole team. */
        const EnvironmentPtr &getEnvironment() const { return robots_.front()->getEnvironment(); }
        const CompositeStateSpacePtr &getCompositeSpace() const { return composite_; }
        /** \brief Timesteps per unit of distance; one timestep moves a robot at most 1/resolution. */
        double getResolution() const { return resolution_; }

        /** \brief Empty if the resolution is fine enough to plan with; otherwise why not. Conflicts are
            found at timesteps, so one timestep of motion must not carry a robot past another: a robot's
            thinnest part (its smallest capsule radius r, at the centre of its bounds) must be at least the
            1/resolution a timestep moves it, i.e. resolution >= 1/r for every robot (Mobile discs: 2; the
            paper uses 128). Coarser plans are still read and validated, but planners refuse them. */
        std::string checkPlanningResolution() const;

        /** \brief The configuration values of robot \e i inside composite state \e state. */
        const double *getRobotValues(const ompl::base::State *state, std::size_t i) const;
        double *getRobotValues(ompl::base::State *state, std::size_t i) const;

        /** \brief True if robot \e i at \e qi and robot \e j at \e qj touch. */
        bool robotsCollide(std::size_t i, const double *qi, std::size_t j, const double *qj) const;

        /** \brief Empty if \e state is valid; otherwise the first reason, naming the robot(s). */
        std::string explainInvalid(const ompl::base::State *state) const;

        /** \brief Empty if the team is valid at \e configs (robot i's configuration values at configs[i]); otherwise
            the first reason: the first robot invalid alone ("robot 'a' is in collision"), else the first pair that
            touches ("robots 'a' and 'b' collide"). A non-empty \e what names the configurations: "start of robot
            'a' ...", "starts of robots 'a' and 'b' collide". Each robot's body is built once for all its pairs. Throws
            ompl::Exception unless there is one configuration per robot. */
        std::string explainInvalid(const std::vector<const double *> &configs, const std::string &what = "") const;

        /** \brief Down-cast \e si, or throw ompl::Exception saying that \e who needs a multi-robot
            SpaceInformation. */
        static MultiRobotSpaceInformationPtr get(const ompl::base::SpaceInformationPtr &si, const std::string &who);

      private:
        std::vector<RobotPtr> robots_;
        CompositeStateSpacePtr composite_;
        double resolution_;
    };
}  // namespace ompl_parc

#endif
