#include "ompl_parc/robots/UrdfArm.h"

#include "ompl_parc/util/TextFile.h"

#include "ompl_parc/collision/CapsuleCollision.h"
#include "ompl_parc/meshes/CapsuleFitCache.h"

#include <console_bridge/console.h>
#include <ompl/util/Exception.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <set>

namespace
{
    const char *const CONTEXT = "UrdfArm";

    /** While it exists, urdfdom's error messages (console_bridge) are kept instead of printed, so that a
        malformed URDF is reported in one line, with the first of them; other messages go on as before.
        console_bridge's handler is global: one parse at a time. */
    class UrdfdomErrors : public console_bridge::OutputHandler
    {
      public:
        UrdfdomErrors() : lock_(mutex()), previous_(console_bridge::getOutputHandler())
        {
            console_bridge::useOutputHandler(this);
        }
        ~UrdfdomErrors() override { console_bridge::restorePreviousOutputHandler(); }
        UrdfdomErrors(const UrdfdomErrors &) = delete;
        UrdfdomErrors &operator=(const UrdfdomErrors &) = delete;

        void log(const std::string &text, console_bridge::LogLevel level, const char *filename, int line) override
        {
            if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR)
            {
                if (first_.empty())
                    first_ = text;
            }
            else if (previous_ != nullptr)
                previous_->log(text, level, filename, line);
        }

        /** \brief The first error urdfdom reported (empty if none). */
        const std::string &first() const { return first_; }

      private:
        static std::mutex &mutex()
        {
            static std::mutex m;
            return m;
        }

