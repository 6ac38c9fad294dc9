#include "ompl_parc/validation/SolutionValidator.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace
{
    constexpr std::size_t OBSTACLE = std::numeric_limits<std::size_t>::max();

    /** What an FCL object stands for: capsule \e part of robot \e robot, or obstacle \e part. */
    struct Tag
    {
        std::size_t robot, part;
    };

    /** Collision test of one team configuration with FCL, reusing its objects from sample to sample. */
    class FclTeamChecker
    {
      public:
        explicit FclTeamChecker(const ompl_parc::MultiRobotSpaceInformation &si) : si_(si)
        {
            const auto &obstacles = si.getEnvironment()->getObstacles();
            for (std::size_t k = 0; k < obstacles.size(); ++k)
            {
                auto object = std::make_unique<fcl::CollisionObjectd>(
                    ompl_parc::Environment::createGeometry(obstacles[k]), obstacles[k].pose);
                object->computeAABB();
                obstacleTags_.push_back({OBSTACLE, k});
                obstacleObjects_.push_back(std::move(object));
            }
            for (std::size_t k = 0; k < obstacleObjects_.size(); ++k)
            {
                obstacleObjects_[k]->setUserData(&obstacleTags_[k]);
                obstacleManager_.registerObject(obstacleObjects_[k].get());
            }
            obstacleManager_.setup();
            bodies_.resize(si.getRobotCount());
        }

        /** Empty if the team at \e configs (one per robot) is collision-free with radii shrunk by \e slack. */
        std::string check(const std::vector<const double *> &configs, double slack)
        {
            for (std::size_t i = 0; i < configs.size(); ++i)
                si_.getRobot(i)->computeBody(configs[i], bodies_[i]);
            placeObjects(slack);
            Query query{this, {}};
            if (!obstacleObjects_.empty())
                robotManager_.collide(&obstacleManager_, &query, &FclTeamChecker::callback);
            if (query.message.empty())
                robotManager_.collide(&query, &FclTeamChecker::callback);
            return query.message;
        }

      private:
        struct Query
        {
            FclTeamChecker *self;
            std::string message;
        };

        struct Capsule
        {
            double radius, length;
        };

        static bool callback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *data)
        {
            auto *query = static_cast<Query *>(data);
            const Tag &a = *static_cast<const Tag *>(o1->getUserData());
            const Tag &b = *static_cast<const Tag *>(o2->getUserData());
            if (a.robot == b.robot && !query->self->isSelfPair(a.robot, a.part, b.part))
                return false;
            fcl::CollisionRequestd request;
            fcl::CollisionResultd result;
            if (fcl::collide(o1, o2, request, result) == 0)
                return false;
            query->message = query->self->describe(a, b);
            return true;
        }

        bool isSelfPair(std::size_t robot, std::size_t p, std::size_t q) const
        {
            const auto &pairs = si_.getRobot(robot)->getSelfCollisionPairs();
            return std::find(pairs.begin(), pairs.end(), std::make_pair(std::min(p, q), std::max(p, q))) != pairs.end();
        }

        std::string describe(const Tag &a, const Tag &b) const
        {
            const Tag &r = a.robot == OBSTACLE ? b : a, &o = a.robot == OBSTACLE ? a : b;
            const std::string robot = "robot '" + si_.getRobot(r.robot)->getName() + "'";
            if (o.robot == OBSTACLE)
                return robot + " hits obstacle '" + si_.getEnvironment()->getObstacles()[o.part].name + "'";
            if (o.robot == r.robot)
                return robot + " is in self-collision (links " + std::to_string(r.part) + " and " +
                       std::to_string(o.part) + ")";
            return "robots '" + si_.getRobot(std::min(r.robot, o.robot))->getName() + "' and '" +
                   si_.getRobot(std::max(r.robot, o.robot))->getName() + "' collide";
        }

        /** Give every capsule an FCL object at its pose; (re)create objects whose shape changed. */
        void placeObjects(double slack)
        {
            bool rebuilt = false;
            std::size_t k = 0;
            for (std::size_t i = 0; i < bodies_.size(); ++i)
                for (std::size_t c = 0; c < bodies_[i].size(); ++c, ++k)
                {
                    const auto &b = bodies_[i];
                    const Eigen::Vector3d p(b.ax_[c], b.ay_[c], b.az_[c]), q(b.bx_[c], b.by_[c], b.bz_[c]);
                    const Capsule shape{std::max(b.radius_[c] - slack, 1e-9), (q - p).norm()};
                    if (k == objects_.size() || std::abs(shapes_[k].radius - shape.radius) > 1e-12 ||
                        std::abs(shapes_[k].length - shape.length) > 1e-12)
                    {
                        setObject(k, i, c, shape);
                        rebuilt = true;
                    }
                    fcl::Transform3d tf = fcl::Transform3d::Identity();
                    tf.translation() = 0.5 * (p + q);
                    if (shape.length > 0.)
                        tf.linear() =
                            Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), q - p).toRotationMatrix();
                    objects_[k]->setTransform(tf);
                    objects_[k]->computeAABB();
                }
            if (rebuilt)
            {
                robotManager_.clear();
                for (std::size_t j = 0; j < objects_.size(); ++j)
                {
                    objects_[j]->setUserData(&tags_[j]);
                    robotManager_.registerObject(objects_[j].get());
                }
                robotManager_.setup();
            }
            else
                robotManager_.update();
        }

        void setObject(std::size_t k, std::size_t robot, std::size_t part, const Capsule &shape)
        {
            std::shared_ptr<fcl::CollisionGeometryd> geometry;
            if (shape.length > 0.)
                geometry = std::make_shared<fcl::Capsuled>(shape.radius, shape.length);
            else
                geometry = std::make_shared<fcl::Sphered>(shape.radius);
            auto object = std::make_unique<fcl::CollisionObjectd>(geometry);
            if (k == objects_.size())
            {
                objects_.push_back(std::move(object));
                shapes_.push_back(shape);
                tags_.push_back({robot, part});
            }
            else
            {
                objects_[k] = std::move(object);
                shapes_[k] = shape;
                tags_[k] = {robot, part};
            }
        }

        const ompl_parc::MultiRobotSpaceInformation &si_;
        std::vector<ompl_parc::CollisionBody> bodies_;
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects_, obstacleObjects_;
        std::vector<Capsule> shapes_;
        std::vector<Tag> tags_, obstacleTags_;
        fcl::DynamicAABBTreeCollisionManagerd robotManager_, obstacleManager_;
    };

    std::string timeLabel(std::size_t t, unsigned int sub, unsigned int substeps)
    {
        std::ostringstream out;
        if (sub == 0)
            out << "t=" << t;
        else
            out << "t=" << static_cast<double>(t) + static_cast<double>(sub) / substeps << " (sub-step)";
        return out.str();
    }
}  // namespace

