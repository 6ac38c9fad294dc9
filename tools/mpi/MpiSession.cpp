#include "MpiSession.h"

#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace
{
    /** \brief Throws std::runtime_error naming \e call unless \e code is MPI_SUCCESS (MPI's default handler aborts
        before; this covers a handler that returns). */
    void check(int code, const char *call)
    {
        if (code != MPI_SUCCESS)
            throw std::runtime_error(std::string(call) + " failed (MPI error " + std::to_string(code) + ")");
    }

    int lengthOf(const std::string &text)
    {
        if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
            throw std::runtime_error("a message of " + std::to_string(text.size()) + " bytes is too long for MPI");
        return static_cast<int>(text.size());
    }

    std::string receiveProbed(const MPI_Status &probed, int tag)
    {
        int length = 0;
        check(MPI_Get_count(&probed, MPI_CHAR, &length), "MPI_Get_count");
        std::string text(static_cast<std::size_t>(length), '\0');
        check(MPI_Recv(text.data(), length, MPI_CHAR, probed.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "MPI_Recv");
        return text;
    }
}  // namespace

ompl_parc::tools::MpiSession::PendingSend::~PendingSend()
{
    if (started_)
        MPI_Wait(&request_, MPI_STATUS_IGNORE);
}

void ompl_parc::tools::MpiSession::PendingSend::start(std::string text, int rank, int tag)
{
    complete();
    text_ = std::move(text);
    check(MPI_Isend(text_.data(), lengthOf(text_), MPI_CHAR, rank, tag, MPI_COMM_WORLD, &request_), "MPI_Isend");
    started_ = true;
}

void ompl_parc::tools::MpiSession::PendingSend::complete()
{
    if (!started_)
        return;
    check(MPI_Wait(&request_, MPI_STATUS_IGNORE), "MPI_Wait");
    started_ = false;
}

ompl_parc::tools::MpiSession::MpiSession(int &argc, char **&argv)
{
    int provided = 0;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    if (provided < MPI_THREAD_FUNNELED)
    {
        MPI_Finalize();
        throw std::runtime_error("this MPI library does not allow threads beside MPI (MPI_THREAD_FUNNELED)");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

ompl_parc::tools::MpiSession::~MpiSession()
{
    MPI_Finalize();
}

void ompl_parc::tools::MpiSession::broadcast(std::string &text) const
{
    int length = isRoot() ? lengthOf(text) : 0;
    check(MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
    text.resize(static_cast<std::size_t>(length));
    check(MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
}

void ompl_parc::tools::MpiSession::send(const std::string &text, int rank, int tag) const
{
    check(MPI_Send(text.data(), lengthOf(text), MPI_CHAR, rank, tag, MPI_COMM_WORLD), "MPI_Send");
}

std::pair<int, std::string> ompl_parc::tools::MpiSession::receive(int rank, int tag) const
{
    MPI_Status probed;
    check(MPI_Probe(rank, tag, MPI_COMM_WORLD, &probed), "MPI_Probe");
    return {probed.MPI_SOURCE, receiveProbed(probed, tag)};
}

std::optional<std::pair<int, std::string>> ompl_parc::tools::MpiSession::tryReceive(int tag) const
{
    int arrived = 0;
    MPI_Status probed;
    check(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &arrived, &probed), "MPI_Iprobe");
    if (!arrived)
        return std::nullopt;
    return std::make_pair(probed.MPI_SOURCE, receiveProbed(probed, tag));
}

std::vector<std::string> ompl_parc::tools::MpiSession::gather(const std::string &text, int tag) const
{
    if (!isRoot())
    {
        send(text, 0, tag);
        return {};
    }
    std::vector<std::string> all{text};
    for (int r = 1; r < size_; ++r)
        all.push_back(receive(r, tag).second);
    return all;
}

std::string ompl_parc::tools::MpiSession::agree(const std::string &error) const
{
    std::string first;
    const auto all = gather(error, TAG_SETUP_ERROR);
    for (std::size_t r = 0; r < all.size() && first.empty(); ++r)
        if (!all[r].empty())
            first = (r == 0 ? "" : "rank " + std::to_string(r) + ": ") + all[r];
    broadcast(first);
    return first;
}

std::string ompl_parc::tools::MpiSession::errorOf(const std::function<void()> &step)
{
    try
    {
        step();
        return {};
    }
    catch (const std::exception &e)
    {
        return e.what();
    }
}

void ompl_parc::tools::MpiSession::barrier() const
{
    check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

void ompl_parc::tools::MpiSession::abort(int code) const
{
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);  // MPI_Abort does not return; should it, this rank still ends
}
