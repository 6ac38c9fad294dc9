#include "ompl_parc/quality/ShortestPathBound.h"

#include "ompl_parc/validation/SolutionValidator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace
{
    /** Segments of each rounded corner of a box's polygon (3: two points inside the arc besides its ends). */
    constexpr int CORNER_SEGMENTS = 3;
    /** Vertices of a disc's polygon. */
    constexpr int DISC_VERTICES = 16;
    /** Largest z component of a box's or cylinder's local x and y axes for which it counts as upright: the
        cross-section then moves by this times its size, far below the rounding tolerance of the visibility test. */
    constexpr double UPRIGHT = 1e-12;
    /** The visibility test's tolerance relative to the coordinates' magnitude. */
    constexpr double RELATIVE_TOLERANCE = 1e-9;

    /** The regular polygon of DISC_VERTICES vertices inscribed in the circle of \e radius about \e centre. */
    std::vector<Eigen::Vector2d> discPolygon(const Eigen::Vector2d &centre, double radius)
    {
        std::vector<Eigen::Vector2d> vertices;
        for (int k = 0; k < DISC_VERTICES; ++k)
        {
            const double angle = 2. * M_PI * k / DISC_VERTICES;
            vertices.push_back(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
        }
        return vertices;
    }
}  // namespace

ompl_parc::ShortestPathBound::ShortestPathBound(const Environment &environment, double radius, double resolution)
{
    // A validated plan keeps its timesteps clear by the radius less the contact tolerance; a step of length h between
    // two such positions reaches at most rho - sqrt(rho^2 - h^2 / 4) deeper (a chord of the ball of radius rho about
    // the obstacle point nearest to the step). With rho <= h / 2 only the obstacle itself is left: the validator
    // catches a centre that tunnels through it.
    const double rho = radius - ValidationOptions().contactTolerance, halfStep = 0.5 / resolution;
    clearance_ = rho > halfStep ? std::sqrt(rho * rho - halfStep * halfStep) : 0.;
    for (const Obstacle &obstacle : environment.getObstacles())
        addObstacle(obstacle);
    double magnitude = 0.;
    for (const Eigen::Vector2d &v : vertices_)
        magnitude = std::max(magnitude, v.cwiseAbs().maxCoeff());
    tolerance_ = RELATIVE_TOLERANCE * (1. + magnitude);
    for (std::size_t v = 0; v < vertices_.size(); ++v)
        for (std::size_t p = 0; p < polygons_.size() && corners_[v].alone; ++p)
            corners_[v].alone = p == corners_[v].polygon || !inside(polygons_[p], vertices_[v]);
    edges_.resize(vertices_.size());
    for (std::size_t i = 0; i < vertices_.size(); ++i)
        for (std::size_t j = i + 1; j < vertices_.size(); ++j)
            if (tangent(i, vertices_[j]) && tangent(j, vertices_[i]) && visible(vertices_[i], vertices_[j]))
            {
                const double d = (vertices_[i] - vertices_[j]).norm();
                edges_[i].emplace_back(j, d);
                edges_[j].emplace_back(i, d);
            }
}

void ompl_parc::ShortestPathBound::addObstacle(const Obstacle &obstacle)
{
    const Eigen::Matrix3d r = obstacle.pose.linear();
    const Eigen::Vector3d c = obstacle.pose.translation();
    const Eigen::Vector2d centre = c.head<2>();
    if (obstacle.shape == Obstacle::Shape::MESH)
        return;  // left out: fewer obstacles never raise a lower bound
    if (obstacle.shape == Obstacle::Shape::SPHERE)
    {
        const double reach = clearance_ + obstacle.size.x();
        if (std::abs(c.z()) < reach)
            addPolygon(discPolygon(centre, std::sqrt(reach * reach - c.z() * c.z())));
        return;
    }
    if (std::max(std::abs(r(2, 0)), std::abs(r(2, 1))) > UPRIGHT)
        return;  // tilted: its cut by the plane is no rectangle or disc
    // Upright, the body's distance to the obstacle is the in-plane distance to its cross-section and dz, the height
    // of the plane above or below the obstacle's z extent: positions within sqrt(clearance^2 - dz^2) of the
    // cross-section are forbidden.
    const double dz = std::max(0., std::abs(c.z()) - 0.5 * obstacle.size.z());
    if (dz > clearance_)
        return;
    const double grown = std::sqrt(std::max(0., clearance_ * clearance_ - dz * dz));
    if (obstacle.shape == Obstacle::Shape::CYLINDER)
    {
        addPolygon(discPolygon(centre, obstacle.size.x() + grown));
        return;
    }
    // A box: each corner of its rectangle contributes the arc of radius grown from one edge normal to the next.
    const Eigen::Vector2d u = r.col(0).head<2>(), v = r.col(1).head<2>();
    const double hx = 0.5 * obstacle.size.x(), hy = 0.5 * obstacle.size.y();
    const int signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    std::vector<Eigen::Vector2d> vertices;
    for (int k = 0; k < 4; ++k)
    {
        const Eigen::Vector2d corner = centre + signs[k][0] * hx * u + signs[k][1] * hy * v;
        for (int j = 0; j <= (grown > 0. ? CORNER_SEGMENTS : 0); ++j)
        {
            const double angle = 0.5 * M_PI * (k + static_cast<double>(j) / CORNER_SEGMENTS);
            vertices.push_back(corner + grown * (std::cos(angle) * u + std::sin(angle) * v));
        }
    }
    addPolygon(std::move(vertices));
}

void ompl_parc::ShortestPathBound::addPolygon(std::vector<Eigen::Vector2d> vertices)
{
    const std::size_t n = vertices.size();
    double area = 0.;
    for (std::size_t k = 0; k < n; ++k)
    {
        const Eigen::Vector2d &a = vertices[k], &b = vertices[(k + 1) % n];
        area += a.x() * b.y() - a.y() * b.x();
    }
    if (area < 0.)
        std::reverse(vertices.begin(), vertices.end());  // a flipped box: counter-clockwise from here on
    Polygon polygon{{}, {}, vertices.front(), vertices.front()};
    const std::size_t first = vertices_.size();
    for (std::size_t k = 0; k < n; ++k)
    {
        const Eigen::Vector2d &a = vertices[k], edge = vertices[(k + 1) % n] - a;
        polygon.lo = polygon.lo.cwiseMin(a);
        polygon.hi = polygon.hi.cwiseMax(a);
        if (edge.norm() == 0.)
            continue;
        const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
        polygon.normals.push_back(normal);
        polygon.offsets.push_back(normal.dot(a));
        vertices_.push_back(a);
    }
    const std::size_t count = vertices_.size() - first;
    for (std::size_t k = 0; k < count; ++k)
        corners_.push_back({first + (k + count - 1) % count, first + (k + 1) % count, polygons_.size(), true});
    polygons_.push_back(std::move(polygon));
}

bool ompl_parc::ShortestPathBound::visible(const Eigen::Vector2d &a, const Eigen::Vector2d &b) const
{
    const Eigen::Vector2d lo = a.cwiseMin(b), hi = a.cwiseMax(b), d = b - a;
    for (const Polygon &polygon : polygons_)
    {
        if ((hi.array() < polygon.lo.array()).any() || (lo.array() > polygon.hi.array()).any())
            continue;
        // Cyrus-Beck: the parameters t in [0, 1] at which a + t d is inside every edge's half-plane, shrunk.
        double enter = 0., exit = 1.;
        bool crosses = true;
        for (std::size_t k = 0; k < polygon.normals.size() && crosses; ++k)
        {
            const double room = polygon.offsets[k] - tolerance_ - polygon.normals[k].dot(a),
                         rate = polygon.normals[k].dot(d);
            if (rate > 0.)
                exit = std::min(exit, room / rate);
            else if (rate < 0.)
                enter = std::max(enter, room / rate);
            crosses = rate != 0. ? enter < exit : room > 0.;
        }
        if (crosses)
            return false;
    }
    return true;
}

bool ompl_parc::ShortestPathBound::inside(const Polygon &polygon, const Eigen::Vector2d &point) const
{
    if ((point.array() < polygon.lo.array() - tolerance_).any() ||
        (point.array() > polygon.hi.array() + tolerance_).any())
        return false;
    for (std::size_t k = 0; k < polygon.normals.size(); ++k)
        if (polygon.normals[k].dot(point) > polygon.offsets[k] + tolerance_)
            return false;
    return true;
}

bool ompl_parc::ShortestPathBound::tangent(std::size_t v, const Eigen::Vector2d &toward) const
{
    const Corner &corner = corners_[v];
    if (!corner.alone)
        return true;
    const Eigen::Vector2d d = toward - vertices_[v], a = vertices_[corner.previous] - vertices_[v],
                          b = vertices_[corner.next] - vertices_[v];
    const double sideA = d.x() * a.y() - d.y() * a.x(), sideB = d.x() * b.y() - d.y() * b.x(),
                 slack = tolerance_ * d.norm();
    return !((sideA > slack && sideB < -slack) || (sideA < -slack && sideB > slack));
}

double ompl_parc::ShortestPathBound::length(const double *start, const double *goal) const
{
    const Eigen::Vector2d s(start[0], start[1]), g(goal[0], goal[1]);
    const double direct = (g - s).norm();
    if (visible(s, g))
        return direct;
    // Dijkstra from the start over the vertices it sees; a vertex's leg to the goal is tested when it is settled.
    constexpr double INF = std::numeric_limits<double>::infinity();
    std::vector<double> distance(vertices_.size(), INF);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t v = 0; v < vertices_.size(); ++v)
        if (tangent(v, s) && visible(s, vertices_[v]))
        {
            distance[v] = (vertices_[v] - s).norm();
            queue.emplace(distance[v], v);
        }
    double best = INF;
    while (!queue.empty())
    {
        const auto [d, u] = queue.top();
        queue.pop();
        if (d >= best)
            break;
        if (d > distance[u])
            continue;
        if (tangent(u, g) && visible(vertices_[u], g))
            best = std::min(best, d + (g - vertices_[u]).norm());
        for (const auto &[w, leg] : edges_[u])
            if (d + leg < distance[w])
            {
                distance[w] = d + leg;
                queue.emplace(distance[w], w);
            }
    }
    return best < INF ? best : direct;
}
