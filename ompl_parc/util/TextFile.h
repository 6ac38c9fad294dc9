#ifndef OMPL_PARC_TEXT_FILE_
#define OMPL_PARC_TEXT_FILE_

#include <cstdint>
#include <string>

namespace ompl_parc
{
    /** \brief Reads the whole of a text file the tools were pointed at, refusing what is not one: a path that is not
        a regular file (a folder, /dev/zero, a pipe: reading those never ends or makes no sense) and a file larger
        than a limit (scenario, solution, URDF and benchmark files are kilobytes to a few megabytes). */
    class TextFile
    {
      public:
        /** \brief Files above this are refused: 256 MiB, a hundred times the largest solution file we write. */
        static constexpr std::uintmax_t MAX_BYTES = std::uintmax_t(256) << 20;

        /** \brief The contents of \e path; throws ompl::Exception(\e context, reason) with a one-line reason naming
            the file if it cannot be opened, is not a regular file or is larger than \e maxBytes. */
        static std::string read(const std::string &path, const std::string &context,
                                std::uintmax_t maxBytes = MAX_BYTES);
    };
}  // namespace ompl_parc

#endif
