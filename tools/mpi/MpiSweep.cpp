#include "MpiSweep.h"

#include "BenchmarkRunner.h"
#include "ToolSupport.h"

#include <iostream>
#include <optional>
#include <sstream>

int ompl_parc::tools::MpiSweep::run(const std::string &path)
{
    // Every input error shows on every rank (they read the same files); the output check is rank 0's. Agreed before
    // any run, so that a bad config ends every rank with exit code 2 and rank 0's one line.
    std::optional<BenchmarkRunner> runner;
    const std::string error = session_.agree(MpiSession::errorOf(
        [&]
        {
            runner.emplace(BenchmarkConfig::read(path));
            if (session_.isRoot())
                runner->checkOutput();
        }));
    if (!error.empty())
    {
        if (session_.isRoot())
            printError("ompl_parc_mpi", error);
        return EXIT_BAD_INPUT;
    }

    const auto ranks = static_cast<std::size_t>(session_.getSize());
    const auto rank = static_cast<std::size_t>(session_.getRank());
    if (session_.isRoot())
        std::cerr << "ompl_parc_mpi: " << runner->describe() << ", " << runner->getRunCount() << " runs over " << ranks
                  << " ranks" << std::endl;
    // Each rank's records as JSON lines (a record's JSON holds no line break).
    std::string mine;
    for (const RunRecord &record : runner->runShare(rank, ranks, std::cerr))
        mine += record.toJson() + "\n";
    const auto shares = session_.gather(mine, TAG_RUNS);
    if (!session_.isRoot())
        return EXIT_SOLVED;
    std::vector<RunRecord> records;
    for (const std::string &share : shares)
    {
        std::istringstream lines(share);
        for (std::string line; std::getline(lines, line);)
            records.push_back(RunRecord::fromJson(line));
    }
    const BenchmarkResults results = runner->write(std::move(records), std::cerr);
    std::cout << results.summary;
    return results.invalid ? EXIT_FAILED : EXIT_SOLVED;
}
