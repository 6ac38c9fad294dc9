#ifndef OMPL_PARC_WORKER_POOL_
#define OMPL_PARC_WORKER_POOL_

#include <boost/asio/thread_pool.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace ompl_parc
{
    /** \brief A planner instance's budget of W worker threads (a Boost.Asio thread pool) running fork-join
        stages, as in the paper's execution model.

        run() starts the same body once per worker (with its index), waits until every worker has returned,
        and reports each worker's thread CPU time over the stage. If a body throws, the others are told to
        stop through aborted() and the first exception is rethrown after all have joined: no thread outlives
        a stage, none is left waiting. A pool of one worker runs its stages on the calling thread (no hand-off:
        ARC is the one-worker case). */
    class WorkerPool
    {
      public:
        /** \brief Throws ompl::Exception for zero workers. */
        explicit WorkerPool(unsigned int workers);
        ~WorkerPool();
        WorkerPool(const WorkerPool &) = delete;
        WorkerPool &operator=(const WorkerPool &) = delete;

        unsigned int getWorkerCount() const { return workers_; }

        /** \brief Run \e body(worker) on every worker; returns per-worker CPU seconds of this stage. */
        std::vector<double> run(const std::function<void(unsigned int)> &body);

        /** \brief True once a body of the current stage has thrown; bodies should then return promptly. */
        bool aborted() const;

      private:
        struct Stage;
        unsigned int workers_;
        std::unique_ptr<boost::asio::thread_pool> pool_;
        std::shared_ptr<Stage> stage_;
    };
}  // namespace ompl_parc

#endif
