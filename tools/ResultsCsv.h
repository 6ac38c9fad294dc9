#ifndef OMPL_PARC_DEMOS_RESULTS_CSV_
#define OMPL_PARC_DEMOS_RESULTS_CSV_

#include <map>
#include <ostream>
#include <string>

namespace ompl_parc::tools
{
    /** \brief What a benchmark run's CSV row says besides the planner's properties. */
    struct CsvRun
    {
        /** \brief The scenario's name (built-in key, scenario file's name, or generated instance's). */
        std::string scenario;
        std::size_t robots{0}, task{0};
        unsigned int seed{0}, workers{1};
        /** \brief The planner's name in the results and its registry name. */
        std::string method, type;
        double timeLimit{0.};
        bool success{false};
        /** \brief OMPL's status text. */
        std::string status;
    };

    /** \brief The benchmark's results as CSV, one row per run: first the columns of the P-ARC authors' published
        runner (results.csv: case, case_title, task_index, seed, method, time_limit_seconds, success,
        first_solution_time_seconds, planning_time_seconds, makespan_timesteps, sum_of_cost_timesteps,
        metrics_json), so that their results and ours go through the same plotting; then ours (scenario, robots,
        type, workers, status, the quality ratios, per-stage times, P-ARC's batch counters, memory) and the
        ompl_parc version. metrics_json holds every property OMPL's Benchmark recorded for the run. */
    class ResultsCsv
    {
      public:
        /** \brief Writes the header line to \e out (kept by reference). */
        explicit ResultsCsv(std::ostream &out);
        /** \brief Writes the row of \e run with the properties \e properties ("name TYPE" → value, as in OMPL's
            Benchmark::RunProperties). */
        void write(const CsvRun &run, const std::map<std::string, std::string> &properties);

      private:
        std::ostream &out_;
    };
}  // namespace ompl_parc::tools

#endif
