#include "ompl_parc/io/ScenarioFile.h"

#include "ompl_parc/io/JsonFields.h"
#include "ompl_parc/model/TeamLimit.h"
#include "ompl_parc/robots/BuiltinModels.h"
#include "ompl_parc/robots/DiscRobot.h"
#include "ompl_parc/robots/PlanarArm.h"
#include "ompl_parc/robots/UrdfArm.h"
#include "ompl_parc/util/TextFile.h"

#include <nlohmann/json.hpp>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using nlohmann::json;
using nlohmann::ordered_json;  // written files keep their fields in a readable order

namespace
{
    const char *const FORMAT = "ompl_parc.scenario";
    constexpr int VERSION = 1;
    constexpr double DEFAULT_RESOLUTION = 128.;

    [[noreturn]] void fail(const std::string &what)
    {
        throw ompl::Exception("ScenarioFile", what);
    }

    /** Checked access to one JSON document: every helper names the field it looks at in its error. */
    const json &field(const json &object, const std::string &key, const std::string &where)
    {
        if (!object.contains(key))
            fail(where + ": missing field '" + key + "'");
        return object.at(key);
    }

    std::string member(const std::string &where, const std::string &key)
    {
        return where.empty() ? key : where + "." + key;
    }

    void requireObject(const json &value, const std::string &where)
    {
        if (!value.is_object())
            fail(where + " must be an object");
    }

    void allowOnly(const json &object, const std::set<std::string> &allowed, const std::string &where)
    {
        ompl_parc::allowOnlyFields(object, allowed, where, "ScenarioFile");
    }

    double number(const json &value, const std::string &where, bool positive = false)
    {
        if (!value.is_number() || !std::isfinite(value.get<double>()) || (positive && !(value.get<double>() > 0.)))
            fail(where + (positive ? " must be a positive number" : " must be a finite number"));
        return value.get<double>();
    }

    /** An array of \e count finite numbers (any non-zero count if \e count is 0). */
    std::vector<double> numbers(const json &value, const std::string &where, std::size_t count)
    {
        if (!value.is_array() || (count != 0 && value.size() != count) || value.empty())
            fail(where + " must be an array of " + (count != 0 ? std::to_string(count) : std::string("some")) +
                 " numbers");
        std::vector<double> out;
        for (std::size_t i = 0; i < value.size(); ++i)
            out.push_back(number(value[i], where + "[" + std::to_string(i) + "]"));
        return out;
    }

    double optionalNumber(const json &object, const std::string &key, double fallback, const std::string &where)
    {
        return object.contains(key) ? number(object.at(key), member(where, key)) : fallback;
    }

