#include "ompl_parc/parallel/WorkerPool.h"

#include "ompl_parc/parallel/StageClock.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <chrono>
#include <utility>

#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#endif

namespace
{
    /** The cores this process may run on (its affinity mask on Linux, e.g. under taskset or a container's
        cpuset; elsewhere the hardware's count). */
    unsigned int usableCores()
    {
#ifdef __linux__
        cpu_set_t allowed;
        if (sched_getaffinity(0, sizeof(allowed), &allowed) == 0)
            return static_cast<unsigned int>(std::max(1, CPU_COUNT(&allowed)));
#endif
        return std::max(1u, std::thread::hardware_concurrency());
    }

#ifdef __linux__
    /** Let the kernel move the calling thread off \e core to another core of \e allowed (its own mask), then give
        it back \e allowed; false if the mask could not be given back (the thread then stays restricted and must not
        try again). Staying put when there is nowhere to go is not a failure. */
    bool leaveCore(int core, const cpu_set_t &allowed)
    {
        cpu_set_t others = allowed;
        CPU_CLR(core, &others);
        if (CPU_COUNT(&others) == 0 || pthread_setaffinity_np(pthread_self(), sizeof(others), &others) != 0)
            return true;
        for (int attempt = 0; attempt < 3; ++attempt)
            if (pthread_setaffinity_np(pthread_self(), sizeof(allowed), &allowed) == 0)
                return true;
        return false;
    }
#endif
}  // namespace

void ompl_parc::WorkerPool::checkWorkers(unsigned int workers, const std::string &who)
{
    if (workers == 0)
        throw ompl::Exception(who, "workers must be at least 1");
}

ompl_parc::WorkerPool::WorkerPool(unsigned int workers) : workers_(workers), spin_(workers <= usableCores())
{
    checkWorkers(workers);
    cpu_.assign(workers, 0.);
    threads_.reserve(workers - 1);
    try
    {
        for (unsigned int w = 1; w < workers; ++w)
            threads_.emplace_back([this, w] { serve(w); });
    }
    catch (...)  // a thread could not start: stop the ones that did before the error leaves
    {
        close();
        throw;
    }
}

ompl_parc::WorkerPool::~WorkerPool()
{
    close();
}

void ompl_parc::WorkerPool::close()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
    }
    stageStarted_.notify_all();
    for (auto &thread : threads_)
        thread.join();
}

template <typename Ready>
void ompl_parc::WorkerPool::spinFor(const Ready &ready) const
{
    if (!spin_)
        return;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(SPIN_SECONDS);
    for (unsigned int k = 1; !ready(); ++k)
    {
        std::this_thread::yield();  // a thread waiting for this core (the caller, say) goes first
        if (k % 64 == 0 && std::chrono::steady_clock::now() > until)
            return;
    }
}

template <typename Ready>
void ompl_parc::WorkerPool::sleepFor(const Ready &ready, std::condition_variable &wake)
{
    std::unique_lock<std::mutex> lock(mutex_);
    wake.wait(lock, ready);
}

void ompl_parc::WorkerPool::serve(unsigned int worker)
{
    unsigned long seen = 0;
    bool spin = false;  // a new thread sleeps until the first stage: it may share the caller's core
#ifdef __linux__
    cpu_set_t allowed;
    bool moving = spin_ && pthread_getaffinity_np(pthread_self(), sizeof(allowed), &allowed) == 0;
#endif
    while (true)
    {
        const auto ready = [&] { return closing_.load() || generation_.load() != seen; };
        if (spin)
            spinFor(ready);
        sleepFor(ready, stageStarted_);
        if (closing_)
            return;
        spin = true;
#ifdef __linux__
        if (const int core = callerCore_.load(); moving && core >= 0 && sched_getcpu() == core)
            moving = leaveCore(core, allowed);
#endif
        seen = generation_.load();
        runBody(worker);
        const std::lock_guard<std::mutex> lock(mutex_);
        if (--running_ == 0)
            stageDone_.notify_one();
    }
}

void ompl_parc::WorkerPool::runBody(unsigned int worker)
{
    const double start = StageClock::threadCpu();
    try
    {
        (*body_)(worker);
    }
    catch (...)
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!error_)
            error_ = std::current_exception();
        aborted_ = true;
    }
    cpu_[worker] = StageClock::threadCpu() - start;  // each worker its own entry; read after the stage's join
}

std::vector<double> ompl_parc::WorkerPool::run(const std::function<void(unsigned int)> &body)
{
#ifdef __linux__
    if (workers_ > 1 && spin_)
        callerCore_ = sched_getcpu();
#endif
    aborted_ = false;
    error_ = nullptr;
    body_ = &body;
    if (workers_ > 1)
    {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            running_ = workers_ - 1;
            ++generation_;
        }
        stageStarted_.notify_all();
        // A worker woken onto this core runs now (and moves off it, see serve()) instead of after our slice.
        std::this_thread::yield();
    }
    runBody(0);
    if (workers_ > 1)
    {
        const auto done = [this] { return running_.load() == 0; };
        spinFor(done);
        sleepFor(done, stageDone_);
    }
    body_ = nullptr;
    if (error_)
        std::rethrow_exception(std::exchange(error_, nullptr));
    return cpu_;
}
