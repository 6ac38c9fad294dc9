#include "ompl_parc/arc/RepairCache.h"

#include <algorithm>

void ompl_parc::RepairCache::add(const std::vector<std::size_t> &team, std::size_t from, std::size_t to)
{
    for (std::size_t a = 0; a < team.size(); ++a)
        for (std::size_t b = a + 1; b < team.size(); ++b)
            intervals_[{std::min(team[a], team[b]), std::max(team[a], team[b])}].emplace_back(from, to);
}

std::vector<std::size_t> ompl_parc::RepairCache::expand(const Conflict &conflict, std::size_t halfWidth) const
{
    const std::size_t lo = conflict.timestep > halfWidth ? conflict.timestep - halfWidth : 0;
    const std::size_t hi = conflict.timestep + halfWidth;
    std::vector<std::size_t> team = {conflict.first, conflict.second};
    // Breadth-first over cached pairs: a robot joins if it shares an overlapping repair with a member.
    for (std::size_t k = 0; k < team.size(); ++k)
        for (const auto &[pair, spans] : intervals_)
        {
            std::size_t other;
            if (pair.first == team[k])
                other = pair.second;
            else if (pair.second == team[k])
                other = pair.first;
            else
                continue;
            if (std::find(team.begin(), team.end(), other) != team.end())
                continue;
            if (std::any_of(spans.begin(), spans.end(), [&](const auto &s) { return s.first <= hi && s.second >= lo; }))
                team.push_back(other);
        }
    std::sort(team.begin(), team.end());
    return team;
}
