#include "MpiRace.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <thread>

namespace ob = ompl::base;
using json = nlohmann::json;

namespace
{
    /** \brief How often a rank's main thread looks for messages and for its planner's return: a stop reaches a
        planner within about this plus the network's latency. */
    constexpr std::chrono::milliseconds POLL_PERIOD{1};
}  // namespace

double ompl_parc::tools::MpiRace::getElapsed() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ompl_parc::tools::MpiRace::run(const Solve &solve, const Describe &describe, double timeLimit)
{
    winner_ = failed_ = -1;
    claims_.clear();
    session_.barrier();  // a common start: every rank has its problem and planner
    start_ = std::chrono::steady_clock::now();

    std::atomic<bool> stopped{false}, returned{false};
    ob::PlannerStatus status;
    std::string reason;
    double returnedAfter = 0.;
    const ob::PlannerTerminationCondition ptc =
        ob::plannerOrTerminationCondition(ob::timedPlannerTerminationCondition(timeLimit),
                                          ob::PlannerTerminationCondition([&] { return stopped.load(); }));
    std::thread planner(
        [&]
        {
            try
            {
                status = solve(ptc);
                reason = status.asString();
            }
            catch (const std::exception &e)
            {
                status = ob::PlannerStatus::CRASH;
                reason = e.what();
            }
            catch (...)
            {
                status = ob::PlannerStatus::CRASH;
                reason = "an exception that is not a std::exception";
            }
            returnedAfter = getElapsed();
            returned = true;
        });
    const auto claim = [&]
    {
        return json{{"status", static_cast<int>(ob::PlannerStatus::StatusType(status))},
                    {"reason", reason},
                    {"returned_after", returnedAfter},
                    {"report", status == ob::PlannerStatus::CRASH ? std::string("{}") : describe()}}
            .dump();
    };
    const auto stop = [&]
    {
        stopped = true;
        planner.join();
    };
    try
    {
        if (session_.isRoot())
            referee([&] { return returned.load(); }, claim, stop);
        else
            play([&] { return returned.load(); }, claim, stop);
    }
    catch (...)
    {
        if (planner.joinable())
            stop();
        throw;
    }
}

void ompl_parc::tools::MpiRace::referee(const std::function<bool()> &returned,
                                        const std::function<std::string()> &claim, const std::function<void()> &stop)
{
    claims_.assign(static_cast<std::size_t>(session_.getSize()), Claim{});
    std::vector<bool> claimed(claims_.size(), false);
    std::size_t count = 0;
    bool decided = false;
    const auto take = [&](int rank, const std::string &text)
    {
        const json j = json::parse(text);
        Claim &c = claims_.at(static_cast<std::size_t>(rank));
        c.status = ob::PlannerStatus(static_cast<ob::PlannerStatus::StatusType>(j.at("status").get<int>()));
        c.reason = j.at("reason").get<std::string>();
        c.returnedAfter = j.at("returned_after").get<double>();
        c.report = j.at("report").get<std::string>();
        claimed[rank] = true;
        ++count;
        if (decided)
            return;
        if (c.status == ob::PlannerStatus::EXACT_SOLUTION)
            winner_ = rank;
        else if (c.status == ob::PlannerStatus::CRASH)
            failed_ = rank;
        decided = winner_ >= 0 || failed_ >= 0 || count == claims_.size();
    };
    while (!decided)
    {
        if (returned() && !claimed[0])
            take(0, claim());
        while (!decided)
        {
            const auto message = session_.tryReceive(TAG_CLAIM);
            if (!message)
                break;
            take(message->first, message->second);
        }
        if (!decided)
            std::this_thread::sleep_for(POLL_PERIOD);
    }
    std::vector<MpiSession::PendingSend> ends(claims_.size());
    const std::string end = json{{"winner", winner_}, {"failed", failed_}}.dump();
    for (int r = 1; r < session_.getSize(); ++r)
        ends[r].start(end, r, TAG_END);
    stop();
    if (!claimed[0])
        take(0, claim());
    while (count < claims_.size())
    {
        const auto [rank, text] = session_.receive(MPI_ANY_SOURCE, TAG_CLAIM);
        take(rank, text);
    }
    for (auto &send : ends)
        send.complete();
}

void ompl_parc::tools::MpiRace::play(const std::function<bool()> &returned, const std::function<std::string()> &claim,
                                     const std::function<void()> &stop)
{
    MpiSession::PendingSend sent;
    std::string end;
    for (;;)
    {
        if (returned() && !sent.started())
            sent.start(claim(), 0, TAG_CLAIM);
        if (auto message = session_.tryReceive(TAG_END))
        {
            end = std::move(message->second);
            break;
        }
        std::this_thread::sleep_for(POLL_PERIOD);
    }
    stop();
    if (!sent.started())
        sent.start(claim(), 0, TAG_CLAIM);
    sent.complete();
    const json outcome = json::parse(end);
    winner_ = outcome.at("winner").get<int>();
    failed_ = outcome.at("failed").get<int>();
}
