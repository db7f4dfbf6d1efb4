// Validation, unambiguous repairs and no-fly subtraction of survey areas with CGAL (exact
// predicates and constructions; Boolean set operations). The only CGAL translation unit of the
// survey-area code.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include "area_internal.hpp"
#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::geometry {
namespace detail {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P2 = K::Point_2;
using Seg = K::Segment_2;
using Poly = CGAL::Polygon_2<K>;
using Pwh = CGAL::Polygon_with_holes_2<K>;
using PSet = CGAL::Polygon_set_2<K>;

std::string num(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

std::string xy(const Point& p) {
  std::ostringstream o;
  o.precision(10);
  o << "(" << p.x() << ", " << p.y() << ")";
  return o.str();
}

P2 cg(const Point& p) { return P2(p.x(), p.y()); }

Poly toPoly(const Ring& r) {
  Poly p;
  for (const auto& q : r) p.push_back(cg(q));
  return p;
}

Poly ccw(const Ring& r) {
  Poly p = toPoly(r);
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

Pwh toPwh(const PolygonWithHoles& r) {
  Pwh p(ccw(r.outer));
  for (const auto& h : r.holes) {
    Poly hp = toPoly(h);
    if (hp.orientation() == CGAL::COUNTERCLOCKWISE) hp.reverse_orientation();
    p.add_hole(hp);
  }
  return p;
}

Ring toRing(const Poly& p) {
  Ring r;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) {
    const Point q(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
    if (r.empty() || (q - r.back()).norm() > 1e-9) r.push_back(q);
  }
  while (r.size() > 1 && (r.front() - r.back()).norm() <= 1e-9) r.pop_back();
  return r;
}

double psetArea(const PSet& s) {
  std::vector<Pwh> parts;
  s.polygons_with_holes(std::back_inserter(parts));
  double a = 0.0;
  for (const auto& p : parts) {
    a += CGAL::to_double(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += CGAL::to_double(h->area());  // holes are CW: negative
  }
  return a;
}

/// Distance from p to the infinite line through a, b [m].
double lineDistance(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double len = d.norm();
  if (len == 0.0) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / len;
}

std::string edgeName(const LabeledRing& r, size_t i) {
  const size_t j = (i + 1) % r.pts.size();
  return "edge " + std::to_string(i) + " (" + r.labels[i] + " -> " + r.labels[j] + ")";
}

/// Consecutive duplicates, the closing vertex, collinear vertices, orientation; throws on fewer
/// than 3 distinct vertices, non-finite coordinates, zero area and self-intersection.
void validateRing(LabeledRing& r, bool wantCcw, const std::string& source, const RepairSettings& s,
                  std::vector<std::string>& notes) {
  const std::string at = source + ": " + r.name;
  for (size_t i = 0; i < r.pts.size(); ++i) {
    if (!std::isfinite(r.pts[i].x()) || !std::isfinite(r.pts[i].y())) {
      throw SurveyAreaError(at + ", " + r.labels[i] + ": non-finite coordinate " + xy(r.pts[i]) + "; expected finite numbers");
    }
  }
  const size_t given = r.pts.size();
  LabeledRing k;
  k.name = r.name;
  k.open = r.open;
  for (size_t i = 0; i < r.pts.size(); ++i) {
    if (!k.pts.empty() && (r.pts[i] - k.pts.back()).norm() <= s.duplicate_tolerance) {
      notes.push_back(at + ": removed " + r.labels[i] + ", a duplicate of the preceding " + k.labels.back());
      continue;
    }
    k.pts.push_back(r.pts[i]);
    k.labels.push_back(r.labels[i]);
  }
  while (k.pts.size() > 1 && (k.pts.back() - k.pts.front()).norm() <= s.duplicate_tolerance) {
    notes.push_back(at + ": removed " + k.labels.back() + ", the repeated closing vertex (same as " + k.labels.front() + ")");
    k.pts.pop_back();
    k.labels.pop_back();
  }
  if (k.open && k.pts.size() > 3) {
    const double d = (k.pts.back() - k.pts.front()).norm();
    if (d <= s.closing_tolerance) {
      notes.push_back(at + ": removed " + k.labels.back() + ", " + num(d) + " m from " + k.labels.front() +
                      ": treated as the repeated closing vertex (closing_tolerance " + num(s.closing_tolerance) + " m)");
      k.pts.pop_back();
      k.labels.pop_back();
    }
  }
  if (k.pts.size() < 3) {
    throw SurveyAreaError(at + ": fewer than 3 distinct vertices (" + std::to_string(given) + " given, " +
                          std::to_string(k.pts.size()) + " distinct); a polygon needs at least 3");
  }
  for (bool changed = true; changed && k.pts.size() >= 3;) {
    changed = false;
    const size_t n = k.pts.size();
    for (size_t j = 0; j < n; ++j) {
      const Point& a = k.pts[(j + n - 1) % n];
      const Point& p = k.pts[j];
      const Point& b = k.pts[(j + 1) % n];
      if (lineDistance(p, a, b) <= s.collinear_tolerance && (p - a).dot(b - a) > 0.0 && (p - b).dot(a - b) > 0.0) {
        notes.push_back(at + ": removed " + k.labels[j] + ", collinear with its neighbours " + k.labels[(j + n - 1) % n] +
                        " and " + k.labels[(j + 1) % n] + " (within " + num(s.collinear_tolerance) + " m)");
        k.pts.erase(k.pts.begin() + static_cast<long>(j));
        k.labels.erase(k.labels.begin() + static_cast<long>(j));
        changed = true;
        break;
      }
    }
  }
  if (k.pts.size() < 3) throw SurveyAreaError(at + ": zero area: all vertices are collinear");
  const Poly poly = toPoly(k.pts);
  if (!poly.is_simple()) {
    const size_t n = k.pts.size();
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = i + 1; j < n; ++j) {
        const Seg si(cg(k.pts[i]), cg(k.pts[(i + 1) % n])), sj(cg(k.pts[j]), cg(k.pts[(j + 1) % n]));
        const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
        bool bad = false;
        if (!adjacent) {
          bad = CGAL::do_intersect(si, sj);
        } else {
          // Adjacent edges share one vertex; they are bad only when they fold back onto each other.
          const size_t shared = (j == i + 1) ? j : i;
          const Point& v = k.pts[shared];
          const Point& p = k.pts[(shared + n - 1) % n];
          const Point& q = k.pts[(shared + 1) % n];
          bad = CGAL::collinear(cg(p), cg(v), cg(q)) && (p - v).dot(q - v) > 0.0;
        }
        if (bad) {
          throw SurveyAreaError(at + ": self-intersection: " + edgeName(k, i) + " and " + edgeName(k, j) +
                                (adjacent ? " fold back onto each other (a spike)" : " intersect"));
        }
      }
    }
    throw SurveyAreaError(at + ": the boundary is not simple");
  }
  const double a = signedArea(k.pts);
  if (std::abs(a) < s.min_area) {
    throw SurveyAreaError(at + ": zero area (" + num(std::abs(a)) + " m^2, less than min_area " + num(s.min_area) +
                          " m^2), starting at " + k.labels.front());
  }
  if ((a > 0.0) != wantCcw) {
    // Reversed, and rotated so that the file's first vertex stays first (plan takes off there by default).
    std::reverse(k.pts.begin(), k.pts.end());
    std::reverse(k.labels.begin(), k.labels.end());
    std::rotate(k.pts.begin(), k.pts.end() - 1, k.pts.end());
    std::rotate(k.labels.begin(), k.labels.end() - 1, k.labels.end());
    notes.push_back(at + ": reversed the vertex order to " + (wantCcw ? "counter-clockwise" : "clockwise") +
                    (wantCcw ? " (outer boundaries run CCW)" : " (holes run CW)") + ", " + k.labels.front() + " still first");
  }
  r = std::move(k);
}

}  // namespace

namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::pair<size_t, size_t>>;

/// The bounding box of the segment a-b, tagged with `info`.
Box segmentBox(const Point& a, const Point& b, std::pair<size_t, size_t> info) {
  double lo[2] = {std::min(a.x(), b.x()), std::min(a.y(), b.y())};
  double hi[2] = {std::max(a.x(), b.x()), std::max(a.y(), b.y())};
  return Box(lo, hi, info);
}

/// For each hole k, the (hole edge, outer edge) pairs whose boxes meet, sorted: a sweep over
/// boxes (CGAL box_intersection_d) instead of every hole edge against every outer edge.
std::vector<std::vector<std::pair<size_t, size_t>>> edgePairsNearOuter(const LabeledPolygon& poly) {
  std::vector<Box> outer, hole;
  const auto& o = poly.outer.pts;
  for (size_t j = 0; j < o.size(); ++j) outer.push_back(segmentBox(o[j], o[(j + 1) % o.size()], {0, j}));
  for (size_t k = 0; k < poly.holes.size(); ++k) {
    const auto& h = poly.holes[k].pts;
    for (size_t i = 0; i < h.size(); ++i) hole.push_back(segmentBox(h[i], h[(i + 1) % h.size()], {k, i}));
  }
  std::vector<std::vector<std::pair<size_t, size_t>>> pairs(poly.holes.size());
  CGAL::box_intersection_d(hole.begin(), hole.end(), outer.begin(), outer.end(), [&](const Box& a, const Box& b) {
    pairs[a.info().first].emplace_back(a.info().second, b.info().second);
  });
  for (auto& p : pairs) std::sort(p.begin(), p.end());
  return pairs;
}

/// For each hole k, the earlier holes m < k whose bounding boxes meet it, ascending.
std::vector<std::vector<size_t>> holePairsNear(const LabeledPolygon& poly) {
  std::vector<Box> boxes;
  for (size_t k = 0; k < poly.holes.size(); ++k) {
    const auto& h = poly.holes[k].pts;
    double lo[2] = {h[0].x(), h[0].y()}, hi[2] = {h[0].x(), h[0].y()};
    for (const auto& q : h) {
      lo[0] = std::min(lo[0], q.x()), lo[1] = std::min(lo[1], q.y());
      hi[0] = std::max(hi[0], q.x()), hi[1] = std::max(hi[1], q.y());
    }
    boxes.emplace_back(lo, hi, std::make_pair(k, k));
  }
  std::vector<std::vector<size_t>> near(poly.holes.size());
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const size_t i = a.info().first, j = b.info().first;
    near[std::max(i, j)].push_back(std::min(i, j));
  });
  for (auto& v : near) std::sort(v.begin(), v.end());
  return near;
}

}  // namespace

