#include <gtest/gtest.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

/* Every test process fixes OMPL's global seed before any RNG exists, so planning tests are
   deterministic; per-test seeds derive from it. */
int main(int argc, char **argv)
{
    ompl::RNG::setSeed(42);
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
