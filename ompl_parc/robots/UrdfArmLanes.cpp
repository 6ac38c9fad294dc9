#include "ompl_parc/robots/UrdfArmLanes.h"

#include "ompl_parc/collision/PrimitiveDistance.h"

#include <xsimd/xsimd.hpp>

#include <algorithm>
#include <cmath>

namespace
{
    using Batch = xsimd::batch<float>;
    constexpr std::size_t WIDTH = Batch::size;

    /** Per-thread buffers of one call: frames (9 rotation + 3 translation batches each, and the centre of the
        frame's sphere: 3), capsule end points (6 batches each) and capsule sphere centres (3 each). Sized once per
        thread and arm size. */
    struct Scratch
    {
        std::vector<Batch> rotations, translations, ends, centers, frameCenters;
        ompl_parc::CollisionBody capsule;  // one lane's capsule, in double, for the exact narrow phase
    };

    Scratch &scratch()
    {
        thread_local Scratch s;
        return s;
    }

    /** The lanes set in \e m, as bits. */
    unsigned int laneBits(const xsimd::batch_bool<float> &m)
    {
        alignas(64) bool set[WIDTH];
        m.store_aligned(set);
        unsigned int bits = 0;
        for (std::size_t l = 0; l < WIDTH; ++l)
            bits |= set[l] ? 1u << l : 0u;
        return bits;
    }

    /** True if the capsule with end points \e end (6 batches, world frame) and radius \e radius touches obstacle \e k
        (whose box, grown by the inflation, is \e boxLo..\e boxHi) in one of the first \e count lanes: the box test on
        all lanes, then ObstacleSet's exact test in double precision (through \e body, one capsule) per lane that
        overlaps. */
    bool laneCapsuleHits(const Batch *end, float radius, const Batch *boxLo, const Batch *boxHi, std::size_t count,
                         const ompl_parc::ObstacleSet &obstacles, std::size_t k, ompl_parc::CollisionBody &body)
    {
        const Batch r(radius);
        auto overlap = (xsimd::min(end[0], end[3]) - r <= boxHi[0]) & (xsimd::max(end[0], end[3]) + r >= boxLo[0]);
        for (int c = 1; c < 3; ++c)
            overlap = overlap & (xsimd::min(end[c], end[3 + c]) - r <= boxHi[c]) &
                      (xsimd::max(end[c], end[3 + c]) + r >= boxLo[c]);
        if (xsimd::none(overlap))
            return false;
        alignas(64) float lane[6][WIDTH];
        for (int c = 0; c < 6; ++c)
            end[c].store_aligned(lane[c]);
        alignas(64) bool near[WIDTH];
        overlap.store_aligned(near);
        for (std::size_t l = 0; l < std::min(count, WIDTH); ++l)
        {
            if (!near[l])
                continue;
            body.ax_[0] = lane[0][l];
            body.ay_[0] = lane[1][l];
            body.az_[0] = lane[2][l];
            body.bx_[0] = lane[3][l];
            body.by_[0] = lane[4][l];
            body.bz_[0] = lane[5][l];
            body.radius_[0] = radius;
            if (obstacles.capsuleHits(body, 0, k))
                return true;
        }
        return false;
    }

    /** row-major 3x3 times vector, for a batch matrix and a constant vector. */
    inline void rotate(const Batch *r, const float *v, const Batch *t, Batch *out)
    {
        for (int row = 0; row < 3; ++row)
            out[row] = t[row] + r[3 * row] * Batch(v[0]) + r[3 * row + 1] * Batch(v[1]) + r[3 * row + 2] * Batch(v[2]);
    }
}  // namespace

