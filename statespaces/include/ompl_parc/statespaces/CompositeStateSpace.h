#ifndef OMPL_PARC_STATESPACES_COMPOSITE_STATE_SPACE_
#define OMPL_PARC_STATESPACES_COMPOSITE_STATE_SPACE_

#include <ompl/base/StateSpace.h>

#include <memory>
#include <vector>

namespace ompl_parc
{
    class CompositeStateSpace;
    using CompositeStateSpacePtr = std::shared_ptr<CompositeStateSpace>;

    /** \brief The composite configuration space of a robot team: one component per robot, in robot order.

        Its distance is the \b maximum of the robots' distances (not OMPL's weighted sum), so a composite
        motion of length d moves no robot further than d. That makes composite paths and the timestep
        grid agree: one composite step of length <= 1/resolution is one legal timestep for every robot.
        Interpolation is OMPL's component-wise one, so all robots move synchronised. Motion checking
        inherits OMPL's compound rule (the most segments any robot space asks for), so each robot is
        checked at its own space's resolution; do not call setLongestValidSegmentFraction() on a
        composite space, as OMPL would push that value down into the shared robot spaces. */
    class CompositeStateSpace : public ompl::base::CompoundStateSpace
    {
      public:
        /** \brief One component per robot space; throws ompl::Exception if \e robotSpaces is empty. */
        explicit CompositeStateSpace(const std::vector<ompl::base::StateSpacePtr> &robotSpaces);

        std::size_t getRobotCount() const { return getSubspaceCount(); }
        const ompl::base::StateSpacePtr &getRobotSpace(std::size_t robot) const
        {
            return getSubspace(static_cast<unsigned int>(robot));
        }

        /** \brief The composite space of a subset of the robots (same robot space objects, given order). */
        CompositeStateSpacePtr createSubspace(const std::vector<std::size_t> &robots) const;

        /** \brief Copy the components of \e robots from \e state into the sub-composite state \e sub. */
        void splitState(const ompl::base::State *state, const std::vector<std::size_t> &robots,
                        ompl::base::State *sub) const;

        /** \brief Copy the sub-composite state \e sub back into the components of \e robots of \e state. */
        void joinState(ompl::base::State *state, const std::vector<std::size_t> &robots,
                       const ompl::base::State *sub) const;

        double distance(const ompl::base::State *state1, const ompl::base::State *state2) const override;
        double getMaximumExtent() const override;

        /** \brief When every robot space is a real vector space (always, for our robots), a composite state is
            one heap block (the compound state, its component pointers, the component states and all values)
            instead of 2 + 2N blocks: planners and the one-state-per-timestep solution paths of big teams
            allocate and free these by the hundred thousand. Other spaces use OMPL's layout. */
        ompl::base::State *allocState() const override;
        void freeState(ompl::base::State *state) const override;

        /** \brief Allocate \e count states into \e out[0 .. count): with the single-block layout, all in one shared
            allocation, each still freed by freeState() (the allocation goes when its last state does). A solution
            path of a big team is hundreds of such states of kilobytes each; one allocation of 512 KiB or more is
            laid on transparent huge pages (Linux, madvise), which fault in once per 2 MiB instead of once per 4 KiB:
            built one by one, the megabytes of a large team's path cost a visible share of ARC's solve in page faults
            alone. Other layouts: one allocState() per state. */
        void allocStates(std::size_t count, ompl::base::State **out) const;

      private:
        void checkRobots(const std::vector<std::size_t> &robots) const;

        /** \brief Lay out one state (header, compound state, component pointers, robot states, values) at
            \e block; \e shared is the allocation it belongs to (nullptr: its own). */
        ompl::base::State *placeState(char *block, void *shared) const;

        /** \brief Single-block layout: whether it applies, byte offsets from the block start (a header holding the
            shared allocation, then the compound state...), and each robot's first value. */
        bool singleBlock_{false};
        std::size_t stateOffset_{0}, componentsOffset_{0}, robotStatesOffset_{0}, valuesOffset_{0}, blockSize_{0};
        std::vector<std::size_t> valueStart_;
        /** \brief Whether every robot space is exactly OMPL's RealVectorStateSpace (a subclass may measure otherwise),
            and their dimensions: distance() then reads the values itself, one square root in all instead of a virtual
            call and a root per robot (OMPL's path length, nearest neighbours of the coupled baselines). */
        bool plainVectors_{false};
        std::vector<unsigned int> dimensions_;
    };
}  // namespace ompl_parc

#endif
