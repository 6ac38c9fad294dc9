#ifndef OMPL_PARC_WORKER_POOL_
#define OMPL_PARC_WORKER_POOL_

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace ompl_parc
{
    /** \brief A planner instance's budget of W workers running fork-join stages, as in the paper's execution model.

        run() starts the same body once per worker (with its index), waits until every worker has returned, and
        reports each worker's thread CPU time over the stage. If a body throws, the others are told to stop through
        aborted() and the first exception is rethrown after all have joined: no body outlives its stage, no thread
        is left waiting. The calling thread is worker 0; W - 1 threads live as long as the pool (a pool of one worker
        runs its stages on the calling thread: ARC is the one-worker case).

        Why not a general thread pool (the Boost.Asio pool this replaced): P-ARC's stages are short (a conflict
        repair takes about a millisecond on Mobile Cross) and follow each other after microseconds of serial work.
        On a 2-core virtual machine, a pool thread that had gone to sleep between two stages started milliseconds
        late, or was woken onto the caller's core, where the two shared one core for milliseconds while
        the other idled; either way one worker did the stage's work alone. So here:
        - a worker that finishes a stage spins for the next one (yielding its core to any thread waiting for it)
          for up to SPIN_SECONDS before it sleeps on a condition variable, and the caller waits for the stage's
          end the same way; nobody spins when the workers outnumber the usable cores;
        - a new thread sleeps until its first stage (spinning then could hold the caller's core);
        - after waking the pool the caller yields once, and a pool thread that runs on the caller's core moves
          to another one (the kernel picks it: the thread leaves that core's bit in its affinity mask for a
          moment, then restores the mask it started with; Linux only).
        Nobody spins or moves in a pool with more workers than usable cores. That rule is per pool: several pools
        in one process (OR-P-ARC's K instances) each decide alone. Between planner runs every worker sleeps. */
    class WorkerPool
    {
      public:
        /** \brief Throws ompl::Exception for zero workers (checkWorkers()). */
        explicit WorkerPool(unsigned int workers);
        ~WorkerPool();
        WorkerPool(const WorkerPool &) = delete;
        WorkerPool &operator=(const WorkerPool &) = delete;

        unsigned int getWorkerCount() const { return workers_; }
        /** \brief Throws ompl::Exception, reported by \e who, for zero workers: the one check of a worker count,
            made by the pool and, as a parameter is set, by the planners that make pools (P-ARC's \e workers). */
        static void checkWorkers(unsigned int workers, const std::string &who = "WorkerPool");

        /** \brief Run \e body(worker) on every worker; returns per-worker CPU seconds of this stage. Not reentrant:
            one stage at a time, from one thread. */
        std::vector<double> run(const std::function<void(unsigned int)> &body);

        /** \brief True once a body of the current stage has thrown; bodies should then return promptly. */
        bool aborted() const { return aborted_.load(); }

        /** \brief How long a worker spins for the next stage (or the caller for the stage's end) before it
            sleeps. */
        static constexpr double SPIN_SECONDS = 2e-3;

      private:
        /** \brief Pool thread \e worker (1..W-1): wait for a stage, run it, repeat until the pool is closed. */
        void serve(unsigned int worker);

        /** \brief Tell the pool threads to end, and join them. */
        void close();

        /** \brief Run the current stage's body as \e worker, recording its CPU time and the first error. */
        void runBody(unsigned int worker);

        /** \brief Spin (yielding the core to any thread waiting for it) until \e ready() holds or SPIN_SECONDS have
            passed; nothing when workers outnumber cores. */
        template <typename Ready>
        void spinFor(const Ready &ready) const;

        /** \brief Sleep until \e ready() holds; whoever makes it true does so under mutex_ and notifies \e wake. */
        template <typename Ready>
        void sleepFor(const Ready &ready, std::condition_variable &wake);

        unsigned int workers_;
        /** \brief Spin only when every worker can have a core of its own. */
        bool spin_;
        std::vector<std::thread> threads_;

        std::mutex mutex_;
        std::condition_variable stageStarted_, stageDone_;
        /** \brief Stages started so far (a new value starts the next one), and the pool's end. */
        std::atomic<unsigned long> generation_{0};
        std::atomic<bool> closing_{false};
        /** \brief Pool threads still running the current stage. */
        std::atomic<unsigned int> running_{0};
        std::atomic<bool> aborted_{false};
        const std::function<void(unsigned int)> *body_{nullptr};
        std::exception_ptr error_;
        std::vector<double> cpu_;
        /** \brief The core the caller started the current stage on (-1: unknown, or nobody moves). */
        std::atomic<int> callerCore_{-1};
    };
}  // namespace ompl_parc

#endif
