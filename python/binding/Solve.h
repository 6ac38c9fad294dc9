#ifndef OMPL_PARC_DEMOS_PYTHON_SOLVE_
#define OMPL_PARC_DEMOS_PYTHON_SOLVE_

#include "ompl_parc/model/MultiRobotPlan.h"
#include "ompl_parc/model/MultiRobotProblem.h"

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

namespace ompl_parc::python
{
    /** \brief How a solve from Python ended. */
    struct SolveResult
    {
        std::string status, planner;
        bool solved{false};
        double time{0.};
        std::optional<MultiRobotPlan> plan;
        /** \brief The planner's PlannerData properties, typed by their OMPL type suffix. */
        pybind11::dict properties;
    };

    /** \brief Solves \e problem with registry planner \e name and \e params ("key=value") for at most \e timeLimit
        seconds, the GIL released; Ctrl-C stops the planner (all workers joined) and raises KeyboardInterrupt. */
    SolveResult solve(const MultiRobotProblem &problem, const std::string &name, double timeLimit,
                      const std::vector<std::string> &params);

    /** \brief Runs benchmark configuration \e path (tools::BenchmarkRunner), the GIL released; returns the CSV's path,
        the summary table and the number of solutions the validator refused. With \e verbose a line per run goes to
        stderr. */
    pybind11::tuple runBenchmark(const std::string &path, bool verbose);
}  // namespace ompl_parc::python

#endif