std::vector<std::string> validateLabeled(LabeledPolygon& poly, const std::string& source, const RepairSettings& s) {
  std::vector<std::string> notes;
  validateRing(poly.outer, true, source, s, notes);
  for (auto& h : poly.holes) validateRing(h, false, source, s, notes);
  const Poly outer = toPoly(poly.outer.pts);
  // Only edges and holes whose boxes meet are compared exactly: thousands of holes cost a sweep,
  // not every pair (2,025 holes took 18 s).
  const auto near_outer = edgePairsNearOuter(poly);
  const auto near_holes = holePairsNear(poly);
  std::vector<Poly> holes;
  for (size_t k = 0; k < poly.holes.size(); ++k) {
    const LabeledRing& h = poly.holes[k];
    const std::string at = source + ": " + h.name;
    const size_t nh = h.pts.size(), no = poly.outer.pts.size();
    bool touches = false;  // some hole edge meets the outer boundary
    for (const auto& [i, j] : near_outer[k]) {
      const P2 a = cg(h.pts[i]), b = cg(h.pts[(i + 1) % nh]);
      const P2 c = cg(poly.outer.pts[j]), d = cg(poly.outer.pts[(j + 1) % no]);
      const auto o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
      const auto o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
      const bool crosses = o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
                           o4 != CGAL::COLLINEAR && o3 != o4;
      const bool meet = CGAL::do_intersect(Seg(a, b), Seg(c, d));
      const bool overlaps = o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR && meet &&
                            CGAL::squared_distance(Seg(a, b), Seg(c, d)) == 0 && !(a == c || a == d || b == c || b == d);
      if (crosses || overlaps) {
        throw SurveyAreaError(at + ": " + edgeName(h, i) + (crosses ? " crosses " : " runs along ") + poly.outer.name +
                              " " + edgeName(poly.outer, j) +
                              (crosses ? "; a hole must lie inside the outer boundary"
                                       : "; a hole may touch the boundary only at points (make it a notch of the outer boundary)"));
      }
      touches = touches || meet;
    }
    for (size_t i = 0; i < nh; ++i) {
      if (outer.bounded_side(cg(h.pts[i])) == CGAL::ON_UNBOUNDED_SIDE) {
        throw SurveyAreaError(at + ", " + h.labels[i] + ": lies outside " + poly.outer.name +
                              "; a hole must lie inside the outer boundary");
      }
    }
    Poly hp = toPoly(h.pts);
    hp.reverse_orientation();  // CCW for the Boolean operations
    // A ring whose vertices are inside and whose edges meet no outer edge lies inside; one that
    // touches the boundary is checked by a Boolean difference.
    if (touches) {
      PSet outside(hp);
      outside.difference(outer);
      if (!outside.is_empty()) {
        throw SurveyAreaError(at + ": lies partly outside " + poly.outer.name + " (" + num(std::abs(psetArea(outside))) +
                              " m^2 outside); a hole must lie inside the outer boundary");
      }
    }
    for (size_t m : near_holes[k]) {
      if (CGAL::do_intersect(holes[m], hp)) {
        throw SurveyAreaError(at + ": overlaps " + poly.holes[m].name + "; merge overlapping holes into one");
      }
    }
    holes.push_back(hp);
  }
  PolygonWithHoles p;
  p.outer = poly.outer.pts;
  for (const auto& h : poly.holes) p.holes.push_back(h.pts);
  if (area(p) < s.min_area) {
    throw SurveyAreaError(source + ": " + poly.outer.name + ": zero area left after subtracting the holes");
  }
  return notes;
}