    void requirePositive(const std::vector<double> &values, const std::string &where)
    {
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!(values[i] > 0.))
                fail(where + "[" + std::to_string(i) + "] must be a positive number");
    }

    std::string nonEmptyString(const json &value, const std::string &where)
    {
        if (!value.is_string() || value.get<std::string>().empty())
            fail(where + " must be a non-empty string");
        return value.get<std::string>();
    }

    /** A name the tools print (summaries, error messages): a control character in it would reach the terminal as
        a command (a cursor move, a colour, a cleared screen), so none is taken: no C0 control, no DEL and no C1
        control (UTF-8 U+0080 to U+009F). Other UTF-8 text is welcome. */
    std::string printableName(const json &value, const std::string &where)
    {
        const std::string name = nonEmptyString(value, where);
        for (std::size_t i = 0; i < name.size(); ++i)
        {
            const auto byte = static_cast<unsigned char>(name[i]);
            const bool c1 = byte == 0xC2 && i + 1 < name.size() && static_cast<unsigned char>(name[i + 1]) >= 0x80 &&
                            static_cast<unsigned char>(name[i + 1]) <= 0x9F;
            if (byte < 0x20 || byte == 0x7F || c1)
                fail(where + " must be printable: it holds a control character at byte " + std::to_string(i));
        }
        return name;
    }

    /** {"low": [...], "high": [...]} with \e count entries each and low < high. */
    ompl::base::RealVectorBounds bounds(const json &value, const std::string &where, std::size_t count)
    {
        requireObject(value, where);
        allowOnly(value, {"low", "high"}, where);
        const auto low = numbers(field(value, "low", where), where + ".low", count);
        const auto high = numbers(field(value, "high", where), where + ".high", count);
        ompl::base::RealVectorBounds out(count);
        for (std::size_t d = 0; d < count; ++d)
        {
            if (!(low[d] < high[d]))
                fail(where + ".low[" + std::to_string(d) + "] must be below " + where + ".high[" + std::to_string(d) +
                     "]");
            out.setLow(d, low[d]);
            out.setHigh(d, high[d]);
        }
        return out;
    }

    ordered_json boundsToJson(const ompl::base::RealVectorBounds &b)
    {
        return {{"low", b.low}, {"high", b.high}};
    }

    /** The yaw of a box2d footprint if \e o is one (a box spanning z in [-1, 1] turned about z only). */
    bool asBox2D(const ompl_parc::Obstacle &o, double &yaw)
    {
        if (o.shape != ompl_parc::Obstacle::Shape::BOX || o.size.z() != 2. || o.pose.translation().z() != 0.)
            return false;
        const Eigen::Matrix3d r = o.pose.rotation();
        yaw = std::atan2(r(1, 0), r(0, 0));
        return r.isApprox(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-12);
    }

    /** "position" [x, y, z] and "orientation" quaternion [w, x, y, z] of an object (both optional). */
    Eigen::Isometry3d poseFromJson(const json &value, const std::string &where)
    {
        const auto p = value.contains("position") ? numbers(value.at("position"), where + ".position", 3)
                                                  : std::vector<double>{0., 0., 0.};
        const auto q = value.contains("orientation") ? numbers(value.at("orientation"), where + ".orientation", 4)
                                                     : std::vector<double>{1., 0., 0., 0.};
        // Scaled by its largest component first, so that huge components do not overflow the norm to infinity.
        const double largest = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
        if (!(largest > 0.))
            fail(where + ".orientation must be a non-zero quaternion [w, x, y, z]");
        Eigen::Quaterniond rotation(q[0] / largest, q[1] / largest, q[2] / largest, q[3] / largest);
        return Eigen::Translation3d(p[0], p[1], p[2]) * rotation.normalized();
    }

    ordered_json poseToJson(const Eigen::Isometry3d &pose)
    {
        const Eigen::Vector3d p = pose.translation();
        const Eigen::Quaterniond q(pose.rotation());
        return {{"position", {p.x(), p.y(), p.z()}}, {"orientation", {q.w(), q.x(), q.y(), q.z()}}};
    }

    ordered_json obstacleToJson(const ompl_parc::Obstacle &o)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        const Eigen::Vector3d p = o.pose.translation();
        double yaw = 0.;
        if (asBox2D(o, yaw))
            return {{"name", o.name},
                    {"shape", "box2d"},
                    {"center", {p.x(), p.y()}},
                    {"size", {o.size.x(), o.size.y()}},
                    {"yaw", yaw}};
        ordered_json out = {{"name", o.name}};
        switch (o.shape)
        {
            case Shape::BOX:
                out["shape"] = "box";
                out["size"] = {o.size.x(), o.size.y(), o.size.z()};
                break;
            case Shape::SPHERE:
                out["shape"] = "sphere";
                out["radius"] = o.size.x();
                break;
            case Shape::CYLINDER:
                out["shape"] = "cylinder";
                out["radius"] = o.size.x();
                out["length"] = o.size.z();
                break;
            case Shape::MESH:
            {
                // An absolute path: the file written may go to another folder than the one read.
                const Eigen::Vector3d &scale = o.mesh->getScale();
                out["shape"] = "mesh";
                out["file"] = std::filesystem::absolute(o.mesh->getFile()).lexically_normal().string();
                out["scale"] = {scale.x(), scale.y(), scale.z()};
                out["fit_resolution"] = o.fitResolution;
                break;
            }
        }
        out.update(poseToJson(o.pose));
        return out;
    }

    /** \e path as the scenario file names it: a relative path is from \e folder, the file's folder. */
    std::filesystem::path inFolder(const std::filesystem::path &path, const std::string &folder)
    {
        return path.is_relative() ? std::filesystem::path(folder) / path : path;
    }

    /** Parse obstacle \e value (at \e where, index \e index) into \e environment. */
    void addObstacle(const json &value, const std::string &where, std::size_t index, const std::string &folder,
                     ompl_parc::Environment &environment)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        requireObject(value, where);
        const std::string shape = nonEmptyString(field(value, "shape", where), where + ".shape");
        const std::string name = value.contains("name") ? printableName(value.at("name"), where + ".name")
                                                        : "obstacle" + std::to_string(index);
        if (shape == "box2d")
        {
            allowOnly(value, {"name", "shape", "center", "size", "yaw"}, where);
            const auto center = numbers(field(value, "center", where), where + ".center", 2);
            const auto size = numbers(field(value, "size", where), where + ".size", 2);
            requirePositive(size, where + ".size");
            environment.addBox2D(name, center[0], center[1], size[0], size[1], optionalNumber(value, "yaw", 0., where));
            return;
        }
        ompl_parc::Obstacle o;
        o.name = name;
        if (shape == "box")
        {
            allowOnly(value, {"name", "shape", "size", "position", "orientation"}, where);
            const auto size = numbers(field(value, "size", where), where + ".size", 3);
            requirePositive(size, where + ".size");
            o.size = Eigen::Vector3d(size[0], size[1], size[2]);
            o.shape = Shape::BOX;
        }
        else if (shape == "sphere")
        {
            allowOnly(value, {"name", "shape", "radius", "position", "orientation"}, where);
            o.size.x() = number(field(value, "radius", where), where + ".radius", true);
            o.shape = Shape::SPHERE;
        }
        else if (shape == "cylinder")
        {
            allowOnly(value, {"name", "shape", "radius", "length", "position", "orientation"}, where);
            o.size.x() = number(field(value, "radius", where), where + ".radius", true);
            o.size.z() = number(field(value, "length", where), where + ".length", true);
            o.shape = Shape::CYLINDER;
        }
        else if (shape == "mesh")
        {
            allowOnly(value, {"name", "shape", "file", "scale", "fit_resolution", "position", "orientation"}, where);
            const std::filesystem::path file = nonEmptyString(field(value, "file", where), where + ".file");
            Eigen::Vector3d scale = Eigen::Vector3d::Ones();
            if (value.contains("scale"))
            {
                const json &s = value.at("scale");
                const auto factors = s.is_number() ? std::vector<double>(3, number(s, where + ".scale", true))
                                                   : numbers(s, where + ".scale", 3);
                requirePositive(factors, where + ".scale");
                scale = Eigen::Vector3d(factors[0], factors[1], factors[2]);
            }
            if (value.contains("fit_resolution"))
            {
                const double cells = number(value.at("fit_resolution"), where + ".fit_resolution", true);
                if (cells != std::floor(cells) || cells > 256.)
                    fail(where + ".fit_resolution must be a whole number of cells, 1 .. 256");
                o.fitResolution = static_cast<unsigned int>(cells);
            }
            try
            {
                o.mesh = ompl_parc::TriangleMesh::read(
                    inFolder(file, folder).lexically_normal().string(),
                    scale);
            }
            catch (const ompl::Exception &e)
            {
                fail(where + ": " + e.what());
            }
            o.shape = Shape::MESH;
        }
        else
            fail(where + ".shape must be one of box, box2d, sphere, cylinder, mesh (got '" + shape + "')");

        o.pose = poseFromJson(value, where);
        environment.addObstacle(o);
    }

    ordered_json robotToJson(const ompl_parc::Robot &robot)
    {
        ordered_json out = {{"name", robot.getName()}, {"kind", robot.getKind()}};
        if (const auto *disc = dynamic_cast<const ompl_parc::DiscRobot *>(&robot))
        {
            out["radius"] = disc->getRadius();
            out["bounds"] = boundsToJson(disc->getBounds());
        }
        else if (const auto *arm = dynamic_cast<const ompl_parc::PlanarArm *>(&robot))
        {
            out["base"] = {{"x", arm->getBaseX()}, {"y", arm->getBaseY()}, {"yaw", arm->getBaseYaw()}};
            out["link_lengths"] = arm->getLinkLengths();
            out["link_width"] = arm->getLinkWidth();
            out["joint_limits"] = boundsToJson(arm->getBounds());
        }
        else if (const auto *urdf = dynamic_cast<const ompl_parc::UrdfArm *>(&robot))
        {
            // A built-in model by name, anything else inline: either way the file stays self-contained.
            const auto &models = ompl_parc::models::builtinUrdfs();
            const auto builtin = std::find_if(models.begin(), models.end(),
                                              [&](const auto &model) { return model.second() == urdf->getUrdfXml(); });
            if (builtin != models.end())
                out["builtin_urdf"] = builtin->first;
            else
                out["urdf"] = urdf->getUrdfXml();
            if (urdf->getSrdf())
                out["srdf"] = urdf->getSrdf()->getXml();
            out["base_link"] = urdf->getBaseLink();
            out["tip_link"] = urdf->getTipLink();
            out["base_pose"] = poseToJson(urdf->getBasePose());
            if (!urdf->getMeshes().empty())
            {
                // Absolute folders: the file written may go to another folder than the one read.
                const auto &options = urdf->getMeshOptions();
                const auto absolute = [](const std::string &path)
                { return std::filesystem::absolute(path).lexically_normal().string(); };
                out["mesh_folder"] = absolute(options.locator.getFolder());
                if (!options.locator.getPackagePath().empty())
                {
                    out["mesh_path"] = ordered_json::array();
                    for (const std::string &path : options.locator.getPackagePath())
                        out["mesh_path"].push_back(absolute(path));
                }
                out["mesh_capsules"] = options.maxCapsules;
            }
        }
        else
            fail("robot '" + robot.getName() + "' of kind '" + robot.getKind() + "' cannot be written");
        if (robot.hasOwnMotionLimits())
        {
            ordered_json velocity = ordered_json::array(), acceleration = ordered_json::array();
            for (const auto &group : robot.getMotionLimits().groups)
            {
                velocity.push_back(group.velocity);
                acceleration.push_back(group.acceleration);
            }
            out["limits"] = {{"velocity", velocity}, {"acceleration", acceleration}};
        }
        return out;
    }

    /** The URDF text of urdf_arm \e value: inline ("urdf"), a built-in model ("builtin_urdf") or a file
        ("urdf_file", relative paths from \e folder, the scenario file's folder; \e urdfFolder becomes the file's
        folder, where its relative mesh paths start). */
    std::string urdfFromJson(const json &value, const std::string &where, const std::string &folder,
                             std::string &urdfFolder)
    {
        urdfFolder = folder;
        if (value.contains("urdf") + value.contains("builtin_urdf") + value.contains("urdf_file") != 1)
            fail(where +
                 " needs exactly one of 'urdf' (the XML), 'builtin_urdf' (a model's name) or 'urdf_file' "
                 "(a path)");
        if (value.contains("urdf"))
            return nonEmptyString(value.at("urdf"), where + ".urdf");
        if (value.contains("builtin_urdf"))
        {
            const std::string model = nonEmptyString(value.at("builtin_urdf"), where + ".builtin_urdf");
            const auto it = ompl_parc::models::builtinUrdfs().find(model);
            if (it == ompl_parc::models::builtinUrdfs().end())
            {
                std::string valid;
                for (const auto &entry : ompl_parc::models::builtinUrdfs())
                    valid += (valid.empty() ? "" : ", ") + entry.first;
                fail(where + ".builtin_urdf must be one of " + valid + " (got '" + model + "')");
            }
            return it->second();
        }
        std::filesystem::path file = nonEmptyString(value.at("urdf_file"), where + ".urdf_file");
        file = inFolder(file, folder);
        urdfFolder = file.parent_path().string();
        return ompl_parc::UrdfArm::readFile(file.string());
    }

    /** A robot's "limits": {"velocity": V, "acceleration": A}, each a number for every group of \e defaults or a
        list of one per group (per joint for an arm, one for a disc's speed); a missing one keeps the default. */
    ompl_parc::MotionLimits limitsFromJson(const json &value, ompl_parc::MotionLimits defaults, const std::string &where)
    {
        requireObject(value, where);
        allowOnly(value, {"velocity", "acceleration"}, where);
        const std::size_t groups = defaults.groups.size();
        for (const char *key : {"velocity", "acceleration"})
        {
            if (!value.contains(key))
                continue;
            const std::string at = where + "." + key;
            const std::vector<double> limits = value.at(key).is_number()
                                                   ? std::vector<double>(groups, number(value.at(key), at, true))
                                                   : numbers(value.at(key), at, groups);
            requirePositive(limits, at);
            for (std::size_t g = 0; g < groups; ++g)
                (std::string(key) == "velocity" ? defaults.groups[g].velocity : defaults.groups[g].acceleration) =
                    limits[g];
        }
        return defaults;
    }

    /** Where urdf_arm \e value's meshes are found and how they are fitted: relative mesh paths from "mesh_folder"
        (else \e urdfFolder), packages also in the folders of "mesh_path", at most "mesh_capsules" capsules a mesh;
        relative folders from \e folder. */
    ompl_parc::UrdfMeshOptions meshOptionsFromJson(const json &value, const std::string &where,
                                                   const std::string &folder, const std::string &urdfFolder)
    {
        const auto fromScenario = [&](const std::string &path)
        {
            return inFolder(path, folder).lexically_normal().string();
        };
        std::string meshFolder = urdfFolder;
        if (value.contains("mesh_folder"))
            meshFolder = fromScenario(nonEmptyString(value.at("mesh_folder"), where + ".mesh_folder"));
        std::vector<std::string> packagePath;
        if (value.contains("mesh_path"))
        {
            const json &path = value.at("mesh_path");
            if (!path.is_array())
                fail(where + ".mesh_path must be a list of folders");
            for (std::size_t k = 0; k < path.size(); ++k)
                packagePath.push_back(
                    fromScenario(nonEmptyString(path[k], where + ".mesh_path[" + std::to_string(k) + "]")));
        }
        ompl_parc::UrdfMeshOptions options{ompl_parc::MeshLocator(meshFolder, packagePath)};
        if (value.contains("mesh_capsules"))
        {
            const double capsules = number(value.at("mesh_capsules"), where + ".mesh_capsules", true);
            if (capsules != std::floor(capsules) || capsules > 64.)
                fail(where + ".mesh_capsules must be a whole number of capsules, 1 .. 64");
            options.maxCapsules = static_cast<unsigned int>(capsules);
        }
        return options;
    }

    /** The SRDF of urdf_arm \e value, if it has one: inline ("srdf") or a file ("srdf_file", relative paths from
        \e folder). */
    ompl_parc::SrdfPtr srdfFromJson(const json &value, const std::string &where, const std::string &folder)
    {
        if (value.contains("srdf") && value.contains("srdf_file"))
            fail(where + " has both 'srdf' (the XML) and 'srdf_file' (a path); give one");
        if (value.contains("srdf"))
            return std::make_shared<ompl_parc::Srdf>(
                ompl_parc::Srdf::parse(nonEmptyString(value.at("srdf"), where + ".srdf")));
        if (!value.contains("srdf_file"))
            return nullptr;
        const std::filesystem::path file = nonEmptyString(value.at("srdf_file"), where + ".srdf_file");
        return std::make_shared<ompl_parc::Srdf>(
            ompl_parc::Srdf::read(inFolder(file, folder).string()));
    }

    /** The robot described by \e value; its start and goal go to \e start and \e goal. */
    ompl_parc::RobotPtr robotFromJson(const json &value, const std::string &where,
                                      const ompl_parc::EnvironmentPtr &environment, const std::string &folder,
                                      std::vector<double> &start, std::vector<double> &goal)
    {
        requireObject(value, where);
        const std::string name = printableName(field(value, "name", where), where + ".name");
        const std::string kind = nonEmptyString(field(value, "kind", where), where + ".kind");
        ompl_parc::RobotPtr robot;
        if (kind == "disc")
        {
            allowOnly(value, {"name", "kind", "radius", "bounds", "limits", "start", "goal"}, where);
            const double radius = number(field(value, "radius", where), where + ".radius", true);
            robot = std::make_shared<ompl_parc::DiscRobot>(name, environment, radius,
                                                           bounds(field(value, "bounds", where), where + ".bounds", 2));
        }
        else if (kind == "planar_arm")
        {
            allowOnly(value,
                      {"name", "kind", "base", "link_lengths", "link_width", "joint_limits", "limits", "start", "goal"},
                      where);
            const json &base = field(value, "base", where);
            requireObject(base, where + ".base");
            allowOnly(base, {"x", "y", "yaw"}, where + ".base");
            const auto links = numbers(field(value, "link_lengths", where), where + ".link_lengths", 0);
            requirePositive(links, where + ".link_lengths");
            const double width = number(field(value, "link_width", where), where + ".link_width", true);
            robot = std::make_shared<ompl_parc::PlanarArm>(
                name, environment, number(field(base, "x", where + ".base"), where + ".base.x"),
                number(field(base, "y", where + ".base"), where + ".base.y"),
                optionalNumber(base, "yaw", 0., where + ".base"), links, width,
                bounds(field(value, "joint_limits", where), where + ".joint_limits", links.size()));
        }
        else if (kind == "urdf_arm")
        {
            // The URDF, the chain's end links, and the base pose ("base_pose": position and orientation).
            allowOnly(value,
                      {"name", "kind", "urdf", "builtin_urdf", "urdf_file", "srdf", "srdf_file", "group", "base_link",
                       "tip_link", "base_pose", "mesh_folder", "mesh_path", "mesh_capsules", "limits", "start", "goal"},
                      where);
            std::string urdfFolder;
            const std::string xml = urdfFromJson(value, where, folder, urdfFolder);
            const ompl_parc::UrdfMeshOptions meshOptions = meshOptionsFromJson(value, where, folder, urdfFolder);
            const ompl_parc::SrdfPtr srdf = srdfFromJson(value, where, folder);
            // The chain: by the SRDF's group, or by its end links.
            std::pair<std::string, std::string> ends;
            if (value.contains("group"))
            {
                if (!srdf)
                    fail(where + ".group needs the SRDF that defines it ('srdf' or 'srdf_file')");
                if (value.contains("base_link") || value.contains("tip_link"))
                    fail(where + " has 'group' and 'base_link'/'tip_link'; give the group or the links");
                ends = srdf->getChain(nonEmptyString(value.at("group"), where + ".group"));
            }
            else
                ends = {nonEmptyString(field(value, "base_link", where), where + ".base_link"),
                        nonEmptyString(field(value, "tip_link", where), where + ".tip_link")};
            Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
            if (value.contains("base_pose"))
            {
                requireObject(value.at("base_pose"), where + ".base_pose");
                allowOnly(value.at("base_pose"), {"position", "orientation"}, where + ".base_pose");
                base = poseFromJson(value.at("base_pose"), where + ".base_pose");
            }
            robot = std::make_shared<ompl_parc::UrdfArm>(name, environment, xml, ends.first, ends.second, base, srdf,
                                                         meshOptions);
        }
        else
            fail(where + ".kind must be one of disc, planar_arm, urdf_arm (got '" + kind + "')");
        if (value.contains("limits"))
            robot->setMotionLimits(limitsFromJson(value.at("limits"), robot->getMotionLimits(), where + ".limits"));
        start = numbers(field(value, "start", where), where + ".start", robot->getDimension());
        goal = numbers(field(value, "goal", where), where + ".goal", robot->getDimension());
        return robot;
    }

    /** \e doc with one line per top-level field and per obstacle and robot, as in the hand-written examples:
        compact, and a diff shows which robot changed. */
    std::string layOut(const ordered_json &doc)
    {
        std::string out = "{";
        for (const auto &field : doc.items())
        {
            out += (out.size() == 1 ? "\n  " : ",\n  ") + ordered_json(field.key()).dump() + ": ";
            const ordered_json &value = field.value();
            if (!value.is_array() || value.empty() || !value.front().is_object())
            {
                out += value.dump();
                continue;
            }
            for (std::size_t i = 0; i < value.size(); ++i)
                out += (i == 0 ? "[\n    " : ",\n    ") + value[i].dump();
            out += "\n  ]";
        }
        return out + "\n}";
    }

    /** "at line L, column C: ..." of a nlohmann parse error, without its "[json.exception...] " prefix. */
    std::string syntaxError(const json::parse_error &e)
    {
        std::string what = e.what();
        const auto at = what.find(" at line ");
        return (at == std::string::npos ? what : what.substr(at + 1)) + " (byte " + std::to_string(e.byte) + ")";
    }
}  // namespace

