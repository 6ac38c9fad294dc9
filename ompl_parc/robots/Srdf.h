#ifndef OMPL_PARC_SRDF_
#define OMPL_PARC_SRDF_

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

namespace ompl_parc
{
    /** \brief What a robot's SRDF (MoveIt's semantic robot description) tells planning: which link pairs may touch
        (`<disable_collisions link1="..." link2="..." reason="..."/>`: an allowed-collision matrix for
        self-collision) and the named chains (`<group name="..."><chain base_link="..." tip_link="..."/></group>`), so
        a URDF arm can be named by its group. Groups of links or joints (a gripper's, say) are known by name but
        cannot name an arm; other SRDF elements (group states, end effectors, virtual joints) are read past. */
    class Srdf
    {
      public:
        /** \brief Parse SRDF text; throws ompl::Exception with a one-line reason for malformed XML, a root that is
            not `<robot>`, a `<disable_collisions>` without both links, a group defined twice or with more than one
            `<chain>` or a chain without both ends. */
        static Srdf parse(const std::string &xml);
        /** \brief parse() of a file's contents; throws ompl::Exception if it cannot be read. */
        static Srdf read(const std::string &path);

        /** \brief True if links \e a and \e b may touch (either order). */
        bool allows(const std::string &a, const std::string &b) const
        {
            return disabled_.count(a < b ? std::make_pair(a, b) : std::make_pair(b, a)) != 0;
        }

        /** \brief The base and tip links of chain group \e group; throws ompl::Exception naming the chain groups
            there are if it is not one. */
        std::pair<std::string, std::string> getChain(const std::string &group) const;

        /** \brief Every link the SRDF names (in disabled pairs and chains), to be checked against the URDF. */
        std::set<std::string> getLinkNames() const;

        /** \brief The text it was parsed from (so it can be written out again). */
        const std::string &getXml() const { return xml_; }

      private:
        std::string xml_;
        std::set<std::pair<std::string, std::string>> disabled_;
        std::map<std::string, std::pair<std::string, std::string>> groups_;
        /** \brief Groups of links or joints, not chains. */
        std::set<std::string> otherGroups_;
    };

    using SrdfPtr = std::shared_ptr<const Srdf>;
}  // namespace ompl_parc

#endif
