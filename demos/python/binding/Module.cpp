/* The compiled part of the Python module ompl_parc (_ompl_parc): problems, planners by name, plans as NumPy arrays,
   the independent validator, solution files, pictures and benchmarks. demos/python/package/ompl_parc/__init__.py wraps
   it with keyword arguments, type hints and docstrings. Bad input raises ValueError with the tools' one-line message.
 */
#include "BenchmarkRunner.h"
#include "InterruptScope.h"

#include "ompl_parc/Version.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/planners/setup/BenchmarkConfig.h"
#include "ompl_parc/planners/setup/MultiRobotSetup.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/util/StopSignal.h"

#include <ompl/base/PlannerData.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace py = pybind11;
namespace ob = ompl::base;
using namespace ompl_parc;

namespace
{
    /** \brief How a solve from Python ended. */
    struct SolveResult
    {
        std::string status, planner, message;
        bool solved{false};
        double time{0.};
        std::optional<MultiRobotPlan> plan;
        /** \brief The planner's PlannerData properties, typed by their OMPL type suffix. */
        py::dict properties;
    };

    /** \brief One robot's motion as breakpoints (TimedPath::appendBreakpoints: where a straight motion or a hold
        starts or ends, and the arrival) with the configuration at each; linear in between, this is the plan's
        motion. */
    py::tuple waypoints(const MultiRobotPlan &plan, std::size_t robot)
    {
        if (robot >= plan.getRobotCount())
            throw std::invalid_argument("no robot " + std::to_string(robot) + " (the plan has " +
                                        std::to_string(plan.getRobotCount()) + ")");
        const TimedPath &path = plan.getPath(robot);
        std::vector<std::size_t> times{0, path.getArrival()};
        path.appendBreakpoints(times);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        const auto d = static_cast<py::ssize_t>(plan.getDimension(robot));
        py::array_t<std::int64_t> t(static_cast<py::ssize_t>(times.size()));
        py::array_t<double> q({static_cast<py::ssize_t>(times.size()), d});
        for (std::size_t i = 0; i < times.size(); ++i)
        {
            t.mutable_at(i) = static_cast<std::int64_t>(times[i]);
            plan.getConfig(robot, times[i], q.mutable_data(i, 0));
        }
        return py::make_tuple(t, q);
    }

    /** \brief Robot \e robot's configuration at every timestep from 0 to its arrival, one row each. */
    py::array_t<double> dense(const MultiRobotPlan &plan, std::size_t robot)
    {
        if (robot >= plan.getRobotCount())
            throw std::invalid_argument("no robot " + std::to_string(robot));
        const std::vector<double> flat = plan.getRobotPath(robot);
        const auto d = static_cast<py::ssize_t>(plan.getDimension(robot));
        py::array_t<double> q({static_cast<py::ssize_t>(flat.size()) / d, d});
        std::copy(flat.begin(), flat.end(), q.mutable_data());
        return q;
    }

    py::array_t<double> array(const std::vector<double> &values)
    {
        return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
    }

