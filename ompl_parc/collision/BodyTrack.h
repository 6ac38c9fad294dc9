#ifndef OMPL_PARC_BODY_TRACK_
#define OMPL_PARC_BODY_TRACK_

#include "ompl_parc/collision/CollisionBody.h"

#include <array>
#include <cstddef>
#include <vector>

namespace ompl_parc
{
    /** \brief The collision bodies of one robot at consecutive timesteps, stored flat: all of their arrays in one
        buffer instead of a CollisionBody (eleven heap arrays) per timestep. Planning around a robot's timed path
        (DynamicObstacles) keeps its bodies for thousands of timesteps, and allocating and freeing them one by one
        cost more than the checks that use them. A body is loaded back into a caller's scratch CollisionBody, bit
        for bit the body appended (bounding spheres and boxes included: the boxes are recomputed, not stored). */
    class BodyTrack
    {
      public:
        /** \brief Append \e body (bounds up to date, as computeBody() leaves them) as the next timestep's. */
        void append(const CollisionBody &body);

        std::size_t size() const { return boundRadius_.size(); }
        bool empty() const { return size() == 0; }

        /** \brief Timestep \e t's body into \e out (t < size()). */
        void load(std::size_t t, CollisionBody &out) const;

        /** \brief bodiesCollide(\e body, timestep \e t's body), exactly; the stored body is loaded (into \e scratch)
            only when the two bounding spheres overlap, which is bodiesCollide()'s first test: most pairs stop there. */
        bool collides(std::size_t t, const CollisionBody &body, CollisionBody &scratch) const;

        /** \brief Timesteps per block of blockMayTouch(). */
        static constexpr std::size_t BLOCK = 32;

        /** \brief False if no body of block \e block (timesteps BLOCK x block onwards, < size()) can touch the box
            [\e lo, \e hi]: the box around their bounding spheres misses it. A body that moves along a straight
            piece is near another robot's track at few of its timesteps; this skips the others BLOCK at a time. */
        bool blockMayTouch(std::size_t block, const std::array<double, 3> &lo, const std::array<double, 3> &hi) const
        {
            const double *b = blockBoxes_.data() + 6 * block;
            return lo[0] <= b[3] && b[0] <= hi[0] && lo[1] <= b[4] && b[1] <= hi[1] && lo[2] <= b[5] && b[2] <= hi[2];
        }

        /** \brief Room for \e timesteps bodies of \e capsules capsules each. */
        void reserve(std::size_t timesteps, std::size_t capsules);

        /** \brief Arrays per capsule stored (ends, radius, bounding sphere). */
        static constexpr std::size_t ARRAYS = 11;

      private:
        /** \brief Per body: its eleven capsule arrays one after another. */
        std::vector<double> values_;
        /** \brief Per body, its bounding sphere. */
        std::vector<double> centerX_, centerY_, centerZ_, boundRadius_;
        /** \brief Where body t starts in values_ (one more entry than bodies). */
        std::vector<std::size_t> offsets_{0};
        std::vector<unsigned char> spheresOnly_;
        /** \brief Per block of BLOCK timesteps: the box (low x, y, z, high x, y, z) around its bounding spheres. */
        std::vector<double> blockBoxes_;
    };
}  // namespace ompl_parc

#endif