        std::lock_guard<std::mutex> lock_;
        console_bridge::OutputHandler *previous_;
        std::string first_;
    };

    Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
        t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                         .normalized()
                         .toRotationMatrix();
        return t;
    }

    /** The offset of the first byte of \e text that does not belong to a complete UTF-8 character (a NUL counts as
        one), or std::string::npos. TinyXML, urdfdom's parser and ours, reads a character's continuation bytes
        without looking for the end of the text: a lead byte at the end made it read past it (found by fuzzing). */
    std::size_t firstInvalidUtf8(const std::string &text)
    {
        for (std::size_t k = 0; k < text.size();)
        {
            const auto lead = static_cast<unsigned char>(text[k]);
            const std::size_t length = lead < 0x80           ? 1
                                       : (lead >> 5) == 0x6  ? 2
                                       : (lead >> 4) == 0xE  ? 3
                                       : (lead >> 3) == 0x1E ? 4
                                                             : 0;
            if (lead == 0 || length == 0 || length > text.size() - k)
                return k;
            for (std::size_t j = 1; j < length; ++j)
                if ((static_cast<unsigned char>(text[k + j]) & 0xC0) != 0x80)
                    return k;
            k += length;
        }
        return std::string::npos;
    }

    /** The checks urdfdom cannot be left to, on the URDF's XML before urdfdom builds anything. Joints that lead
        back to a link already on the way (a loop), or a link that is the child of two joints: urdfdom links such a
        tree into a cycle of owners and, when it then fails (no root link), returns nothing it could be freed
        through. And a `<collision>` element whose geometry urdfdom would read only in part: it takes the first
        shape of a `<geometry>` and the first `<geometry>` of a `<collision>` and drops the rest without a word.
        (Elements it cannot read at all it reports as errors, which parseChain() refuses.) */
    void checkStructure(const std::string &urdfXml)
    {
        TiXmlDocument document;
        document.Parse(urdfXml.c_str());
        const TiXmlElement *robot = document.RootElement();
        if (document.Error() || robot == nullptr)
            return;  // urdfdom reports it
        // Child elements of \e parent named \e name (any name if null).
        const auto count = [](const TiXmlElement &parent, const char *name)
        {
            int n = 0;
            for (const TiXmlElement *e = parent.FirstChildElement(); e != nullptr; e = e->NextSiblingElement())
                n += name == nullptr || e->ValueStr() == name;
            return n;
        };
        const auto text = [](const char *value) { return std::string(value != nullptr ? value : ""); };
        for (const TiXmlElement *link = robot->FirstChildElement("link"); link != nullptr;
             link = link->NextSiblingElement("link"))
            for (const TiXmlElement *collision = link->FirstChildElement("collision"); collision != nullptr;
                 collision = collision->NextSiblingElement("collision"))
            {
                const std::string where = "link '" + text(link->Attribute("name")) + "'";
                if (count(*collision, "geometry") != 1 || count(*collision, "origin") > 1)
                    throw ompl::Exception(CONTEXT, "malformed URDF: " + where +
                                                       " has a <collision> without exactly one <geometry> (or with "
                                                       "two <origin>s)");
                if (count(*collision->FirstChildElement("geometry"), nullptr) != 1)
                    throw ompl::Exception(CONTEXT, "malformed URDF: " + where +
                                                       " has a <collision> whose <geometry> does not hold exactly "
                                                       "one shape");
            }
        // The tree: each link's parent link, then a walk up from every link, each link walked once.
        std::map<std::string, std::string> parentOf;
        for (const TiXmlElement *joint = robot->FirstChildElement("joint"); joint != nullptr;
             joint = joint->NextSiblingElement("joint"))
        {
            const TiXmlElement *parent = joint->FirstChildElement("parent"), *child = joint->FirstChildElement("child");
            if (parent == nullptr || child == nullptr)
                continue;  // urdfdom reports it (after linking the other joints: their loops are refused here)
            const std::string from = text(parent->Attribute("link")), to = text(child->Attribute("link"));
            if (from == to)
                throw ompl::Exception(CONTEXT, "the URDF's joints form a loop through link '" + to + "'");
            if (!parentOf.emplace(to, from).second)
                throw ompl::Exception(CONTEXT, "malformed URDF: link '" + to + "' is the child of two joints");
        }
        enum class Walk
        {
            ON_PATH,
            DONE
        };
        std::map<std::string, Walk> walked;
        std::vector<std::string> path;
        for (const auto &entry : parentOf)
        {
            path.clear();
            for (std::string link = entry.first;;)
            {
                const auto seen = walked.find(link);
                if (seen != walked.end())
                {
                    if (seen->second == Walk::ON_PATH)
                        throw ompl::Exception(CONTEXT, "the URDF's joints form a loop through link '" + link + "'");
                    break;
                }
                walked.emplace(link, Walk::ON_PATH);
                path.push_back(link);
                const auto up = parentOf.find(link);
                if (up == parentOf.end())
                    break;
                link = up->second;
            }
            for (const std::string &link : path)
                walked[link] = Walk::DONE;
        }
    }

    /** urdfdom's links own their child links (shared_ptr): joints that loop would make a cycle of owners that is
        never freed. checkStructure() refuses such URDFs before urdfdom reads them, where it can read the XML;
        this clears every link's children when the parse is done with a model, normally or by an exception, so
        that no model urdfdom returns can keep a cycle alive either. */
    struct UnlinkedOnExit
    {
        const urdf::ModelInterfaceSharedPtr &model;
        ~UnlinkedOnExit()
        {
            if (model)
                for (auto &entry : model->links_)
                {
                    entry.second->child_links.clear();
                    entry.second->child_joints.clear();
                }
        }
    };

    /** The capsules fitted around mesh \e meshIndex of the arm, placed by \e pose in chain frame \e frame, as
        primitives: a cylinder is the capsule of its axis and radius (a sphere where the axis has no length). */
    void addFittedCapsules(const std::string &link, const ompl_parc::CapsuleFit &fit, std::size_t frame,
                           const Eigen::Isometry3d &pose, int meshIndex,
                           std::vector<ompl_parc::UrdfArm::Primitive> &out)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        for (const auto &capsule : fit.getCapsules())
        {
            ompl_parc::Obstacle shape;
            shape.name = link;
            const Eigen::Vector3d axis = capsule.b - capsule.a;
            shape.pose = pose * Eigen::Translation3d(0.5 * (capsule.a + capsule.b));
            shape.size.x() = capsule.radius;
            shape.shape = Shape::SPHERE;
            if (axis.norm() > 0.)
            {
                shape.shape = Shape::CYLINDER;
                shape.size.z() = axis.norm();
                shape.pose.rotate(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis));
            }
            out.push_back({frame, shape, meshIndex});
        }
    }

    /** The primitives of one <collision> element of \e link, placed by \e linkPose in chain frame \e frame: one
        for a box, cylinder or sphere, the fitted capsules for a mesh (then also an entry of \e meshes). */
    void addPrimitives(const urdf::Link &link, const urdf::Collision &collision, std::size_t frame,
                       const Eigen::Isometry3d &linkPose, const ompl_parc::UrdfArm::MeshOptions &options,
                       std::vector<ompl_parc::UrdfArm::Primitive> &out, std::vector<ompl_parc::UrdfArm::LinkMesh> &meshes)
    {
        using Shape = ompl_parc::Obstacle::Shape;
        ompl_parc::Obstacle shape;
        shape.name = link.name;
        shape.pose = linkPose * toIsometry(collision.origin);
        if (!shape.pose.matrix().allFinite())
            throw ompl::Exception(CONTEXT, "link '" + link.name + "' has a <collision> with a non-finite <origin>");
        const auto *geometry = collision.geometry.get();
        if (geometry == nullptr)
            throw ompl::Exception(CONTEXT, "link '" + link.name + "' has a <collision> without <geometry>");
        switch (geometry->type)
        {
            case urdf::Geometry::SPHERE:
                shape.shape = Shape::SPHERE;
                shape.size.x() = static_cast<const urdf::Sphere *>(geometry)->radius;
                break;
            case urdf::Geometry::BOX:
            {
                const auto &dim = static_cast<const urdf::Box *>(geometry)->dim;
                shape.shape = Shape::BOX;
                shape.size = Eigen::Vector3d(dim.x, dim.y, dim.z);
                break;
            }
            case urdf::Geometry::CYLINDER:
            {
                const auto *cylinder = static_cast<const urdf::Cylinder *>(geometry);
                shape.shape = Shape::CYLINDER;
                shape.size = Eigen::Vector3d(cylinder->radius, 0., cylinder->length);
                break;
            }
            case urdf::Geometry::MESH:
            {
                const auto *mesh = static_cast<const urdf::Mesh *>(geometry);
                const Eigen::Vector3d scale(mesh->scale.x, mesh->scale.y, mesh->scale.z);
                try
                {
                    ompl_parc::UrdfArm::LinkMesh entry{link.name, frame, shape.pose, "", scale, ompl_parc::CapsuleFit()};
                    entry.file = options.locator.resolve(mesh->filename);
                    entry.fit = ompl_parc::CapsuleFitCache::fit(entry.file, scale, options.maxCapsules,
                                                                options.writeCache);
                    addFittedCapsules(link.name, entry.fit, frame, shape.pose, static_cast<int>(meshes.size()), out);
                    meshes.push_back(std::move(entry));
                }
                catch (const ompl::Exception &e)
                {
                    throw ompl::Exception(CONTEXT, "link '" + link.name + "': " + e.what());
                }
                return;
            }
        }
        // Every dimension a shape uses must be positive and finite (a negative radius is not a smaller shape).
        const auto positive = [](double v) { return std::isfinite(v) && v > 0.; };
        bool sized = positive(shape.size.x());  // a sphere's radius, a cylinder's radius, a box's x size
        if (shape.shape == Shape::BOX)
            sized = sized && positive(shape.size.y()) && positive(shape.size.z());
        else if (shape.shape == Shape::CYLINDER)
            sized = sized && positive(shape.size.z());
        if (!sized)
            throw ompl::Exception(CONTEXT, "link '" + link.name + "' has a collision primitive of non-positive size");
        out.push_back({frame, shape, -1});
    }

    /** The range of movable joint \e joint: its <limit> (revolute and prismatic: finite, lower < upper), or
        [-pi, pi] for a continuous joint. */
    std::pair<double, double> jointRange(const urdf::Joint &joint)
    {
        if (joint.type == urdf::Joint::CONTINUOUS)
            return {-M_PI, M_PI};
        const std::string what =
            (joint.type == urdf::Joint::PRISMATIC ? "prismatic joint '" : "revolute joint '") + joint.name + "'";
        if (!joint.limits)
            throw ompl::Exception(CONTEXT, what + " has no <limit>");
        if (!std::isfinite(joint.limits->lower) || !std::isfinite(joint.limits->upper))
            throw ompl::Exception(CONTEXT, what + " has a non-finite <limit>");
        if (!(joint.limits->lower < joint.limits->upper))
            throw ompl::Exception(CONTEXT, what + " has an empty <limit>");
        return {joint.limits->lower, joint.limits->upper};
    }

    /** The URDF's velocity limit of \e joint, or 0 if it gives none (or none that is positive and finite). */
    double jointVelocity(const urdf::Joint &joint)
    {
        return joint.limits && std::isfinite(joint.limits->velocity) && joint.limits->velocity > 0.
                   ? joint.limits->velocity
                   : 0.;
    }

    /** Movable joint \e joint (revolute, continuous or prismatic; others are refused) hanging from frame \e parent
        at \e origin; its coordinate is left to the caller. */
    ompl_parc::UrdfArm::Joint movableJoint(const urdf::Joint &joint, std::size_t parent,
                                           const Eigen::Isometry3d &origin)
    {
        if (joint.type != urdf::Joint::REVOLUTE && joint.type != urdf::Joint::CONTINUOUS &&
            joint.type != urdf::Joint::PRISMATIC)
            throw ompl::Exception(
                CONTEXT, "joint '" + joint.name + "' is not revolute, continuous, prismatic or fixed (unsupported)");
        if (!origin.matrix().allFinite())
            throw ompl::Exception(CONTEXT, "joint '" + joint.name + "' has a non-finite <origin>");
        const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
        if (!axis.allFinite() || !(axis.norm() > 1e-9))
            throw ompl::Exception(CONTEXT, "joint '" + joint.name + "' has a zero or non-finite <axis>");
        ompl_parc::UrdfArm::Joint out;
        out.name = joint.name;
        out.prismatic = joint.type == urdf::Joint::PRISMATIC;
        out.parent = parent;
        out.origin = origin;
        out.axis = axis.normalized();
        return out;
    }

    /** The value movable joint \e joint off the chain is held at, or nothing if it mimics (through mimics of
        mimics) a joint of the chain, \e onChain, or its mimics cannot be followed (resolveMimic() reports why). A
        joint that mimics nothing is held at 0 clamped into its <limit> (a gripper's fingers while an arm's chain is
        planned, as MoveIt keeps joints outside the group planned); one that mimics a held joint follows its value. */
    std::optional<double> heldValue(const urdf::ModelInterface &model, const urdf::Joint &joint,
                                    const std::vector<const urdf::Joint *> &onChain)
    {
        double multiplier = 1., offset = 0.;  // joint = multiplier * current + offset
        std::set<const urdf::Joint *> seen;
        const urdf::Joint *current = &joint;
        for (; current->mimic; current = model.getJoint(current->mimic->joint_name).get())
        {
            if (!seen.insert(current).second || !model.getJoint(current->mimic->joint_name))
                return std::nullopt;
            offset += multiplier * current->mimic->offset;
            multiplier *= current->mimic->multiplier;
        }
        if (std::find(onChain.begin(), onChain.end(), current) != onChain.end() || current->type == urdf::Joint::FIXED)
            return std::nullopt;
        double value = 0.;
        if (current->type != urdf::Joint::CONTINUOUS && current->limits)
            value = std::clamp(0., current->limits->lower, current->limits->upper);
        return multiplier * value + offset;
    }

    /** Primitives of \e root (in frame \e frame) and of the links hanging off it by fixed joints (not \e onChain
        ones), by joints held still (heldValue()) or by mimic joints of the chain: each of the last gets a frame of
        its own, appended to \e joints (its URDF joint to \e urdfJoints). Iterative (a chain of thousands of fixed
        links must not overflow the stack), and each link is visited once: a URDF whose joints lead back to a link
        already visited is refused. */
    void collectPrimitives(const urdf::ModelInterface &model, const urdf::Link &root, std::size_t frame,
                           const Eigen::Isometry3d &rootPose, const std::vector<const urdf::Joint *> &onChain,
                           const ompl_parc::UrdfArm::MeshOptions &options, std::set<const urdf::Link *> &visited,
                           std::vector<ompl_parc::UrdfArm::Primitive> &out,
                           std::vector<ompl_parc::UrdfArm::LinkMesh> &meshes,
                           std::vector<ompl_parc::UrdfArm::Joint> &joints, std::vector<const urdf::Joint *> &urdfJoints)
    {
        struct Hanging
        {
            const urdf::Link *link;
            std::size_t frame;
            Eigen::Isometry3d pose;
        };
        std::vector<Hanging> pending = {{&root, frame, rootPose}};
        while (!pending.empty())
        {
            const Hanging at = pending.back();
            pending.pop_back();
            if (!visited.insert(at.link).second)
                throw ompl::Exception(CONTEXT, "the URDF's joints form a loop through link '" + at.link->name + "'");
            for (const auto &collision : at.link->collision_array)
                addPrimitives(*at.link, *collision, at.frame, at.pose, options, out, meshes);
            for (const auto &joint : at.link->child_joints)
            {
                if (std::find(onChain.begin(), onChain.end(), joint.get()) != onChain.end())
                    continue;
                const auto child = model.getLink(joint->child_link_name);
                if (!child)
                    throw ompl::Exception(CONTEXT, "joint '" + joint->name + "' has no child link");
                const Eigen::Isometry3d origin = at.pose * toIsometry(joint->parent_to_joint_origin_transform);
                if (joint->type == urdf::Joint::FIXED)
                {
                    pending.push_back({child.get(), at.frame, origin});
                    continue;
                }
                ompl_parc::UrdfArm::Joint moving = movableJoint(*joint, at.frame, origin);
                if (const auto held = heldValue(model, *joint, onChain))
                {
                    const Eigen::Isometry3d motion =
                        moving.prismatic ? Eigen::Isometry3d(Eigen::Translation3d(*held * moving.axis))
                                         : Eigen::Isometry3d(Eigen::AngleAxisd(*held, moving.axis));
                    pending.push_back({child.get(), at.frame, origin * motion});
                    continue;
                }
                joints.push_back(moving);
                urdfJoints.push_back(joint.get());
                pending.push_back({child.get(), joints.size(), Eigen::Isometry3d::Identity()});
            }
        }
    }

    /** Mimic joint \e joint's value as multiplier * q[coordinate] + offset of the coordinate it follows, through
        mimics of mimics; \e coordinates are the chain's movable joints that mimic nothing, by name. */
    void resolveMimic(const urdf::ModelInterface &model, const urdf::Joint &joint,
                      const std::map<std::string, unsigned int> &coordinates, const std::string &chainName,
                      ompl_parc::UrdfArm::Joint &out)
    {
        const std::string what = "joint '" + joint.name + "' mimics joint '" + joint.mimic->joint_name + "'";
        double multiplier = 1., offset = 0.;  // joint = multiplier * current + offset
        std::set<const urdf::Joint *> seen = {&joint};
        for (const urdf::Joint *current = &joint; current->mimic;)
        {
            const urdf::JointMimic &mimic = *current->mimic;
            if (!std::isfinite(mimic.multiplier) || !std::isfinite(mimic.offset))
                throw ompl::Exception(CONTEXT, "joint '" + current->name + "' has a non-finite <mimic>");
            offset += multiplier * mimic.offset;
            multiplier *= mimic.multiplier;
            const auto target = model.getJoint(mimic.joint_name);
            if (!target)
                throw ompl::Exception(CONTEXT, what + ", which leads to unknown joint '" + mimic.joint_name + "'");
            if (!seen.insert(target.get()).second)
                throw ompl::Exception(CONTEXT, what + ": the mimics form a loop through joint '" + target->name + "'");
            if (target->type != urdf::Joint::REVOLUTE && target->type != urdf::Joint::CONTINUOUS &&
                target->type != urdf::Joint::PRISMATIC)
                throw ompl::Exception(CONTEXT,
                                      what + ", which leads to joint '" + target->name + "', not a movable joint");
            current = target.get();
            if (!current->mimic)
            {
                const auto coordinate = coordinates.find(current->name);
                if (coordinate == coordinates.end())
                    throw ompl::Exception(CONTEXT, what + ", which leads to joint '" + current->name +
                                                       "', not a movable joint of chain " + chainName);
                out.coordinate = coordinate->second;
            }
        }
        if (!std::isfinite(multiplier) || !std::isfinite(offset))
            throw ompl::Exception(CONTEXT, "joint '" + joint.name + "' has a non-finite <mimic>");
        out.multiplier = multiplier;
        out.offset = offset;
    }
}  // namespace

