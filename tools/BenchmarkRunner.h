#ifndef OMPL_PARC_DEMOS_BENCHMARK_RUNNER_
#define OMPL_PARC_DEMOS_BENCHMARK_RUNNER_

#include "RunRecord.h"

#include "ompl_parc/model/MultiRobotProblem.h"
#include "ompl_parc/planners/setup/BenchmarkConfig.h"
#include "ompl_parc/validation/SolutionValidator.h"

#include <ompl/base/Planner.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace ompl_parc::tools
{
    /** \brief What a benchmark wrote and found. */
    struct BenchmarkResults
    {
        /** \brief The CSV (one row per run, ResultsCsv) and the OMPL logs written (one per task whose runs all
            ended: every task's unless the runs were stopped). */
        std::filesystem::path csv;
        std::vector<std::filesystem::path> logs;
        /** \brief The runs done (the CSV's rows). */
        std::size_t runs{0};
        /** \brief Solutions the independent validator refused (each also a failed run). */
        std::size_t invalid{0};
        /** \brief Success rate, median time and median makespan ratio per planner, as a Markdown table. */
        std::string summary;
    };

    /** \brief One problem of the experiment, its CSV scenario label, the planners made for it and the independent
        validator that re-checks their solutions (made once per problem, used for every run). */
    struct Instance
    {
        MultiRobotProblem problem;
        std::string scenario;
        std::size_t task{0};
        std::vector<ompl::base::PlannerPtr> planners;
        std::shared_ptr<const SolutionValidator> validator;
    };

    /** \brief Runs a benchmark configuration (BenchmarkConfig) with OMPL's own ompl::tools::Benchmark, one run at a
        time (so that the runs can be shared among processes, runShare(), and merged, write()): run j of every planner
        seeded with [benchmark] seed + j, every solution re-checked by the independent
        SolutionValidator. Writes <output>/<name>.log (OMPL's log format, for ompl_benchmark_statistics; with
        [problem] instances = N one per task, <name>_<task>.log) and <output>/<name>.csv. The tool and the Python
        module run benchmarks through it. */
    class BenchmarkRunner
    {
      public:
        /** \brief Builds every problem and planner of \e config: every input error (a bad scenario, planner,
            parameter or worker budget) throws here, before any run. */
        explicit BenchmarkRunner(BenchmarkConfig config);
        ~BenchmarkRunner();

        /** \brief "NAME: K problem(s) of N robots, P planners, config ok". */
        std::string describe() const;

        /** \brief Runs everything, one line per run on \e log, each run's CSV row written as it ends; throws
            std::invalid_argument if the output cannot be written (checked before the first run). Writes what
            write(runShare(0, 1, log), log) would. Once \e stopped (if given) returns true, no further run starts
            (the one in progress ends at its time limit: OMPL's Benchmark owns its termination condition) and what
            the runs done make is written: their CSV rows, the logs of the tasks whose runs all ended. */
        BenchmarkResults run(std::ostream &log, const std::function<bool()> &stopped = {});

        /** \brief The number of runs in all: problems x planners x run_count. */
        std::size_t getRunCount() const;
        /** \brief Creates the output folder and checks that the logs and the CSV can be written there (returns their
            paths, the CSV last); throws std::invalid_argument otherwise. */
        std::vector<std::filesystem::path> checkOutput() const;
        /** \brief Runs share \e rank of \e ranks: the runs k = rank, rank + ranks, ... of all runs in OMPL's order
            (problem, then planner, then run index), one line each on \e log. Run j of a planner is seeded with
            [benchmark] seed + j in any share, so a run gives the same result wherever it runs (planners without a
            seed parameter draw from OMPL's global sequence, which depends on what ran before). */
        std::vector<RunRecord> runShare(std::size_t rank, std::size_t ranks, std::ostream &log);
        /** \brief Writes \e records (every share's, in any order) as one experiment: the OMPL logs and the CSV in
            OMPL's order, the summary; as if one process had run them all. */
        BenchmarkResults write(std::vector<RunRecord> records, std::ostream &log) const;

      private:
        /** \brief Runs share \e rank of \e ranks (see runShare()), handing each run's record to \e take as it ends;
            none starts once \e stopped (if given) returns true. */
        void runRuns(std::size_t rank, std::size_t ranks, std::ostream &log, const std::function<void(RunRecord)> &take,
                     const std::function<bool()> &stopped = {});

        BenchmarkConfig config_;
        std::vector<Instance> instances_;
        /** \brief The planners without a seed parameter (warned about on rank 0's log). */
        std::vector<std::string> seedless_;
    };
}  // namespace ompl_parc::tools

#endif
