#include "ompl_parc/collision/BodyTrack.h"

#include "ompl_parc/collision/CapsuleCollision.h"

#include <algorithm>
#include <array>

namespace
{
    /** The arrays of \e body in storage order. */
    template <typename Body>
    auto arraysOf(Body &body)
    {
        return std::array{&body.ax_,     &body.ay_,      &body.az_,      &body.bx_,      &body.by_,          &body.bz_,
                          &body.radius_, &body.sphereX_, &body.sphereY_, &body.sphereZ_, &body.sphereRadius_};
    }
}  // namespace

void ompl_parc::BodyTrack::append(const CollisionBody &body)
{
    for (const auto *array : arraysOf(body))
        values_.insert(values_.end(), array->begin(), array->end());
    offsets_.push_back(values_.size());
    centerX_.push_back(body.centerX_);
    centerY_.push_back(body.centerY_);
    centerZ_.push_back(body.centerZ_);
    boundRadius_.push_back(body.boundRadius_);
    spheresOnly_.push_back(body.spheresOnly_ ? 1 : 0);
    const double lo[3] = {body.centerX_ - body.boundRadius_, body.centerY_ - body.boundRadius_,
                          body.centerZ_ - body.boundRadius_};
    const double hi[3] = {body.centerX_ + body.boundRadius_, body.centerY_ + body.boundRadius_,
                          body.centerZ_ + body.boundRadius_};
    if ((size() - 1) % BLOCK == 0)
    {
        blockBoxes_.insert(blockBoxes_.end(), lo, lo + 3);
        blockBoxes_.insert(blockBoxes_.end(), hi, hi + 3);
        return;
    }
    double *box = blockBoxes_.data() + blockBoxes_.size() - 6;
    for (int d = 0; d < 3; ++d)
    {
        box[d] = std::min(box[d], lo[d]);
        box[3 + d] = std::max(box[3 + d], hi[d]);
    }
}

void ompl_parc::BodyTrack::load(std::size_t t, CollisionBody &out) const
{
    const double *v = values_.data() + offsets_[t];
    const std::size_t n = (offsets_[t + 1] - offsets_[t]) / ARRAYS;
    out.resize(n, spheresOnly_[t] != 0);
    for (auto *array : arraysOf(out))
    {
        std::copy(v, v + n, array->begin());
        v += n;
    }
    out.centerX_ = centerX_[t];
    out.centerY_ = centerY_[t];
    out.centerZ_ = centerZ_[t];
    out.boundRadius_ = boundRadius_[t];
    out.updateBoxes();
}

bool ompl_parc::BodyTrack::collides(std::size_t t, const CollisionBody &body, CollisionBody &scratch) const
{
    const double cx = body.centerX_ - centerX_[t], cy = body.centerY_ - centerY_[t], cz = body.centerZ_ - centerZ_[t];
    const double rb = body.boundRadius_ + boundRadius_[t];
    if (cx * cx + cy * cy + cz * cz >= rb * rb)
        return false;
    load(t, scratch);
    return bodiesCollide(body, scratch);
}

void ompl_parc::BodyTrack::reserve(std::size_t timesteps, std::size_t capsules)
{
    values_.reserve(timesteps * capsules * ARRAYS);
    offsets_.reserve(timesteps + 1);
    spheresOnly_.reserve(timesteps);
    blockBoxes_.reserve(6 * (timesteps / BLOCK + 1));
    for (auto *v : {&centerX_, &centerY_, &centerZ_, &boundRadius_})
        v->reserve(timesteps);
}
