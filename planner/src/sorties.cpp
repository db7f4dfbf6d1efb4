// A coverage flight split into battery-sized sorties (sorties.hpp).
#include "wattswath/planner/sorties.hpp"

#include <algorithm>
#include <functional>
#include <future>
#include <cmath>
#include <utility>
#include <limits>
#include <stdexcept>
#include <string>

#include "wattswath/planner/margin.hpp"
#include "wattswath/planner/transit.hpp"

namespace wattswath::planner {
namespace {

namespace geo = wattswath::geometry;
constexpr double kInf = std::numeric_limits<double>::infinity();

geo::PathLeg transitLeg(const geo::Point& a, const geo::Point& b, double altitude) {
  geo::PathLeg l;
  l.kind = geo::PrimitiveKind::Line;
  l.role = geo::LegRole::Transit;
  l.start = a;
  l.end = b;
  l.heading_start = l.heading_end = std::atan2(b.y() - a.y(), b.x() - a.x());
  l.altitude = altitude;
  return l;
}

// `l` flown the other way (the same line, arc or turn in place, end to start).
geo::PathLeg reverseLeg(const geo::PathLeg& l) {
  geo::PathLeg r = l;
  std::swap(r.start, r.end);
  r.heading_start = l.heading_end + M_PI;
  r.heading_end = l.heading_start + M_PI;
  r.turn_angle = -l.turn_angle;
  return r;
}

// `plan` with every straight sweep longer than 2 x `piece_m` cut into equal pieces of at most
// `piece_m` [m] (flown through at its cruise speed; energy shared by length), so a sortie may end
// mid-sweep; `origin` gets the plan's leg index of every leg.
FlownPath cutSweeps(const FlownPath& plan, double piece_m, std::vector<int>& origin) {
  FlownPath out;
  origin.clear();
  const auto& legs = plan.path.legs;
  for (std::size_t i = 0; i < legs.size(); ++i) {
    const auto& l = legs[i];
    const double len = l.length(), e = i < plan.leg_energy.size() ? plan.leg_energy[i] : 0.0;
    const int n = l.role == geo::LegRole::Sweep && l.kind == geo::PrimitiveKind::Line && len > 2.0 * piece_m
                      ? static_cast<int>(std::ceil(len / piece_m)) : 1;
    for (int k = 0; k < n; ++k) {
      geo::PathLeg p = l;
      p.start = l.start + (l.end - l.start) * (static_cast<double>(k) / n);
      p.end = l.start + (l.end - l.start) * (static_cast<double>(k + 1) / n);
      out.path.legs.push_back(p);
      out.speeds.cruise.push_back(plan.speeds.cruise[i]);
      out.speeds.junction.push_back(k == 0 ? plan.speeds.junction[i] : plan.speeds.cruise[i]);
      out.leg_energy.push_back(e / n);
      origin.push_back(static_cast<int>(i));
    }
  }
  out.speeds.junction.push_back(plan.speeds.junction.back());
  return out;
}

// A transit as stop-to-stop straight legs along the shortest route around the obstacles.
struct Transit {
  std::vector<geo::Point> route;
  double energy_j = 0.0;
};

class Splitter {
 public:
  Splitter(const FlownPath& plan, const SurveyProblem& problem, RouteScorer& scorer, double scale, double piece_m,
           const std::vector<double>& piece_weight)
      : plan_(cutSweeps(plan, piece_m, origin_)), problem_(problem), scorer_(scorer), router_(noFlyZones(problem)), scale_(scale) {
    const auto& legs = plan_.path.legs;
    for (std::size_t i = 0; i < legs.size(); ++i)
      if (legs[i].role == geo::LegRole::Sweep) sweeps_.push_back(static_cast<int>(i));
    if (sweeps_.empty()) throw std::invalid_argument("splitIntoSorties: the plan has no sweep leg");
    // Leg weights: a piece's weight applies to it and to the connectors before the next piece.
    std::vector<double> w(legs.size(), 1.0);
    if (!piece_weight.empty()) {
      if (piece_weight.size() != sweeps_.size())
        throw std::invalid_argument("SortieSettings.piece_weight has " + std::to_string(piece_weight.size()) + " entries, expected " +
                                    std::to_string(sweeps_.size()) + " (one per piece of sweep)");
      for (std::size_t p = 0; p < sweeps_.size(); ++p)
        for (std::size_t i = static_cast<std::size_t>(sweeps_[p]); i < (p + 1 < sweeps_.size() ? static_cast<std::size_t>(sweeps_[p + 1]) : legs.size()); ++i)
          w[i] = piece_weight[p];
    }
    prefix_.assign(legs.size() + 1, 0.0);
    for (std::size_t i = 0; i < legs.size(); ++i) prefix_[i + 1] = prefix_[i] + w[i] * (i < plan_.leg_energy.size() ? plan_.leg_energy[i] : 0.0);
    for (int s : sweeps_) {
      const auto& l = legs[static_cast<std::size_t>(s)];
      out_.push_back(transit(problem.home, l.start));
      back_.push_back(transit(l.end, problem.home));
      out_rev_.push_back(transit(problem.home, l.end));
      back_rev_.push_back(transit(l.start, problem.home));
    }
  }

