#include "ellipsoids/AutoDistance.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace ellipsoids {

// The measured table (docs/benchmarks.md, "Fastest certified method per Ar and
// eps_d"): on random packings with Ar in {1/6,1/3,2/3,3/2,3,6}, alpha_p 0.05-0.25
// and eps_d/R_eq in 1e-3..1e-8, the dual method had the smallest median time in
// all 36 (Ar, eps_d) cells, 3-60x ahead of GJK and Moving Balls
// (applications/benchmarks/distanceBenchmark/runBenchmarks regenerates it).
std::vector<AutoDistance::Rule> AutoDistance::defaultTable() {
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  return {{inf, inf, "dual"}};
}

std::vector<AutoDistance::Rule> AutoDistance::paperTable() {
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  // elongation < 3 <=> 1/3 < Ar < 3 for spheroids
  return {{3 * (1 - 1e-12), inf, "movingBalls"}, {inf, inf, "gjk"}};
}

namespace {
const std::vector<std::string> kAutoFallback = {"dual", "gjk", "movingBalls"};
const std::vector<std::string> kPaperFallback = {"gjk", "movingBalls"};

/// The methods of a table row or fallback chain: any single method, not auto or paper.
std::unique_ptr<DistanceMethod> makeMember(const std::string& method, const char* where) {
  if (method == "auto" || method == "paper") {
    throw std::invalid_argument(std::string("AutoDistance: ") + where + " cannot name '" + method + "'");
  }
  return makeDistanceMethod(method);  // throws on unknown names
}
}  // namespace

AutoDistance::AutoDistance() : AutoDistance(defaultTable()) {}

AutoDistance::AutoDistance(const std::vector<Rule>& table) : AutoDistance(table, "auto", kAutoFallback) {}

AutoDistance::AutoDistance(const std::vector<Rule>& table, const std::string& name,
                           const std::vector<std::string>& fallback)
    : name_(name), table_(table) {
  if (table_.empty()) {
    throw std::invalid_argument("AutoDistance: the method table is empty");
  }
  for (const Rule& r : table_) tableMethods_.push_back(makeMember(r.method, "a table row"));
  for (const std::string& m : fallback) fallback_.push_back(makeMember(m, "the fallback chain"));
}

std::unique_ptr<AutoDistance> AutoDistance::paper() {
  return std::make_unique<AutoDistance>(paperTable(), "paper", kPaperFallback);
}

const DistanceMethod& AutoDistance::choose(const Ellipsoid& e1, const Ellipsoid& e2,
                                           Scalar epsD) const {
  const Scalar elongation = std::max(e1.elongation(), e2.elongation());
  const Scalar relEps = epsD / std::min(e1.equivalentRadius(), e2.equivalentRadius());
  for (std::size_t i = 0; i < table_.size(); ++i) {
    if (elongation <= table_[i].maxElongation && relEps <= table_[i].maxRelativeEps) {
      return *tableMethods_[i];
    }
  }
  return *tableMethods_.back();
}

DistanceResult AutoDistance::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                      const DistanceOptions& options) const {
  options.validate();
  DistanceOptions certified = options;
  certified.stopRule = StopRule::certified;

  auto acceptable = [&](const DistanceResult& r) {
    return r.status == DistanceStatus::overlapping ||
           (r.status == DistanceStatus::converged && r.bracketWidth() <= options.epsD);
  };
  // a signed answer (dual) made unsigned; upper stays: 0 only for a certain overlap
  auto unsign = [](DistanceResult r) {
    if (r.status == DistanceStatus::overlapping) {
      r.distance = 0;
      r.lower = 0;
      r.upper = std::max(r.upper, Scalar(0));
    }
    return r;
  };

  const DistanceMethod& first = choose(e1, e2, options.epsD);
  DistanceResult best = first.distance(e1, e2, certified);
  if (acceptable(best)) {
    return unsign(best);
  }
  int iterations = best.iterations;
  for (const auto& m : fallback_) {
    if (m->name() == first.name()) continue;
    DistanceResult r = m->distance(e1, e2, certified);
    iterations += r.iterations;
    if (acceptable(r)) {
      r.iterations = iterations;
      return unsign(r);
    }
    if (r.bracketWidth() < best.bracketWidth()) best = r;
  }
  best.iterations = iterations;
  // no method certified within epsD: the tightest bracket, not a converged answer
  if (best.status == DistanceStatus::converged) best.status = DistanceStatus::failed;
  return unsign(best);
}

}  // namespace ellipsoids