ompl_parc::UrdfArmLanes::UrdfArmLanes(const Eigen::Isometry3d &basePose, unsigned int dimension,
                                      std::vector<Joint> joints, const std::vector<Eigen::Matrix3d> &offsetRotations,
                                      const std::vector<Eigen::Vector3d> &offsetTranslations,
                                      std::vector<Capsule> capsules,
                                      std::vector<std::pair<std::size_t, std::size_t>> selfPairs)
    : dimension_(dimension), joints_(std::move(joints)), selfPairs_(std::move(selfPairs))
{
    // Every frame's origin is within the joint offsets and prismatic travels of all joints from the base.
    double reach = 0., extent = 0.;
    for (std::size_t k = 0; k < joints_.size(); ++k)
        reach += offsetTranslations[k].norm() + joints_[k].travel;
    for (const Capsule &c : capsules)
        extent = std::max(extent, std::max(c.a.norm(), c.b.norm()) + c.radius);
    selfInflation_ = (reach + extent) * static_cast<double>(joints_.size() + 4) * std::ldexp(1., -20);
    inflation_ = selfInflation_ + (basePose.translation().norm() + reach + extent) * std::ldexp(1., -21);

    for (int row = 0; row < 3; ++row)
    {
        for (int col = 0; col < 3; ++col)
            baseRotation_[3 * row + col] = static_cast<float>(basePose.linear()(row, col));
        baseTranslation_[row] = static_cast<float>(basePose.translation()[row]);
    }
    for (std::size_t k = 0; k < joints_.size(); ++k)
        for (int row = 0; row < 3; ++row)
        {
            for (int col = 0; col < 3; ++col)
                offsetRotations_.push_back(static_cast<float>(offsetRotations[k](row, col)));
            offsetTranslations_.push_back(static_cast<float>(offsetTranslations[k][row]));
        }
    for (const Capsule &c : capsules)
    {
        frame_.push_back(c.frame);
        for (int r = 0; r < 3; ++r)
        {
            localA_.push_back(static_cast<float>(c.a[r]));
            localB_.push_back(static_cast<float>(c.b[r]));
        }
        selfRadius_.push_back(static_cast<float>(c.radius + selfInflation_));
        sphereRadius_.push_back(static_cast<float>(0.5 * (c.b - c.a).norm() + c.radius + 2. * selfInflation_));
        radius_.push_back(static_cast<float>(c.radius + inflation_));
        pairRadius_.push_back(static_cast<float>(c.radius + 2. * inflation_));
        pairCoreRadius_.push_back(static_cast<float>(std::max(0., c.radius - 2. * inflation_)));
        pairHalfLength_.push_back(static_cast<float>(0.5 * (c.b - c.a).norm() + inflation_));
        sphere_.push_back(c.a == c.b);
    }
    for (int r = 0; r < 3; ++r)
        basePosition_[r] = basePose.translation()[r];
    reach_ = reach + extent;

    // Per frame a sphere around its capsules' spheres (the centre of their end points' box), grown by the rounding of
    // its own centre's kinematics (as a capsule's sphere is grown by its own).
    const std::size_t frames = joints_.size() + 1;
    frameCenter_.assign(3 * frames, 0.f);
    frameRadius_.assign(frames, 0.f);
    frameObstacleRadius_.assign(frames, 0.f);
    frameBegin_.assign(frames + 1, 0);
    for (std::size_t f = 0; f < frames; ++f)
    {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
        for (std::size_t i = 0; i < capsules.size(); ++i)
            if (capsules[i].frame == f)
            {
                byFrame_.push_back(i);
                lo = lo.cwiseMin(capsules[i].a.cwiseMin(capsules[i].b));
                hi = hi.cwiseMax(capsules[i].a.cwiseMax(capsules[i].b));
            }
        frameBegin_[f + 1] = byFrame_.size();
        if (!hasCapsules(f))
            continue;
        const Eigen::Vector3d centre = 0.5 * (lo + hi);
        double radius = 0.;
        for (std::size_t m = frameBegin_[f]; m < frameBegin_[f + 1]; ++m)
        {
            const Capsule &c = capsules[byFrame_[m]];
            radius = std::max(radius, (0.5 * (c.a + c.b) - centre).norm() + 0.5 * (c.b - c.a).norm() + c.radius);
        }
        for (int r = 0; r < 3; ++r)
            frameCenter_[3 * f + r] = static_cast<float>(centre[r]);
        frameRadius_[f] = static_cast<float>(radius + 4. * selfInflation_);
        frameObstacleRadius_[f] = static_cast<float>(radius + 3. * inflation_);
    }
    std::stable_sort(
        selfPairs_.begin(), selfPairs_.end(),
        [this](const std::pair<std::size_t, std::size_t> &x, const std::pair<std::size_t, std::size_t> &y)
        { return std::minmax(frame_[x.first], frame_[x.second]) < std::minmax(frame_[y.first], frame_[y.second]); });
    for (std::size_t p = 0; p < selfPairs_.size(); ++p)
    {
        const auto [a, b] = std::minmax(frame_[selfPairs_[p].first], frame_[selfPairs_[p].second]);
        if (framePairs_.empty() || framePairs_.back().a != a || framePairs_.back().b != b)
            framePairs_.push_back({a, b, p, p});
        framePairs_.back().end = p + 1;
    }
}

