#include "ompl_parc/meshes/MeshLocator.h"

#include <ompl/util/Exception.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace
{
    /** The folders of a colon-separated path variable (none if unset). */
    std::vector<std::string> pathVariable(const char *name)
    {
        std::vector<std::string> folders;
        const char *value = std::getenv(name);
        std::istringstream in(value != nullptr ? value : "");
        for (std::string folder; std::getline(in, folder, ':');)
            if (!folder.empty())
                folders.push_back(folder);
        return folders;
    }
}  // namespace

ompl_parc::MeshLocator::MeshLocator(std::string folder, std::vector<std::string> packagePath)
    : folder_(std::move(folder)), packagePath_(std::move(packagePath))
{
}

std::string ompl_parc::MeshLocator::resolve(const std::string &uri) const
{
    namespace fs = std::filesystem;
    const std::string package = "package://", file = "file://";
    if (uri.compare(0, file.size(), file) == 0)
        return uri.substr(file.size());
    if (uri.compare(0, package.size(), package) != 0)
    {
        if (uri.find("://") != std::string::npos)
            throw ompl::Exception("MeshLocator",
                                  "mesh '" + uri + "': only package://, file:// and plain paths are supported");
        const fs::path path(uri);
        return (path.is_relative() ? fs::path(folder_) / path : path).lexically_normal().string();
    }
    const std::string rest = uri.substr(package.size());
    const std::size_t slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    if (name.empty() || slash == std::string::npos || slash + 1 == rest.size())
        throw ompl::Exception("MeshLocator", "mesh '" + uri + "' is not package://NAME/PATH");
    const std::string inside = rest.substr(slash + 1);
    std::vector<std::string> searched = packagePath_;
    for (const char *variable : {"OMPL_PARC_PACKAGE_PATH", "ROS_PACKAGE_PATH"})
        for (const std::string &folder : pathVariable(variable))
            searched.push_back(folder);
    std::error_code error;
    for (fs::path up = fs::absolute(folder_, error).lexically_normal(); up.has_relative_path(); up = up.parent_path())
        searched.push_back(up.string());
    for (const std::string &folder : searched)
    {
        fs::path root = fs::path(folder).lexically_normal();
        if (!root.has_filename())  // a trailing slash
            root = root.parent_path();
        for (const fs::path &candidate : {root / name, root})
            if (candidate.filename() == name && fs::is_directory(candidate, error))
                return (candidate / inside).lexically_normal().string();
    }
    std::string list;
    for (const std::string &folder : searched)
        list += (list.empty() ? "" : ", ") + folder;
    throw ompl::Exception("MeshLocator", "mesh '" + uri + "': package '" + name +
                                             "' is in none of the folders searched (" + list +
                                             "); add its parent folder to OMPL_PARC_PACKAGE_PATH");
}
