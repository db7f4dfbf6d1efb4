#include "wattswath/planner/transit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

namespace wattswath::planner {
namespace {

using geometry::Point;
using geometry::Ring;
constexpr double kEps = 1e-9;  // [m] geometric tolerance for orientation tests

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }
double orient(const Point& a, const Point& b, const Point& c) { return cross(b - a, c - a); }

// Proper crossing of segments ab and cd (interiors cross at one point).
bool properCross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > kEps && o2 < -kEps) || (o1 < -kEps && o2 > kEps)) &&
         ((o3 > kEps && o4 < -kEps) || (o3 < -kEps && o4 > kEps));
}

// Whether `p` lies on an edge of `ring` (within kEps).
bool onBoundary(const Point& p, const Ring& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % n];
    const Point d = b - a;
    const double l2 = d.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    if ((p - (a + d * t)).norm() <= kEps) return true;
  }
  return false;
}

std::string fmt(const Point& p) { return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ") m"; }

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, double>>;

}  // namespace

bool insideRing(const Point& p, const Ring& ring) {
  bool in = false;
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) in = !in;
    }
  }
  return in;
}

bool segmentEntersRing(const Point& a, const Point& b, const Ring& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i)
    if (properCross(a, b, ring[i], ring[(i + 1) % n])) return true;
  // No proper crossing: the segment is inside or outside except for touching points. Sample it
  // between the ring vertices it touches (a segment along a diagonal touches two vertices).
  std::vector<double> ts{0.0, 1.0};
  const Point d = b - a;
  const double len2 = d.squaredNorm();
  if (len2 > 0.0) {
    for (const auto& v : ring) {
      const double t = (v - a).dot(d) / len2;
      if (t > 0.0 && t < 1.0 && std::abs(orient(a, b, v)) <= kEps * std::sqrt(len2)) ts.push_back(t);
    }
  }
  std::sort(ts.begin(), ts.end());
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts[i + 1] - ts[i] < 1e-12) continue;
    const Point m = a + d * (0.5 * (ts[i] + ts[i + 1]));
    if (insideRing(m, ring) && !onBoundary(m, ring)) return true;
  }
  return false;
}

struct TransitRouter::Impl {
  std::vector<Ring> obstacles;
  std::vector<Eigen::AlignedBox2d> boxes;  // bounding box of each obstacle
  TransitSettings settings;
  std::vector<Point> nodes;  // obstacle vertices pushed outwards by the clearance
  Graph graph;
  Eigen::MatrixXd dist;                    // [m] shortest node-to-node distance in the graph
  std::vector<std::vector<size_t>> pred;   // pred[i][j]: node before j on the shortest path from i

  bool clear(const Point& a, const Point& b) const {
    Eigen::AlignedBox2d seg(a.cwiseMin(b), a.cwiseMax(b));
    for (size_t i = 0; i < obstacles.size(); ++i)
      if (seg.intersects(boxes[i]) && segmentEntersRing(a, b, obstacles[i])) return false;
    return true;
  }
  bool blocked(const Point& p) const {
    for (size_t i = 0; i < obstacles.size(); ++i)
      if (boxes[i].contains(p) && insideRing(p, obstacles[i])) return true;
    return false;
  }
};