    /** \brief The "name TYPE" properties as {name: value} with REAL as float, INTEGER as int, BOOLEAN as bool. */
    py::dict typedProperties(const std::map<std::string, std::string> &properties)
    {
        py::dict out;
        for (const auto &[key, value] : properties)
        {
            const auto space = key.rfind(' ');
            const std::string name = space == std::string::npos ? key : key.substr(0, space),
                              type = space == std::string::npos ? "" : key.substr(space + 1);
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

    /** \brief Solves \e problem with registry planner \e name and \e params ("key=value") for at most \e timeLimit
        seconds, the GIL released; Ctrl-C stops the planner (all workers joined) and raises KeyboardInterrupt. */
    SolveResult solve(const MultiRobotProblem &problem, const std::string &name, double timeLimit,
                      const std::vector<std::string> &params)
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

    /** \brief Runs benchmark configuration \e path (BenchmarkRunner), the GIL released; returns the CSV's path and
        the summary table. With \e verbose a line per run goes to stderr. */
    py::tuple runBenchmark(const std::string &path, bool verbose)
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
}  // namespace

PYBIND11_MODULE(_ompl_parc, m)
{
    m.doc() = "The compiled part of ompl_parc (see ompl_parc's own docstrings).";
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // Bad input is a ValueError with the tools' one-line message (the scenario reader's own errors are
    // ompl::Exceptions).
    py::register_exception_translator(
        [](std::exception_ptr error)
        {
            try
            {
                if (error)
                    std::rethrow_exception(error);
            }
            catch (const ompl::Exception &e)
            {
                PyErr_SetString(PyExc_ValueError, e.what());
            }
        });

    m.attr("__version__") = OMPL_PARC_VERSION;
    m.attr("OMPL_VERSION") = OMPL_PARC_OMPL_VERSION;
    m.def("planner_names", &PlannerRegistry::names);
    m.def("scenario_names", &scenarios::scenarioNames);
    m.def(
        "planner_parameters",
        [](const std::string &name)
        {
            // The declared parameters do not depend on the team: a planner on a two-disc team tells them.
            const auto planner = PlannerRegistry::create(name, scenarios::createMobileCross(2).getSpaceInformation());
            std::map<std::string, std::string> ranges;
            for (const auto &[key, parameter] : planner->params().getParams())
                ranges[key] = parameter->getRangeSuggestion();
            return ranges;
        },
        py::arg("name"),
        "The declared parameters of the registry planner named name with their ranges (\"1:1:64\", \"0,1\", "
        "\"linear,exponential\", or \"\" where none is declared): the keywords solve() takes.");
    m.def("set_log_level", [](int level) { ompl::msg::setLogLevel(static_cast<ompl::msg::LogLevel>(level)); });

    py::class_<MultiRobotProblem>(m, "Problem")
        .def_static(
            "scenario",
            [](const std::string &name, std::size_t robots, std::size_t task, double resolution)
            {
                MultiRobotProblem problem = scenarios::createScenario(name, robots, resolution, task);
                if (const std::string reason = problem.checkEndpoints(); !reason.empty())
                    throw std::invalid_argument(reason);
                return problem;
            },
            py::arg("name"), py::arg("robots"), py::arg("task") = 0, py::arg("resolution") = 128.)
        .def_static("load", &ScenarioFile::read, py::arg("path"))
        .def_static("from_json", &ScenarioFile::fromJson, py::arg("text"), py::arg("folder") = "")
        .def("save",
             [](const MultiRobotProblem &problem, const std::string &path) { ScenarioFile::write(path, problem); })
        .def("to_json", &ScenarioFile::toJson)
        .def_property_readonly("name", &MultiRobotProblem::getName)
        .def_property_readonly("robot_count", &MultiRobotProblem::getRobotCount)
        .def_property_readonly("resolution",
                               [](const MultiRobotProblem &p) { return p.getSpaceInformation()->getResolution(); })
        .def_property_readonly("robot_names",
                               [](const MultiRobotProblem &p)
                               {
                                   std::vector<std::string> names;
                                   for (const auto &robot : p.getSpaceInformation()->getRobots())
                                       names.push_back(robot->getName());
                                   return names;
                               })
        .def("start", [](const MultiRobotProblem &p, std::size_t i) { return array(p.getStart(i)); })
        .def("goal", [](const MultiRobotProblem &p, std::size_t i) { return array(p.getGoal(i)); })
        .def("check", &MultiRobotProblem::checkEndpoints);

    py::class_<MultiRobotPlan>(m, "Plan")
        .def_property_readonly("robot_count", &MultiRobotPlan::getRobotCount)
        .def_property_readonly("makespan", &MultiRobotPlan::getMakespan)
        .def_property_readonly("sum_of_costs", &MultiRobotPlan::getSumOfCosts)
        .def_property_readonly("resolution", &MultiRobotPlan::getResolution)
        .def("arrival", &MultiRobotPlan::getArrival)
        .def("waypoints", &waypoints, py::arg("robot"))
        .def("dense", &dense, py::arg("robot"))
        .def(
            "at",
            [](const MultiRobotPlan &plan, std::size_t robot, std::size_t t)
            {
                std::vector<double> q(plan.getDimension(robot));
                plan.getConfig(robot, t, q.data());
                return array(q);
            },
            py::arg("robot"), py::arg("t"));

    py::class_<SolveResult>(m, "SolveResult")
        .def_readonly("status", &SolveResult::status)
        .def_readonly("solved", &SolveResult::solved)
        .def_readonly("planner", &SolveResult::planner)
        .def_readonly("time", &SolveResult::time)
        .def_readonly("plan", &SolveResult::plan)
        .def_readonly("properties", &SolveResult::properties);
    m.def("solve", &solve, py::arg("problem"), py::arg("planner"), py::arg("time_limit"), py::arg("params"));

    py::class_<ValidationReport>(m, "Validation")
        .def_readonly("valid", &ValidationReport::valid)
        .def_readonly("message", &ValidationReport::message)
        .def("__bool__", [](const ValidationReport &r) { return r.valid; });
    m.def(
        "validate",
        [](const MultiRobotProblem &problem, const MultiRobotPlan &plan, unsigned int substeps)
        {
            ValidationOptions options;
            options.substeps = substeps;
            const py::gil_scoped_release released;
            return SolutionValidator(problem, options).validate(plan);
        },
        py::arg("problem"), py::arg("plan"), py::arg("substeps") = 4);

    m.def("write_solution", [](const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan &plan)
          { SolutionFile::write(path, plan, *problem.getSpaceInformation()); });
    m.def("read_solution", [](const std::string &path, const MultiRobotProblem &problem)
          { return SolutionFile::read(path, *problem.getSpaceInformation()); });
    m.def(
        "write_svg",
        [](const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan, bool animate)
        {
            SvgOptions options;
            options.animate = animate;
            SvgWriter::write(path, problem, plan, options);
        },
        py::arg("path"), py::arg("problem"), py::arg("plan") = nullptr, py::arg("animate") = true);
    m.def("run_benchmark", &runBenchmark, py::arg("path"), py::arg("verbose") = false);
}
