# Finds ompl_parc's dependencies. Included by the top-level CMakeLists.txt and by the installed
# ompl_parcConfig.cmake, so a consumer resolves exactly what the library was built against.
include(CMakeFindDependencyMacro)

find_dependency(Threads)
find_dependency(Eigen3)
find_dependency(fcl)
find_dependency(ccd)
find_dependency(urdfdom)
find_dependency(assimp)
find_dependency(nlohmann_json)
find_dependency(Boost COMPONENTS program_options serialization filesystem system)
# The installed config sets OMPL_PARC_OMPL_VERSION and OMPL_PARC_OMPL_DIR to the OMPL the library was built
# with: that exact version, also looked for where it was then (an OMPL of another version, e.g. the system's, is
# passed over); without a known version, only that folder. The build itself takes the OMPL CMAKE_PREFIX_PATH gives.
if(OMPL_PARC_OMPL_VERSION)
    find_dependency(ompl ${OMPL_PARC_OMPL_VERSION} EXACT HINTS "${OMPL_PARC_OMPL_DIR}")
elseif(OMPL_PARC_OMPL_DIR)
    find_dependency(ompl PATHS "${OMPL_PARC_OMPL_DIR}" NO_DEFAULT_PATH)
else()
    find_dependency(ompl)
endif()

# OMPL >= 1.6 exports the target ompl::ompl; Debian's 1.5.2 only sets variables. Give both the
# same imported target so the rest of the build (and our consumers) need not care.
if(NOT TARGET ompl::ompl)
    add_library(ompl::ompl INTERFACE IMPORTED)
    set_target_properties(ompl::ompl PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIRS}"
        INTERFACE_LINK_LIBRARIES "${OMPL_LIBRARIES}")
endif()
if(NOT TARGET ompl_parc::urdfdom)
    add_library(ompl_parc::urdfdom INTERFACE IMPORTED)
    set_target_properties(ompl_parc::urdfdom PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${urdfdom_INCLUDE_DIRS}"
        INTERFACE_LINK_LIBRARIES "${urdfdom_LIBRARIES}")
endif()
