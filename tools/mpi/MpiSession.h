#ifndef OMPL_PARC_DEMOS_MPI_SESSION_
#define OMPL_PARC_DEMOS_MPI_SESSION_

#include <mpi.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ompl_parc::tools
{
    /** \brief The tags of our tools' messages, one per kind, so that no two kinds are ever mistaken. */
    enum MpiTag
    {
        TAG_CLAIM = 1,
        TAG_END,
        TAG_SETUP_ERROR,
        TAG_PLAN_INFO,
        TAG_PLAN,
        TAG_RUNS
    };

    /** \brief MPI for our tools: initialises MPI (threads allowed, only the main thread calls MPI: planners run
        their workers beside it) and finalises it when it goes, and moves text between ranks of MPI_COMM_WORLD.

        Everything our tools send is text (a scenario file, a solution file, a JSON report): one message per text,
        its length taken from the message itself (MPI_Probe / MPI_Get_count), so nothing needs a shared binary
        layout across the nodes. */
    class MpiSession
    {
      public:
        /** \brief A message sent without waiting (MPI_Isend): keeps its text until complete(). */
        class PendingSend
        {
          public:
            PendingSend() = default;
            PendingSend(const PendingSend &) = delete;
            PendingSend &operator=(const PendingSend &) = delete;
            ~PendingSend();

            /** \brief Starts sending \e text to \e rank with \e tag; a send still pending is completed first. */
            void start(std::string text, int rank, int tag);
            /** \brief Waits until the message has left this rank's buffer (MPI_Wait); nothing if none is pending. */
            void complete();
            /** \brief Whether a send was started and not yet completed. */
            bool started() const { return started_; }

          private:
            std::string text_;
            MPI_Request request_{MPI_REQUEST_NULL};
            bool started_{false};
        };

        /** \brief MPI_Init_thread asking for MPI_THREAD_FUNNELED; throws std::runtime_error if MPI gives less. */
        MpiSession(int &argc, char **&argv);
        /** \brief MPI_Finalize. */
        ~MpiSession();
        MpiSession(const MpiSession &) = delete;
        MpiSession &operator=(const MpiSession &) = delete;

        /** \brief This process's rank in MPI_COMM_WORLD, and how many ranks there are. */
        int getRank() const { return rank_; }
        int getSize() const { return size_; }
        /** \brief Whether this is rank 0, the one that reads, decides and writes for the run. */
        bool isRoot() const { return rank_ == 0; }

        /** \brief Rank 0's \e text on every rank (two broadcasts: the length, then the bytes). */
        void broadcast(std::string &text) const;
        /** \brief Sends \e text to \e rank with \e tag, blocking until its buffer is free. */
        void send(const std::string &text, int rank, int tag) const;
        /** \brief The next message with \e tag from \e rank (MPI_ANY_SOURCE: anyone), waiting for it; with the
            sender. */
        std::pair<int, std::string> receive(int rank, int tag) const;
        /** \brief The next message with \e tag from anyone, if one has arrived (MPI_Iprobe); never waits. */
        std::optional<std::pair<int, std::string>> tryReceive(int tag) const;
        /** \brief Every rank's \e text, in rank order, on rank 0 (empty elsewhere). */
        std::vector<std::string> gather(const std::string &text, int tag) const;
        /** \brief Waits until every rank is here (MPI_Barrier). */
        void barrier() const;
        /** \brief Collective: every rank's \e error (empty: none) goes to rank 0, which picks the first and tells
            everyone; returns it on every rank, prefixed "rank r: " where r is not 0. For set-up steps that can fail
            on some ranks only: all go on, or all stop. */
        std::string agree(const std::string &error) const;
        /** \brief Runs \e step, returning the message of the exception it throws (empty: it went well): the input
            of agree(). */
        static std::string errorOf(const std::function<void()> &step);
        /** \brief Ends every rank of the job at once (MPI_Abort) with exit code \e code: the way out of a failure
            that leaves the other ranks waiting for a message that will not come. */
        [[noreturn]] void abort(int code) const;

      private:
        int rank_{0}, size_{1};
    };
}  // namespace ompl_parc::tools

#endif
