// Microbenchmarks of the geometry core (Google Benchmark): support mapping,
// overlap test, one distance query per method, on equal-volume spheroid
// pairs with gaps up to 0.1 R_eq (the near pairs of a packing).
//   geometryMicrobenchmarks [--benchmark_filter=...]
#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

using namespace ellipsoids;

namespace {

struct Pair {
  Ellipsoid e1, e2;
};

Quat randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<Scalar> g;
  Quat q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q;
}

/// 256 separated pairs of equal-volume spheroids (D_eq = 1) of aspect ratio ar.
const std::vector<Pair>& pairs(double ar) {
  static std::vector<std::pair<double, std::vector<Pair>>> cache;
  for (const auto& c : cache) {
    if (c.first == ar) return c.second;
  }
  std::mt19937_64 rng(42);
  std::normal_distribution<Scalar> g;
  std::uniform_real_distribution<Scalar> gap(0, 0.05);
  std::vector<Pair> ps;
  while (ps.size() < 256) {
    const Ellipsoid e1 = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), randomRotation(rng));
    const Ellipsoid shape = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), randomRotation(rng));
    const Vec3 n = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 c2 = e1.support(n) + shape.support(n) + gap(rng) * n;
    ps.push_back({e1, Ellipsoid(shape.semiAxes(), c2, shape.orientation())});
  }
  cache.emplace_back(ar, ps);
  return cache.back().second;
}

void supportMapping(benchmark::State& state) {
  const auto& ps = pairs(3);
  std::size_t k = 0;
  Vec3 n(0.3, -0.5, 0.8);
  for (auto _ : state) {
    benchmark::DoNotOptimize(ps[k++ & 255].e1.support(n));
  }
}
BENCHMARK(supportMapping);

void overlapTest(benchmark::State& state) {
  const auto& ps = pairs(3);
  const JiaOverlapTest jia;
  std::size_t k = 0;
  for (auto _ : state) {
    const Pair& p = ps[k++ & 255];
    benchmark::DoNotOptimize(jia.test(p.e1, p.e2));
  }
}
BENCHMARK(overlapTest);

void distanceQuery(benchmark::State& state, const std::string& name, double ar) {
  const auto& ps = pairs(ar);
  const auto m = makeDistanceMethod(name);
  DistanceOptions o;
  o.epsD = 1e-5 * 0.5;  // 1e-5 R_eq
  o.stopRule = StopRule::certified;
  std::size_t k = 0;
  for (auto _ : state) {
    const Pair& p = ps[k++ & 255];
    benchmark::DoNotOptimize(m->distance(p.e1, p.e2, o).distance);
  }
}

/// The dual method's batch API over the same 256 pairs: time per query.
void dualBatch(benchmark::State& state, double ar) {
  const auto& ps = pairs(ar);
  std::vector<DistancePair> batch;
  for (const Pair& p : ps) batch.push_back({&p.e1, &p.e2, nullptr});
  std::vector<DistanceResult> results(batch.size());
  const DualNewton dual;
  DistanceOptions o;
  o.epsD = 1e-5 * 0.5;
  for (auto _ : state) {
    dual.distances(batch.data(), batch.size(), o, results.data());
    benchmark::DoNotOptimize(results.data());
  }
  state.SetItemsProcessed(state.iterations() * long(batch.size()));
  state.counters["ns_per_query"] = benchmark::Counter(double(state.iterations()) * double(batch.size()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(dualBatch, Ar3, 3.0);
BENCHMARK_CAPTURE(dualBatch, Ar1over6, 1.0 / 6);
BENCHMARK_CAPTURE(distanceQuery, dual_Ar3, std::string("dual"), 3.0);
BENCHMARK_CAPTURE(distanceQuery, gjk_Ar3, std::string("gjk"), 3.0);
BENCHMARK_CAPTURE(distanceQuery, movingBalls_Ar3, std::string("movingBalls"), 3.0);
BENCHMARK_CAPTURE(distanceQuery, auto_Ar3, std::string("auto"), 3.0);
BENCHMARK_CAPTURE(distanceQuery, newtonCoulomb_Ar3, std::string("newtonCoulomb"), 3.0);
BENCHMARK_CAPTURE(distanceQuery, dual_Ar1over6, std::string("dual"), 1.0 / 6);
BENCHMARK_CAPTURE(distanceQuery, gjk_Ar1over6, std::string("gjk"), 1.0 / 6);
BENCHMARK_CAPTURE(distanceQuery, movingBalls_Ar1over6, std::string("movingBalls"), 1.0 / 6);

BENCHMARK_MAIN();