void checkRegionsDisjoint(const std::vector<PolygonWithHoles>& regions, const std::string& source,
                          const std::vector<std::string>& names) {
  const auto named = [&](size_t i) { return i < names.size() ? names[i] : "area polygon " + std::to_string(i); };
  std::vector<Pwh> ps;
  for (const auto& r : regions) ps.push_back(toPwh(r));
  std::vector<CGAL::Bbox_2> boxes;
  for (const auto& p : ps) boxes.push_back(p.outer_boundary().bbox());
  for (size_t i = 0; i < ps.size(); ++i) {
    for (size_t j = i + 1; j < ps.size(); ++j) {
      if (CGAL::do_overlap(boxes[i], boxes[j]) && CGAL::do_intersect(ps[i], ps[j])) {
        throw SurveyAreaError(source + ": " + named(i) + " and " + named(j) +
                              " overlap; the parts of an area must be disjoint (merge them into one polygon, or mark one "
                              "as a no-fly zone)");
      }
    }
  }
}

}  // namespace detail

std::vector<std::string> validatePolygon(PolygonWithHoles& poly, const std::string& source, const RepairSettings& settings) {
  auto label = [](const Ring& r, const std::string& name) {
    detail::LabeledRing l;
    l.pts = r;
    l.name = name;
    for (size_t i = 0; i < r.size(); ++i) l.labels.push_back("vertex " + std::to_string(i));
    return l;
  };
  detail::LabeledPolygon lp;
  lp.outer = label(poly.outer, "outer boundary");
  for (size_t k = 0; k < poly.holes.size(); ++k) lp.holes.push_back(label(poly.holes[k], "hole " + std::to_string(k)));
  auto notes = detail::validateLabeled(lp, source, settings);
  poly.outer = lp.outer.pts;
  poly.holes.clear();
  for (const auto& h : lp.holes) poly.holes.push_back(h.pts);
  return notes;
}

