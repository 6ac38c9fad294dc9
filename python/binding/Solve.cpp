#include "Solve.h"

#include "BenchmarkRunner.h"
#include "InterruptScope.h"
#include "ToolSupport.h"

#include "ompl_parc/planners/setup/BenchmarkConfig.h"
#include "ompl_parc/planners/setup/MultiRobotSetup.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/PlannerData.h>

#include <fstream>
#include <iostream>

namespace py = pybind11;
namespace ob = ompl::base;

namespace
{
    /** \brief The "name TYPE" properties as {name: value} with REAL as float, INTEGER as int, BOOLEAN as bool. */
    py::dict typedProperties(const std::map<std::string, std::string> &properties)
    {
        py::dict out;
        for (const auto &[key, value] : properties)
        {
            const auto [name, type] = ompl_parc::tools::splitPropertyKey(key);
            try
            {
                if (type == "REAL")
                    out[py::str(name)] = std::stod(value);
                else if (type == "INTEGER" || type == "ENUM")
                    out[py::str(name)] = std::stoll(value);
                else if (type == "BOOLEAN")
                    out[py::str(name)] = value == "1" || value == "true";
                else
                    out[py::str(name)] = value;
            }
            catch (const std::exception &)  // "nan", "inf" or empty: keep the text
            {
                out[py::str(name)] = value;
            }
        }
        return out;
    }
}  // namespace

ompl_parc::python::SolveResult ompl_parc::python::solve(const MultiRobotProblem &problem, const std::string &name,
                                                        double timeLimit, const std::vector<std::string> &params)
{
    if (!(timeLimit > 0.) || !(timeLimit <= 1e7))
        throw std::invalid_argument("time_limit must be a number above 0 and at most 1e+07 (got " +
                                    std::to_string(timeLimit) + ")");
    if (const std::string reason = problem.checkEndpoints(); !reason.empty())
        throw std::invalid_argument(reason);
    MultiRobotSetup setup(problem);
    setup.setPlanner(PlannerRegistry::create(name, problem.getSpaceInformation(), params));
    ob::PlannerStatus status;
    bool listened = false;
    {
        const python::InterruptScope interrupt;  // with the GIL: raises a Ctrl-C that came just before
        listened = interrupt.listens();
        const py::gil_scoped_release released;
        const auto ptc = ob::plannerOrTerminationCondition(
            ob::timedPlannerTerminationCondition(timeLimit),
            ob::PlannerTerminationCondition([listened] { return listened && python::InterruptScope::fired(); }));
        const StopSignal::Scope scope(ptc);
        status = setup.solve(ptc);
    }
    // Read after the scope gave SIGINT back to Python: a Ctrl-C in between reached one of the two.
    if (listened && python::InterruptScope::fired())
    {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
    }
    SolveResult result;
    result.status = status.asString();
    result.planner = setup.getPlanner()->getName();
    result.time = setup.getLastPlanComputationTime();
    result.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
    if (result.solved)
        result.plan = setup.getPlan();
    ob::PlannerData data(problem.getSpaceInformation());
    setup.getPlanner()->getPlannerData(data);
    result.properties = typedProperties(data.properties);
    return result;
}

py::tuple ompl_parc::python::runBenchmark(const std::string &path, bool verbose)
{
    tools::BenchmarkRunner runner(BenchmarkConfig::read(path));
    std::ofstream quiet;  // not open: discards what it is given
    tools::BenchmarkResults results;
    {
        const py::gil_scoped_release released;
        results = runner.run(verbose ? std::cerr : static_cast<std::ostream &>(quiet));
    }
    return py::make_tuple(results.csv.string(), results.summary, results.invalid);
}
