#include "MpiSweep.h"

#include "BenchmarkRunner.h"
#include "ToolSupport.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <optional>

using json = nlohmann::json;

int ompl_parc::tools::MpiSweep::run(const std::string &path)
{
    // Every input error shows on every rank (they read the same files); rank 0's output check is its own. Agreed
    // before any run, so a bad config ends every rank with exit code 2 and rank 0's one line.
    std::optional<BenchmarkRunner> runner;
    std::string error;
    try
    {
        runner.emplace(BenchmarkConfig::read(path));
        if (session_.isRoot())
            runner->checkOutput();
    }
    catch (const std::exception &e)
    {
        error = e.what();
    }
    const std::string agreed = session_.agree(error);
    if (!agreed.empty())
    {
        if (session_.isRoot())
            std::cerr << "ompl_parc_mpi: " << agreed << std::endl;
        return EXIT_BAD_INPUT;
    }

    const auto ranks = static_cast<std::size_t>(session_.size()), rank = static_cast<std::size_t>(session_.rank());
    if (session_.isRoot())
        std::cerr << "ompl_parc_mpi: " << runner->describe() << ", " << runner->getRunCount() << " runs over " << ranks
                  << " ranks" << std::endl;
    const std::vector<RunRecord> mine = runner->runShare(rank, ranks, std::cerr);
    json texts = json::array();
    for (const RunRecord &record : mine)
        texts.push_back(record.toJson());
    const auto shares = session_.gather(texts.dump(), TAG_RUNS);
    if (!session_.isRoot())
        return EXIT_SOLVED;
    std::vector<RunRecord> records;
    for (const std::string &share : shares)
        for (const auto &text : json::parse(share))
            records.push_back(RunRecord::fromJson(text.get<std::string>()));
    const BenchmarkResults results = runner->write(std::move(records), std::cerr);
    std::cout << results.summary;
    return results.invalid ? EXIT_FAILED : EXIT_SOLVED;
}