std::string ompl_parc::ScenarioFile::toJson(const MultiRobotProblem &problem)
{
    const auto &si = *problem.getSpaceInformation();
    const EnvironmentPtr &environment = si.getRobot(0)->getEnvironment();
    ordered_json obstacles = ordered_json::array();
    for (const auto &o : environment->getObstacles())
        obstacles.push_back(obstacleToJson(o));
    ordered_json robots = ordered_json::array();
    for (std::size_t i = 0; i < si.getRobotCount(); ++i)
    {
        const Robot &robot = *si.getRobot(i);
        if (robot.getEnvironment() != environment)
            fail("robot '" + robot.getName() + "' has an Environment of its own; a scenario file has one");
        ordered_json entry = robotToJson(robot);
        entry["start"] = problem.getStart(i);
        entry["goal"] = problem.getGoal(i);
        robots.push_back(std::move(entry));
    }
    const ordered_json doc = {{"format", FORMAT},
                              {"version", VERSION},
                              {"name", problem.getName()},
                              {"resolution", si.getResolution()},
                              {"obstacles", std::move(obstacles)},
                              {"robots", std::move(robots)}};
    return layOut(doc);
}

void ompl_parc::ScenarioFile::write(const std::string &path, const MultiRobotProblem &problem)
{
    const std::string text = toJson(problem);
    std::ofstream out(path);
    if (!out)
        fail("cannot write '" + path + "'");
    out << text << '\n';
    if (!out)
        fail("error writing '" + path + "'");
}

