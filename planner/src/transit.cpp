#include "wattswath/planner/transit.hpp"

#include "wattswath/geometry/check.hpp"

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

bool segmentEntersRing(const Point& a, const Point& b, const Ring& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i)
    if (properCross(a, b, ring[i], ring[(i + 1) % n])) return true;
  // No proper crossing: the segment is inside or outside except for touching points. Sample it
  // between the ring vertices it touches (a segment along a diagonal touches two vertices).
  const Point d = b - a;
  const double len2 = d.squaredNorm();
  std::vector<double> ts;  // allocated only when the segment touches a vertex
  if (len2 > 0.0) {
    for (const auto& v : ring) {
      const double t = (v - a).dot(d) / len2;
      if (t > 0.0 && t < 1.0 && std::abs(orient(a, b, v)) <= kEps * std::sqrt(len2)) ts.push_back(t);
    }
  }
  if (ts.empty()) {
    const Point m = a + 0.5 * d;
    return geometry::insideRing(ring, m) && !onBoundary(m, ring);
  }
  ts.push_back(0.0);
  ts.push_back(1.0);
  std::sort(ts.begin(), ts.end());
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts[i + 1] - ts[i] < 1e-12) continue;
    const Point m = a + d * (0.5 * (ts[i] + ts[i + 1]));
    if (geometry::insideRing(ring, m) && !onBoundary(m, ring)) return true;
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
      if (boxes[i].contains(p) && geometry::insideRing(obstacles[i], p)) return true;
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

namespace {

// Shortest way from `a` to `b` over the node graph, given the nodes each end sees (node, distance).
std::vector<Point> viaNodes(const Point& a, const Point& b, const std::vector<std::pair<size_t, double>>& from_a,
                            const std::vector<std::pair<size_t, double>>& to_b, const std::vector<Point>& nodes,
                            const Eigen::MatrixXd& dist, const std::vector<std::vector<size_t>>& pred) {
  double best = std::numeric_limits<double>::infinity();
  size_t bi = 0, bj = 0;
  for (const auto& [i, da] : from_a)
    for (const auto& [j, db] : to_b) {
      const double d = da + dist(i, j) + db;
      if (d < best) {
        best = d;
        bi = i;
        bj = j;
      }
    }
  if (!std::isfinite(best))
    throw std::runtime_error("transit: no route from " + fmt(a) + " to " + fmt(b) + " around the no-fly zones");
  std::vector<Point> path{b};
  for (size_t v = bj;; v = pred[bi][v]) {
    path.push_back(nodes[v]);
    if (v == bi) break;
  }
  path.push_back(a);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::vector<std::pair<size_t, double>> TransitRouter::visibleNodes(const Point& p) const {
  std::vector<std::pair<size_t, double>> out;
  for (size_t i = 0; i < impl_->nodes.size(); ++i)
    if (impl_->clear(p, impl_->nodes[i])) out.emplace_back(i, (p - impl_->nodes[i]).norm());
  return out;
}

std::vector<Point> TransitRouter::route(const Point& a, const Point& b) const {
  if (impl_->blocked(a)) throw std::runtime_error("transit: start point " + fmt(a) + " is inside a no-fly zone");
  if (impl_->blocked(b)) throw std::runtime_error("transit: end point " + fmt(b) + " is inside a no-fly zone");
  if (impl_->clear(a, b)) return {a, b};
  return viaNodes(a, b, visibleNodes(a), visibleNodes(b), impl_->nodes, impl_->dist, impl_->pred);
}

std::vector<std::vector<Point>> TransitRouter::routeAll(const std::vector<Point>& points) const {
  const size_t n = points.size();
  for (const auto& p : points)
    if (impl_->blocked(p)) throw std::runtime_error("transit: point " + fmt(p) + " is inside a no-fly zone");
  std::vector<std::vector<std::pair<size_t, double>>> seen(n);
  std::vector<bool> seen_done(n, false);
  std::vector<std::vector<Point>> out(n * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (impl_->clear(points[i], points[j])) {
        out[i * n + j] = {points[i], points[j]};
        continue;
      }
      for (size_t k : {i, j})
        if (!seen_done[k]) {
          seen[k] = visibleNodes(points[k]);
          seen_done[k] = true;
        }
      out[i * n + j] = viaNodes(points[i], points[j], seen[i], seen[j], impl_->nodes, impl_->dist, impl_->pred);
    }
  return out;
}

}  // namespace wattswath::planner
