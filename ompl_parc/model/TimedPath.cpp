#include "ompl_parc/model/TimedPath.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace
{
    bool sameBits(const double *a, const double *b, unsigned int dimension)
    {
        return std::memcmp(a, b, dimension * sizeof(double)) == 0;
    }

    bool equalValues(const double *a, const double *b, unsigned int dimension)
    {
        return std::equal(a, a + dimension, b);
    }

    /** True if a motion from \e q to itself lays \e q itself at every step: from + (to - from) x s rounds to
        from bit for bit unless from is -0 (which becomes +0) or not finite. */
    bool holdsExactly(const double *q, unsigned int dimension)
    {
        return std::all_of(q, q + dimension, [](double v) { return std::isfinite(v) && !(v == 0. && std::signbit(v)); });
    }
}  // namespace

ompl_parc::TimedPath::TimedPath(unsigned int dimension, const double *q) : dimension_(dimension)
{
    appendHold(q, 0);
}

ompl_parc::TimedPath ompl_parc::TimedPath::fromDense(unsigned int dimension, const std::vector<double> &flat)
{
    if (dimension == 0 || flat.empty() || flat.size() % dimension != 0)
        throw ompl::Exception("TimedPath", "a dense path must hold a whole, non-zero number of states");
    TimedPath path(dimension);
    for (std::size_t t = 0; t < flat.size() / dimension; ++t)
        path.appendHold(flat.data() + t * dimension, t);
    return path;
}

void ompl_parc::TimedPath::interpolate(const double *from, const double *to, std::size_t s, std::size_t steps,
                                       unsigned int dimension, double *out)
{
    if (s >= steps)
    {
        std::copy_n(to, dimension, out);
        return;
    }
    // OMPL's RealVectorStateSpace::interpolate at t = s / steps (built without FP contraction: see CMakeLists).
    const double x = static_cast<double>(s) / static_cast<double>(steps);
    for (unsigned int i = 0; i < dimension; ++i)
        out[i] = from[i] + (to[i] - from[i]) * x;
}

std::size_t ompl_parc::TimedPath::getArrival() const
{
    if (pieces_.empty())
        throw ompl::Exception("TimedPath", "the path has no states");
    return arrival_;
}

std::size_t ompl_parc::TimedPath::locate(std::size_t t) const
{
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                     [](std::size_t time, const Piece &p) { return time < p.start; });
    return static_cast<std::size_t>(it - pieces_.begin()) - 1;
}

void ompl_parc::TimedPath::evaluate(std::size_t k, std::size_t t, double *out) const
{
    const Piece &p = pieces_[k];
    interpolate(getFrom(k), getTo(k), p.offset + (t - p.start), p.steps, dimension_, out);
}

void ompl_parc::TimedPath::getConfig(std::size_t t, double *out) const
{
    t = std::min(t, getArrival());
    evaluate(locate(t), t, out);
}

void ompl_parc::TimedPath::Cursor::get(std::size_t t, double *out)
{
    t = std::min(t, path_->getArrival());
    path_->evaluate(seek(t), t, out);
}

std::size_t ompl_parc::TimedPath::Cursor::seek(std::size_t t)
{
    const auto &pieces = path_->pieces_;
    t = std::min(t, path_->getArrival());
    if (piece_ >= pieces.size() || pieces[piece_].start > t)
        piece_ = path_->locate(t);
    while (piece_ + 1 < pieces.size() && pieces[piece_ + 1].start <= t)
        ++piece_;
    return piece_;
}

std::vector<double> ompl_parc::TimedPath::toDense() const
{
    std::vector<double> flat((getArrival() + 1) * dimension_);
    Cursor cursor(*this);
    for (std::size_t t = 0; t <= arrival_; ++t)
        cursor.get(t, flat.data() + t * dimension_);
    return flat;
}

void ompl_parc::TimedPath::push(const Piece &piece, const double *from, const double *to)
{
    pieces_.push_back(piece);
    anchors_.insert(anchors_.end(), from, from + dimension_);
    anchors_.insert(anchors_.end(), to, to + dimension_);
}

void ompl_parc::TimedPath::appendMotion(const double *from, const double *to, std::size_t steps)
{
    if (steps == 0)
        return;
    const std::size_t last = getArrival() + steps;
    // A robot that stays where it is extends the previous piece's hold (the same states, bit for bit).
    if (atTo(pieces_.size() - 1, arrival_) && sameBits(getTo(pieces_.size() - 1), from, dimension_) &&
        sameBits(from, to, dimension_) && holdsExactly(from, dimension_))
        arrival_ = last;
    else
        appendPiece({arrival_ + 1, 1, steps}, from, to, last);
}

void ompl_parc::TimedPath::appendPiece(const Piece &piece, const double *from, const double *to, std::size_t last)
{
    const std::size_t start = pieces_.empty() ? 0 : arrival_ + 1;
    if (piece.start != start || last < start)
        throw ompl::Exception("TimedPath", "a piece must start right after the arrival and cover at least one timestep");
    push(piece, from, to);
    arrival_ = last;
}

void ompl_parc::TimedPath::appendHold(const double *q, std::size_t last)
{
    if (!pieces_.empty() && last <= arrival_)
        return;
    if (!pieces_.empty() && atTo(pieces_.size() - 1, arrival_) && sameBits(getTo(pieces_.size() - 1), q, dimension_))
        arrival_ = last;
    else
        appendPiece({pieces_.empty() ? 0 : arrival_ + 1, 0, 0}, q, q, last);
}

