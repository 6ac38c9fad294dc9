#ifndef OMPL_PARC_STATESPACES_SPACE_TIME_STATE_SPACE_
#define OMPL_PARC_STATESPACES_SPACE_TIME_STATE_SPACE_

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/TimeStateSpace.h>

#include <limits>
#include <memory>

namespace ompl_parc
{
    class SpaceTimeStateSpace;
    using SpaceTimeStateSpacePtr = std::shared_ptr<SpaceTimeStateSpace>;

    /** \brief A robot's configuration space times time, for planning among moving obstacles.

        OMPL 1.5 has no space-time space; this one behaves like OMPL >= 1.6's
        ompl::base::SpaceTimeStateSpace, and is only built against OMPL < 1.6 (ompl_parc plans in
        spacetime::SpaceTimeStateSpace of ompl_parc/spacetime/SpaceTimeInUse.h, whichever is in use). It is a
        compound of the space component (weight 1 - timeWeight) and a TimeStateSpace (weight timeWeight).
        The distance between two states is infinite when going from one to the other would need a speed above
        vMax; otherwise it is the weighted sum of the space distance and the time difference. Like OMPL's,
        the distance is symmetric (some planners need that): it does not forbid going backwards in time, the
        motion validator or the planner must. */
    class SpaceTimeStateSpace : public ompl::base::CompoundStateSpace
    {
      public:
        /** \brief Throws ompl::Exception if \e timeWeight is outside [0, 1] or \e vMax is not positive. */
        explicit SpaceTimeStateSpace(const ompl::base::StateSpacePtr &spaceComponent, double vMax = 1.0,
                                     double timeWeight = 0.5);

        /** \brief Infinite if reaching one state from the other needs a speed above vMax, else the weighted
            sum of space distance and time difference. */
        double distance(const ompl::base::State *state1, const ompl::base::State *state2) const override;

        /** \brief The least time needed to cover the space distance between the two states at vMax. */
        double timeToCoverDistance(const ompl::base::State *state1, const ompl::base::State *state2) const;

        /** \brief The distance of the space components only. */
        double distanceSpace(const ompl::base::State *state1, const ompl::base::State *state2) const;

        /** \brief The absolute time difference of the two states. */
        double distanceTime(const ompl::base::State *state1, const ompl::base::State *state2) const;

        /** \brief The time of a state of a space-time space. */
        static double getStateTime(const ompl::base::State *state);

        /** \brief Bound the time component to [lb, ub]; without a call time is unbounded. */
        void setTimeBounds(double lb, double ub);

        double getVMax() const { return vMax_; }
        void setVMax(double vMax);

        ompl::base::StateSpacePtr getSpaceComponent() const { return components_[0]; }
        ompl::base::TimeStateSpace *getTimeComponent() const
        {
            return components_[1]->as<ompl::base::TimeStateSpace>();
        }

        /** \brief Not a metric: infinite distances break the triangle inequality. */
        bool isMetricSpace() const override { return false; }

        /** \brief Infinite, since the distance can be infinite even with bounded time. */
        double getMaximumExtent() const override { return std::numeric_limits<double>::infinity(); }

        /** \brief Scale the speed test's round-off tolerance to the time (or space) extent; call after
            setting bounds. */
        void updateEpsilon();

      protected:
        double vMax_;
        double eps_{std::numeric_limits<float>::epsilon()};
    };
}  // namespace ompl_parc

#endif
