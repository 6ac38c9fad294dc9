#ifndef OMPL_PARC_SCENARIOS_PROBLEM_FAMILIES_
#define OMPL_PARC_SCENARIOS_PROBLEM_FAMILIES_

#include "ompl_parc/model/MultiRobotProblem.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ompl_parc
{
    namespace scenarios
    {
        /** \brief Random problem families beyond the paper's four scenarios, so that robustness and speed are
            checked on problems nothing was tuned on. An instance is drawn from (family, robots, instance)
            alone with Boost.Random's engine and distributions, whose output is fixed by their definition:
            the same instance on every machine. Every instance's starts and goals are valid
            (MultiRobotProblem::checkEndpoints()) and, for the disc families, every start and goal lies in one
            free region (a flood fill of disc positions on a grid), so an instance is solvable in principle.

            - "rooms": 2 or 3 rooms in a row joined by one door each (1.5 to 2.5 wide, for discs of diameter
              1); every robot starts in one room and goes to a random cell of another.
            - "crossing": a 4-way intersection of two corridors 3 to 4.5 wide; every robot starts in one arm
              and leaves by another.
            - "ring": discs packed on a ring (1.3 to 2.2 apart along it), each going to the antipode, around a
              square block in the middle when the ring is wide enough (every other instance).
            - "field": a square field with random boxes (about one per two robots); the robots permute their
              start positions at random.
            - "planar_cell": 3-link planar arms on a jittered grid with overlapping reach, random start and
              goal configurations.
            - "panda_cell": Pandas around the cage of Panda Cage (2, 4, 8 or 16) with a random task drawn as the
              stored tasks are (generatePandaCageTask()), from the instance's own seed.

            Throws ompl::Exception for an unknown family, fewer than 2 robots (more than 16 for "panda_cell",
            or a count other than 2, 4, 8, 16), or an instance whose team does not fit after many draws. */
        MultiRobotProblem generateFamilyInstance(const std::string &family, std::size_t robots, std::uint32_t instance,
                                                 double resolution = 128.);

        /** \brief The family names generateFamilyInstance() accepts. */
        std::vector<std::string> familyNames();
    }  // namespace scenarios
}  // namespace ompl_parc

#endif
