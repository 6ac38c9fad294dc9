#include "ProgressLine.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

ompl_parc::tools::ProgressLine::ProgressLine(std::string label, const ArcProgress *progress, std::size_t robots)
    : label_(std::move(label)), progress_(progress), robots_(robots), start_(std::chrono::steady_clock::now())
{
    if (isatty(STDOUT_FILENO) != 0)
        thread_ = std::thread([this] { run(); });
}

ompl_parc::tools::ProgressLine::~ProgressLine()
{
    stop();
}

void ompl_parc::tools::ProgressLine::stop()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable())
        thread_.join();
}

std::string ompl_parc::tools::ProgressLine::describe() const
{
    if (progress_ == nullptr)
        return "";
    char text[160];
    switch (progress_->getStage())
    {
        case ArcProgress::Stage::INITIAL:
            // OR-P-ARC's instances each plan every robot: the count is theirs together.
            std::snprintf(text, sizeof(text), ", initial stage: %u robot paths planned (team of %zu)",
                          progress_->getRobotsPlanned(), robots_);
            break;
        case ArcProgress::Stage::RESOLVING:
            std::snprintf(text, sizeof(text), ", resolving: %u of %u conflicts resolved, %u solver calls, makespan %zu",
                          progress_->getConflictsResolved(), progress_->getConflictsFound(),
                          progress_->getSolverCalls(), progress_->getMakespan());
            break;
        default:
            std::snprintf(text, sizeof(text), ", %s", ArcProgress::stageName(progress_->getStage()));
    }
    return text;
}

void ompl_parc::tools::ProgressLine::run()
{
    bool shown = false;
    std::size_t width = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; }))
    {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (elapsed < 1.)
            continue;
        char seconds[32];
        std::snprintf(seconds, sizeof(seconds), " %.1f s", elapsed);
        const std::string line = label_ + seconds + describe();
        // Pad with blanks over the end of a longer previous line.
        std::fprintf(stderr, "\r%-*s", static_cast<int>(std::max(width, line.size())), line.c_str());
        width = std::max(width, line.size());
        std::fflush(stderr);
        shown = true;
    }
    if (shown)
    {
        std::fprintf(stderr, "\r%*s\r", static_cast<int>(width), "");
        std::fflush(stderr);
    }
}
