#include "ompl_parc/arc/RepairWorkspace.h"

#include <ompl/util/Exception.h>

ompl_parc::RepairWorkspace::RepairWorkspace(const MultiRobotSpaceInformation &si, unsigned int workers)
    : detector_(si), pool_(std::make_unique<WorkerPool>(workers))
{
    batchDetector_ =
        std::make_unique<BatchDetector>(detector_, *pool_, BatchDetector::UNBOUNDED, capacityFor(workers, 1), false);
}

void ompl_parc::RepairWorkspace::checkBatchPerWorker(unsigned int batchPerWorker, const std::string &who)
{
    if (batchPerWorker == 0)
        throw ompl::Exception(who, "batch_per_worker must be at least 1");
}

std::size_t ompl_parc::RepairWorkspace::capacityFor(unsigned int workers, unsigned int batchPerWorker)
{
    checkBatchPerWorker(batchPerWorker);
    return workers == 1 ? 1 : std::size_t{workers} * batchPerWorker;
}

void ompl_parc::RepairWorkspace::configure(unsigned int workers, std::size_t horizon, unsigned int batchPerWorker,
                                           bool optimistic)
{
    const std::size_t capacity = capacityFor(workers, batchPerWorker);
    if (pool_->getWorkerCount() != workers)
    {
        auto pool = std::make_unique<WorkerPool>(workers);
        batchDetector_ = std::make_unique<BatchDetector>(detector_, *pool, horizon, capacity, optimistic);
        pool_ = std::move(pool);  // the old batch detector, which used the old pool, is gone
        return;
    }
    batchDetector_->configure(horizon, capacity, optimistic);
}

void ompl_parc::RepairWorkspace::reset()
{
    detector_.reset();
    batchDetector_->reset();
}
