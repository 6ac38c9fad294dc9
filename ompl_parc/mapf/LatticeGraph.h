#ifndef OMPL_PARC_LATTICE_GRAPH_
#define OMPL_PARC_LATTICE_GRAPH_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace ompl_parc
{
    /** \brief The free points of a regular lattice in a box and the free straight moves between axis neighbours:
        the graph a team of translating robots is planned on by ConfigurationSearch.

        Robots standing on distinct points of a lattice whose step exceeds twice their bounding radius never touch,
        and neither do robots moving one step each at the same time unless one enters, at right angles, the point
        another leaves (ConfigurationSearch::followLevels orders those; from a step of 2 sqrt 2 radii on they may move
        at once), so a plan over this graph needs no robot-robot check beyond its rules. Points and moves are checked
       against the static obstacles once, when the graph is built. */
    class LatticeGraph
    {
      public:
        using Vertex = std::uint32_t;
        static constexpr Vertex NONE = std::numeric_limits<Vertex>::max();
        static constexpr std::uint32_t UNREACHABLE = std::numeric_limits<std::uint32_t>::max();
        static constexpr unsigned int MAX_DIMENSION = 3;

        /** \brief Whether a robot may stand on a point (a configuration of getDimension() values). */
        using PointCheck = std::function<bool(const double *)>;
        /** \brief Whether a robot may move straight between two points. */
        using MoveCheck = std::function<bool(const double *, const double *)>;

        /** \brief The points origin + step x (integer coordinates) inside [\e low, \e high] kept where \e free holds,
            joined where \e move holds between axis neighbours. Throws ompl::Exception for a step that is not
            positive, bounds of different sizes or of more than MAX_DIMENSION values, or more than \e maxPoints
            lattice points in the box (countPoints()). */
        LatticeGraph(const std::vector<double> &low, const std::vector<double> &high, const std::vector<double> &origin,
                     double step, const PointCheck &free, const MoveCheck &move, std::size_t maxPoints);

        /** \brief The number of lattice points in the box, checked or not (a caller declines boxes too large for it
            before building); saturates at the largest std::size_t. */
        static std::size_t countPoints(const std::vector<double> &low, const std::vector<double> &high,
                                       const std::vector<double> &origin, double step);

        unsigned int getDimension() const { return dimension_; }
        double getStep() const { return step_; }
        /** \brief The number of free points (vertices). */
        std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
        const double *getPoint(Vertex v) const { return points_.data() + static_cast<std::size_t>(v) * dimension_; }
        /** \brief The neighbours of \e v, in [first, second). */
        std::pair<const Vertex *, const Vertex *> getNeighbours(Vertex v) const
        {
            return {adjacency_.data() + offsets_[v], adjacency_.data() + offsets_[v + 1]};
        }

        /** \brief The vertices within \e radius of \e q, nearest first. */
        std::vector<Vertex> near(const double *q, double radius) const;

        /** \brief Moves from every vertex to \e target (breadth-first; UNREACHABLE where none) into \e hops. */
        void hopsTo(Vertex target, std::vector<std::uint32_t> &hops) const;

        /** \brief The connected component of each vertex (labels 0, 1, ...). */
        std::vector<std::uint32_t> components() const;

        /** \brief Whether the moves a -> b -> c continue one line (equal lattice offsets). */
        bool straight(Vertex a, Vertex b, Vertex c) const;

      private:
        unsigned int dimension_{0};
        double step_{0.};
        std::vector<double> origin_;
        /** \brief The box's first lattice coordinate and extent per axis (lattice points, not vertices). */
        std::vector<long> first_, extent_;
        /** \brief Vertex of each lattice point of the box (NONE where not free), row-major. */
        std::vector<Vertex> index_;
        std::vector<double> points_;
        std::vector<std::int32_t> coords_;
        std::vector<std::size_t> offsets_;
        std::vector<Vertex> adjacency_;
    };
}  // namespace ompl_parc

#endif