  int sweeps() const { return static_cast<int>(sweeps_.size()); }

  // Closed-form energy of the sortie flying sweeps a..b (inclusive), in the plan's direction or
  // reversed (from the end of sweep b back to the start of sweep a), whichever transits less.
  double cost(int a, int b, double overhead) const {
    return overhead + scale_ * (prefix_[sweeps_[b] + 1] - prefix_[sweeps_[a]] + std::min(forward(a, b), reversed(a, b)));
  }
  double forward(int a, int b) const { return out_[a].energy_j + back_[b].energy_j; }
  double reversed(int a, int b) const { return out_rev_[b].energy_j + back_rev_[a].energy_j; }

  Sortie build(int a, int b, double overhead) const {
    Sortie s;
    s.first_sweep = a;
    s.last_sweep = b;
    s.estimate_j = cost(a, b, overhead);
    FlownPath& f = s.flown;
    const double alt = problem_.altitude;
    auto addTransit = [&](const Transit& t) {
      for (std::size_t k = 1; k < t.route.size(); ++k) {
        const double len = (t.route[k] - t.route[k - 1]).norm();
        if (len < 1e-6) continue;
        f.path.legs.push_back(transitLeg(t.route[k - 1], t.route[k], alt));
        f.speeds.cruise.push_back(scorer_.legCruise(len, 0.0, 0.0, kInf));
        f.speeds.junction.push_back(0.0);
        f.leg_energy.push_back(scorer_.legEnergy(len, 0.0, 0.0, kInf));
      }
    };
    const bool rev = reversed(a, b) < forward(a, b);
    s.reversed = rev;
    addTransit(rev ? out_rev_[b] : out_[a]);
    int last_origin = -1;
    for (int n = 0; n <= sweeps_[b] - sweeps_[a]; ++n) {
      const int i = rev ? sweeps_[b] - n : sweeps_[a] + n;
      const auto k = static_cast<std::size_t>(i);
      const geo::PathLeg leg = rev ? reverseLeg(plan_.path.legs[k]) : plan_.path.legs[k];
      const double e = k < plan_.leg_energy.size() ? plan_.leg_energy[k] : 0.0;
      if (origin_[k] == last_origin) {  // a piece of the same sweep: one leg again
        f.path.legs.back().end = leg.end;
        f.leg_energy.back() += e;
        continue;
      }
      last_origin = origin_[k];
      f.path.legs.push_back(leg);
      f.speeds.cruise.push_back(plan_.speeds.cruise[k]);
      f.speeds.junction.push_back(n == 0 ? 0.0 : plan_.speeds.junction[rev ? k + 1 : k]);
      f.leg_energy.push_back(e);
    }
    addTransit(rev ? back_rev_[a] : back_[b]);
    f.speeds.junction.push_back(0.0);
    for (std::size_t k = 0; k < f.path.legs.size(); ++k) {
      f.length += f.path.legs[k].length();
      f.energy += f.leg_energy[k];
    }
    return s;
  }

 private:
  Transit transit(const geo::Point& a, const geo::Point& b) const {
    Transit t;
    t.route = router_.route(a, b);
    for (std::size_t k = 1; k < t.route.size(); ++k)
      t.energy_j += scorer_.legEnergy((t.route[k] - t.route[k - 1]).norm(), 0.0, 0.0, kInf);
    return t;
  }

