/* The compiled part of the Python module ompl_parc (_ompl_parc): problems, planners by name, plans as NumPy arrays,
   the independent validator, solution files, pictures and benchmarks. python/package/ompl_parc/__init__.py wraps
   it with keyword arguments, type hints and docstrings. Bad input raises ValueError with the tools' one-line message.
 */
#include "Solve.h"

#include "ompl_parc/Version.h"
#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/io/TrajectoryFile.h"
#include "ompl_parc/io/HtmlWriter.h"
#include "ompl_parc/io/SvgWriter.h"
#include "ompl_parc/planners/setup/PlannerRegistry.h"
#include "ompl_parc/scenarios/Scenarios.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>

namespace py = pybind11;
using namespace ompl_parc;

namespace
{
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

    py::class_<python::SolveResult>(m, "SolveResult")
        .def_readonly("status", &python::SolveResult::status)
        .def_readonly("solved", &python::SolveResult::solved)
        .def_readonly("planner", &python::SolveResult::planner)
        .def_readonly("time", &python::SolveResult::time)
        .def_readonly("plan", &python::SolveResult::plan)
        .def_readonly("properties", &python::SolveResult::properties);
    m.def("solve", &python::solve, py::arg("problem"), py::arg("planner"), py::arg("time_limit"), py::arg("params"));

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
    m.def(
        "write_html",
        [](const std::string &path, const MultiRobotProblem &problem, const MultiRobotPlan *plan)
        { HtmlWriter::write(path, problem, plan); },
        py::arg("path"), py::arg("problem"), py::arg("plan") = nullptr);
    m.def(
        "trajectory_json",
        [](const MultiRobotProblem &problem, const MultiRobotPlan &plan, std::size_t phaseSteps, double maxDeviation)
        {
            const py::gil_scoped_release released;
            return TrajectoryFile::fromPlan(problem, plan, phaseSteps, maxDeviation).dump();
        },
        py::arg("problem"), py::arg("plan"), py::arg("phase_steps") = 4,
        py::arg("max_deviation") = TimeParameterization::DEFAULT_MAX_DEVIATION);
    m.def("run_benchmark", &python::runBenchmark, py::arg("path"), py::arg("verbose") = false);
}
