#ifndef OMPL_PARC_ARC_SETTINGS_
#define OMPL_PARC_ARC_SETTINGS_

#include <string>
#include <vector>

namespace ompl_parc
{
    class MultiRobotSpaceInformation;

    /** \brief The knobs of ARC's conflict resolution, shared by ARC and P-ARC (which expose them as
        declared planner parameters). Defaults are the authors' tuned values for the mobile scenarios. */
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

        /** \brief Initial half-width of the repair window, in timesteps. */
        unsigned int window{200};
        Growth growth{Growth::LINEAR};
        double growthStep{200.};
        /** \brief Above 1: windows less than this factor longer than the first of their size are tried
            ConflictResolver::WINDOW_TRIES times, the schedule's others skipped. The authors' exponential schedule
            starts at +1, +2, +4, ... timesteps, and a window widened at an endpoint past the schedule stays the same
            for many steps: nearly the same subproblem again, which ARC retried for most of its budget on the Panda
            cells it failed. A failed global round then starts the schedule over (fresh seeds), so a window that needs
            more tries gets them between global rounds. 1 (the mobile and planar profiles): every window of the
            schedule is tried, and one equal to the failed window goes global. The panda profile uses 1.25: arm teams
            whose windows fail repeat nearly the same subproblem otherwise; on 2D robots it loses instances
            (measured in CHANGELOG). */
        double minWindowGrowth{1.};
        /** \brief Timesteps by which an invalid local start (goal) side is widened until it is valid. */
        unsigned int endpointStep{200};
        /** \brief Local bounds: the window's path bounding box widened by margin x its size on each side,
            at least minBoundRange wide, clipped to the robot's bounds. */
        double boundMargin{2.};
        double minBoundRange{2.};
        /** \brief Planner iterations allowed on a local window (none on the global problem). */
        unsigned int sampleCap{5000};
        /** \brief Composite RRT-Connect first, then prioritised ST-RRT around the other robots: as fast as the
            authors' composite-only runs on Mobile Cross, Mobile Circle and Planar Cross, and it solves generated
            families (ring, field, crossing) where composite-only times out (README); the paper's hierarchy
            (prioritised first) is one parameter away. With latticeMapf, the MAPF solver comes between the two. */
        Solvers solvers{Solvers::COMPOSITE_FIRST};
        /** \brief Shortcut the initial single-robot paths with OMPL's simplifier. */
        bool simplifyInitial{true};
        /** \brief A robot whose straight motion from start to goal is valid takes it in the initial stage instead of
            being planned: the shortest path, at the cost of one motion check. In open space this is most robots,
            and building a planner per robot (its space, trees, samplers, random generators) would be most of the
            stage. Off: every robot is planned, as the authors do. */
        bool straightInitial{true};
        /** \brief Shorten composite repair patches before they are spliced (OMPL's simplifier on the team's composite
            path, bounded like the initial paths'). Off in the mobile and planar profiles, as in the paper: there plan
            quality is PlanSmoother's job after the solve, and shortening costs planning time (README). On in the
            panda profile: an arm patch wanders in a team space of 14-28 dimensions, the smoother's shortcuts on 16
            arms are few per second, and shortening cuts the unsmoothed median makespans of Panda Cage 8 and 16 by
            40 % and 51 % at about the same median time to the first solution (docs/results-plan-quality.md). */
        bool shortenPatches{false};
        /** \brief Add multi-agent path finding on a lattice (LatticeMapfSolver) to the hierarchies that have more than
            one solver: after composite RRT-Connect in COMPOSITE_FIRST, last in HIERARCHY. It applies to teams of
            translating robots only (the others decline it at once) and solves the dense 2D teams where the other two
            fail (the generator's crossing family, CHANGELOG), at a cost in plan length. Off: the solvers of the
            paper. */
        bool latticeMapf{true};
        /** \brief Add moving the team's robots one at a time (SequentialRRTConnectSolver) right after composite
            RRT-Connect: for arms whose workspaces overlap, where the coupled search runs out of time and most orders
            of single-arm moves do not (README: what it gains and costs). */
        bool sequential{false};

        /** \brief The fields, as bits of explicitFields. */
        enum Field : unsigned int
        {
            WINDOW = 1u << 0,
            GROWTH = 1u << 1,
            GROWTH_STEP = 1u << 2,
            ENDPOINT_STEP = 1u << 3,
            BOUND_MARGIN = 1u << 4,
            MIN_BOUND_RANGE = 1u << 5,
            SAMPLE_CAP = 1u << 6,
            SOLVERS = 1u << 7,
            SIMPLIFY_INITIAL = 1u << 8,
            SHORTEN_PATCHES = 1u << 9,
            STRAIGHT_INITIAL = 1u << 10,
            MIN_WINDOW_GROWTH = 1u << 11,
            LATTICE_MAPF = 1u << 12,
            SEQUENTIAL = 1u << 13
        };
        /** \brief The fields set one by one (planner parameters): a profile applied later keeps them, so a
            profile and explicit parameters give the same settings in any order (OMPL's ParamSet applies a
            map of parameters alphabetically, "profile" after "bound_margin"). */
        unsigned int explicitFields{0};

        /** \brief Set every field that was not set explicitly to profile \e name's value (see profile()). */
        void applyProfile(const std::string &name);

        /** \brief The authors' tuned values: "mobile" (w 200, linear +200, margin 2, min range 2, cap 5000),
            "planar" (w 100, exponential 1.05, endpoint step 10, margin 1, min range 0.5, cap 50000),
            "panda" (as planar with w 20; ours: min window growth 1.25, composite RRT-Connect only, sequential,
            patches shortened). Throws
            ompl::Exception for another name. */
        static ArcSettings profile(const std::string &name);

        /** \brief These settings with an eager repair schedule: a quarter of the sample cap (at least 1000; none stays
            none) and twice the minimum window growth (at most 4), so fewer samples on each window and fewer windows
            before the team's global problem. For the odd instances of an OR race (ORPARC's \e diversify): on a team
            of arms that no window can repair (Panda Cage 16 tasks 3 and 4), the default schedule spends seconds on
            hopeless windows and an eager instance wins; where windows do repair, the default instance does. */
        ArcSettings eager() const;

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
    };
}  // namespace ompl_parc

#endif
