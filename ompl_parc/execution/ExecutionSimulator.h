#ifndef OMPL_PARC_EXECUTION_SIMULATOR_
#define OMPL_PARC_EXECUTION_SIMULATOR_

#include "ompl_parc/execution/ExecutionCheck.h"
#include "ompl_parc/execution/TeamTrajectory.h"
#include "ompl_parc/execution/TemporalPlanGraph.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Executes a plan with robots that start late and run slower than planned, and checks every executed
        instant with the independent validator (ExecutionCheck): what happens to a conflict-free plan on real robots.

        Each robot follows the plan's path on the trajectory's linear timing (TeamTrajectory's knots, without blends),
        started getStartDelay() late and with every duration divided by its speed scale. Two ways to execute:
        - TIME_INDEXED: each robot follows its own clock, as if the plan's times were commands, ignoring the others;
        - COORDINATED: each robot runs the TemporalPlanGraph: it starts a motion once its own previous motions and the
          motions of others the graph puts before it are done; synchronised motions start together and move through
          their phase at the same pace (the slowest member's). */
    class ExecutionSimulator
    {
      public:
        enum class Mode
        {
            TIME_INDEXED,
            COORDINATED
        };

        /** \brief Per robot, how late it starts (seconds) and the factor on its speed (durations are divided by it). */
        struct Disturbance
        {
            std::vector<double> startDelay, speedScale;

            /** \brief Delays uniform in [0, \e maxDelay] and scales uniform in [\e minScale, 1], from \e seed. */
            static Disturbance random(std::size_t robots, std::uint64_t seed, double maxDelay = 1.,
                                      double minScale = 0.7);
        };

        struct Outcome
        {
            /** \brief True if no executed instant collides (ExecutionCheck). */
            bool collisionFree{false};
            std::string message;
            /** \brief Seconds from the start until the last robot arrives. */
            double makespan{0.};
        };

        /** \brief \e trajectory and \e graph must be of \e plan (TimeParameterization, TemporalPlanGraph). */
        ExecutionSimulator(const MultiRobotProblem &problem, const MultiRobotPlan &plan,
                           const TeamTrajectory &trajectory, const TemporalPlanGraph &graph, double maxSpeed);

        Outcome run(Mode mode, const Disturbance &disturbance) const;

        /** \brief The undisturbed execution's makespan (the linear timing's span), seconds. */
        double getNominalMakespan() const { return times_.back() - times_.front(); }

      private:
        /** \brief Robot \e i's configuration at fractional plan timestep \e step. */
        void configAt(std::size_t i, double step, double *out) const;
        Outcome finish(double makespan, const ExecutionCheck::Motion &motion) const;

        const MultiRobotPlan &plan_;
        const TeamTrajectory &trajectory_;
        const TemporalPlanGraph &graph_;
        ExecutionCheck check_;
        double maxSpeed_;
        /** \brief Per phase boundary, its time on the linear timing. */
        std::vector<double> times_;
    };
}  // namespace ompl_parc

#endif
