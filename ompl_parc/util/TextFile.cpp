#include "ompl_parc/util/TextFile.h"

#include <ompl/util/Exception.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

std::string ompl_parc::TextFile::read(const std::string &path, const std::string &context, std::uintmax_t maxBytes)
{
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status))
        throw ompl::Exception(context, "cannot open '" + path + "'");
    if (!std::filesystem::is_regular_file(status))
        throw ompl::Exception(context, "'" + path + "' is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || size > maxBytes)
        throw ompl::Exception(context, "'" + path + "' is larger than " + std::to_string(maxBytes >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw ompl::Exception(context, "cannot open '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
