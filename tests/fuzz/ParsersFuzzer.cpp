/* libFuzzer target for the four parsers of user files: scenario files (ScenarioFile::fromJson), solution files
   (SolutionFile::fromJson, against a fixed team of two discs), benchmark configs (BenchmarkConfig::parse) and URDF
   arms (UrdfArm: urdfdom and the chain built from it; the file's first line names the base and the tip link).
   The first byte picks the parser, the rest is the file. A clean refusal is any exception derived from
   std::exception (ompl::Exception, std::invalid_argument, ...); what the fuzzer reports is anything else: a crash, a
   sanitizer error (the target is built with AddressSanitizer and UndefinedBehaviorSanitizer), a hang or unbounded
   memory. Built with -DOMPL_PARC_FUZZ=ON by clang; scripts/fuzz.sh builds it and runs it briefly on the corpus. */
#include "ompl_parc/planners/setup/BenchmarkConfig.h"

#include "ompl_parc/io/ScenarioFile.h"
#include "ompl_parc/io/SolutionFile.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/UrdfArm.h"

#include <ompl/util/Console.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>

namespace
{
    const ompl_parc::MultiRobotSpaceInformation &twoDiscs()
    {
        static const auto si = []
        {
            ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
            auto env = std::make_shared<ompl_parc::Environment>();
            ompl::base::RealVectorBounds bounds(2);
            bounds.setLow(-10.);
            bounds.setHigh(10.);
            std::vector<ompl_parc::RobotPtr> team = {std::make_shared<ompl_parc::DiscRobot>("a", env, 0.5, bounds),
                                                     std::make_shared<ompl_parc::DiscRobot>("b", env, 0.5, bounds)};
            return std::make_shared<ompl_parc::MultiRobotSpaceInformation>(team, 128.);
        }();
        return *si;
    }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::string text(reinterpret_cast<const char *>(data) + 1, size - 1);
    try
    {
        switch (data[0] % 4)
        {
            case 0:
                ompl_parc::ScenarioFile::fromJson(text, "");
                break;
            case 1:
                ompl_parc::SolutionFile::fromJson(text, twoDiscs());
                break;
            case 2:
            {
                std::istringstream in(text);
                ompl_parc::BenchmarkConfig::parse(in, ".");
                break;
            }
            default:
            {
                const std::size_t line = text.find('\n');
                std::istringstream links(text.substr(0, line));
                std::string base, tip;
                links >> base >> tip;
                ompl_parc::UrdfArm("arm", nullptr, line == std::string::npos ? "" : text.substr(line + 1), base, tip,
                                   Eigen::Isometry3d::Identity());
            }
        }
    }
    catch (const std::exception &)
    {
        // a clean refusal
    }
    return 0;
}