TransitRouter::TransitRouter(std::vector<Ring> obstacles, TransitSettings settings) : impl_(std::make_unique<Impl>()) {
  if (!(settings.clearance > 0.0 && settings.clearance <= 100.0))
    throw std::invalid_argument("TransitSettings.clearance = " + std::to_string(settings.clearance) +
                                " m is outside (0, 100]");
  for (size_t i = 0; i < obstacles.size(); ++i)
    if (obstacles[i].size() < 3)
      throw std::invalid_argument("TransitRouter: obstacle " + std::to_string(i) + " has " +
                                  std::to_string(obstacles[i].size()) + " vertices (at least 3 expected)");
  impl_->obstacles = std::move(obstacles);
  for (const auto& r : impl_->obstacles) {
    Eigen::AlignedBox2d box;
    for (const auto& p : r) box.extend(p);
    impl_->boxes.push_back(box);
  }
  impl_->settings = settings;
  // Convex vertices (seen from outside) pushed out along the outward bisector; only those can be on
  // a shortest path. The pushed vertex sits `clearance` from both adjacent edges.
  for (const auto& ring : impl_->obstacles) {
    const double sgn = geometry::signedArea(ring) > 0.0 ? 1.0 : -1.0;  // +1: counter-clockwise
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Point& p = ring[(i + n - 1) % n];
      const Point& v = ring[i];
      const Point& q = ring[(i + 1) % n];
      const Point e1 = (v - p).normalized(), e2 = (q - v).normalized();
      if (sgn * cross(e1, e2) <= kEps) continue;  // reflex (or straight) vertex of the obstacle
      const Point n1(sgn * e1.y(), -sgn * e1.x()), n2(sgn * e2.y(), -sgn * e2.x());  // outward normals
      const Point bis = (n1 + n2).normalized();
      const double c = std::max(bis.dot(n1), 0.2);  // limit the push-out at very sharp vertices
      const Point w = v + bis * (settings.clearance / c);
      if (!impl_->blocked(w)) impl_->nodes.push_back(w);
    }
  }
  impl_->graph = Graph(impl_->nodes.size());
  for (size_t i = 0; i < impl_->nodes.size(); ++i)
    for (size_t j = i + 1; j < impl_->nodes.size(); ++j)
      if (impl_->clear(impl_->nodes[i], impl_->nodes[j]))
        boost::add_edge(i, j, (impl_->nodes[i] - impl_->nodes[j]).norm(), impl_->graph);
  // All node-to-node shortest paths once (Dijkstra from every node): queries then only connect
  // their two end points to the nodes they see.
  const size_t m = impl_->nodes.size();
  impl_->dist = Eigen::MatrixXd::Constant(m, m, std::numeric_limits<double>::infinity());
  impl_->pred.assign(m, std::vector<size_t>(m));
  std::vector<double> d(m);
  for (size_t i = 0; i < m; ++i) {
    boost::dijkstra_shortest_paths(impl_->graph, i,
                                   boost::distance_map(d.data()).predecessor_map(impl_->pred[i].data()));
    for (size_t j = 0; j < m; ++j) impl_->dist(i, j) = d[j];
  }
}

TransitRouter::~TransitRouter() = default;
TransitRouter::TransitRouter(TransitRouter&&) noexcept = default;
TransitRouter& TransitRouter::operator=(TransitRouter&&) noexcept = default;

const std::vector<Ring>& TransitRouter::obstacles() const { return impl_->obstacles; }
bool TransitRouter::clear(const Point& a, const Point& b) const { return impl_->clear(a, b); }
bool TransitRouter::blocked(const Point& p) const { return impl_->blocked(p); }

std::vector<Point> TransitRouter::route(const Point& a, const Point& b) const {
  if (impl_->blocked(a)) throw std::runtime_error("transit: start point " + fmt(a) + " is inside a no-fly zone");
  if (impl_->blocked(b)) throw std::runtime_error("transit: end point " + fmt(b) + " is inside a no-fly zone");
  if (impl_->clear(a, b)) return {a, b};
  const size_t m = impl_->nodes.size();
  std::vector<std::pair<size_t, double>> from_a, to_b;  // visible nodes and the distance to them
  for (size_t i = 0; i < m; ++i) {
    if (impl_->clear(a, impl_->nodes[i])) from_a.emplace_back(i, (a - impl_->nodes[i]).norm());
    if (impl_->clear(b, impl_->nodes[i])) to_b.emplace_back(i, (b - impl_->nodes[i]).norm());
  }
  double best = std::numeric_limits<double>::infinity();
  size_t bi = 0, bj = 0;
  for (const auto& [i, da] : from_a)
    for (const auto& [j, db] : to_b) {
      const double d = da + impl_->dist(i, j) + db;
      if (d < best) {
        best = d;
        bi = i;
        bj = j;
      }
    }
  if (!std::isfinite(best))
    throw std::runtime_error("transit: no route from " + fmt(a) + " to " + fmt(b) + " around the no-fly zones");
  std::vector<Point> path{b};
  for (size_t v = bj;; v = impl_->pred[bi][v]) {
    path.push_back(impl_->nodes[v]);
    if (v == bi) break;
  }
  path.push_back(a);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace wattswath::planner
