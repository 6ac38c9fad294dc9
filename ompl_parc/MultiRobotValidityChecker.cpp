#include "ompl_parc/MultiRobotValidityChecker.h"

#include "ompl_parc/CapsuleCollision.h"
#include "ompl_parc/MultiRobotSpaceInformation.h"

ompl_parc::MultiRobotValidityChecker::MultiRobotValidityChecker(MultiRobotSpaceInformation *si)
    : ompl::base::StateValidityChecker(si), mrsi_(si)
{
}

bool ompl_parc::MultiRobotValidityChecker::isValid(const ompl::base::State *state) const
{
    thread_local std::vector<CollisionBody> bodies;
    const std::size_t n = mrsi_->getRobotCount();
    bodies.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const double *q = mrsi_->getRobotValues(state, i);
        if (!mrsi_->getRobot(i)->isValid(q))
            return false;
        mrsi_->getRobot(i)->computeBody(q, bodies[i]);
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (bodiesCollide(bodies[i], bodies[j]))
                return false;
    return true;
}
