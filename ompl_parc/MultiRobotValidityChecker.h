#ifndef OMPL_PARC_MULTI_ROBOT_VALIDITY_CHECKER_
#define OMPL_PARC_MULTI_ROBOT_VALIDITY_CHECKER_

#include <ompl/base/StateValidityChecker.h>

namespace ompl_parc
{
    class MultiRobotSpaceInformation;

    /** \brief Validity of a composite state: every robot valid alone, and every robot pair apart.

        Bodies are computed once per robot per call (thread-local buffers, so the checker is safe to share
        between planner threads), then all pairs are tested with the bounding-sphere early-out. */
    class MultiRobotValidityChecker : public ompl::base::StateValidityChecker
    {
      public:
        explicit MultiRobotValidityChecker(MultiRobotSpaceInformation *si);
        bool isValid(const ompl::base::State *state) const override;

      private:
        const MultiRobotSpaceInformation *mrsi_;
    };
}  // namespace ompl_parc

#endif