ompl_parc::SolutionValidator::SolutionValidator(MultiRobotProblem problem, ValidationOptions options)
    : problem_(std::move(problem)), options_(options)
{
    if (options_.substeps == 0)
        options_.substeps = 1;
    if (options_.substepSlack < 0.)
        options_.substepSlack = 0.5 / problem_.getSpaceInformation()->getResolution();
}

std::string ompl_parc::SolutionValidator::checkStructure(const MultiRobotPlan &plan) const
{
    const auto &si = *problem_.getSpaceInformation();
    if (plan.getRobotCount() != si.getRobotCount())
        return "plan has " + std::to_string(plan.getRobotCount()) + " robots, problem has " +
               std::to_string(si.getRobotCount());
    if (std::abs(plan.getResolution() - si.getResolution()) > 1e-9)
        return "plan resolution " + std::to_string(plan.getResolution()) + " differs from the problem's " +
               std::to_string(si.getResolution());
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        if (plan.getDimension(i) != si.getRobot(i)->getDimension())
            return "robot '" + si.getRobot(i)->getName() + "' has the wrong configuration size";
        if (plan.getStateCount(i) == 0)
            return "robot '" + si.getRobot(i)->getName() + "' has no states";
    }
    return "";
}

std::string ompl_parc::SolutionValidator::checkEndpoints(const MultiRobotPlan &plan) const
{
    const auto &si = *problem_.getSpaceInformation();
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
    {
        std::vector<double> first(plan.getDimension(i)), last(plan.getDimension(i));
        plan.getConfig(i, 0, first.data());
        plan.getConfig(i, plan.getArrival(i), last.data());
        for (unsigned int d = 0; d < plan.getDimension(i); ++d)
        {
            if (std::abs(first[d] - problem_.getStart(i)[d]) > options_.endpointTolerance)
                return "robot '" + si.getRobot(i)->getName() + "' does not start at its start";
            if (std::abs(last[d] - problem_.getGoal(i)[d]) > options_.endpointTolerance)
                return "robot '" + si.getRobot(i)->getName() + "' does not end at its goal";
        }
    }
    return "";
}

