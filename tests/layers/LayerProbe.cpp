/* A translation unit compiled with one layer's include directories (tests/CMakeLists.txt, layers.*): it includes a
   header of that layer, and with OMPL_PARC_PLANTED_INCLUDE defined also a header of a layer above it, which must not
   be found. */
#include OMPL_PARC_LAYER_HEADER
#ifdef OMPL_PARC_PLANTED_INCLUDE
#include OMPL_PARC_PLANTED_INCLUDE
#endif