void subtractNoFlyZones(SurveyArea& area, const NoFlyZones& zones) {
  using namespace detail;
  area.repairs.insert(area.repairs.end(), zones.repairs.begin(), zones.repairs.end());
  PSet flyable, outline;
  for (const auto& r : area.regions) {
    flyable.join(toPwh(r));
    outline.join(ccw(r.outer));
  }
  bool changed = false;
  for (size_t k = 0; k < zones.zones.size(); ++k) {
    const std::string name = zones.source + ": no-fly zone " + std::to_string(k);
    const Poly z = ccw(zones.zones[k]);
    area.no_fly.push_back(toRing(z));
    if (!flyable.do_intersect(z)) {
      area.repairs.push_back(name + " does not overlap the flyable area; ignored");
      continue;
    }
    PSet outside(z);
    outside.difference(outline);
    if (!outside.is_empty()) {
      area.repairs.push_back(name + " extends outside the area (" + num(std::abs(psetArea(outside))) + " of " +
                             num(std::abs(CGAL::to_double(z.area()))) + " m^2); clipped to the area");
    }
    flyable.difference(z);
    changed = true;
    if (flyable.is_empty()) throw SurveyAreaError(name + " covers the whole survey area of " + area.source);
  }
  if (!changed) return;
  std::vector<Pwh> parts;
  flyable.polygons_with_holes(std::back_inserter(parts));
  area.regions.clear();
  for (const auto& p : parts) {
    PolygonWithHoles r;
    r.outer = toRing(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) r.holes.push_back(toRing(*h));
    area.regions.push_back(std::move(r));
  }
}

}  // namespace wattswath::geometry
