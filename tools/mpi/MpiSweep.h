#ifndef OMPL_PARC_DEMOS_MPI_SWEEP_
#define OMPL_PARC_DEMOS_MPI_SWEEP_

#include "MpiSession.h"

#include <string>

namespace ompl_parc::tools
{
    /** \brief A benchmark configuration's runs shared over MPI ranks: every rank reads the configuration and builds
        its problems and planners (BenchmarkRunner), runs its share (runs k = rank, rank + K, ...: static, so any
        rank can tell which runs are whose), and sends the records (RunRecord, JSON) to rank 0, which writes the
        .log and CSV exactly as a single process (ompl_parc_benchmark) would: the same rows, in the same order. */
    class MpiSweep
    {
      public:
        explicit MpiSweep(const MpiSession &session) : session_(session) {}

        /** \brief Runs the configuration at \e path (a collective call); returns this rank's exit code (as
            ompl_parc_benchmark's: rank 0 has the verdict, the others return 0 unless the input is bad). */
        int run(const std::string &path);

      private:
        const MpiSession &session_;
    };
}  // namespace ompl_parc::tools

#endif
