#ifndef OMPL_PARC_UTIL_OMPL_COMPAT_
#define OMPL_PARC_UTIL_OMPL_COMPAT_

/** \file
    \brief The one place that checks OMPL's version (1.5 to 2.x): feature macros for what differs between
    versions, and small wrappers that call the right OMPL name. Code elsewhere uses these, never
    OMPL_VERSION_VALUE itself (the OMPL_VERSION string is empty in Debian's 1.5.2). */

#include <ompl/config.h>
#include <ompl/geometric/PathSimplifier.h>

#ifndef OMPL_VERSION_VALUE
#error "ompl/config.h defines no OMPL_VERSION_VALUE"
#endif

/** \brief 1 when OMPL has its own SpaceTimeStateSpace and STRRTstar (OMPL >= 1.6), else 0. */
#define OMPL_PARC_OMPL_HAS_SPACE_TIME (OMPL_VERSION_VALUE >= 1006000)

/** \brief 1 when PathSimplifier::shortcutPath is named partialShortcutPath (OMPL >= 1.7), else 0. */
#define OMPL_PARC_OMPL_HAS_PARTIAL_SHORTCUT (OMPL_VERSION_VALUE >= 1007000)

namespace ompl_parc::compat
{
    /** \brief Shortcut \e path with random shortcuts between its segments: at most \e maxSteps attempts,
        stopping after \e maxEmptySteps without improvement (OMPL's PathSimplifier::shortcutPath, called
        partialShortcutPath from OMPL 1.7 on). True if the path changed. */
    inline bool shortcutPath(ompl::geometric::PathSimplifier &simplifier, ompl::geometric::PathGeometric &path,
                             unsigned int maxSteps, unsigned int maxEmptySteps)
    {
#if OMPL_PARC_OMPL_HAS_PARTIAL_SHORTCUT
        return simplifier.partialShortcutPath(path, maxSteps, maxEmptySteps);
#else
        return simplifier.shortcutPath(path, maxSteps, maxEmptySteps);
#endif
    }
}  // namespace ompl_parc::compat

#endif