std::size_t ompl_parc::UrdfArmLanes::width()
{
    return WIDTH;
}

void ompl_parc::UrdfArmLanes::computeKinematics(const double *configs, std::size_t count) const
{
    const std::size_t frames = joints_.size() + 1, capsules = frame_.size();
    Scratch &s = scratch();
    s.rotations.resize(9 * frames);
    s.translations.resize(3 * frames);
    s.ends.resize(6 * capsules);
    s.centers.resize(3 * capsules);

    // Forward kinematics in the base frame (small coordinates, small rounding), lane l = configuration l (the
    // last one repeated into unused lanes).
    for (int e = 0; e < 9; ++e)
        s.rotations[e] = Batch(e % 4 == 0 ? 1.f : 0.f);
    for (int e = 0; e < 3; ++e)
        s.translations[e] = Batch(0.f);
    for (std::size_t k = 0; k < joints_.size(); ++k)
    {
        const Joint &joint = joints_[k];
        alignas(64) float value[WIDTH];
        for (std::size_t l = 0; l < WIDTH; ++l)
            value[l] = static_cast<float>(
                joint.multiplier * configs[std::min(l, count - 1) * dimension_ + joint.coordinate] + joint.offset);
        const Batch q = Batch::load_aligned(value);
        const Batch *r = &s.rotations[9 * joint.parent];
        const float *o = &offsetRotations_[9 * k];
        Batch *t = &s.translations[3 * (k + 1)];
        rotate(r, &offsetTranslations_[3 * k], &s.translations[3 * joint.parent], t);
        Batch *next = &s.rotations[9 * (k + 1)];
        // Row by row, the parent's rotation times the offset rotation.
        const auto turned = [r, o](int row, Batch *out)
        {
            for (int col = 0; col < 3; ++col)
                out[col] = r[3 * row] * Batch(o[col]) + r[3 * row + 1] * Batch(o[3 + col]) +
                           r[3 * row + 2] * Batch(o[6 + col]);
        };
        if (joint.prismatic)
        {
            // Right-multiplying by a translation along z moves the origin along the third column.
            for (int row = 0; row < 3; ++row)
            {
                turned(row, next + 3 * row);
                t[row] += q * next[3 * row + 2];
            }
            continue;
        }
        const auto sc = xsimd::sincos(q);
        const Batch &sine = sc.first, &cosine = sc.second;
        for (int row = 0; row < 3; ++row)
        {
            Batch row3[3];
            turned(row, row3);
            // Right-multiplying by Rz(q) turns the first two columns only.
            next[3 * row] = cosine * row3[0] + sine * row3[1];
            next[3 * row + 1] = cosine * row3[1] - sine * row3[0];
            next[3 * row + 2] = row3[2];
        }
    }
    for (std::size_t i = 0; i < capsules; ++i)
    {
        const Batch *r = &s.rotations[9 * frame_[i]], *t = &s.translations[3 * frame_[i]];
        Batch *end = &s.ends[6 * i];
        rotate(r, &localA_[3 * i], t, end);
        rotate(r, &localB_[3 * i], t, end + 3);
        for (int c = 0; c < 3; ++c)
            s.centers[3 * i + c] = Batch(0.5f) * (end[c] + end[3 + c]);
    }

    s.frameCenters.resize(3 * frames);
    for (std::size_t f = 0; f < frames; ++f)
        if (hasCapsules(f))
            rotate(&s.rotations[9 * f], &frameCenter_[3 * f], &s.translations[3 * f], &s.frameCenters[3 * f]);
}