ompl_parc::UrdfArm::Chain ompl_parc::UrdfArm::parseChain(const std::string &urdfXml, const std::string &baseLink,
                                                         const std::string &tipLink, const MeshOptions &options)
{
    if (const std::size_t bad = firstInvalidUtf8(urdfXml); bad != std::string::npos)
        throw ompl::Exception(CONTEXT, "malformed URDF: not UTF-8 text (byte " + std::to_string(bad) + ")");
    checkStructure(urdfXml);
    urdf::ModelInterfaceSharedPtr model;
    const UnlinkedOnExit unlink{model};
    {
        UrdfdomErrors errors;
        try
        {
            model = urdf::parseURDF(urdfXml);
        }
        catch (const std::exception &e)
        {
            throw ompl::Exception(CONTEXT, std::string("malformed URDF: ") + e.what());
        }
        // urdfdom drops an element it cannot read (a <collision> whose radius is "nan", an unknown shape, a
        // box of two sizes) with an error message and goes on: a link would silently lose its collision body.
        // Every error it reports refuses the URDF.
        if (!model || !errors.first().empty())
            throw ompl::Exception(
                CONTEXT, "malformed URDF: " +
                             (errors.first().empty() ? std::string("urdfdom could not parse it") : errors.first()));
    }
    const auto base = model->getLink(baseLink), tip = model->getLink(tipLink);
    if (!base)
        throw ompl::Exception(CONTEXT, "URDF '" + model->getName() + "' has no base link '" + baseLink + "'");
    if (!tip)
        throw ompl::Exception(CONTEXT, "URDF '" + model->getName() + "' has no tip link '" + tipLink + "'");

    // Joints from the tip up to the base, then reversed.
    std::vector<const urdf::Joint *> joints;
    std::set<const urdf::Link *> onPath;
    for (auto link = tip; link != base; link = link->getParent())
    {
        if (!link->getParent())
            throw ompl::Exception(CONTEXT, "tip link '" + tipLink + "' is not below base link '" + baseLink + "'");
        if (!onPath.insert(link.get()).second)  // e.g. a joint whose parent and child are the same link
            throw ompl::Exception(CONTEXT, "the URDF's joints form a loop through link '" + link->name + "'");
        joints.push_back(link->parent_joint.get());
    }
    std::reverse(joints.begin(), joints.end());

    Chain chain;
    std::vector<double> low, high;
    // The URDF joint of each of chain.joints; the coordinates by joint name.
    std::vector<const urdf::Joint *> urdfJoints;
    std::map<std::string, unsigned int> coordinates;
    // Chain link frames: frame k is the child link of the k-th movable joint; a link reached through fixed
    // joints sits at `pending` in the frame of the last movable joint's child.
    Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();
    std::vector<std::pair<std::size_t, Eigen::Isometry3d>> linkPoses = {{0, pending}};
    for (const urdf::Joint *joint : joints)
    {
        pending = pending * toIsometry(joint->parent_to_joint_origin_transform);
        if (!pending.matrix().allFinite())
            throw ompl::Exception(CONTEXT, "joint '" + joint->name + "' has a non-finite <origin>");
        if (joint->type != urdf::Joint::FIXED)
        {
            chain.joints.push_back(movableJoint(*joint, chain.joints.size(), pending));
            urdfJoints.push_back(joint);
            if (!joint->mimic)
            {
                const auto [lower, upper] = jointRange(*joint);
                chain.joints.back().coordinate = static_cast<unsigned int>(low.size());
                coordinates.emplace(joint->name, static_cast<unsigned int>(low.size()));
                low.push_back(lower);
                high.push_back(upper);
                chain.names.push_back(joint->name);
                const double velocity = jointVelocity(*joint);
                chain.velocities.push_back(velocity > 0. ? velocity : 1.);
            }
            pending.setIdentity();
        }
        linkPoses.emplace_back(chain.joints.size(), pending);
    }
    const std::string chainName = "'" + baseLink + "' .. '" + tipLink + "'";
    if (chain.joints.empty())
        throw ompl::Exception(CONTEXT, "chain " + chainName + " has no movable joint");
    chain.chainJoints = chain.joints.size();
    chain.tipOffset = pending;
    for (const auto &[linkName, link] : model->links_)
        chain.linkNames.insert(linkName);

    // The chain's links, base first, each with what hangs off it by fixed joints and by mimic joints.
    std::vector<const urdf::Link *> links = {base.get()};
    for (const urdf::Joint *joint : joints)
        links.push_back(model->getLink(joint->child_link_name).get());
    std::set<const urdf::Link *> visited;
    for (std::size_t k = 0; k < links.size(); ++k)
        collectPrimitives(*model, *links[k], linkPoses[k].first, linkPoses[k].second, joints, options, visited,
                          chain.primitives, chain.meshes, chain.joints, urdfJoints);
    if (chain.primitives.empty())
        throw ompl::Exception(CONTEXT, "chain " + chainName + " has no collision geometry");

    // Mimic joints follow a coordinate; their limits narrow its range (and their velocity limits its velocity
    // limit), so that a planned configuration keeps every joint within its limits.
    for (std::size_t k = 0; k < chain.joints.size(); ++k)
    {
        const urdf::Joint &joint = *urdfJoints[k];
        if (!joint.mimic)
            continue;
        Joint &mimic = chain.joints[k];
        resolveMimic(*model, joint, coordinates, chainName, mimic);
        const unsigned int c = mimic.coordinate;
        const double velocity = jointVelocity(joint);
        if (velocity > 0. && mimic.multiplier != 0.)
            chain.velocities[c] = std::min(chain.velocities[c], velocity / std::abs(mimic.multiplier));
        if (joint.type == urdf::Joint::CONTINUOUS)
            continue;
        const auto [lower, upper] = jointRange(joint);
        if (mimic.multiplier == 0.)
        {
            if (!(mimic.offset >= lower && mimic.offset <= upper))
                throw ompl::Exception(CONTEXT, "mimic joint '" + joint.name + "' stays at " +
                                                   std::to_string(mimic.offset) + ", outside its <limit>");
            continue;
        }
        const double a = (lower - mimic.offset) / mimic.multiplier, b = (upper - mimic.offset) / mimic.multiplier;
        low[c] = std::max(low[c], std::min(a, b));
        high[c] = std::min(high[c], std::max(a, b));
        if (!(low[c] < high[c]))
            throw ompl::Exception(CONTEXT, "mimic joint '" + joint.name + "' leaves joint '" + chain.names[c] +
                                               "' no range within both joints' <limit>s");
    }
    chain.limits.resize(low.size());
    chain.limits.low = low;
    chain.limits.high = high;
    return chain;
}

