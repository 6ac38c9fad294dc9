#include "ompl_parc/arc/ConflictBatch.h"

#include <algorithm>

ompl_parc::ConflictBatch::ConflictBatch(bool optimistic, std::size_t capacity, std::size_t robots)
    : optimistic_(optimistic), capacity_(std::max<std::size_t>(capacity, 1)), inBatch_(robots, 0), involved_(robots, 0)
{
}

bool ompl_parc::ConflictBatch::offer(const Conflict &conflict, std::vector<std::size_t> team)
{
    const auto contains = [&team](std::size_t r) { return std::find(team.begin(), team.end(), r) != team.end(); };
    bool accept = !full() && std::none_of(team.begin(), team.end(), [this](std::size_t r) { return inBatch_[r]; });
    if (optimistic_)
    {
        // Every earlier deferred conflict sharing robots with this one must have all its unexplained robots
        // inside this team (then the robots outside the shared set were in the batch back then).
        for (const auto &unexplained : unexplained_)
        {
            const bool shares = std::any_of(unexplained.begin(), unexplained.end(), contains);
            if (shares && !std::all_of(unexplained.begin(), unexplained.end(), contains))
                accept = false;
        }
    }
    else
        accept = accept && std::none_of(team.begin(), team.end(), [this](std::size_t r) { return involved_[r]; });

    for (std::size_t r : team)
        involved_[r] = 1;
    if (!accept)
    {
        std::vector<std::size_t> unexplained;
        for (std::size_t r : team)
            if (!inBatch_[r])
                unexplained.push_back(r);
        if (!unexplained.empty())
            unexplained_.push_back(std::move(unexplained));
        return false;
    }
    for (std::size_t r : team)
        inBatch_[r] = 1;
    entries_.push_back({conflict, std::move(team)});
    return true;
}

bool ompl_parc::ConflictBatch::skipPair(std::size_t i, std::size_t j) const
{
    if (optimistic_)
        return inBatch_[i] || inBatch_[j];
    return involved_[i] && involved_[j];
}
