#ifndef OMPL_PARC_ARC_SETTINGS_
#define OMPL_PARC_ARC_SETTINGS_

#include <string>
#include <vector>

namespace ompl_parc
{
    class MultiRobotSpaceInformation;

    /** \brief The knobs of ARC's conflict resolution, shared by ARC and P-ARC (which expose them as
        declared planner parameters). Defaults are the authors' tuned values for the mobile scenarios.

        Each knob is one entry of ompl_parc/arc/ArcKnobs.def: its field, planner parameter, range check, profile
        values and why it is there. Its field here, profile(), applyProfile() and the planners' parameters are made
        from that entry:
        \verbinclude ompl_parc/arc/ArcKnobs.def */
    struct ArcSettings
    {
        /** \brief How the half-width of the repair window grows after a failed attempt k = 1, 2, ...:
            LINEAR: window + step * k; EXPONENTIAL: window + step * 2^(k-1) (the authors' schedule). */
        enum class Growth
        {
            LINEAR,
            EXPONENTIAL
        };

        /** \brief Which subproblem solvers to try, in order, on each window. */
        enum class Solvers
        {
            HIERARCHY,       ///< prioritised ST-RRT first, then composite RRT-Connect (the paper's text)
            COMPOSITE,       ///< composite RRT-Connect only (the authors' runs)
            PRIORITIZED,     ///< prioritised ST-RRT only
            COMPOSITE_FIRST  ///< composite RRT-Connect first, then prioritised ST-RRT around the other robots
        };

#define OMPL_PARC_ARC_KNOB(Name, member, parameter, Type, Parameter, range, valid, otherwise, mobile, planar, panda) \
    Type member{mobile};
#include "ompl_parc/arc/ArcKnobs.def"

        /** \brief The knobs, in ArcKnobs.def's order: positions of explicitFields' bits. */
        enum class Knob : unsigned int
        {
#define OMPL_PARC_ARC_KNOB(Name, member, ...) member,
#include "ompl_parc/arc/ArcKnobs.def"
            COUNT
        };
        static_assert(static_cast<unsigned int>(Knob::COUNT) <= 32, "explicitFields has a bit for each knob");

        /** \brief The knobs set one by one (planner parameters), a bit each: a profile applied later keeps them, so a
            profile and explicit parameters give the same settings in any order (OMPL's ParamSet applies a
            map of parameters alphabetically, "profile" after "bound_margin"). */
        unsigned int explicitFields{0};
        /** \brief Mark \e knob as set one by one: applyProfile() keeps its value. */
        void setExplicit(Knob knob) { explicitFields |= 1u << static_cast<unsigned int>(knob); }
        bool isExplicit(Knob knob) const { return ((explicitFields >> static_cast<unsigned int>(knob)) & 1u) != 0; }

        /** \brief Set every field that was not set explicitly to profile \e name's value (see profile()). */
        void applyProfile(const std::string &name);

        /** \brief The authors' tuned values: "mobile" (w 200, linear +200, margin 2, min range 2, cap 5000),
            "planar" (w 100, exponential 1.05, endpoint step 10, margin 1, min range 0.5, cap 50000),
            "panda" (as planar with w 20; ours: cap 12500, min window growth 2.5, composite RRT-Connect only,
            sequential, patches shortened). Throws
            ompl::Exception for another name. */
        static ArcSettings profile(const std::string &name);

        /** \brief These settings with an eager repair schedule: a quarter of the sample cap (at least 1000; none stays
            none) and twice the minimum window growth (at most 4), so fewer samples on each window and fewer windows
            before the team's global problem. For the odd instances of an OR race (ORPARC's \e diversify): on a team
            of arms that no window can repair, a patient schedule spends seconds on hopeless windows and an eager
            instance wins; where windows do repair, the patient instance does. A schedule eager already (a minimum
            window growth of EAGER_GROWTH or more: the panda profile) is returned as it is: more eager still, the odd
            instances lost Panda Cage 16 task 4's race (docs/results-arm-tail.md). */
        ArcSettings eager() const;

        /** \brief The least minimum window growth of a schedule that is eager already (the panda profile's). */
        static constexpr double EAGER_GROWTH = 2.5;

        /** \brief Half-width of the window for attempt \e k (0 = the first). */
        std::size_t halfWidth(unsigned int k) const;

        /** \brief The profile the team of \e si gets when the user names none ("auto", the planners' default): "panda"
           if any robot is a URDF arm, else "planar" if any is a planar arm, else "mobile". The mobile defaults on an
           arm team repair with 200-timestep windows of 5000 samples: Panda Cage 16 then spends its budget on windows
           the panda profile skips. */
        static std::string profileFor(const MultiRobotSpaceInformation &si);

        static std::vector<std::string> profileNames();
        static Growth growthFromString(const std::string &name);
        static std::string toString(Growth growth);
        static Solvers solversFromString(const std::string &name);
        static std::string toString(Solvers solvers);

        /** \name A knob's value from its planner parameter's and back: the value itself, an enumerator by its name
            (fromParameter()'s second argument, the knob's field, only chooses the conversion)
            @{ */
        template <typename T>
        static T fromParameter(const T &value, T * /*knob*/)
        {
            return value;
        }
        static Growth fromParameter(const std::string &name, Growth * /*knob*/) { return growthFromString(name); }
        static Solvers fromParameter(const std::string &name, Solvers * /*knob*/) { return solversFromString(name); }
        template <typename T>
        static T toParameter(T value)
        {
            return value;
        }
        static std::string toParameter(Growth growth) { return toString(growth); }
        static std::string toParameter(Solvers solvers) { return toString(solvers); }
        /** @} */
    };
}  // namespace ompl_parc

#endif
