// CGAL translation unit (slow to compile): vertical decomposition, straight-skeleton offsets and
// Minkowski sums (rings inflated by a margin).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_vertical_decomposition_2.h>
#include <CGAL/create_offset_polygons_2.h>
#include <CGAL/create_straight_skeleton_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cgal_ops.hpp"

namespace wattswath::geometry::detail {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using EPolygon = CGAL::Polygon_2<EK>;
using EPolygonWithHoles = CGAL::Polygon_with_holes_2<EK>;
using IPolygon = CGAL::Polygon_2<IK>;

// Repeated vertices (also the last equal to the first) are dropped: a zero-length edge breaks
// CGAL's sweeps (a segmentation fault in Release, where its preconditions are not checked).
EPolygon toExact(const Ring& r, bool ccw) {
  EPolygon p;
  for (const auto& v : r) {
    const EK::Point_2 q(v.x(), v.y());
    if (p.size() == 0 || q != *(p.vertices_end() - 1)) p.push_back(q);
  }
  while (p.size() > 1 && *p.vertices_begin() == *(p.vertices_end() - 1)) p.erase(p.vertices_end() - 1);
  if (p.size() >= 3 && (p.orientation() == CGAL::COUNTERCLOCKWISE) != ccw) p.reverse_orientation();
  return p;
}

// Exact vertices rounded to doubles; vertices that round onto their predecessor are dropped.
Ring toRing(const EPolygon& p) {
  Ring r;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) {
    const Point q(CGAL::to_double(it->x()), CGAL::to_double(it->y()));
    if (r.empty() || q != r.back()) r.push_back(q);
  }
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  return r;
}

Ring toRing(const IPolygon& p) {
  Ring r;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) r.emplace_back(it->x(), it->y());
  return r;
}

}  // namespace

std::vector<PolygonWithHoles> regularizedRegions(const PolygonWithHoles& area) {
  CGAL::Polygon_set_2<EK> set(toExact(area.outer, true));
  for (const auto& h : area.holes) set.difference(toExact(h, true));
  std::vector<EPolygonWithHoles> out;
  set.polygons_with_holes(std::back_inserter(out));
  std::vector<PolygonWithHoles> regions;
  for (const auto& pwh : out) {
    PolygonWithHoles r;
    r.outer = toRing(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) r.holes.push_back(toRing(*h));
    regions.push_back(std::move(r));
  }
  return regions;
}

std::vector<Ring> minkowskiUnion(const std::vector<Ring>& rings, double circumradius, int sides) {
  EPolygon disk;
  for (int k = 0; k < sides; ++k) {  // edge normals at multiples of 2 pi / sides (east, north, ...)
    const double a = 2.0 * M_PI * (k + 0.5) / sides;
    disk.push_back(EK::Point_2(circumradius * std::cos(a), circumradius * std::sin(a)));
  }
  CGAL::Polygon_set_2<EK> set;
  for (size_t i = 0; i < rings.size(); ++i) {
    const EPolygon p = toExact(rings[i], true);
    if (p.size() < 3 || !p.is_simple())
      throw std::invalid_argument("ring " + std::to_string(i) + " is not a simple polygon");
    set.join(CGAL::minkowski_sum_2(p, disk));
  }
  std::vector<EPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<Ring> out;
  for (const auto& part : parts) out.push_back(toRing(part.outer_boundary()));
  return out;
}

std::vector<Ring> verticalDecomposition(const PolygonWithHoles& poly) {
  EPolygonWithHoles pwh(toExact(poly.outer, true));
  for (const auto& h : poly.holes) pwh.add_hole(toExact(h, false));
  std::vector<EPolygon> pieces;
  CGAL::Polygon_vertical_decomposition_2<EK> decompose;
  decompose(pwh, std::back_inserter(pieces));
  std::vector<Ring> out;
  out.reserve(pieces.size());
  for (const auto& p : pieces) out.push_back(toRing(p));
  return out;
}

struct InwardOffsetter::Impl {
  boost::shared_ptr<CGAL::Straight_skeleton_2<IK>> skeleton;
  struct Edge {
    Point a, b;
    double ta, tb;
  };
  std::vector<Edge> edges;
  double depth = 0.0;
};

InwardOffsetter::InwardOffsetter(const Ring& ring) {
  auto impl = std::make_shared<Impl>();
  IPolygon poly;
  for (const auto& v : ring) poly.push_back(IK::Point_2(v.x(), v.y()));
  if (poly.size() >= 3 && poly.is_simple()) {
    if (poly.orientation() != CGAL::COUNTERCLOCKWISE) poly.reverse_orientation();
    impl->skeleton = CGAL::create_interior_straight_skeleton_2(poly.vertices_begin(), poly.vertices_end(), IK());
  }
  if (impl->skeleton) {
    for (auto h = impl->skeleton->halfedges_begin(); h != impl->skeleton->halfedges_end(); ++h) {
      if (!h->is_bisector() || h->id() > h->opposite()->id()) continue;  // each skeleton edge once
      const auto& u = h->vertex();
      const auto& w = h->opposite()->vertex();
      impl->edges.push_back({Point(u->point().x(), u->point().y()), Point(w->point().x(), w->point().y()),
                             u->time(), w->time()});
      impl->depth = std::max({impl->depth, u->time(), w->time()});
    }
  }
  impl_ = impl;
}

bool InwardOffsetter::ok() const { return static_cast<bool>(impl_->skeleton); }

std::vector<Ring> InwardOffsetter::at(double offset) const {
  std::vector<Ring> rings;
  if (!impl_->skeleton) return rings;
  for (const auto& p : CGAL::create_offset_polygons_2<IPolygon>(offset, *impl_->skeleton)) {
    if (p && p->size() >= 3) rings.push_back(toRing(*p));
  }
  return rings;
}

std::vector<std::pair<Point, double>> InwardOffsetter::depthSamples(double step) const {
  std::vector<std::pair<Point, double>> out;
  for (const auto& e : impl_->edges) {
    const int n = std::max(1, static_cast<int>(std::ceil((e.b - e.a).norm() / step)));
    for (int k = 0; k <= n; ++k) {
      const double f = static_cast<double>(k) / n;
      out.emplace_back(e.a + f * (e.b - e.a), e.ta + f * (e.tb - e.ta));
    }
  }
  return out;
}

double InwardOffsetter::depth() const { return impl_->depth; }

}  // namespace wattswath::geometry::detail
