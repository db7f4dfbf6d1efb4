#include "ring_index.hpp"

#include <algorithm>
#include <limits>

#include "wattswath/geometry/check.hpp"
#include "wattswath/geometry/tolerances.hpp"

namespace wattswath::geometry::detail {
namespace {

double cross2(const Point& u, const Point& v) { return u.x() * v.y() - u.y() * v.x(); }

}  // namespace

void edgeCrossing(const Point& a, const Point& b, const Point& p, const Point& e, std::vector<double>& ts) {
  const Point d = b - a;
  const double den = cross2(d, e);
  if (std::abs(den) <= 1e-15 * std::max(1.0, d.squaredNorm() + e.squaredNorm())) {
    // Parallel: the ends of a collinear overlap split the segment.
    const double l2 = d.squaredNorm();
    if (l2 > 0.0) {
      ts.push_back((p - a).dot(d) / l2);
      ts.push_back((p + e - a).dot(d) / l2);
    }
    return;
  }
  const double t = cross2(p - a, e) / den, u = cross2(p - a, d) / den;
  if (u >= -1e-12 && u <= 1.0 + 1e-12) ts.push_back(t);
}

RingIndex::RingIndex(const Ring& ring) : ring_(ring) {
  std::vector<Value> values;
  values.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % ring.size()];
    values.emplace_back(Box(BgPoint(std::min(p.x(), q.x()), std::min(p.y(), q.y())),
                            BgPoint(std::max(p.x(), q.x()), std::max(p.y(), q.y()))),
                        i);
  }
  tree_ = decltype(tree_)(values.begin(), values.end());  // bulk loading (packing)
}

template <class F>
void RingIndex::forEdgesIn(const Box& query, F f) const {
  namespace bgi = boost::geometry::index;
  for (auto it = tree_.qbegin(bgi::intersects(query)); it != tree_.qend(); ++it) f(it->second);
}

namespace {

// A little more than `d` around a query (boxes that only touch still count): rounding in a box's
// corners must not drop an edge the plain loop would test.
double slack(double d, const Point& p) { return d + 1e-9 * (1.0 + std::abs(d) + p.cwiseAbs().maxCoeff()); }

}  // namespace

bool RingIndex::inside(const Point& p) const {
  // The even-odd test of insideRing, on the edges whose boxes meet the ray from p to +x.
  bool in = false;
  const double far = std::numeric_limits<double>::max(), e = slack(0.0, p);
  forEdgesIn(Box(BgPoint(p.x() - e, p.y() - e), BgPoint(far, p.y() + e)), [&](std::size_t i) {
    const Point& a = ring_[(i + 1) % ring_.size()];
    const Point& b = ring_[i];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) in = !in;
    }
  });
  return in;
}

bool RingIndex::near(const Point& p, double d) const {
  bool found = false;
  const double r = slack(d, p);
  forEdgesIn(Box(BgPoint(p.x() - r, p.y() - r), BgPoint(p.x() + r, p.y() + r)), [&](std::size_t i) {
    found = found || distanceToSegment(p, ring_[i], ring_[(i + 1) % ring_.size()]) <= d;
  });
  return found;
}

void RingIndex::crossingParams(const Point& a, const Point& b, std::vector<double>& ts) const {
  const double e = slack(0.0, Point(std::max(std::abs(a.x()), std::abs(b.x())), std::max(std::abs(a.y()), std::abs(b.y()))));
  const Box query(BgPoint(std::min(a.x(), b.x()) - e, std::min(a.y(), b.y()) - e),
                  BgPoint(std::max(a.x(), b.x()) + e, std::max(a.y(), b.y()) + e));
  forEdgesIn(query, [&](std::size_t i) {
    const Point& p = ring_[i];
    edgeCrossing(a, b, p, ring_[(i + 1) % ring_.size()] - p, ts);
  });
}

HoleIndex::HoleIndex(const std::vector<Ring>& holes) : holes_(holes) {
  std::vector<Value> values;
  values.reserve(holes.size());
  for (std::size_t i = 0; i < holes.size(); ++i) {
    if (holes[i].empty()) continue;
    Point lo = holes[i].front(), hi = lo;
    for (const auto& v : holes[i]) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    values.emplace_back(Box(BgPoint(lo.x(), lo.y()), BgPoint(hi.x(), hi.y())), i);
  }
  tree_ = decltype(tree_)(values.begin(), values.end());  // bulk loading (packing)
}

bool HoleIndex::segmentEnters(const Point& a, const Point& b) const {
  namespace bgi = boost::geometry::index;
  const double e = slack(0.0, a.cwiseAbs().cwiseMax(b.cwiseAbs()));
  const Box query(BgPoint(std::min(a.x(), b.x()) - e, std::min(a.y(), b.y()) - e),
                  BgPoint(std::max(a.x(), b.x()) + e, std::max(a.y(), b.y()) + e));
  for (auto it = tree_.qbegin(bgi::intersects(query)); it != tree_.qend(); ++it)
    if (segmentEntersRing(holes_[it->second], a, b)) return true;
  return false;
}

}  // namespace wattswath::geometry::detail
