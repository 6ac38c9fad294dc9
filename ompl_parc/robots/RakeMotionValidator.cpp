#include "ompl_parc/robots/RakeMotionValidator.h"

#include "ompl_parc/util/StopSignal.h"

#include <vector>

ompl_parc::RakeMotionValidator::RakeMotionValidator(ompl::base::SpaceInformation *si, BatchCheck check,
                                                    const ompl::base::StateValidityChecker *checker,
                                                    SweepCheck sweep)
  : ompl::base::DiscreteMotionValidator(si), check_(std::move(check)), sweep_(std::move(sweep)), checker_(checker)
{
}

template <typename Check>
bool ompl_parc::RakeMotionValidator::rake(unsigned int n, Check check)
{
    unsigned int stride = 1;
    while (2 * stride < n)
        stride *= 2;
    // A motion given up on (the planning stopped) counts as invalid: never a wrong "valid". Polled on entry
    // too, so that many short checks (a path simplifier's) also end once the planning stops.
    if (StopSignal::raised())
        return false;
    unsigned int polls = 0;
    for (; stride >= 1; stride /= 2)
        for (unsigned int j = stride; j < n; j += 2 * stride)
            if (!check(j) || (++polls % StopSignal::POLL_INTERVAL == 0 && StopSignal::raised()))
                return false;
    return true;
}

bool ompl_parc::RakeMotionValidator::checkBatched(const std::vector<double> &from, const std::vector<double> &to,
                                                  unsigned int n) const
{
    thread_local std::vector<double> samples;
    const std::size_t d = from.size();
    samples.resize(static_cast<std::size_t>(BATCH) * d);
    std::copy(to.begin(), to.end(), samples.begin());  // the end state first
    unsigned int count = 1;
    const auto flush = [&]
    {
        const bool valid = check_(samples.data(), count);
        count = 0;
        return valid;
    };
    const bool valid = rake(n,
                            [&](unsigned int j)
                            {
                                // RealVectorStateSpace::interpolate's arithmetic, so the samples are the same
                                const double t = static_cast<double>(j) / static_cast<double>(n);
                                double *q = samples.data() + static_cast<std::size_t>(count) * d;
                                for (std::size_t k = 0; k < d; ++k)
                                    q[k] = from[k] + (to[k] - from[k]) * t;
                                return ++count < BATCH || flush();
                            });
    return valid && (count == 0 || flush());
}

std::optional<bool> ompl_parc::RakeMotionValidator::checkStraight(const std::vector<double> &from,
                                                                  const std::vector<double> &to, unsigned int n) const
{
    if (!check_)
        return std::nullopt;
    if (const std::optional<bool> swept = sweep_ ? sweep_(from.data(), to.data()) : std::nullopt)
        return *swept;
    return checkBatched(from, to, n);
}

bool ompl_parc::RakeMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const
{
    // s1 is assumed valid, as in OMPL
    ompl::base::StateSpace &space = *si_->getStateSpace();  // DiscreteMotionValidator keeps its own private
    const unsigned int n = space.validSegmentCount(s1, s2);
    bool valid;
    if (check_ && si_->getStateValidityChecker().get() == checker_)
    {
        thread_local std::vector<double> from, to;
        space.copyToReals(from, s1);
        space.copyToReals(to, s2);
        valid = *checkStraight(from, to, n);
    }
    else
    {
        valid = si_->isValid(s2);
        if (valid && n >= 2)
        {
            ompl::base::State *test = si_->allocState();
            valid = rake(n,
                         [&](unsigned int j)
                         {
                             space.interpolate(s1, s2, static_cast<double>(j) / static_cast<double>(n), test);
                             return si_->isValid(test);
                         });
            si_->freeState(test);
        }
    }
    if (valid)
        valid_++;
    else
        invalid_++;
    return valid;
}
