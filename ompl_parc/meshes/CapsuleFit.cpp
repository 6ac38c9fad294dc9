#include "ompl_parc/meshes/CapsuleFit.h"

#include <Eigen/Eigenvalues>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
    using Capsule = ompl_parc::CapsuleFit::Capsule;

    double segmentDistance(const Capsule &c, const Eigen::Vector3d &p)
    {
        const Eigen::Vector3d ab = c.b - c.a;
        const double length2 = ab.squaredNorm();
        const double t = length2 > 0. ? std::clamp((p - c.a).dot(ab) / length2, 0., 1.) : 0.;
        return (c.a + t * ab - p).norm();
    }

    /** The capsule along unit \e d (with \e u, \e v completing an orthonormal basis) around \e points: the
        smallest circle across d found by Badoiu-Clarkson steps (any centre gives a containing capsule; a better
        one a thinner one), then the shortest segment whose capsule holds every point. */
    Capsule fitAlong(const std::vector<Eigen::Vector3d> &points, const Eigen::Vector3d &d, const Eigen::Vector3d &u,
                     const Eigen::Vector3d &v, double pad)
    {
        std::vector<Eigen::Vector2d> across(points.size());
        Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY), high = -low;
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            across[i] = Eigen::Vector2d(u.dot(points[i]), v.dot(points[i]));
            low = low.cwiseMin(across[i]);
            high = high.cwiseMax(across[i]);
        }
        const auto farthest = [&](const Eigen::Vector2d &c, std::size_t &index)
        {
            double best = -1.;
            for (std::size_t i = 0; i < across.size(); ++i)
                if (const double r = (across[i] - c).squaredNorm(); r > best)
                {
                    best = r;
                    index = i;
                }
            return std::sqrt(best);
        };
        Eigen::Vector2d centre = 0.5 * (low + high), best = centre;
        std::size_t index = 0;
        double radius = farthest(centre, index);
        for (int step = 1; step <= 64; ++step)
        {
            centre += (across[index] - centre) / (step + 1.);
            if (const double r = farthest(centre, index); r < radius)
            {
                radius = r;
                best = centre;
            }
        }
        radius = farthest(best, index);
        double t0 = INFINITY, t1 = -INFINITY;
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            const double t = d.dot(points[i]);
            const double reach = std::sqrt(std::max(0., radius * radius - (across[i] - best).squaredNorm()));
            t0 = std::min(t0, t + reach);
            t1 = std::max(t1, t - reach);
        }
        if (t0 > t1)  // a sphere holds them all
            t0 = t1 = 0.5 * (t0 + t1);
        const Eigen::Vector3d base = best.x() * u + best.y() * v;
        // Points on the rounded ends lie on the surface exactly: the pad keeps rounding from putting them out.
        return {base + t0 * d, base + t1 * d, radius + pad};
    }
}  // namespace

ompl_parc::CapsuleFit::CapsuleFit(const TriangleMesh &mesh, unsigned int maxCapsules)
    : meshVolume_(mesh.isClosed() ? mesh.getVolume() : 0.)
{
    if (maxCapsules == 0)
        throw ompl::Exception("CapsuleFit", "at least one capsule per mesh is needed");
    // The principal axes of the vertices.
    const std::vector<Eigen::Vector3d> &corners = mesh.getVertices();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto &p : corners)
        mean += p;
    mean /= static_cast<double>(corners.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto &p : corners)
        covariance += (p - mean) * (p - mean).transpose();
    const Eigen::Matrix3d axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors();
    // Rounding slack: give every radius a hair more than the farthest point needs.
    const double pad = 1e-9 * std::max(1., mesh.getBounds().sizes().norm());

    constexpr unsigned int CANDIDATE_SAMPLES = 4096, REPORT_SAMPLES = 65536;
    double bestVolume = INFINITY;
    std::vector<Eigen::Vector3d> slab;
    for (unsigned int count = 1; count <= maxCapsules; ++count)
        for (int k = 0; k < 3; ++k)
        {
            const Eigen::Vector3d d = axes.col(k), u = axes.col((k + 1) % 3), v = axes.col((k + 2) % 3);
            double low = INFINITY, high = -INFINITY;
            for (const auto &p : corners)
            {
                low = std::min(low, d.dot(p));
                high = std::max(high, d.dot(p));
            }
            std::vector<Capsule> candidate;
            for (unsigned int s = 0; s < count; ++s)
            {
                slab.clear();
                if (count == 1)
                    slab = corners;
                else  // the outer planes at +-infinity: rounding never drops a corner beyond them
                    mesh.clipToSlab(d, s == 0 ? -INFINITY : low + (high - low) * s / count,
                                    s + 1 == count ? INFINITY : low + (high - low) * (s + 1) / count, slab);
                if (!slab.empty())
                    candidate.push_back(fitAlong(slab, d, u, v, pad));
            }
            const double volume = estimateVolume(candidate, CANDIDATE_SAMPLES);
            // Another capsule costs every check on the hot path: it has to pay for itself.
            if (volume < (candidate.size() > capsules_.size() ? 0.9 : 1.) * bestVolume)
            {
                bestVolume = volume;
                capsules_ = std::move(candidate);
            }
        }
    fitVolume_ = estimateVolume(capsules_, REPORT_SAMPLES);
}

ompl_parc::CapsuleFit::CapsuleFit(std::vector<Capsule> capsules, double meshVolume, double fitVolume)
    : capsules_(std::move(capsules)), meshVolume_(meshVolume), fitVolume_(fitVolume)
{
}

bool ompl_parc::CapsuleFit::contains(const Eigen::Vector3d &p, double tolerance) const
{
    return std::any_of(capsules_.begin(), capsules_.end(),
                       [&](const Capsule &c) { return segmentDistance(c, p) <= c.radius + tolerance; });
}

double ompl_parc::CapsuleFit::estimateVolume(const std::vector<Capsule> &capsules, unsigned int samples)
{
    Eigen::AlignedBox3d box;
    for (const Capsule &c : capsules)
    {
        box.extend(c.a.cwiseMin(c.b) - Eigen::Vector3d::Constant(c.radius));
        box.extend(c.a.cwiseMax(c.b) + Eigen::Vector3d::Constant(c.radius));
    }
    if (box.isEmpty())
        return 0.;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> unit(0., 1.);
    unsigned int inside = 0;
    for (unsigned int k = 0; k < samples; ++k)
    {
        const Eigen::Vector3d p =
            box.min() + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(box.sizes());
        inside += std::any_of(capsules.begin(), capsules.end(),
                              [&](const Capsule &c) { return segmentDistance(c, p) <= c.radius; });
    }
    return box.volume() * inside / samples;
}
