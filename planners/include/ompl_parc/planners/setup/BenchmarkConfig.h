#ifndef OMPL_PARC_PLANNERS_SETUP_BENCHMARK_CONFIG_
#define OMPL_PARC_PLANNERS_SETUP_BENCHMARK_CONFIG_

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief One planner of a benchmark: a registry planner with parameters by their declared names. */
    struct BenchmarkPlanner
    {
        /** \brief The key declaring it in [planner] (unique in the file). */
        std::string label;
        /** \brief The registry name (PlannerRegistry::names()). */
        std::string type;
        /** \brief The name in the log and the CSV: "label.name", else the label. */
        std::string name;
        /** \brief "key=value" assignments, in file order, for PlannerRegistry::create(). */
        std::vector<std::string> params;
    };

    /** \brief A benchmark configuration in OMPL.app's INI format (read with Boost.PropertyTree), so that one
        file describes a whole experiment and the results can be reproduced from it.

        \code
        [problem]
        # experiment name: the results go to <output>/<name>.log and <output>/<name>.csv
        name = mobile_cross_8
        # a built-in scenario (scenarios::scenarioNames()) and its team size
        scenario = mobile_cross
        robots = 8
        # optional: timesteps per unit of distance (128)
        resolution = 128
        # optional: the scenario's task (0), and how many consecutive tasks to run (1): with a generated
        # family (ProblemFamilies.h) "instances = 20" runs every planner run_count times on each of 20 random
        # instances, logs each to <output>/<name>_<task>.log and reports success rate and median time per
        # planner over all of them
        task = 0
        instances = 1
        # or instead of scenario, robots and resolution: a scenario file (ScenarioFile.h), relative to the
        # config file's folder
        file = ../../scenarios/doorway_swap.json

        [benchmark]
        time_limit = 30
        mem_limit = 4096
        run_count = 30
        # optional: relative to the config file's folder, which is also the default
        output = results
        # optional: run j of every planner gets seed + j (1)
        seed = 1
        # optional worker budget (this machine's hardware threads); a planner needing more is an error
        workers = 16

        [planner]
        # OMPL.app's "planner=": the label is the registry name
        arc =
        parc =
        # parameters by declared name, as OMPL.app's "rrt.range=50", and OMPL.app's renaming "name"
        parc.workers = 2
        parc.name = P-ARC-2
        # a second P-ARC: a new label whose value is the registry name
        parc4 = parc
        parc4.workers = 4
        \endcode

        Differences from OMPL.app, forced by PropertyTree's INI parser, which rejects duplicate keys: OMPL.app
        repeats "rrtconnect=" for a second instance and applies the following parameter lines to it; here
        every planner has a unique label and names its registry planner in the value when the label differs.
        Comments are whole lines starting with '#' or ';'.
        Unknown sections, keys, labels and planner names, malformed numbers and out-of-range values throw
        std::invalid_argument with a one-line reason naming the valid choices. Planner parameter names are
        checked when the planners are created (PlannerRegistry::create()). */
    class BenchmarkConfig
    {
      public:
        /** \brief Reads \e path; a relative output folder is taken relative to the file's folder. */
        static BenchmarkConfig read(const std::string &path);
        /** \brief Parses \e in; \e folder is the folder the output is relative to. */
        static BenchmarkConfig parse(std::istream &in, const std::string &folder);

        const std::string &getProblemName() const { return problemName_; }
        const std::string &getScenario() const { return scenario_; }
        std::size_t getRobots() const { return robots_; }
        /** \brief The first task of the scenario, and how many consecutive tasks make the experiment. */
        std::size_t getTask() const { return task_; }
        std::size_t getInstances() const { return instances_; }
        double getResolution() const { return resolution_; }
        const std::string &getScenarioFile() const { return scenarioFile_; }

        double getTimeLimit() const { return timeLimit_; }
        double getMemLimit() const { return memLimit_; }
        unsigned int getRunCount() const { return runCount_; }
        const std::string &getOutput() const { return output_; }
        unsigned int getSeed() const { return seed_; }
        unsigned int getWorkers() const { return workers_; }

        const std::vector<BenchmarkPlanner> &getPlanners() const { return planners_; }

      private:
        std::string problemName_, scenario_, scenarioFile_;
        std::size_t robots_{0}, task_{0}, instances_{1};
        double resolution_{128.};
        double timeLimit_{0.}, memLimit_{0.};
        unsigned int runCount_{0};
        std::string output_;
        unsigned int seed_{1};
        unsigned int workers_{1};
        std::vector<BenchmarkPlanner> planners_;
    };
}  // namespace ompl_parc

#endif
