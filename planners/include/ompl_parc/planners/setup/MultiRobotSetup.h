#ifndef OMPL_PARC_PLANNERS_SETUP_MULTI_ROBOT_SETUP_
#define OMPL_PARC_PLANNERS_SETUP_MULTI_ROBOT_SETUP_

#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/quality/PlanSmoother.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/geometric/SimpleSetup.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace ompl_parc
{
    /** \brief OMPL's SimpleSetup for a robot team: the robots and their per-robot starts and goals (by name or
        index, no composite state layout to know), a planner by registry name with typed parameters, solve, the
        per-robot MultiRobotPlan, smoothing, validation and the solution and picture files.

        \code
        ompl_parc::MultiRobotSetup setup(team);             // std::vector<RobotPtr>, 128 timesteps per unit
        setup.setStart("r0", {-8., -2.});
        setup.setGoal("r0", {8., -2.});                     // ... every robot
        setup.setPlanner("parc");                           // PlannerRegistry names: arc, parc, orparc, ...
        setup.setPlannerParameter("workers", 2);
        setup.setPlannerParameter("seed", 1);
        if (setup.solve(30.) == ompl::base::PlannerStatus::EXACT_SOLUTION)
            std::cout << setup.getPlan().getMakespan() << " timesteps\n";
        \endcode

        Underneath is an ompl::geometric::SimpleSetup over the composite space (getSimpleSetup()): everything OMPL
        offers (its solution path, planner data, benchmark tools) works on it. */
    class MultiRobotSetup
    {
      public:
        /** \brief A team of \e robots (unique names, one Environment) with \e resolution timesteps per unit
            (MultiRobotSpaceInformation's checks apply); starts and goals to be set. */
        explicit MultiRobotSetup(std::vector<RobotPtr> robots, double resolution = 128.);
        /** \brief The team, starts and goals of \e problem (a built-in scenario, a scenario file). */
        explicit MultiRobotSetup(const MultiRobotProblem &problem);

        const MultiRobotSpaceInformationPtr &getSpaceInformation() const { return si_; }
        /** \brief The OMPL setup underneath (its ProblemDefinition gets the composite start and goal at solve()). */
        ompl::geometric::SimpleSetup &getSimpleSetup() { return setup_; }
        std::size_t getRobotCount() const { return si_->getRobotCount(); }
        /** \brief The index of the robot named \e name; throws std::invalid_argument naming the team otherwise. */
        std::size_t getRobotIndex(const std::string &name) const;

        /** \name Per-robot starts and goals: one value per degree of freedom of the robot (x, y for a disc; joint
            angles for an arm); throws std::invalid_argument for an unknown robot or the wrong number of values.
            @{ */
        void setStart(std::size_t robot, const std::vector<double> &configuration);
        void setStart(const std::string &robot, const std::vector<double> &configuration);
        void setGoal(std::size_t robot, const std::vector<double> &configuration);
        void setGoal(const std::string &robot, const std::vector<double> &configuration);
        /** @} */

        /** \brief The team with its starts and goals; throws std::invalid_argument naming a robot whose start or
            goal is not set. */
        MultiRobotProblem getProblem() const;

        /** \brief Planner \e name of the PlannerRegistry ("arc", "parc", "orparc", "pp-st-rrt", ...), with its
            default parameters; throws std::invalid_argument listing the names for an unknown one. */
        void setPlanner(const std::string &name);
        /** \brief Any OMPL planner over getSpaceInformation(). */
        void setPlanner(const ompl::base::PlannerPtr &planner);
        /** \brief The planner (null before setPlanner()). */
        const ompl::base::PlannerPtr &getPlanner() const { return setup_.getPlanner(); }

        /** \brief Sets the planner's declared parameter \e key to \e value: a number, a bool or text. Throws
            std::invalid_argument for no planner, an unknown key (naming the valid ones), a value outside the
            declared range or one the parameter does not take (PlannerRegistry::setParameter()). */
        template <typename T>
        void setPlannerParameter(const std::string &key, const T &value)
        {
            if constexpr (std::is_same_v<T, bool>)
                setPlannerParameterText(key, value ? "1" : "0");
            else if constexpr (std::is_arithmetic_v<T>)
            {
                std::ostringstream text;
                text.precision(17);
                text << +value;
                setPlannerParameterText(key, text.str());
            }
            else
                setPlannerParameterText(key, std::string(value));
        }

        /** \brief Solves from the starts to the goals (getProblem()) with the planner, for at most \e seconds. After a
            change of a start or goal the planner starts over (clear()); otherwise a later solve() continues where the
            last one stopped (OMPL's convention: a timed-out ARC resumes its repairs). */
        ompl::base::PlannerStatus solve(double seconds);
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc);
        /** \brief Wall seconds of the last solve(). */
        double getLastPlanComputationTime() const { return setup_.getLastPlanComputationTime(); }

        /** \brief The solution of the last solve() as per-robot timed paths (PlannerRegistry::planOf()); throws
            std::logic_error if it found no exact solution. */
        const MultiRobotPlan &getPlan() const;

        /** \brief The planner's progress properties now (name → value; the ARC family's: stage, robots planned,
            conflicts found and resolved, batches, solver calls, makespan, elapsed). For ompl_parc's ARC family
            (ARC, PARC, ORPARC) it may be called from another thread while solve() runs. */
        std::map<std::string, std::string> getProgress() const;

        /** \brief Time-aware smoothing of the solution (PlanSmoother) for at most \e seconds, seeded with \e seed;
            the plan stays conflict-free. Throws std::logic_error without a solution. */
        SmoothingReport simplify(double seconds, unsigned int seed = 1);

        /** \brief The independent validator's verdict on the solution (SolutionValidator). */
        ValidationReport validate(const ValidationOptions &options = ValidationOptions()) const;
        /** \brief Writes the solution file (SolutionFile). */
        void writeSolution(const std::string &path) const;
        /** \brief Draws the problem and, if solved, the solution (PictureFile): an interactive 3D page for a .html
            \e path, else an SVG (with \e options). */
        void writePicture(const std::string &path, const SvgOptions &options = SvgOptions()) const;

      private:
        void setPlannerParameterText(const std::string &key, const std::string &value);
        void checkConfiguration(std::size_t robot, const std::vector<double> &configuration) const;

        MultiRobotSpaceInformationPtr si_;
        ompl::geometric::SimpleSetup setup_;
        std::string name_;
        std::vector<std::optional<std::vector<double>>> starts_, goals_;
        /** \brief Whether a start or goal changed since the last solve(). */
        bool changed_{true};
        /** \brief The last solve()'s exact solution, per robot. */
        std::optional<MultiRobotPlan> plan_;
    };
}  // namespace ompl_parc

#endif
