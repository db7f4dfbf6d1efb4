#pragma once
// Internal to planner/src: flying a candidate and checking that it keeps coverage, and which of
// two candidates is the better plan.
#include <string>
#include <vector>

#include "search_context.hpp"

namespace wattswath::planner::detail {

constexpr double kMinCoveragePct = 99.0;  // [%] coverage a plan must keep (issue 5: >= 99 %)

/// The area minus its holes and no-fly zones (subtracted with CGAL as `plan` does; a zone partly
/// outside is clipped): what the coverage must reach.
std::vector<geometry::PolygonWithHoles> freeRegions(const SurveyProblem& pr);

/// Coverage of `path` over `regions` [%], exact, by geometry's own checker: the swaths (a square
/// footprint `footprint` [m] wide along every sweep line and arc) united with CGAL Boolean operations.
double coverageOf(const std::vector<geometry::PolygonWithHoles>& regions, double footprint,
                  const geometry::CoveragePath& path);

/// Flies the route of `a` with its widest arcs; coverage_pct is NaN until verify() has run.
PlanCandidate flyUnverified(RouteScorer& scorer, const AngleResult& a, const std::string& pattern);

/// Checks the coverage of `c` (flown from `a` by flyUnverified) over `free`. Rounded corners must
/// keep it: when the arcs leave more than kMinCoveragePct uncovered, the same route is flown with
/// the arcs allowed to cut in less (halving), down to stops everywhere.
void verify(const std::vector<geometry::PolygonWithHoles>& free, double footprint, RouteScorer& scorer,
            const AngleResult& a, PlanCandidate& c);

/// flyUnverified() then verify(), unless the flown path's swaths are those of a candidate in
/// `checked` (verified over the same `free`) that keeps kMinCoveragePct: then its coverage is taken,
/// the number verify() would compute, without a second exact check.
PlanCandidate finish(const std::vector<geometry::PolygonWithHoles>& free, double footprint, RouteScorer& scorer,
                     const AngleResult& a, const std::string& pattern, const std::vector<const PlanCandidate*>& checked = {});

/// Whether candidate `c` should replace `plan`: keeping coverage (>= kMinCoveragePct) first, then
/// less energy; between candidates that both miss it, more coverage first.
bool better(const PlanCandidate& c, const PlanCandidate& plan);

}  // namespace wattswath::planner::detail
