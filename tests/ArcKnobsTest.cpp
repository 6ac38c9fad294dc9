#include "ompl_parc/arc/ArcSettings.h"
#include "ompl_parc/arc/RepairWorkspace.h"
#include "ompl_parc/planners/ARC.h"
#include "ompl_parc/planners/ORPARC.h"
#include "ompl_parc/planners/PARC.h"
#include "ompl_parc/scenarios/Scenarios.h"

#include <gtest/gtest.h>
#include <ompl/util/Exception.h>

#include <string>
#include <type_traits>
#include <vector>

using namespace ompl_parc;

/* The knobs are made from one table (ompl_parc/arc/ArcKnobs.def). These tests hold what the table makes against
   values written out here: the profiles' values as ArcSettings::profile() set them by hand before the table, each
   knob's declared parameter with its range, setting it by name, the knob surviving a later profile, and the range
   checks' messages. */

namespace
{
    /** Every knob's value, field by field, as one profile sets it. */
    struct KnobValues
    {
        unsigned int window;
        ArcSettings::Growth growth;
        double growthStep, minWindowGrowth;
        unsigned int endpointStep;
        double boundMargin, minBoundRange;
        unsigned int sampleCap;
        ArcSettings::Solvers solvers;
        bool simplifyInitial, straightInitial, shortenPatches, latticeMapf, sequential;
    };

    // ArcSettings::profile() before the table: planar and panda set window, growth (exponential, step 1.05),
    // endpoint step 10, margin 1, min range 0.5 and cap 50000 (panda: 12500), panda also min window growth 2.5,
    // composite solvers, sequential and shortened patches; mobile kept the defaults.
    // clang-format off
    //                               window growth                            step  minGrowth endpoint margin range
    //                               cap    solvers                           simplify straight shorten mapf sequential
    const KnobValues MOBILE_KNOBS{   200,   ArcSettings::Growth::LINEAR,      200., 1.,       200,     2.,    2.,
                                     5000,  ArcSettings::Solvers::COMPOSITE_FIRST, true, true,  false,  true, false};
    const KnobValues PLANAR_KNOBS{   100,   ArcSettings::Growth::EXPONENTIAL, 1.05, 1.,       10,      1.,    0.5,
                                     50000, ArcSettings::Solvers::COMPOSITE_FIRST, true, true,  false,  true, false};
    const KnobValues PANDA_KNOBS{    20,    ArcSettings::Growth::EXPONENTIAL, 1.05, 2.5,      10,      1.,    0.5,
                                     12500, ArcSettings::Solvers::COMPOSITE,       true, true,  true,   true, true};
    // clang-format on

    void expectKnobValues(const ArcSettings &s, const KnobValues &v)
    {
        EXPECT_EQ(s.window, v.window);
        EXPECT_EQ(s.growth, v.growth);
        EXPECT_EQ(s.growthStep, v.growthStep);
        EXPECT_EQ(s.minWindowGrowth, v.minWindowGrowth);
        EXPECT_EQ(s.endpointStep, v.endpointStep);
        EXPECT_EQ(s.boundMargin, v.boundMargin);
        EXPECT_EQ(s.minBoundRange, v.minBoundRange);
        EXPECT_EQ(s.sampleCap, v.sampleCap);
        EXPECT_EQ(s.solvers, v.solvers);
        EXPECT_EQ(s.simplifyInitial, v.simplifyInitial);
        EXPECT_EQ(s.straightInitial, v.straightInitial);
        EXPECT_EQ(s.shortenPatches, v.shortenPatches);
        EXPECT_EQ(s.latticeMapf, v.latticeMapf);
        EXPECT_EQ(s.sequential, v.sequential);
    }

    /** A knob's declared parameter: its name and range, a valid value other than some profile's (as the parameter
        writes it), and a refused value with its message (none where every value of the type is valid). */
    struct KnobParameter
    {
        std::string name, range, value, refused, message;
    };

    const std::vector<KnobParameter> KNOB_PARAMETERS = {
        {"window", "1:10:2000", "80", "0", "window must be at least 1 timestep"},
        {"growth", "linear,exponential", "linear", "cubic", "unknown growth 'cubic' (valid: linear, exponential)"},
        {"growth_step", "0.:1.:1000.", "7.5", "0", "growth_step must be positive"},
        {"min_window_growth", "1.:0.05:4.", "1.5", "0.5", "min_window_growth must be between 1 and 1e6"},
        {"endpoint_step", "1:10:1000", "30", "0", "endpoint_step must be at least 1 timestep"},
        {"bound_margin", "0.:0.5:10.", "0.25", "-1", "bound_margin must be non-negative"},
        {"min_bound_range", "0.1:0.1:10.", "3.5", "0", "min_bound_range must be positive"},
        {"sample_cap", "0:1000:100000", "1234", "", ""},
        {"solvers", "hierarchy,composite,prioritized,composite-first", "hierarchy", "magic",
         "unknown solvers 'magic' (valid: hierarchy, composite, prioritized, composite-first)"},
        {"simplify_initial", "0,1", "0", "", ""},
        {"straight_initial", "0,1", "0", "", ""},
        {"shorten_patches", "0,1", "1", "", ""},
        {"lattice_mapf", "0,1", "0", "", ""},
        {"sequential", "0,1", "1", "", ""},
    };

