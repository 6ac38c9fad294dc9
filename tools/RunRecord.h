#ifndef OMPL_PARC_DEMOS_RUN_RECORD_
#define OMPL_PARC_DEMOS_RUN_RECORD_

#include <ompl/tools/benchmark/Benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ompl_parc::tools
{
    /** \brief One benchmark run as OMPL's Benchmark recorded it, with what is needed to put it back in its place: a
        run done anywhere (another thread, another MPI rank) merges into the same experiment log and CSV as if one
        process had done them all. Text only, so that it travels as JSON. */
    struct RunRecord
    {
        /** \brief Its place: the problem (task) index, the planner index (configuration order) and the run index. */
        std::size_t instance{0}, planner{0}, run{0};
        /** \brief Whether the planner's solution was refused by the independent validator. */
        bool invalid{false};
        /** \brief The planner's name as OMPL's log has it ("geometric_" + its name). */
        std::string plannerName;
        /** \brief The run's properties, and its planner's common properties (its parameters), as OMPL recorded. */
        ompl::tools::Benchmark::RunProperties properties, common;
        /** \brief The planner's progress properties' names and this run's samples of them. */
        std::vector<std::string> progressNames;
        ompl::tools::Benchmark::RunProgressData progress;
        /** \brief The machine it ran on, the SimpleSetup's description and OMPL's program seed there. */
        std::string host, cpuInfo, setupInfo;
        std::uint64_t programSeed{0};
        /** \brief When the run started (seconds since the epoch) and how long it took with its validation. */
        double started{0.}, duration{0.};

        /** \brief One line of JSON (no line break inside). */
        std::string toJson() const;
        /** \brief Throws std::invalid_argument on text that toJson() did not write. */
        static RunRecord fromJson(const std::string &text);
    };
}  // namespace ompl_parc::tools

#endif