void ompl_parc::UrdfArmLanes::moveScratchToWorld() const
{
    const std::size_t frames = joints_.size() + 1, capsules = frame_.size();
    Scratch &s = scratch();
    Batch rotation[9], translation[3];
    for (int e = 0; e < 9; ++e)
        rotation[e] = Batch(baseRotation_[e]);
    for (int e = 0; e < 3; ++e)
        translation[e] = Batch(baseTranslation_[e]);
    const auto toWorld = [&](Batch *point)
    {
        const Batch local[3] = {point[0], point[1], point[2]};
        for (int row = 0; row < 3; ++row)
            point[row] = translation[row] + rotation[3 * row] * local[0] + rotation[3 * row + 1] * local[1] +
                         rotation[3 * row + 2] * local[2];
    };
    for (std::size_t i = 0; i < capsules; ++i)
    {
        toWorld(&s.ends[6 * i]);
        toWorld(&s.ends[6 * i + 3]);
    }
    for (std::size_t f = 0; f < frames; ++f)
        if (hasCapsules(f))
            toWorld(&s.frameCenters[3 * f]);
}

bool ompl_parc::UrdfArmLanes::anyCollides(const double *configs, std::size_t count, const ObstacleSet &obstacles,
                                          Placed *placed) const
{
    const std::size_t frames = joints_.size() + 1;
    computeKinematics(configs, count);
    Scratch &s = scratch();

    // Self-collision: per pair of frames their spheres' clearance, then per pair of capsules theirs, the exact segment
    // distance only where some lane is close.
    for (const FramePairs &group : framePairs_)
    {
        const Batch *ca = &s.frameCenters[3 * group.a], *cb = &s.frameCenters[3 * group.b];
        const Batch dx = ca[0] - cb[0], dy = ca[1] - cb[1], dz = ca[2] - cb[2];
        const float reach = frameRadius_[group.a] + frameRadius_[group.b];
        if (xsimd::none(dx * dx + dy * dy + dz * dz < Batch(reach * reach)))
            continue;
        for (std::size_t p = group.begin; p < group.end; ++p)
        {
            const auto [i, j] = selfPairs_[p];
            const Batch *ci = &s.centers[3 * i], *cj = &s.centers[3 * j];
            const Batch ex = ci[0] - cj[0], ey = ci[1] - cj[1], ez = ci[2] - cj[2];
            const float near = sphereRadius_[i] + sphereRadius_[j], touch = selfRadius_[i] + selfRadius_[j];
            if (xsimd::none(ex * ex + ey * ey + ez * ez < Batch(near * near)))
                continue;
            const Batch *a = &s.ends[6 * i], *b = &s.ends[6 * j];
            const Batch d2 =
                segmentSegmentDistanceSquared(a[0], a[1], a[2], a[3], a[4], a[5], b[0], b[1], b[2], b[3], b[4], b[5]);
            if (xsimd::any(d2 < Batch(touch * touch)))
                return true;
        }
    }

    // Environment, in the world frame: each capsule's box against each obstacle's box, then the exact test per
    // lane that overlaps.
    moveScratchToWorld();
    s.capsule.resize(1, false);
    // The box of every frame's obstacle sphere in every lane: an obstacle box it misses misses each of them, as the
    // same float bounds compare below, and is passed with six comparisons.
    float armLo[3], armHi[3];
    armBox(armLo, armHi);
    for (std::size_t k = 0; k < obstacles.size(); ++k)
    {
        double lo[3], hi[3];
        obstacles.getBox(k, lo, hi);
        float fLo[3], fHi[3];
        bool apart = false;
        for (int c = 0; c < 3; ++c)
        {
            fLo[c] = static_cast<float>(lo[c] - inflation_);
            fHi[c] = static_cast<float>(hi[c] + inflation_);
            apart = apart || armLo[c] > fHi[c] || armHi[c] < fLo[c];
        }
        if (apart)
            continue;
        Batch boxLo[3], boxHi[3];
        for (int c = 0; c < 3; ++c)
        {
            boxLo[c] = Batch(fLo[c]);
            boxHi[c] = Batch(fHi[c]);
        }
        for (std::size_t f = 0; f < frames; ++f)
        {
            if (!hasCapsules(f))
                continue;
            const Batch *centre = &s.frameCenters[3 * f];
            const Batch reach(frameObstacleRadius_[f]);
            auto touches = (centre[0] - reach <= boxHi[0]) & (centre[0] + reach >= boxLo[0]);
            for (int c = 1; c < 3; ++c)
                touches = touches & (centre[c] - reach <= boxHi[c]) & (centre[c] + reach >= boxLo[c]);
            if (xsimd::none(touches))
                continue;
            for (std::size_t m = frameBegin_[f]; m < frameBegin_[f + 1]; ++m)
                if (laneCapsuleHits(&s.ends[6 * byFrame_[m]], radius_[byFrame_[m]], boxLo, boxHi, count, obstacles, k,
                                    s.capsule))
                    return true;
        }
    }
    if (placed != nullptr)
        storePlaced(count, *placed);
    return false;
}

