#ifndef OMPL_PARC_MESH_LOCATOR_
#define OMPL_PARC_MESH_LOCATOR_

#include <string>
#include <vector>

namespace ompl_parc
{
    /** \brief Finds the file a URDF's `<mesh filename="...">` names, as ROS tools do.

        - `package://NAME/PATH`: PATH in the folder of package NAME. A package is a folder named NAME in (or
          named by) one of the folders of the search path: getPackagePath() first, then the folders of the
          environment variables OMPL_PARC_PACKAGE_PATH and ROS_PACKAGE_PATH (colon-separated), then the folders
          above the URDF's (a URDF in NAME/urdf/ finds NAME's meshes with no set-up).
        - `file:///PATH` and absolute paths: as they are.
        - a relative path: from the URDF's folder (the scenario's for a URDF given inline). */
    class MeshLocator
    {
      public:
        /** \brief Relative paths from the working folder. */
        MeshLocator() = default;

        /** \brief Relative paths from \e folder; \e packagePath searched first for packages. */
        explicit MeshLocator(std::string folder, std::vector<std::string> packagePath = {});

        /** \brief The file \e uri names. Throws ompl::Exception, one line with the folders searched, if a
            package cannot be found or the URI's scheme is not one of the above; a file that does not exist is
            TriangleMesh::read()'s to report. */
        std::string resolve(const std::string &uri) const;

        const std::string &getFolder() const { return folder_; }
        const std::vector<std::string> &getPackagePath() const { return packagePath_; }

      private:
        std::string folder_{"."};
        std::vector<std::string> packagePath_;
    };
}  // namespace ompl_parc

#endif