  std::vector<int> origin_;  // per leg of plan_: the plan's leg it is (a piece of); declared before plan_
  const FlownPath plan_;
  const SurveyProblem& problem_;
  RouteScorer& scorer_;
  TransitRouter router_;
  std::vector<int> sweeps_;
  std::vector<double> prefix_;
  std::vector<Transit> out_, back_, out_rev_, back_rev_;
  double scale_ = 1.0;
};

void check(const SortieSettings& s) {
  if (!(s.budget_j > 0.0 && std::isfinite(s.budget_j)))
    throw std::invalid_argument("SortieSettings.budget_j = " + std::to_string(s.budget_j) + ", expected > 0");
  if (!(s.overhead_j >= 0.0 && s.overhead_j < s.budget_j))
    throw std::invalid_argument("SortieSettings.overhead_j = " + std::to_string(s.overhead_j) + ", expected 0 .. budget");
  if (!(s.piece_m >= 5.0 && s.piece_m <= 1e4)) throw std::invalid_argument("SortieSettings.piece_m = " + std::to_string(s.piece_m) + ", expected 5..10000");
  if (!(s.scale > 0.0 && s.scale <= 10.0)) throw std::invalid_argument("SortieSettings.scale = " + std::to_string(s.scale) + ", expected (0, 10]");
  if (s.count < 0 || s.count > 1000) throw std::invalid_argument("SortieSettings.count = " + std::to_string(s.count) + ", expected 0..1000");
}

// Cut points (start sweep of each sortie) of the naive split.
std::vector<int> naiveCuts(const Splitter& sp, const SortieSettings& s) {
  std::vector<int> starts;
  for (int a = 0; a < sp.sweeps();) {
    int b = a;
    while (b + 1 < sp.sweeps() && sp.cost(a, b + 1, s.overhead_j) <= s.budget_j) ++b;
    starts.push_back(a);
    a = b + 1;
  }
  return starts;
}

// Cut points of the fewest sorties and, among those, the least total energy (lexicographic: a
// sortie more costs a battery swap and a landing, worth more than the few kJ it may save):
// best[j] covers pieces 0..j-1.
// Whether the run of pieces a..b may be one sortie: within the budget (closed form), or, for the
// flown split, no longer than the longest run from a that flies.
using RunAllowed = std::function<bool(int a, int b)>;

RunAllowed withinBudget(const Splitter& sp, const SortieSettings& s) {
  return [&sp, &s](int a, int b) { return sp.cost(a, b, s.overhead_j) <= s.budget_j; };
}

std::vector<int> optimalCutsAnyCount(const Splitter& sp, const SortieSettings& s, const RunAllowed& allowed) {
  const int m = sp.sweeps();
  std::vector<std::pair<int, double>> best(m + 1, {std::numeric_limits<int>::max(), kInf});
  std::vector<int> from(m + 1, -1);
  best[0] = {0, 0.0};
  for (int j = 1; j <= m; ++j)
    for (int a = j - 1; a >= 0; --a) {
      if (!allowed(a, j - 1)) break;  // a longer run only costs more (energies are positive)
      const double c = sp.cost(a, j - 1, s.overhead_j);
      if (!std::isfinite(best[a].second)) continue;
      const std::pair<int, double> cand{best[a].first + 1, best[a].second + c};
      if (cand < best[j]) {
        best[j] = cand;
        from[j] = a;
      }
    }
  if (!std::isfinite(best[m].second)) throw std::runtime_error("no split keeps every sortie within " + std::to_string(s.budget_j / 1000.0) + " kJ");
  std::vector<int> starts;
  for (int j = m; j > 0; j = from[j]) starts.insert(starts.begin(), from[j]);
  return starts;
}

// Cut points of the least total energy with exactly s.count sorties.
std::vector<int> optimalCuts(const Splitter& sp, const SortieSettings& s, const RunAllowed& allowed) {
  if (s.count == 0) return optimalCutsAnyCount(sp, s, allowed);
  const int m = sp.sweeps(), kmax = s.count;
  if (kmax > m) throw std::runtime_error(std::to_string(kmax) + " sorties for " + std::to_string(m) + " pieces of sweep: fewer are needed");
  std::vector<std::vector<double>> best(kmax + 1, std::vector<double>(m + 1, kInf));
  std::vector<std::vector<int>> from(kmax + 1, std::vector<int>(m + 1, -1));
  best[0][0] = 0.0;
  for (int k = 1; k <= kmax; ++k)
    for (int j = 1; j <= m; ++j)
      for (int a = j - 1; a >= 0; --a) {
        if (!allowed(a, j - 1)) break;
        const double c = sp.cost(a, j - 1, s.overhead_j);
        if (best[k - 1][a] + c < best[k][j]) {
          best[k][j] = best[k - 1][a] + c;
          from[k][j] = a;
        }
      }
  if (!std::isfinite(best[kmax][m]))
    throw std::runtime_error("no split into " + std::to_string(kmax) + " sorties keeps every sortie within " +
                             std::to_string(s.budget_j / 1000.0) + " kJ");
  std::vector<int> starts;
  for (int k = kmax, j = m; k > 0; j = from[k][j], --k) starts.insert(starts.begin(), from[k][j]);
  return starts;
}

// For first pieces from..to-1, the last piece of the longest run from each that `flies` accepts
// (taking a run to fly when a longer one from the same piece does, so that the longest run from a
// ends no earlier than the one from a - 1), into `last`. From the first piece: the longest run
// within the budget, then longer runs in growing steps while they fly, then the boundary
// bisected; from each next piece, the run one piece past the previous end, extended while it
// flies: about two flights a piece. Throws naming the piece when it does not fly alone.
void longestFlyingRuns(const Splitter& sp, const SortieSettings& s, const SortieCheck& flies, int from, int to,
                       std::vector<int>& last) {
  const int m = sp.sweeps();
  for (int a = from; a < to; ++a) {
    // A run from a that ends within the run from a - 1 is part of a run that flies: it flies.
    const int known = a > from ? last[static_cast<std::size_t>(a - 1)] : a - 1;
    auto fliesRun = [&](int b) { return b <= known || flies(sp.build(a, b, s.overhead_j)); };
    int ok = std::max(a - 1, known), bad = m;  // the longest run known to fly, the shortest known not to
    if (a == from) {
      int guess = a;
      while (guess + 1 < m && sp.cost(a, guess + 1, s.overhead_j) <= s.budget_j) ++guess;
      (fliesRun(guess) ? ok : bad) = guess;
    }
    if (bad == m) {
      for (int step = 1; ok + step < m; step *= 2) {
        if (!fliesRun(ok + step)) {
          bad = ok + step;
          break;
        }
        ok += step;
      }
    }
    while (bad - ok > 1) {
      const int mid = ok + (bad - ok) / 2;
      (fliesRun(mid) ? ok : bad) = mid;
    }
    if (ok < a) {
      throw std::runtime_error("sweep piece " + std::to_string(a + 1) + " alone, with its transits from and to home, does "
                               "not land with the reserve when flown");
    }
    last[static_cast<std::size_t>(a)] = ok;
  }
}

// longestFlyingRuns over all first pieces, the second half on a thread of its own (the flights
// dominate; `flies` is called from both).
std::vector<int> longestFlyingRuns(const Splitter& sp, const SortieSettings& s, const SortieCheck& flies) {
  const int m = sp.sweeps();
  std::vector<int> last(static_cast<std::size_t>(m));
  if (m < 16) {
    longestFlyingRuns(sp, s, flies, 0, m, last);
    return last;
  }
  auto second = std::async(std::launch::async, [&] { longestFlyingRuns(sp, s, flies, m / 2, m, last); });
  try {
    longestFlyingRuns(sp, s, flies, 0, m / 2, last);
  } catch (...) {
    second.wait();
    throw;
  }
  second.get();
  return last;
}

// The sorties starting at `starts`.
SortieSplit assemble(const Splitter& sp, const std::vector<int>& starts, const SortieSettings& s) {
  SortieSplit out;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const int b = k + 1 < starts.size() ? starts[k + 1] - 1 : sp.sweeps() - 1;
    out.sorties.push_back(sp.build(starts[k], b, s.overhead_j));
    out.estimate_j += out.sorties.back().estimate_j;
  }
  return out;
}

}  // namespace