void ompl_parc::TimedPath::appendRange(std::size_t from, std::size_t to, TimedPath &out) const
{
    if (out.dimension_ != dimension_ || from > to)
        throw ompl::Exception("TimedPath", "invalid range or dimension");
    const std::size_t base = out.pieces_.empty() ? 0 : out.arrival_ + 1, end = std::min(to, getArrival());
    for (std::size_t k = from <= end ? locate(from) : pieces_.size(); k < pieces_.size() && pieces_[k].start <= end;
         ++k)
    {
        const Piece &p = pieces_[k];
        const std::size_t a = std::max(p.start, from),
                          b = k + 1 < pieces_.size() ? std::min(pieces_[k + 1].start - 1, end) : end;
        out.appendPiece({a - from + base, p.offset + (a - p.start), p.steps}, getFrom(k), getTo(k), b - from + base);
    }
    if (to > end)  // past the arrival: hold the arrival's state
    {
        std::vector<double> q(dimension_);
        evaluate(pieces_.size() - 1, arrival_, q.data());
        out.appendHold(q.data(), to - from + base);
    }
}

void ompl_parc::TimedPath::splice(std::size_t from, std::size_t to, const TimedPath &segment)
{
    if (from > to || segment.empty() || segment.dimension_ != dimension_ || empty())
        throw ompl::Exception("TimedPath", "invalid splice");
    TimedPath out(dimension_);
    if (from > 0)
        appendRange(0, from - 1, out);
    segment.appendRange(0, segment.arrival_, out);
    if (to < arrival_)
        appendRange(to + 1, arrival_, out);
    out.trimArrival();
    *this = std::move(out);
}

bool ompl_parc::TimedPath::isStill(std::size_t k) const
{
    const Piece &p = pieces_[k];
    return p.offset >= p.steps || equalValues(getFrom(k), getTo(k), dimension_);
}

void ompl_parc::TimedPath::trimArrival()
{
    if (pieces_.empty())
        return;
    std::vector<double> last(dimension_), q(dimension_);
    std::size_t k = pieces_.size() - 1, a = arrival_;
    evaluate(k, a, last.data());
    while (a > 0)
    {
        if (pieces_[k].start == a)
        {
            evaluate(k - 1, a - 1, q.data());
            if (!equalValues(q.data(), last.data(), dimension_))
                break;
            --k;
            --a;
        }
        else if (isStill(k))
            a = pieces_[k].start;  // its value at a equals the last, so do all it covers
        else
        {
            evaluate(k, a - 1, q.data());
            if (!equalValues(q.data(), last.data(), dimension_))
                break;
            --a;
        }
    }
    pieces_.resize(k + 1);
    anchors_.resize(2 * (k + 1) * dimension_);
    arrival_ = a;
}

void ompl_parc::TimedPath::bounds(std::size_t from, std::size_t to, double *lo, double *hi) const
{
    std::fill_n(lo, dimension_, std::numeric_limits<double>::infinity());
    std::fill_n(hi, dimension_, -std::numeric_limits<double>::infinity());
    std::vector<double> q(dimension_);
    const auto include = [&](std::size_t k, std::size_t t)
    {
        evaluate(k, t, q.data());
        for (unsigned int i = 0; i < dimension_; ++i)
        {
            lo[i] = std::min(lo[i], q[i]);
            hi[i] = std::max(hi[i], q[i]);
        }
    };
    const std::size_t first = std::min(from, getArrival()), end = std::min(to, arrival_);
    for (std::size_t k = locate(first); k < pieces_.size() && pieces_[k].start <= end; ++k)
    {
        const Piece &p = pieces_[k];
        const std::size_t a = std::max(p.start, first),
                          b = k + 1 < pieces_.size() ? std::min(pieces_[k + 1].start - 1, end) : end;
        // Before its last step a piece moves monotonically in every coordinate; then it is at `to`.
        include(k, a);
        include(k, b);
        const std::size_t stop = p.start + p.steps - std::min(p.steps, p.offset);  // first timestep at `to`
        if (stop > a && stop <= b)
            include(k, stop - 1);
    }
}

void ompl_parc::TimedPath::appendBreakpoints(std::vector<std::size_t> &times) const
{
    std::vector<double> previous(dimension_), q(dimension_);
    for (std::size_t k = 0; k < pieces_.size(); ++k)
    {
        const Piece &p = pieces_[k];
        const std::size_t a = p.start, b = k + 1 < pieces_.size() ? pieces_[k + 1].start - 1 : getArrival();
        bool continues = false;  // does the line of the previous breakpoint run on through this piece?
        if (k > 0)
        {
            evaluate(k - 1, a - 1, previous.data());
            evaluate(k, a, q.data());
            continues = (isStill(k) && sameBits(previous.data(), q.data(), dimension_)) ||
                        (p.offset == 1 && atTo(k - 1, a - 1) && sameBits(getTo(k - 1), getFrom(k), dimension_));
        }
        if (!continues)
            times.push_back(a);
        const std::size_t stop = p.start + p.steps - std::min(p.steps, p.offset);  // where it reaches `to`
        if (stop >= a && stop < b)
            times.push_back(stop);
        times.push_back(b);
    }
}

bool ompl_parc::TimedPath::operator==(const TimedPath &other) const
{
    const auto samePiece = [](const Piece &a, const Piece &b)
    { return a.start == b.start && a.offset == b.offset && a.steps == b.steps; };
    return dimension_ == other.dimension_ && arrival_ == other.arrival_ && anchors_ == other.anchors_ &&
           std::equal(pieces_.begin(), pieces_.end(), other.pieces_.begin(), other.pieces_.end(), samePiece);
}