std::string ompl_parc::SolutionValidator::checkMotionBound(const MultiRobotPlan &plan) const
{
    const double maxStep = 1. / plan.getResolution() * (1. + 1e-9) + 1e-12;
    for (std::size_t i = 0; i < plan.getRobotCount(); ++i)
        for (std::size_t t = 0; t < plan.getArrival(i); ++t)
        {
            std::vector<double> a(plan.getDimension(i)), b(plan.getDimension(i));
            plan.getConfig(i, t, a.data());
            plan.getConfig(i, t + 1, b.data());
            double d2 = 0.;
            for (unsigned int d = 0; d < plan.getDimension(i); ++d)
                d2 += (b[d] - a[d]) * (b[d] - a[d]);
            if (std::sqrt(d2) > maxStep)
                return "t=" + std::to_string(t) + ": robot '" + problem_.getSpaceInformation()->getRobot(i)->getName() +
                       "' moves " + std::to_string(std::sqrt(d2)) + " in one timestep (limit " +
                       std::to_string(1. / plan.getResolution()) + ")";
        }
    return "";
}

std::string ompl_parc::SolutionValidator::checkBounds(std::size_t robot, const double *q) const
{
    const auto &r = *problem_.getSpaceInformation()->getRobot(robot);
    for (unsigned int d = 0; d < r.getDimension(); ++d)
        if (!(q[d] >= r.getBounds().low[d] && q[d] <= r.getBounds().high[d]))
            return "robot '" + r.getName() + "' is out of bounds in coordinate " + std::to_string(d);
    return "";
}

ompl_parc::ValidationReport ompl_parc::SolutionValidator::validate(const MultiRobotPlan &plan) const
{
    ValidationReport report;
    for (auto check :
         {&SolutionValidator::checkStructure, &SolutionValidator::checkEndpoints, &SolutionValidator::checkMotionBound})
    {
        report.message = (this->*check)(plan);
        if (!report.message.empty())
            return report;
    }

    const auto &si = *problem_.getSpaceInformation();
    const std::size_t n = plan.getRobotCount();
    FclTeamChecker checker(si);
    std::vector<std::vector<double>> samples(n), ends(2 * n);
    std::vector<const double *> configs(n);
    const std::size_t makespan = plan.getMakespan();
    for (std::size_t t = 0; t <= makespan; ++t)
        for (unsigned int sub = 0; sub < (t < makespan ? options_.substeps : 1u); ++sub)
        {
            const double s = static_cast<double>(sub) / options_.substeps;
            for (std::size_t i = 0; i < n; ++i)
            {
                auto &a = ends[2 * i], &b = ends[2 * i + 1];
                a.resize(plan.getDimension(i));
                b.resize(plan.getDimension(i));
                plan.getConfig(i, t, a.data());
                plan.getConfig(i, t + 1, b.data());
                samples[i].resize(plan.getDimension(i));
                for (unsigned int d = 0; d < plan.getDimension(i); ++d)
                    samples[i][d] = a[d] + s * (b[d] - a[d]);
                configs[i] = samples[i].data();
                report.message = checkBounds(i, configs[i]);
                if (!report.message.empty())
                {
                    report.message = timeLabel(t, sub, options_.substeps) + ": " + report.message;
                    return report;
                }
            }
            report.configurationsChecked += n;
            report.message = checker.check(configs, sub == 0 ? options_.contactTolerance : options_.substepSlack);
            if (!report.message.empty())
            {
                report.message = timeLabel(t, sub, options_.substeps) + ": " + report.message;
                return report;
            }
        }
    report.valid = true;
    return report;
}