SortieSplit splitIntoSorties(const FlownPath& plan, const SurveyProblem& problem, RouteScorer& scorer, const SortieSettings& s) {
  check(s);
  const Splitter sp(plan, problem, scorer, s.scale, s.piece_m, s.piece_weight);
  for (int a = 0; a < sp.sweeps(); ++a)
    if (sp.cost(a, a, s.overhead_j) > s.budget_j)
      throw std::runtime_error("sweep " + std::to_string(a + 1) + " alone, with its transits from and to home, needs " +
                               std::to_string(sp.cost(a, a, s.overhead_j) / 1000.0) + " kJ, more than the " +
                               std::to_string(s.budget_j / 1000.0) + " kJ one sortie may use");
  return assemble(sp, s.naive ? naiveCuts(sp, s) : optimalCuts(sp, s, withinBudget(sp, s)), s);
}

SortieSplit splitIntoFlownSorties(const FlownPath& plan, const SurveyProblem& problem, RouteScorer& scorer, const SortieSettings& s,
                                  const SortieCheck& flies) {
  SortieSettings plain = s;
  plain.piece_weight.clear();
  check(plain);
  const Splitter sp(plan, problem, scorer, plain.scale, plain.piece_m, {});
  const std::vector<int> longest = longestFlyingRuns(sp, plain, flies);
  const RunAllowed allowed = [&longest](int a, int b) { return b <= longest[static_cast<std::size_t>(a)]; };
  return assemble(sp, optimalCuts(sp, plain, allowed), plain);
}

}  // namespace wattswath::planner
