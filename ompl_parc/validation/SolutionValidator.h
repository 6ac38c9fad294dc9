#ifndef OMPL_PARC_SOLUTION_VALIDATOR_
#define OMPL_PARC_SOLUTION_VALIDATOR_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/validation/DisplacementBound.h"

#include <optional>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Tolerances of the SolutionValidator. */
    struct ValidationOptions
    {
        /** \brief Largest per-coordinate difference accepted between a path end and its start/goal. */
        double endpointTolerance{1e-6};
        /** \brief Fewest samples per timestep interval of the check between timesteps; more are taken where the
            motion needs them to cover every instant, so no value (0 and 1 included) switches that check off. */
        unsigned int substeps{4};
        /** \brief Radius reduction between timesteps; negative means half a timestep (0.5/resolution); zero
            or not finite is refused.
            The plan's guarantee is collision-freedom at timesteps; between them grazing overlaps far
            below a timestep are expected, tunnelling through a robot or obstacle is not. */
        double substepSlack{-1.};
        /** \brief Radius reduction at timesteps: contacts shallower than this are below FCL's GJK
            tolerance and are not reported. */
        double contactTolerance{1e-6};
        /** \brief Threads of the check; 0 means one per hardware thread. The report does not depend on it. */
        unsigned int threads{0};
    };

    /** \brief Outcome of SolutionValidator::validate(). */
    struct ValidationReport
    {
        bool valid{false};
        /** \brief The earliest violation in time, readable ("t=42: robots 'r0' and 'r1' collide"); empty if
            valid. */
        std::string message;
        /** \brief When the earliest violation happens (a timestep, fractional between timesteps), if the plan is
            invalid in time rather than in shape (a mismatched team or a wrong start has none). */
        std::optional<double> time;
        /** \brief Number of (robot, sample) configurations that went through FCL's narrow phase: a robot of a
            tested pair, obstacle or self test counts once per timestep or sub-step sample; what the broad phase
            and the swept tests rule out is not counted. */
        std::size_t configurationsChecked{0};
    };

    /** \brief Re-checks a plan against its problem, independently of every planner.

        It shares the robot kinematics (computeBody) with the planners, nothing else: bounds, the motion bound,
        the broad phase and the displacement bounds are its own code, and collisions (environment, self and every
        robot pair) are tested with FCL's narrow phase on its own FCL shapes (FclBodies), not with the planners'
        capsule test or the robots' validity checkers. Checks, in order: team size and resolution; each robot
        starts at its start and ends at its goal; no timestep moves a robot more than 1/resolution; then, the
        earliest in time first, every configuration is in bounds and collision-free: at every timestep (robots
        hold their goals after arrival) with radii shrunk by contactTolerance, and at every instant between
        timesteps with radii shrunk by substepSlack (down to a segment or point: tunnelling through a thin wall
        or another robot is caught, however fast).

        How: each robot's motion is read as linear pieces (LinearMotion). Time is cut into blocks of 64
        timesteps; per robot and block a box contains its body at every instant of the block (for a disc the
        hull of its bodies at the ends of each piece, for an arm its bodies at the timesteps grown by half a
        timestep's DisplacementBound). Only pairs and obstacles whose boxes overlap in a block are tested (the pairs
        found by a uniform grid, BoxOverlaps), and only when one of them moves there. A disc on a piece is tested whole:
        its swept capsule against an obstacle, the closest approach of two discs' linear relative motion against the
        sum of radii. The rest goes timestep by timestep. Per interval [t, t + 1], each capsule gets a box around it at
        t and t + 1 grown by half its own displacement bound of a step (DisplacementBound::capsuleBound()); only the
        capsules whose boxes meet the other side's are tested further. Then one FCL test of those capsules at t, each grown
        by its displacement over the whole step (with the largest radius any sample uses): every sample of the
        interval lies inside, so if nothing touches, the interval is clear. Otherwise FCL at the timestep, and
        between timesteps FCL at m samples with radii grown by each capsule's displacement to the nearest sample
        (at most the body's DisplacementBound / 2m), m chosen so the growth stays within half the slack: any
        overlap at any instant shows at a sample. A capsule that does not move on a piece (an arm's base) is tested
        against an obstacle once per span. Blocks, pairs and obstacles run on several threads; the report is the
        earliest violation whatever the threads. */
    class SolutionValidator
    {
      public:
        /** \brief Throws std::invalid_argument for a robot kind without a displacement bound and for options
            that are not finite or would switch a guarantee off (a zero slack, a negative tolerance). */
        explicit SolutionValidator(MultiRobotProblem problem, ValidationOptions options = ValidationOptions());

        ValidationReport validate(const MultiRobotPlan &plan) const;

      private:
        std::string checkStructure(const MultiRobotPlan &plan) const;

        MultiRobotProblem problem_;
        ValidationOptions options_;
        std::vector<DisplacementBound> displacement_;
    };
}  // namespace ompl_parc

#endif
