#include "ompl_parc/arc/ArcProgress.h"

void ompl_parc::ArcProgress::reset()
{
    stage_ = 0;
    robotsPlanned_ = conflictsFound_ = conflictsResolved_ = batches_ = solverCalls_ = 0;
    makespan_ = 0;
    start_ = 0;
}

void ompl_parc::ArcProgress::startSolve()
{
    start_ = std::chrono::steady_clock::now().time_since_epoch().count();
}

void ompl_parc::ArcProgress::reachStage(Stage stage)
{
    int current = stage_.load();
    while (current < static_cast<int>(stage) && !stage_.compare_exchange_weak(current, static_cast<int>(stage)))
    {
    }
}

double ompl_parc::ArcProgress::getElapsed() const
{
    const auto start = start_.load();
    if (start == 0)
        return 0.;
    const std::chrono::steady_clock::duration since(std::chrono::steady_clock::now().time_since_epoch().count() -
                                                    start);
    return std::chrono::duration<double>(since).count();
}

const char *ompl_parc::ArcProgress::stageName(Stage stage)
{
    switch (stage)
    {
        case Stage::IDLE:
            return "idle";
        case Stage::INITIAL:
            return "initial";
        case Stage::RESOLVING:
            return "resolving";
        case Stage::SMOOTHING:
            return "smoothing";
        case Stage::SOLVED:
            return "solved";
    }
    return "unknown";
}

std::map<std::string, std::function<std::string()>> ompl_parc::ArcProgress::properties() const
{
    const auto count = [](const auto &value) { return [&value] { return std::to_string(value.load()); }; };
    return {
        {"stage INTEGER", count(stage_)},
        {"robots planned INTEGER", count(robotsPlanned_)},
        {"conflicts found INTEGER", count(conflictsFound_)},
        {"conflicts resolved INTEGER", count(conflictsResolved_)},
        {"batches detected INTEGER", count(batches_)},
        {"solver calls made INTEGER", count(solverCalls_)},
        {"current makespan INTEGER", count(makespan_)},
        {"elapsed REAL", [this] { return std::to_string(getElapsed()); }},
    };
}
