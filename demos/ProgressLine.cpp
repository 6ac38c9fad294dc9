#include "ProgressLine.h"

#include <unistd.h>

#include <cstdio>

ompl_parc::tools::ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now())
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

void ompl_parc::tools::ProgressLine::run()
{
    bool shown = false;
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; }))
    {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (elapsed < 1.)
            continue;
        std::fprintf(stderr, "\r%s %.1f s elapsed", label_.c_str(), elapsed);
        std::fflush(stderr);
        shown = true;
    }
    if (shown)
    {
        std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 24, "");
        std::fflush(stderr);
    }
}