void ompl_parc::UrdfArmLanes::armBox(float lo[3], float hi[3]) const
{
    const Scratch &s = scratch();
    Batch low[3], high[3];
    for (int c = 0; c < 3; ++c)
    {
        low[c] = Batch(INFINITY);
        high[c] = Batch(-INFINITY);
    }
    for (std::size_t f = 0; f + 1 < frameBegin_.size(); ++f)
        if (hasCapsules(f))
        {
            const Batch reach(frameObstacleRadius_[f]);
            for (int c = 0; c < 3; ++c)
            {
                low[c] = xsimd::min(low[c], s.frameCenters[3 * f + c] - reach);
                high[c] = xsimd::max(high[c], s.frameCenters[3 * f + c] + reach);
            }
        }
    alignas(64) float lanes[WIDTH];
    for (int c = 0; c < 3; ++c)
    {
        low[c].store_aligned(lanes);
        lo[c] = *std::min_element(lanes, lanes + WIDTH);
        high[c].store_aligned(lanes);
        hi[c] = *std::max_element(lanes, lanes + WIDTH);
    }
}

void ompl_parc::UrdfArmLanes::place(const double *configs, std::size_t count, Placed &placed) const
{
    computeKinematics(configs, count);
    moveScratchToWorld();
    storePlaced(count, placed);
}

void ompl_parc::UrdfArmLanes::storePlaced(std::size_t count, Placed &placed) const
{
    const std::size_t frames = joints_.size() + 1, capsules = frame_.size();
    const Scratch &s = scratch();
    placed.ends.resize(6 * capsules * WIDTH);
    placed.mids.resize(3 * capsules * WIDTH);
    placed.frameCenters.resize(3 * frames * WIDTH);
    for (std::size_t e = 0; e < 6 * capsules; ++e)
        s.ends[e].store_unaligned(&placed.ends[e * WIDTH]);
    for (std::size_t i = 0; i < capsules; ++i)
        for (int c = 0; c < 3; ++c)
            (Batch(0.5f) * (s.ends[6 * i + c] + s.ends[6 * i + 3 + c]))
                .store_unaligned(&placed.mids[(3 * i + c) * WIDTH]);
    // The arm's box per lane: around its frames' spheres as nearLanes() grows them.
    Batch lo[3], hi[3];
    for (int c = 0; c < 3; ++c)
    {
        lo[c] = Batch(INFINITY);
        hi[c] = Batch(-INFINITY);
    }
    for (std::size_t f = 0; f < frames; ++f)
        if (hasCapsules(f))
        {
            const Batch reach(pairFrameRadius(f));
            for (int c = 0; c < 3; ++c)
            {
                const Batch &centre = s.frameCenters[3 * f + c];
                centre.store_unaligned(&placed.frameCenters[(3 * f + c) * WIDTH]);
                lo[c] = xsimd::min(lo[c], centre - reach);
                hi[c] = xsimd::max(hi[c], centre + reach);
            }
        }
    placed.box.resize(6 * WIDTH);
    for (int c = 0; c < 3; ++c)
    {
        lo[c].store_unaligned(&placed.box[c * WIDTH]);
        hi[c].store_unaligned(&placed.box[(3 + c) * WIDTH]);
    }
    placed.count = count;
}

