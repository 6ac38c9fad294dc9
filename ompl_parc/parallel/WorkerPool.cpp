#include "ompl_parc/parallel/WorkerPool.h"

#include "ompl_parc/parallel/StageClock.h"

#include <boost/asio/post.hpp>
#include <ompl/util/Exception.h>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>

struct ompl_parc::WorkerPool::Stage
{
    std::mutex mutex;
    std::condition_variable done;
    unsigned int running{0};
    std::exception_ptr error;
    std::atomic<bool> aborted{false};
    std::vector<double> cpu;
};

ompl_parc::WorkerPool::WorkerPool(unsigned int workers) : workers_(workers)
{
    if (workers == 0)
        throw ompl::Exception("WorkerPool", "needs at least one worker");
    if (workers > 1)
        pool_ = std::make_unique<boost::asio::thread_pool>(workers);
}

ompl_parc::WorkerPool::~WorkerPool()
{
    if (pool_)
        pool_->join();
}

bool ompl_parc::WorkerPool::aborted() const
{
    return stage_ && stage_->aborted.load();
}

std::vector<double> ompl_parc::WorkerPool::run(const std::function<void(unsigned int)> &body)
{
    auto stage = std::make_shared<Stage>();
    stage_ = stage;
    if (!pool_)  // one worker: the calling thread runs the stage, no hand-off (ARC)
    {
        const double start = StageClock::threadCpu();
        body(0);
        return {StageClock::threadCpu() - start};
    }
    stage->running = workers_;
    stage->cpu.assign(workers_, 0.);
    for (unsigned int w = 0; w < workers_; ++w)
        boost::asio::post(*pool_,
                          [stage, w, &body]
                          {
                              const double start = StageClock::threadCpu();
                              try
                              {
                                  body(w);
                              }
                              catch (...)
                              {
                                  std::lock_guard<std::mutex> lock(stage->mutex);
                                  if (!stage->error)
                                      stage->error = std::current_exception();
                                  stage->aborted = true;
                              }
                              const double cpu = StageClock::threadCpu() - start;
                              std::lock_guard<std::mutex> lock(stage->mutex);
                              stage->cpu[w] = cpu;
                              if (--stage->running == 0)
                                  stage->done.notify_all();
                          });
    std::unique_lock<std::mutex> lock(stage->mutex);
    stage->done.wait(lock, [&stage] { return stage->running == 0; });
    if (stage->error)
        std::rethrow_exception(stage->error);
    return stage->cpu;
}