    /** The message of the ompl::Exception that \e set throws, empty if it throws none. */
    template <typename F>
    std::string knobError(F &&set)
    {
        try
        {
            set();
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
        return "";
    }
}  // namespace

TEST(ArcKnobs, ProfilesHaveTheirTunedValues)
{
    expectKnobValues(ArcSettings(), MOBILE_KNOBS);  // the defaults are the mobile profile
    expectKnobValues(ArcSettings::profile("mobile"), MOBILE_KNOBS);
    expectKnobValues(ArcSettings::profile("planar"), PLANAR_KNOBS);
    expectKnobValues(ArcSettings::profile("panda"), PANDA_KNOBS);
    EXPECT_EQ(ArcSettings::profile("mobile").explicitFields, 0u);
    ArcSettings applied;
    applied.applyProfile("panda");
    expectKnobValues(applied, PANDA_KNOBS);
    applied.applyProfile("planar");
    expectKnobValues(applied, PLANAR_KNOBS);
    EXPECT_EQ(knobError([] { ArcSettings::profile("humanoid"); }),
              "ArcSettings: unknown profile 'humanoid' (valid: mobile, planar, panda)");
}

TEST(ArcKnobs, EveryKnobIsADeclaredParameterOfTheArcFamily)
{
    const auto problem = scenarios::createMobileCross(4);
    ARC arc(problem.getSpaceInformation());
    PARC parc(problem.getSpaceInformation());
    ORPARC orparc(problem.getSpaceInformation());
    for (ompl::base::Planner *planner : std::vector<ompl::base::Planner *>{&arc, &parc, &orparc})
        for (const KnobParameter &knob : KNOB_PARAMETERS)
        {
            SCOPED_TRACE(planner->getName() + " " + knob.name);
            ASSERT_TRUE(planner->params().hasParam(knob.name));
            EXPECT_EQ(planner->params().getParam(knob.name)->getRangeSuggestion(), knob.range);
        }
    for (const char *name : {"workers", "horizon", "batch_per_worker", "grow_batches", "optimistic", "local_or"})
    {
        EXPECT_TRUE(parc.params().hasParam(name)) << name;
        EXPECT_FALSE(arc.params().hasParam(name)) << name;
    }
}

TEST(ArcKnobs, SetByNameRoundTripsAndSurvivesAProfile)
{
    const auto problem = scenarios::createMobileCross(4);
    for (const KnobParameter &knob : KNOB_PARAMETERS)
        for (const std::string profile : {"mobile", "planar", "panda"})
        {
            SCOPED_TRACE(knob.name + " then profile " + profile);
            PARC planner(problem.getSpaceInformation());
            auto &params = planner.params();
            ASSERT_TRUE(params.setParam(knob.name, knob.value));
            EXPECT_EQ(params.getParam(knob.name)->getValue(), knob.value);
            ASSERT_TRUE(params.setParam("profile", profile));
            EXPECT_EQ(params.getParam(knob.name)->getValue(), knob.value);
            // The other knobs take the profile's values: as on a planner with the profile set first.
            PARC reference(problem.getSpaceInformation());
            ASSERT_TRUE(reference.params().setParam("profile", profile));
            ASSERT_TRUE(reference.params().setParam(knob.name, knob.value));
            for (const KnobParameter &other : KNOB_PARAMETERS)
                EXPECT_EQ(params.getParam(other.name)->getValue(), reference.params().getParam(other.name)->getValue())
                    << other.name;
        }
}

TEST(ArcKnobs, RangeChecksRefuseWithTheirReasonAndKeepTheValue)
{
    const auto problem = scenarios::createMobileCross(4);
    ARC arc(problem.getSpaceInformation());
    for (const KnobParameter &knob : KNOB_PARAMETERS)
    {
        if (knob.refused.empty())
            continue;
        SCOPED_TRACE(knob.name);
        const std::string before = arc.params().getParam(knob.name)->getValue();
        const std::string error = knobError([&] { arc.params().setParam(knob.name, knob.refused); });
        const std::string from = knob.message.rfind("unknown", 0) == 0 ? "ArcSettings: " : "ARC: ";
        EXPECT_EQ(error, from + knob.message);
        EXPECT_EQ(arc.params().getParam(knob.name)->getValue(), before);
    }
    EXPECT_EQ(arc.getSettings().explicitFields, 0u);  // nothing refused counts as set
    EXPECT_EQ(knobError([&] { arc.setMinWindowGrowth(2e6); }), "ARC: min_window_growth must be between 1 and 1e6");
}

TEST(ArcKnobs, ParallelValuesHaveOneCheckEach)
{
    const auto problem = scenarios::createMobileCross(4);
    PARC parc(problem.getSpaceInformation());
    EXPECT_EQ(knobError([&] { parc.setWorkers(0); }), "PARC: workers must be at least 1");
    EXPECT_EQ(knobError([&] { parc.setHorizon(0); }), "PARC: horizon must be at least 1 timestep");
    EXPECT_EQ(knobError([&] { parc.setBatchPerWorker(0); }), "PARC: batch_per_worker must be at least 1");
    EXPECT_EQ(knobError([&] { parc.params().setParam("batch_per_worker", "0"); }),
              "PARC: batch_per_worker must be at least 1");
    EXPECT_EQ(parc.getBatchPerWorker(), 8u);
    EXPECT_EQ(parc.getHorizon(), 400u);
    RepairWorkspace workspace(*MultiRobotSpaceInformation::get(problem.getSpaceInformation(), "test"), 2);
    EXPECT_EQ(knobError([&] { workspace.configure(2, 10, 0, true); }),
              "RepairWorkspace: batch_per_worker must be at least 1");
    EXPECT_EQ(knobError([&] { workspace.configure(0, 10, 8, true); }), "WorkerPool: workers must be at least 1");
    EXPECT_EQ(knobError([&] { workspace.configure(2, 0, 8, true); }),
              "BatchDetector: horizon must be at least 1 timestep");
}

/* The setters and getters the table makes have the signatures written by hand before it. */
TEST(ArcKnobs, SettersAndGettersKeepTheirSignatures)
{
    using B = ArcPlannerBase;
    using SetNumber = void (B::*)(unsigned int);
    using SetReal = void (B::*)(double);
    using SetFlag = void (B::*)(bool);
    using SetName = void (B::*)(const std::string &);
    static_assert(std::is_same_v<decltype(&B::setWindow), SetNumber>);
    static_assert(std::is_same_v<decltype(&B::getWindow), unsigned int (B::*)() const>);
    static_assert(std::is_same_v<decltype(&B::setGrowth), SetName>);
    static_assert(std::is_same_v<decltype(&B::getGrowth), std::string (B::*)() const>);
    static_assert(std::is_same_v<decltype(&B::setGrowthStep), SetReal>);
    static_assert(std::is_same_v<decltype(&B::getGrowthStep), double (B::*)() const>);
    static_assert(std::is_same_v<decltype(&B::setMinWindowGrowth), SetReal>);
    static_assert(std::is_same_v<decltype(&B::setEndpointStep), SetNumber>);
    static_assert(std::is_same_v<decltype(&B::setBoundMargin), SetReal>);
    static_assert(std::is_same_v<decltype(&B::setMinBoundRange), SetReal>);
    static_assert(std::is_same_v<decltype(&B::setSampleCap), SetNumber>);
    static_assert(std::is_same_v<decltype(&B::setSolvers), SetName>);
    static_assert(std::is_same_v<decltype(&B::getSolvers), std::string (B::*)() const>);
    static_assert(std::is_same_v<decltype(&B::setSimplifyInitial), SetFlag>);
    static_assert(std::is_same_v<decltype(&B::setStraightInitial), SetFlag>);
    static_assert(std::is_same_v<decltype(&B::setShortenPatches), SetFlag>);
    static_assert(std::is_same_v<decltype(&B::setLatticeMapf), SetFlag>);
    static_assert(std::is_same_v<decltype(&B::setSequential), SetFlag>);
    static_assert(std::is_same_v<decltype(&B::getSequential), bool (B::*)() const>);
    static_assert(std::is_same_v<decltype(&PARC::setWorkers), SetNumber>);
    static_assert(std::is_same_v<decltype(&PARC::getHorizon), unsigned int (B::*)() const>);
    static_assert(std::is_same_v<decltype(&PARC::setBatchPerWorker), SetNumber>);
    static_assert(std::is_same_v<decltype(&PARC::setGrowBatches), SetFlag>);
    static_assert(std::is_same_v<decltype(&PARC::setOptimistic), SetFlag>);
    static_assert(std::is_same_v<decltype(&PARC::getLocalOr), bool (B::*)() const>);
    const auto problem = scenarios::createPlanarCross(4);
    PARC parc(problem.getSpaceInformation());
    parc.setWindow(80);
    parc.setGrowth("linear");
    parc.setSolvers("composite");
    parc.setSequential(true);
    parc.setWorkers(3);
    parc.setLocalOr(false);
    EXPECT_EQ(parc.getWindow(), 80u);
    EXPECT_EQ(parc.getGrowth(), "linear");
    EXPECT_EQ(parc.getSettings().growth, ArcSettings::Growth::LINEAR);
    EXPECT_EQ(parc.getSolvers(), "composite");
    EXPECT_TRUE(parc.getSequential());
    EXPECT_EQ(parc.getWorkers(), 3u);
    EXPECT_FALSE(parc.getLocalOr());
}
