#ifndef OMPL_PARC_RAKE_MOTION_VALIDATOR_
#define OMPL_PARC_RAKE_MOTION_VALIDATOR_

#include <ompl/base/DiscreteMotionValidator.h>

#include <functional>
#include <optional>
#include <vector>

namespace ompl_parc
{
    /** \brief Checks a motion's samples far-apart first, several at a time, without allocating per sample.

        The sample set is DiscreteMotionValidator's (the end state, then the fractions j / n for j = 1 .. n - 1,
        n = validSegmentCount(), one per timestep for our spaces), so plans stay valid at every timestep; only
        the order changes: the end state, then level by level of a bisection, stride = the largest power of two
        below n, then its halves, each level checking the odd multiples of its stride (like VAMP's rake, the first
        samples are spread over the whole motion, so a blocked motion is rejected after few checks). OMPL's
        validator visits the same bisection through a std::queue, allocating per motion; here the order is
        plain index arithmetic.

        Given a batch check (Robot::allValid() for a robot's space, MultiRobotValidityChecker::allValid() for a
        team's), the samples go to it BATCH at a time, in that order, as flat arrays of the state's real values
        (StateSpace::copyToReals() order, interpolated with RealVectorStateSpace's arithmetic): kinds with a
        kernel over several configurations (UrdfArm's SIMD lanes) check a batch in one call. Without one,
        samples go to the space information's validity checker one at a time.
        checkMotion(s1, s2, lastValid) must report the last valid state before the first invalid one, so it
        stays OMPL's sequential scan. */
    class RakeMotionValidator : public ompl::base::DiscreteMotionValidator
    {
      public:
        /** \brief Checks \e count configurations (flat, the state's real values each): true if all are valid. */
        using BatchCheck = std::function<bool(const double *configs, std::size_t count)>;

        /** \brief Checks the whole straight motion between two configurations at once where it can (see
            Robot::sweepValid()); std::nullopt sends the motion to the samples. */
        using SweepCheck = std::function<std::optional<bool>(const double *from, const double *to)>;

        /** \brief Samples per batch check: at least every kernel's lane count, small enough that a blocked motion
            stops early. */
        static constexpr unsigned int BATCH = 8;

        using ompl::base::DiscreteMotionValidator::checkMotion;

        /** \brief Validates motions of \e si, whose states are real vectors or compounds of them. With \e check,
            batch by batch, as long as \e si's validity checker is still \e checker, the one \e check stands for
            (a user who sets another one gets it asked, state by state); \e sweep, if given, is asked first. */
        explicit RakeMotionValidator(ompl::base::SpaceInformation *si, BatchCheck check = BatchCheck(),
                                     const ompl::base::StateValidityChecker *checker = nullptr,
                                     SweepCheck sweep = SweepCheck());

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;

        /** \brief The check of checkMotion() on real values: the straight motion from \e from (valid) to \e to in \e n
            segments, swept at once where the kind can, else sampled batch by batch in rake order; std::nullopt
            without a batch check. It leaves OMPL's motion counters alone (they are not atomic), so threads may
            share the validator: a robot's own, in ARC's initial stage. */
        std::optional<bool> checkStraight(const std::vector<double> &from, const std::vector<double> &to,
                                          unsigned int n) const;

      private:
        /** \brief The samples of a motion of \e n segments (n >= 2): calls \e check with each rake level's fractions'
            numerators j (1 .. n - 1), in order, until it returns false. */
        template <typename Check>
        static bool rake(unsigned int n, Check check);

        /** \brief The samples of the motion \e from .. \e to (real values) of \e n segments, batch by batch. */
        bool checkBatched(const std::vector<double> &from, const std::vector<double> &to, unsigned int n) const;

        BatchCheck check_;
        SweepCheck sweep_;
        const ompl::base::StateValidityChecker *checker_;
    };
}  // namespace ompl_parc

#endif