ompl_parc::UrdfArm::UrdfArm(std::string name, EnvironmentPtr environment, const std::string &urdfXml,
                            const std::string &baseLink, const std::string &tipLink, const Eigen::Isometry3d &basePose,
                            SrdfPtr srdf, const MeshOptions &meshOptions)
    : UrdfArm(std::move(name), std::move(environment), parseChain(urdfXml, baseLink, tipLink, meshOptions), basePose,
              std::move(srdf))
{
    meshOptions_ = meshOptions;
    urdfXml_ = urdfXml;
    baseLink_ = baseLink;
    tipLink_ = tipLink;
}

ompl_parc::UrdfArm::UrdfArm(std::string name, EnvironmentPtr environment, Chain chain,
                            const Eigen::Isometry3d &basePose, SrdfPtr srdf)
    : Robot(std::move(name), std::move(environment), chain.limits),
      basePose_(basePose),
      srdf_(std::move(srdf)),
      velocities_(std::move(chain.velocities)),
      joints_(std::move(chain.joints)),
      chainJoints_(chain.chainJoints),
      jointNames_(std::move(chain.names)),
      tipOffset_(chain.tipOffset),
      primitives_(std::move(chain.primitives)),
      meshes_(std::move(chain.meshes))
{
    if (srdf_)
        for (const std::string &link : srdf_->getLinkNames())
            if (chain.linkNames.count(link) == 0)
                throw ompl::Exception(CONTEXT, "the SRDF names link '" + link + "', which the URDF does not have");
    // Aligned frame k = URDF frame k turned by A_k, where A_k takes z onto joint k's axis u_k. Since
    // R(u_k, q) = A_k Rz(q) A_k^T and T(u_k q) = A_k T(z q) A_k^T, frame k = frame p * O_k * R(u_k, q) (revolute) or
    // frame p * O_k * T(u_k q) (prismatic), with p the parent frame, becomes, for aligned frames,
    // aligned k = aligned p * (A_p^T O_k A_k) * Rz(q) or * T(z q).
    alignment_.push_back(Eigen::Matrix3d::Identity());
    for (const Joint &joint : joints_)
    {
        const Eigen::Matrix3d &parent = alignment_[joint.parent];
        const Eigen::Matrix3d align =
            Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), joint.axis).toRotationMatrix();
        offsetRotations_.push_back(parent.transpose() * joint.origin.linear() * align);
        offsetTranslations_.push_back(parent.transpose() * joint.origin.translation());
        alignment_.push_back(align);
    }

    using Shape = Obstacle::Shape;
    for (const Primitive &p : primitives_)
    {
        const Obstacle &s = p.shape;
        Eigen::Vector3d half = Eigen::Vector3d::Zero();  // half the capsule's axis, in the primitive's frame
        double radius = s.size.x();
        if (s.shape == Shape::CYLINDER)
            half.z() = 0.5 * s.size.z();
        else if (s.shape == Shape::BOX)
        {
            // Axis along the longest side; the radius reaches the corners of the cross-section.
            int longest;
            const Eigen::Vector3d h = 0.5 * s.size;
            h.maxCoeff(&longest);
            half[longest] = h[longest];
            radius = std::sqrt(h.squaredNorm() - h[longest] * h[longest]);
        }
        const Eigen::Matrix3d toAligned = alignment_[p.frame].transpose();
        capsules_.push_back({p.frame, toAligned * (s.pose * (-half)), toAligned * (s.pose * half), radius});
    }
    spheresOnly_ = std::all_of(capsules_.begin(), capsules_.end(), [](const LocalCapsule &c) { return c.a == c.b; });
    // Groups pay where a link carries several capsules (on average at least GROUPED): a pair test then rules
    // links out by their spheres, and the bounds skip the capsule boxes. A capsule per link or two (our Panda)
    // stays with the boxes.
    constexpr std::size_t GROUPED = 3;
    for (std::size_t i = 1; i <= capsules_.size(); ++i)
        if (i == capsules_.size() || capsules_[i].frame != capsules_[i - 1].frame)
            groupEnds_.push_back(static_cast<std::uint32_t>(i));
    if (capsules_.size() < GROUPED * groupEnds_.size())
        groupEnds_.clear();
    if (!groupEnds_.empty())  // each group's sphere in its frame: a body's group sphere of the local capsules
    {
        CollisionBody local;
        for (const LocalCapsule &c : capsules_)
            local.addCapsule(c.a.x(), c.a.y(), c.a.z(), c.b.x(), c.b.y(), c.b.z(), c.radius);
        local.setGroups(groupEnds_.data(), groupEnds_.size());
        local.updateBound();
        for (std::size_t g = 0, begin = 0; g < groupEnds_.size(); begin = groupEnds_[g], ++g)
        {
            const CollisionBody::Group &group = local.groups_[g];
            groupSpheres_.push_back(
                {capsules_[begin].frame, Eigen::Vector3d(group.x, group.y, group.z), group.radius});
        }
    }
    std::vector<double> zero(getDimension());
    for (unsigned int k = 0; k < getDimension(); ++k)
        zero[k] = std::clamp(0., getBounds().low[k], getBounds().high[k]);
    CollisionBody body;
    computeBody(zero.data(), body);
    computeSelfCollisionPairs(body);
    checkFixedLinks(body);
    std::vector<UrdfArmLanes::Capsule> laneCapsules;
    for (const LocalCapsule &c : capsules_)
        laneCapsules.push_back({c.frame, c.a, c.b, c.radius});
    std::vector<UrdfArmLanes::Joint> laneJoints;
    for (const Joint &joint : joints_)
        laneJoints.push_back({joint.parent, joint.coordinate, joint.multiplier, joint.offset, joint.prismatic,
                              joint.prismatic ? getLargestJointValue(joint) : 0.});
    lanes_ = std::make_unique<UrdfArmLanes>(basePose_, getDimension(), std::move(laneJoints), offsetRotations_,
                                            offsetTranslations_, std::move(laneCapsules), selfCollisionPairs_);
}

