#ifndef OMPL_PARC_SHORTEST_PATH_BOUND_
#define OMPL_PARC_SHORTEST_PATH_BOUND_

#include "ompl_parc/collision/Environment.h"

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

namespace ompl_parc
{
    /** \brief A lower bound on the length of a disc robot's shortest collision-free path among the static obstacles,
        alone: the obstacle-aware counterpart of the straight-line bound (PlanQuality).

        A disc of radius r at (x, y) (its body a sphere at (x, y, 0)) may not come within r of an obstacle. For an
        obstacle whose cut by the plane z = 0 is simple, the forbidden centre positions form a convex set: a box or
        a cylinder standing upright (rotated about z only, or flipped) gives its rectangle or disc grown by r (less
        where the obstacle ends above or below the plane), a sphere a disc. Each such set gets a convex polygon
        inscribed in it (vertices on its boundary: rectangles with a few points on each rounded corner, discs a
        regular 16-gon), so the polygon lies inside the forbidden set and the plane less the polygons' interiors
        holds every collision-free path: the shortest path there, found on the visibility graph of the polygon
        vertices, is no longer than the true shortest path. The graph keeps only the edges that can be part of a
        shortest path: those tangent to the polygon at each end (bending around a polygon's vertex, a shortest path
        has the polygon on one side), except at vertices on or in another polygon, where the obstacle is not one
        polygon and every visible edge is kept. Obstacles of any other kind (a tilted box, a lying
        cylinder) are left out, which only lowers the bound; so does every doubt in the visibility test, which
        lets an edge through unless it crosses a polygon shrunk by a rounding tolerance.

        The radius is not r itself but what a plan the SolutionValidator accepts keeps clear: it checks the
        timesteps with the radius less its contact tolerance, and a straight step of 1/resolution between two such
        positions cuts into that grown set by at most the sagitta of its chord. Inscribed in the set grown by the
        radius less both, the polygons are crossed by no validated plan.

        Built once per environment and radius (the polygons and the visibility graph among their vertices), then
        asked for any number of start and goal pairs; the queries are const and thread safe. */
    class ShortestPathBound
    {
      public:
        /** \brief The polygons of the obstacles of \e environment for a disc of radius \e radius on a plan of
            \e resolution timesteps per unit, and the visibility graph among their vertices. */
        ShortestPathBound(const Environment &environment, double radius, double resolution);

        /** \brief The length of the shortest path from \e start to \e goal (x, y each) that enters no polygon; the
            straight-line distance where there is none (a start or goal inside a polygon: not a valid problem). */
        double length(const double *start, const double *goal) const;

        /** \brief The radius the forbidden sets are grown by (the disc's radius less what a validated plan may
            graze). */
        double getClearance() const { return clearance_; }

        /** \brief How many obstacles got a polygon. */
        std::size_t getPolygonCount() const { return polygons_.size(); }

      private:
        /** \brief One convex polygon: its edges' outward unit normals and offsets (inside: normal . x < offset)
            and its bounding box. */
        struct Polygon
        {
            std::vector<Eigen::Vector2d> normals;
            std::vector<double> offsets;
            Eigen::Vector2d lo, hi;
        };

        /** \brief A polygon vertex: its neighbours on its polygon (indices into vertices_), its polygon, and
            whether it lies clear of every other polygon (only then are edges not tangent at it left out). */
        struct Corner
        {
            std::size_t previous, next, polygon;
            bool alone;
        };

        /** \brief Adds the polygon of \e obstacle, if its cut by the plane is simple. */
        void addObstacle(const Obstacle &obstacle);

        /** \brief Adds the convex polygon of \e vertices (either orientation, at least three). */
        void addPolygon(std::vector<Eigen::Vector2d> vertices);

        /** \brief False if the segment from \e a to \e b crosses the interior of a polygon shrunk by tolerance_. */
        bool visible(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const;

        /** \brief False if the segment from vertex \e v to \e toward cannot be on a shortest path: \e v lies
            outside the other polygons and its neighbours are strictly on either side of the segment's line. */
        bool tangent(std::size_t v, const Eigen::Vector2d &toward) const;

        /** \brief True if \e point is in \e polygon grown by tolerance_ (touching counts). */
        bool inside(const Polygon &polygon, const Eigen::Vector2d &point) const;

        double clearance_;
        double tolerance_{0.};
        std::vector<Eigen::Vector2d> vertices_;
        std::vector<Corner> corners_;
        std::vector<Polygon> polygons_;
        /** \brief Per vertex, the vertices it sees and how far they are. */
        std::vector<std::vector<std::pair<std::size_t, double>>> edges_;
    };
}  // namespace ompl_parc

#endif