unsigned int ompl_parc::UrdfArmLanes::nearLanes(const UrdfArmLanes &a, const Placed &pa, const UrdfArmLanes &b,
                                                const Placed &pb, unsigned int &touching)
{
    touching = 0;
    const double bx = a.basePosition_[0] - b.basePosition_[0], by = a.basePosition_[1] - b.basePosition_[1],
                 bz = a.basePosition_[2] - b.basePosition_[2], reach = a.reach_ + b.reach_;
    if (bx * bx + by * by + bz * bz > reach * reach * (1. + 1e-9) + 1e-9)
        return 0;  // apart at every configuration
    const unsigned int lanes = (1u << std::min(pa.count, pb.count)) - 1u;
    const auto load = [](const std::vector<float> &rows, std::size_t row, Batch *out, int n)
    {
        for (int c = 0; c < n; ++c)
            out[c] = Batch::load_unaligned(&rows[(row + c) * WIDTH]);
    };
    // Frame spheres (pairFrameRadius()) contain the float capsules within the pair test's reach below, and each arm's
    // box (Placed::box) contains its frame spheres: a frame of one arm is compared with the other arm's frames only
    // where its sphere meets that arm's box.
    Batch boxB[6];
    load(pb.box, 0, boxB, 6);
    unsigned int near = 0;
    for (std::size_t fa = 0; fa + 1 < a.frameBegin_.size(); ++fa)
    {
        if (!a.hasCapsules(fa))
            continue;
        Batch ca[3];
        load(pa.frameCenters, 3 * fa, ca, 3);
        const Batch ra(a.pairFrameRadius(fa));
        auto meets = (ca[0] - ra <= boxB[3]) & (ca[0] + ra >= boxB[0]);
        for (int c = 1; c < 3; ++c)
            meets = meets & (ca[c] - ra <= boxB[3 + c]) & (ca[c] + ra >= boxB[c]);
        if (xsimd::none(meets))
            continue;
        for (std::size_t fb = 0; fb + 1 < b.frameBegin_.size(); ++fb)
        {
            if (!b.hasCapsules(fb))
                continue;
            Batch cb[3];
            load(pb.frameCenters, 3 * fb, cb, 3);
            const Batch dx = ca[0] - cb[0], dy = ca[1] - cb[1], dz = ca[2] - cb[2];
            const float spheres = a.pairFrameRadius(fa) + b.pairFrameRadius(fb);
            if (xsimd::none(dx * dx + dy * dy + dz * dz < Batch(spheres * spheres)))
                continue;
            const float frameB = b.pairFrameRadius(fb);
            for (std::size_t m = a.frameBegin_[fa]; m < a.frameBegin_[fa + 1]; ++m)
            {
                const std::size_t i = a.byFrame_[m];
                // A float capsule lies within its pairHalfLength_ of its midpoint: capsule i against frame fb's sphere,
                // then against each of its capsules, their midpoints first (for two spheres, whose end points are
                // computed alike, that is their distance), then their segments.
                Batch mida[3];
                load(pa.mids, 3 * i, mida, 3);
                const Batch fx = mida[0] - cb[0], fy = mida[1] - cb[1], fz = mida[2] - cb[2];
                const float toFrame = a.pairHalfLength_[i] + a.pairRadius_[i] + frameB;
                if (xsimd::none(fx * fx + fy * fy + fz * fz < Batch(toFrame * toFrame)))
                    continue;
                for (std::size_t k = b.frameBegin_[fb]; k < b.frameBegin_[fb + 1]; ++k)
                {
                    const std::size_t j = b.byFrame_[k];
                    Batch midb[3];
                    load(pb.mids, 3 * j, midb, 3);
                    const Batch ex = mida[0] - midb[0], ey = mida[1] - midb[1], ez = mida[2] - midb[2];
                    const Batch mid2 = ex * ex + ey * ey + ez * ez;
                    const float reach = a.pairRadius_[i] + b.pairRadius_[j];
                    const float around = a.pairHalfLength_[i] + b.pairHalfLength_[j] + reach;
                    if (xsimd::none(mid2 < Batch(around * around)))
                        continue;
                    Batch d2 = mid2;
                    if (!a.sphere_[i] || !b.sphere_[j])
                    {
                        Batch ea[6], eb[6];
                        load(pa.ends, 6 * i, ea, 6);
                        load(pb.ends, 6 * j, eb, 6);
                        d2 = segmentSegmentDistanceSquared(ea[0], ea[1], ea[2], ea[3], ea[4], ea[5], eb[0], eb[1],
                                                           eb[2], eb[3], eb[4], eb[5]);
                    }
                    const auto close = d2 < Batch(reach * reach);
                    if (xsimd::none(close))
                        continue;
                    const float core = a.pairCoreRadius_[i] + b.pairCoreRadius_[j];
                    touching = laneBits(d2 < Batch(core * core)) & lanes;
                    if (touching != 0)
                        return 0;
                    near |= laneBits(close) & lanes;
                }
            }
        }
    }
    return near;
}