bool ompl_parc::UrdfArm::allValid(const double *configs, std::size_t count) const
{
    const unsigned int n = getDimension();
    if (!withinBounds(configs, count))
        return false;
    const ObstacleSet &obstacles = getEnvironment()->getObstacleSet();
    const std::size_t width = UrdfArmLanes::width();
    for (std::size_t first = 0; first < count; first += width)
        if (lanes_->anyCollides(configs + first * n, std::min(width, count - first), obstacles))
            return false;
    return true;
}

std::string ompl_parc::UrdfArm::readFile(const std::string &path)
{
    return TextFile::read(path, CONTEXT);
}

Eigen::Isometry3d ompl_parc::UrdfArm::pose(double x, double y, double z, double roll, double pitch, double yaw)
{
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(x, y, z);
    t.linear() =
        (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    return t;
}

double ompl_parc::UrdfArm::getLargestJointValue(const Joint &joint) const
{
    const double atLow = joint.multiplier * getBounds().low[joint.coordinate] + joint.offset;
    const double atHigh = joint.multiplier * getBounds().high[joint.coordinate] + joint.offset;
    return std::max(std::abs(atLow), std::abs(atHigh));
}

void ompl_parc::UrdfArm::computeSelfCollisionPairs(const CollisionBody &zeroBody)
{
    const auto parent = [this](std::size_t frame) { return frame == 0 ? frame : joints_[frame - 1].parent; };
    for (std::size_t i = 0; i < capsules_.size(); ++i)
        for (std::size_t j = i + 1; j < capsules_.size(); ++j)
        {
            const std::size_t fi = capsules_[i].frame, fj = capsules_[j].frame;
            const bool adjacent = fi == fj || parent(fi) == fj || parent(fj) == fi;
            if (!adjacent && !capsulesCollide(zeroBody, i, zeroBody, j) &&
                !(srdf_ && srdf_->allows(primitives_[i].shape.name, primitives_[j].shape.name)))
                selfCollisionPairs_.emplace_back(i, j);
        }
}

void ompl_parc::UrdfArm::checkFixedLinks(const CollisionBody &body) const
{
    if (!getEnvironment())
        return;
    for (std::size_t k = 0; k < capsules_.size(); ++k)
    {
        if (capsules_[k].frame != 0)
            continue;
        if (const Obstacle *obstacle = getEnvironment()->findCollision(body, k))
            throw ompl::Exception(CONTEXT, "robot '" + getName() + "': link '" + primitives_[k].shape.name +
                                               "', fixed to the base, collides with obstacle '" + obstacle->name +
                                               "' at this base pose (every configuration would be invalid)");
    }
}

void ompl_parc::UrdfArm::computeAlignedFrames(const double *q, std::vector<Eigen::Matrix3d> &rotations,
                                              std::vector<Eigen::Vector3d> &translations) const
{
    const std::size_t n = joints_.size();
    rotations.resize(n + 1);
    translations.resize(n + 1);
    rotations[0] = basePose_.linear();
    translations[0] = basePose_.translation();
    for (std::size_t k = 0; k < n; ++k)
    {
        const Joint &joint = joints_[k];
        const std::size_t p = joint.parent;
        const double value = joint.multiplier * q[joint.coordinate] + joint.offset;
        Eigen::Matrix3d &r = rotations[k + 1];
        Eigen::Vector3d &t = translations[k + 1];
        t.noalias() = translations[p] + rotations[p] * offsetTranslations_[k];
        if (joint.prismatic)
        {
            // Right-multiplying by a translation along z moves the origin along the third column.
            r.noalias() = rotations[p] * offsetRotations_[k];
            t += value * r.col(2);
            continue;
        }
        Eigen::Matrix3d turned;
        turned.noalias() = rotations[p] * offsetRotations_[k];
        // Right-multiplying by Rz(q) turns the first two columns only.
        const double c = std::cos(value), s = std::sin(value);
        r.col(0) = c * turned.col(0) + s * turned.col(1);
        r.col(1) = c * turned.col(1) - s * turned.col(0);
        r.col(2) = turned.col(2);
    }
}

void ompl_parc::UrdfArm::computeFrames(const double *q, std::vector<Eigen::Isometry3d> &frames) const
{
    thread_local std::vector<Eigen::Matrix3d> rotations;
    thread_local std::vector<Eigen::Vector3d> translations;
    computeAlignedFrames(q, rotations, translations);
    frames.resize(rotations.size());
    for (std::size_t k = 0; k < frames.size(); ++k)
    {
        frames[k].linear() = rotations[k] * alignment_[k].transpose();
        frames[k].translation() = translations[k];
        frames[k].makeAffine();
    }
}

Eigen::Isometry3d ompl_parc::UrdfArm::computeTipPose(const double *q) const
{
    std::vector<Eigen::Isometry3d> frames;
    computeFrames(q, frames);
    return frames[chainJoints_] * tipOffset_;
}

void ompl_parc::UrdfArm::computeCapsules(const double *q, CollisionBody &body) const
{
    thread_local std::vector<Eigen::Matrix3d> rotations;
    thread_local std::vector<Eigen::Vector3d> translations;
    computeAlignedFrames(q, rotations, translations);
    body.resize(capsules_.size(), spheresOnly_);
    for (std::size_t i = 0; i < capsules_.size(); ++i)
    {
        const LocalCapsule &c = capsules_[i];
        const Eigen::Matrix3d &r = rotations[c.frame];
        const Eigen::Vector3d &t = translations[c.frame];
        const Eigen::Vector3d a = r * c.a + t, b = r * c.b + t;
        body.ax_[i] = a.x();
        body.ay_[i] = a.y();
        body.az_[i] = a.z();
        body.bx_[i] = b.x();
        body.by_[i] = b.y();
        body.bz_[i] = b.z();
        body.radius_[i] = c.radius;
    }
    if (groupEnds_.empty())
        return;
    body.setGroups(groupEnds_.data(), groupEnds_.size());
    for (std::size_t g = 0; g < groupSpheres_.size(); ++g)
    {
        const LocalSphere &s = groupSpheres_[g];
        const Eigen::Vector3d c = rotations[s.frame] * s.center + translations[s.frame];
        CollisionBody::Group &group = body.groups_[g];
        group.x = c.x();
        group.y = c.y();
        group.z = c.z();
        // The capsules and the centre are moved by the same rotation and translation, each with a few roundings
        // of the coordinates (and the rotation's own, from the joint products, far below 2^-40 relative): the pad
        // covers both many times over.
        group.radius = s.radius + 0x1p-36 * (s.radius + s.center.norm() + c.cwiseAbs().maxCoeff());
    }
    body.keepGroupSpheres();
}

bool ompl_parc::UrdfArm::solvePositionIk(const Eigen::Vector3d &target, std::mt19937 &rng, std::vector<double> &q,
                                         unsigned int restarts, double tolerance) const
{
    constexpr int ITERATIONS = 300;
    constexpr double DAMPING = 0.05;
    const unsigned int n = getDimension();
    const auto &bounds = getBounds();
    std::vector<Eigen::Matrix3d> rotations;
    std::vector<Eigen::Vector3d> translations;
    Eigen::MatrixXd jacobian(3, n);
    q.resize(n);
    for (unsigned int attempt = 0; attempt < restarts; ++attempt)
    {
        for (unsigned int k = 0; k < n; ++k)
            q[k] = std::uniform_real_distribution<double>(bounds.low[k], bounds.high[k])(rng);
        for (int it = 0; it < ITERATIONS; ++it)
        {
            computeAlignedFrames(q.data(), rotations, translations);
            const Eigen::Vector3d tip =
                rotations[chainJoints_] * (alignment_[chainJoints_].transpose() * tipOffset_.translation()) +
                translations[chainJoints_];
            const Eigen::Vector3d error = target - tip;
            if (error.norm() < tolerance)
            {
                if (isValid(q.data()))
                    return true;
                break;
            }
            // Chain joint k turns chain link k + 1 about its axis (the z axis of its aligned frame) through its
            // origin, or slides it along that axis; its coordinate moves it multiplier times as fast.
            jacobian.setZero();
            for (std::size_t k = 0; k < chainJoints_; ++k)
            {
                const Joint &joint = joints_[k];
                const Eigen::Vector3d axis = rotations[k + 1].col(2);
                if (joint.prismatic)
                    jacobian.col(joint.coordinate) += joint.multiplier * axis;
                else
                    jacobian.col(joint.coordinate) += joint.multiplier * axis.cross(tip - translations[k + 1]);
            }
            const Eigen::Matrix3d jjt =
                jacobian * jacobian.transpose() + DAMPING * DAMPING * Eigen::Matrix3d::Identity();
            const Eigen::VectorXd step = jacobian.transpose() * jjt.ldlt().solve(error);
            for (unsigned int k = 0; k < n; ++k)
                q[k] = std::clamp(q[k] + step[k], bounds.low[k], bounds.high[k]);
        }
    }
    return false;
}

ompl_parc::MotionLimits ompl_parc::UrdfArm::defaultMotionLimits() const
{
    std::vector<double> acceleration;
    for (double velocity : velocities_)
        acceleration.push_back(3. * velocity);
    return MotionLimits::perCoordinate(velocities_, acceleration);
}