ompl_parc::MultiRobotProblem ompl_parc::ScenarioFile::read(const std::string &path)
{
    return fromJson(TextFile::read(path, "ScenarioFile"), std::filesystem::path(path).parent_path().string());
}

ompl_parc::MultiRobotProblem ompl_parc::ScenarioFile::fromJson(const std::string &text, const std::string &folder)
{
    json doc;
    try
    {
        doc = json::parse(text);
    }
    catch (const json::parse_error &e)
    {
        fail("not valid JSON " + syntaxError(e));
    }
    catch (const json::exception &e)  // e.g. a number beyond double's range (1e999)
    {
        fail(std::string("not valid JSON: ") + e.what());
    }
    requireObject(doc, "the scenario");
    allowOnly(doc, {"format", "version", "name", "resolution", "obstacles", "robots"}, "scenario");
    const json &format = field(doc, "format", "scenario");
    if (!format.is_string() || format.get<std::string>() != FORMAT)
        fail("'format' must be \"" + std::string(FORMAT) + "\"");
    const json &version = field(doc, "version", "scenario");
    if (!version.is_number_integer() || version.get<std::int64_t>() != VERSION)
        fail("unsupported 'version' (this build reads version " + std::to_string(VERSION) + ")");
    const std::string name = printableName(field(doc, "name", "scenario"), "name");
    const double resolution =
        doc.contains("resolution") ? number(doc.at("resolution"), "resolution", true) : DEFAULT_RESOLUTION;

    auto environment = std::make_shared<Environment>();
    if (doc.contains("obstacles"))
    {
        const json &obstacles = doc.at("obstacles");
        if (!obstacles.is_array())
            fail("obstacles must be an array");
        for (std::size_t i = 0; i < obstacles.size(); ++i)
            addObstacle(obstacles[i], "obstacles[" + std::to_string(i) + "]", i, folder, *environment);
    }

    const json &robots = field(doc, "robots", "scenario");
    if (!robots.is_array() || robots.empty())
        fail("robots must be a non-empty array");
    checkTeamSize(robots.size(), "scenario file");  // before the robots are built
    std::vector<RobotPtr> team;
    std::vector<std::vector<double>> starts(robots.size()), goals(robots.size());
    std::map<std::string, std::size_t> names;
    for (std::size_t i = 0; i < robots.size(); ++i)
    {
        const std::string where = "robots[" + std::to_string(i) + "]";
        team.push_back(robotFromJson(robots[i], where, environment, folder, starts[i], goals[i]));
        const auto [previous, fresh] = names.emplace(team.back()->getName(), i);
        if (!fresh)
            fail(where + ".name '" + team.back()->getName() + "' is already used by robots[" +
                 std::to_string(previous->second) + "]");
    }
    MultiRobotProblem problem(std::make_shared<MultiRobotSpaceInformation>(team, resolution), std::move(starts),
                              std::move(goals), name);
    const std::string reason = problem.checkEndpoints();
    if (!reason.empty())
        fail(reason);
    return problem;
}
