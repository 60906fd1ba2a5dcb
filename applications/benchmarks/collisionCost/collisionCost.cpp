/**
 * collisionCost: the cost of one collision evaluation (collision::CollisionModel::forces,
 * one call per body sub-step) for 1000 equal-volume spheroids at volume fraction 0.25,
 * cold and warm start, against a naive peer measured in the same run.
 *
 *   collisionCost --table out.csv [--quick] [--repetitions N] [--seed N]   CSV of docs/collisionCost.md
 *   collisionCost [--benchmark_filter=...] [other --benchmark_* flags]      Google Benchmark
 *   collisionCost --help
 *
 * Scene (per aspect ratio Ar in {1/6, 1/3, 1, 3, 6}): N = 1000 spheroids, D_eq = 1,
 * a = Ar^(2/3)/2, b = c = Ar^(-1/3)/2, placed by random sequential addition (src/packing,
 * seeded) in a cube of side l = (N pi/(6 phi))^(1/3) = 12.79 at phi = 0.25. The collision model
 * has no periodic images: the bodies are used as placed in [0, L)^3 (pairs across the faces of
 * the box are not seen). Density 1 (mass = pi/6), velocity of magnitude 1 and angular velocity
 * of magnitude 1 rad/s in random directions (they only enter the contact and lubrication
 * forces, not the cost of finding them).
 *
 * Motion between calls: a chain of S states, each obtained from the previous one by moving
 * every body by 1e-3 D_eq in a random direction and rotating it by 1e-3 rad about a random
 * axis. Calls walk the chain back and forth (0, 1, ..., S-1, S-2, ..., 0, 1, ...), so every
 * call sees the bodies one such small step away from the previous call, and the scene
 * does not drift away from the packing however many calls are timed.
 *
 * Timed per round (interleaved, so that the load of the shared machine hits all alike; the
 * thread's CPU time around each call, its wall time beside it; medians over the rounds):
 *   warm        CollisionModel::forces with the history of the previous call (previous state);
 *   damping     CollisionModel::dampingForces on the pairs the warm call recorded (the implicit
 *               lubrication solve of a sub-step, the bodies' velocities as end velocities;
 *               lubricationContact; no film pairs: the scene has no mesh);
 *   cold        the same on another model, clearHistory() just before the call (timed apart);
 *   stages      steps 1-3 of forces() replicated one after the other (StagedReplica), each timed
 *               on its own: setup (bounding spheres, grown bodies), PairSearch::find, the Jia
 *               prefilter, the dual distances of the pairs kept, cold and warm-started; the rest
 *               of a call (forces, history bookkeeping) is the call minus these stages;
 *   naive       the peer: all N(N-1)/2 pairs tested with the same bounding spheres, then
 *               ellipsoids::DualNewton (cold, same accuracy) for every overlapping pair, no
 *               prefilter and no forces (only the distances); its two phases timed apart;
 *   paper       CollisionModel::forces with distanceMethod paper (the founding paper's
 *               choice: Moving Balls for 1/3 < Ar < 3, GJK otherwise, certified stop;
 *               overlaps from the dual), warm and cold as above, on its own two models;
 *   film A/B    two more warm models called back to back, in alternating order from round
 *               to round (the first call of a pair pays for the caches the other left): one
 *               as `warm`, one whose lubrication has its tangential terms off (the film's
 *               tangential law and, for pairs that are not two spheres, the coupling of
 *               normal and tangential motion from the gap's cubic terms). Their ratio is what
 *               the tangential terms cost (lubricationContact; 1 up to noise in contact mode).
 * The replicas are checked against the model's own statistics (same candidate pairs, same
 * prefilter rejections, same distance queries) on every round: a mismatch stops the run with
 * a message.
 *
 * Google Benchmark mode: cold/, warm/, naive/ and pairSearch/ (bounding spheres + PairSearch)
 * per mode and Ar, and warmNormalFilm/ (lubricationContact without the film's tangential
 * terms), on the same scenes (seed 1, 32 states), each call on the next state.
 */
#include "collision/CollisionModel.hpp"
#include "collision/PairSearch.hpp"
#include "collision/RigidBody.hpp"
#include "ellipsoids/DualNewton.hpp"
#include "ellipsoids/OverlapTest.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include <benchmark/benchmark.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace {

using collision::CollisionBody;
using collision::CollisionModel;
using collision::CollisionSettings;
using collision::Scalar;
using collision::Vec3;
using collision::Quat;
using collision::kPi;

constexpr int kBodies = 1000;
constexpr double kVolumeFraction = 0.25;
constexpr double kStep = 1e-3;       ///< displacement per call (D_eq) and rotation (rad)
constexpr double kViscosity = 1e-3;  ///< lubricationContact
constexpr double kContactTime = 1e-2, kSubDt = 1e-3;

/// CPU time of this thread (s): what a call costs, without the time the shared machine's
/// other jobs take while this one is preempted (wall time is reported beside it)
double cpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

const char* kUsage = R"(Usage:
  collisionCost --table FILE.csv [--quick] [--repetitions N] [--seed N]
  collisionCost [--benchmark_* flags of Google Benchmark]
  collisionCost --help

Cost of one collision evaluation (CollisionModel::forces: pair search, Jia
prefilter, signed distances, contact and lubrication forces) for 1000
equal-volume spheroids (D_eq = 1) at volume fraction 0.25, Ar in
{1/6, 1/3, 1, 3, 6}, modes contact and lubricationContact (viscosity 1e-3),
cold (history cleared before each call) and warm (bodies moved by 1e-3 D_eq
and rotated by 1e-3 rad since the previous call), against a naive peer (all
pairs with bounding spheres, then a cold dual-Newton distance for every
overlapping pair) measured in the same run, and the same calls with
distanceMethod paper (the founding paper's Moving Balls / GJK choice) in the
same rounds. See docs/collisionCost.md.

Table mode:
  --table FILE     write one CSV row per (Ar, mode) with the medians, ratios,
                   statistics, machine and date (progress on stderr)
  --quick          few repetitions (checks that it all runs; < 20 s)
  --repetitions N  timed rounds per (Ar, mode), >= 3 (default 201, quick 5)
  --seed N         seed of the packings and of the motion, 0 .. 2^64-1 (default 1)
Without --table the Google Benchmark microbenchmarks run (--benchmark_filter=
REGEX selects them, e.g. --benchmark_filter='warm/contact'; --benchmark_list_tests).
Exit status: 0 done; 1 a run failed; 2 bad arguments.
)";

[[noreturn]] void usageError(const std::string& message) {
  std::cerr << "collisionCost: " << message << "\n(collisionCost --help for the usage)\n";
  std::exit(2);
}

// ---------------------------------------------------------------------------------------------
// scene

struct Case {
  const char* name;  ///< "1/6"
  double ar;
};
const std::vector<Case> kCases = {{"1/6", 1.0 / 6}, {"1/3", 1.0 / 3}, {"1", 1.0}, {"3", 3.0}, {"6", 6.0}};
/// the configurations measured, by the OpenFOAM collision type they stand for
enum class CollisionMode { contact, lubricationContact };
const char* toString(CollisionMode mode) {
  return mode == CollisionMode::contact ? "contact" : "lubricationContact";
}
const std::vector<CollisionMode> kModes = {CollisionMode::contact, CollisionMode::lubricationContact};

/// uniform unit vector from two uniform draws (Archimedes: z uniform in [-1, 1])
Vec3 unitVector(std::mt19937_64& rng) {
  const double z = 2 * packing::random::uniform01(rng) - 1;
  const double phi = 2 * kPi * packing::random::uniform01(rng);
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  return Vec3(s * std::cos(phi), s * std::sin(phi), z);
}

struct Scene {
  Case c;
  double boxLength = 0;
  std::vector<std::vector<CollisionBody>> states;  ///< the chain of states walked back and forth
  std::size_t next = 0;                            ///< calls made (position on the walk)

  /// the state of call number t: 0, 1, ..., S-1, S-2, ..., 1, 0, 1, ...
  const std::vector<CollisionBody>& state(std::size_t t) const {
    const std::size_t s = states.size();
    if (s == 1) return states[0];
    const std::size_t period = 2 * (s - 1), r = t % period;
    return states[r < s ? r : period - r];
  }
  const std::vector<CollisionBody>& advance() { return state(next++); }
};

std::unique_ptr<Scene> makeScene(const Case& c, std::uint64_t seed, int stateCount) {
  packing::RsaOptions o;
  o.aspectRatio = c.ar;
  o.volumeFraction = kVolumeFraction;
  o.seed = seed;
  o.equivalentDiameter = 1;
  o.boxLengthRelative = std::cbrt(kBodies * kPi / (6 * kVolumeFraction));
  if (packing::rsaBodyCount(o) != std::size_t(kBodies)) {
    throw std::logic_error("box length gives " + std::to_string(packing::rsaBodyCount(o)) +
                           " bodies instead of " + std::to_string(kBodies));
  }
  const packing::Packing p = packing::randomSequentialAddition(o);
  auto scene = std::make_unique<Scene>();
  scene->c = c;
  scene->boxLength = p.boxLength;

  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::vector<collision::RigidBody> bodies;
  for (const ellipsoids::Ellipsoid& e : p.bodies) {
    collision::RigidBody b;
    b.semiAxes = e.semiAxes();
    b.centre = e.centre();
    b.orientation = e.orientation();
    b.density = 1;
    b.velocity = unitVector(rng);
    b.angularVelocity = unitVector(rng);
    bodies.push_back(b);
  }
  for (int s = 0; s < stateCount; ++s) {
    if (s > 0) {
      for (collision::RigidBody& b : bodies) {
        b.centre += kStep * unitVector(rng);
        b.orientation = (Quat(Eigen::AngleAxis<Scalar>(kStep, unitVector(rng))) * b.orientation).normalized();
      }
    }
    std::vector<CollisionBody> state;
    state.reserve(bodies.size());
    for (const collision::RigidBody& b : bodies) state.push_back(b.collisionBody());
    scene->states.push_back(std::move(state));
  }
  return scene;
}

/// The settings of one measured configuration: the numerical settings, the laws'
/// parameters, and the pair and wall model (springDashpot or lubricatedSpringDashpot).
struct Settings : CollisionSettings {
  CollisionMode mode = CollisionMode::contact;
  collision::InteractionParameters laws;
  Scalar viscosity = 0;
};

Settings settingsFor(CollisionMode mode) {
  Settings s;
  s.mode = mode;
  s.viscosity = mode == CollisionMode::lubricationContact ? kViscosity : 0;
  s.laws.viscosity = s.viscosity;
  return s;
}

/// The model of a configuration (lubricationContact: with the film correction, as the
/// OpenFOAM type of that name by default; the bodies here have no film gap).
CollisionModel modelFor(const Settings& s) {
  const std::string name =
      s.mode == CollisionMode::lubricationContact ? "lubricatedSpringDashpot" : "springDashpot";
  return CollisionModel(s, collision::PairModel::New(name, s.laws),
                        collision::WallModel::New(name, s.laws), {},
                        s.viscosity > 0 ? std::make_unique<collision::FilmCorrection>(s.viscosity)
                                        : nullptr);
}

// ---------------------------------------------------------------------------------------------
// the measured operations besides forces(): replicas of the model's first steps, and the peer

/// The model's bounding spheres (CollisionModel::forces, step 1) and its grown bodies (step 2).
struct Spheres {
  std::vector<Vec3> centres;
  std::vector<Scalar> radii;
  std::vector<ellipsoids::Ellipsoid> grown;
  std::vector<Vec3> halfExtent;  ///< axis-aligned half extents of the grown bodies

  void compute(const std::vector<CollisionBody>& bodies, const Settings& settings,
               bool withGrown) {
    const std::size_t n = bodies.size();
    const bool lubrication = settings.mode == CollisionMode::lubricationContact;
    centres.resize(n);
    radii.resize(n);
    if (withGrown) {
      grown.clear();
      halfExtent.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const ellipsoids::Ellipsoid& e = bodies[i].shape;
      const Scalar reach =
          lubrication ? 0.5 * settings.laws.lubrication.pairActivation * e.maxOfMaxCurvatureRadius() : 0;
      centres[i] = e.centre();
      radii[i] = e.maxSemiAxis() + reach;
      if (withGrown) {
        grown.push_back(reach > 0 ? ellipsoids::Ellipsoid(e.semiAxes() * (1 + reach / e.minSemiAxis()),
                                                          e.centre(), e.orientation())
                                  : e);
        halfExtent[i] = grown.back().shapeMatrix().diagonal().cwiseSqrt();
      }
    }
  }
};

Scalar epsD(const Settings& s, const ellipsoids::Ellipsoid& e1, const ellipsoids::Ellipsoid& e2) {
  return s.distanceAccuracy * std::min(e1.minGaussianRadius(), e2.minGaussianRadius());
}

struct PeerStatistics {
  long pairsTested = 0, sphereOverlaps = 0, queries = 0, iterations = 0, notConverged = 0;
  double spheresSeconds = 0, distancesSeconds = 0;  ///< the two phases of the last call
};

/**
 * The naive peer: every pair i < j tested against the bounding spheres (the overlapping
 * pairs listed), then a cold dual distance for each overlapping pair (no prefilter). The two
 * phases are timed on their own (into st); returns a checksum.
 */
Scalar naiveDistances(const std::vector<CollisionBody>& bodies, const Settings& settings,
                      Spheres& sp, const ellipsoids::DualNewton& dual,
                      std::vector<std::pair<int, int>>& overlapping, PeerStatistics& st) {
  const double t0 = cpuNow();
  sp.compute(bodies, settings, false);
  const int n = static_cast<int>(bodies.size());
  overlapping.clear();
  for (int i = 0; i < n; ++i) {
    const Vec3 ci = sp.centres[i];
    const Scalar ri = sp.radii[i];
    for (int j = i + 1; j < n; ++j) {
      const Scalar reach = ri + sp.radii[j];
      if ((ci - sp.centres[j]).squaredNorm() <= reach * reach) overlapping.emplace_back(i, j);
    }
  }
  const double t1 = cpuNow();
  Scalar sum = 0;
  for (const auto& [i, j] : overlapping) {
    ellipsoids::DistanceOptions o;
    o.epsD = epsD(settings, bodies[i].shape, bodies[j].shape);
    const ellipsoids::DistanceResult r = dual.distance(bodies[i].shape, bodies[j].shape, o);
    st.iterations += r.iterations;
    if (r.status == ellipsoids::DistanceStatus::maxIterations ||
        r.status == ellipsoids::DistanceStatus::failed) {
      ++st.notConverged;
    }
    sum += r.distance;
  }
  const double t2 = cpuNow();
  st.pairsTested += long(n) * (n - 1) / 2;
  st.sphereOverlaps += static_cast<long>(overlapping.size());
  st.queries += static_cast<long>(overlapping.size());
  st.spheresSeconds = t1 - t0;
  st.distancesSeconds = t2 - t1;
  return sum;
}

/// Step 1 of forces(): bounding spheres and pair search; the candidate pairs.
long searchOnly(const std::vector<CollisionBody>& bodies, const Settings& settings,
                Spheres& sp, collision::PairSearch& search) {
  sp.compute(bodies, settings, false);
  return static_cast<long>(search.find(sp.centres, sp.radii).size());
}

/**
 * Steps 1-3 of forces() one after the other, each timed on its own: bounding spheres and
 * grown bodies (setup), PairSearch::find (search), the Jia test on the grown bodies of every
 * candidate pair (prefilter), the dual distance of every pair kept, cold and then warm-started
 * from this replica's answers of the previous call (as the model does). No forces.
 */
struct StagedReplica {
  Spheres sp;
  collision::PairSearch search;
  ellipsoids::JiaOverlapTest jia;
  ellipsoids::DualNewton dual;
  std::vector<std::pair<int, int>> kept, previous;
  std::vector<Vec3> directions, previousDirections;
  std::vector<const Vec3*> initial;

  struct Result {
    double setup = 0, search = 0, prefilter = 0, distancesCold = 0, distancesWarm = 0;  // s
    long candidates = 0, rejected = 0, queries = 0, coldIterations = 0, warmIterations = 0;
  };

  Result run(const std::vector<CollisionBody>& bodies, const Settings& settings) {
    Result r;
    const double t0 = cpuNow();
    sp.compute(bodies, settings, true);
    const double t1 = cpuNow();
    const auto& pairs = search.find(sp.centres, sp.radii);
    const double t2 = cpuNow();
    kept.clear();
    for (const collision::CandidatePair& pair : pairs) {
      const int i = pair.first, j = pair.second;  // (no periodic axes here: no image shift)
      if (!bodies[i].movable && !bodies[j].movable) continue;
      const bool boxesApart =
          ((sp.centres[i] - sp.centres[j]).cwiseAbs() - sp.halfExtent[i] - sp.halfExtent[j])
              .maxCoeff() > 0;
      if (boxesApart ||
          jia.test(sp.grown[i], sp.grown[j]) == ellipsoids::OverlapStatus::separated) {
        ++r.rejected;
      } else {
        kept.emplace_back(i, j);
      }
    }
    const double t3 = cpuNow();
    Scalar sum = 0;
    for (const auto& [i, j] : kept) {
      ellipsoids::DistanceOptions o;
      o.epsD = epsD(settings, bodies[i].shape, bodies[j].shape);
      const ellipsoids::DistanceResult d = dual.distance(bodies[i].shape, bodies[j].shape, o);
      r.coldIterations += d.iterations;
      sum += d.distance;
    }
    const double t4 = cpuNow();
    // warm starts of the pairs also kept last call (the search does not sort
    // its pairs: sort them here, not timed, so that the merge finds them)
    std::sort(kept.begin(), kept.end());
    initial.assign(kept.size(), nullptr);
    for (std::size_t k = 0, m = 0; k < kept.size(); ++k) {
      while (m < previous.size() && previous[m] < kept[k]) ++m;
      if (m < previous.size() && previous[m] == kept[k]) initial[k] = &previousDirections[m];
    }
    directions.resize(kept.size());
    const double t5 = cpuNow();
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const auto [i, j] = kept[k];
      ellipsoids::DistanceOptions o;
      o.epsD = epsD(settings, bodies[i].shape, bodies[j].shape);
      if (initial[k]) {
        o.useInitialDirection = true;
        o.initialDirection = *initial[k];
      }
      const ellipsoids::DistanceResult d = dual.distance(bodies[i].shape, bodies[j].shape, o);
      r.warmIterations += d.iterations;
      directions[k] = d.direction;
      sum += d.distance;
    }
    const double t6 = cpuNow();
    previous.swap(kept);
    previousDirections.swap(directions);
    sink_ = sink_ + sum;
    const auto sec = [](double a, double b) { return b - a; };
    r.setup = sec(t0, t1);
    r.search = sec(t1, t2);
    r.prefilter = sec(t2, t3);
    r.distancesCold = sec(t3, t4);
    r.distancesWarm = sec(t5, t6);
    r.candidates = static_cast<long>(pairs.size());
    r.queries = static_cast<long>(previous.size());
    return r;
  }

 private:
  volatile Scalar sink_ = 0;
};

// ---------------------------------------------------------------------------------------------
// table mode

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// the q-quantile (linear interpolation) of the values
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double x = q * double(v.size() - 1);
  const std::size_t k = static_cast<std::size_t>(x);
  if (k + 1 >= v.size()) return v.back();
  return v[k] + (x - double(k)) * (v[k + 1] - v[k]);
}

std::string cpuModel() {
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      std::string m = line.substr(line.find(':') + 1);
      m.erase(0, m.find_first_not_of(" \t"));
      return m;
    }
  }
  return "unknown";
}

int processorCount() {  // what nproc prints: the CPUs this process may run on
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return CPU_COUNT(&set);
  return static_cast<int>(std::thread::hardware_concurrency());
}

/// the 1-minute load average (other jobs on the machine), -1 if unknown
double loadAverage() {
  std::ifstream f("/proc/loadavg");
  double load = -1;
  if (!(f >> load)) return -1;
  return load;
}

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string csvText(std::string s) {
  for (char& ch : s) {
    if (ch == '"') ch = '\'';
  }
  return s.find_first_of(",'\n") == std::string::npos ? s : "\"" + s + "\"";
}

struct TableOptions {
  std::string out;
  bool quick = false;
  int repetitions = 0;  ///< 0: default
  std::uint64_t seed = 1;
};

/// Seconds per call, one entry per timed round.
struct Timings {
  std::vector<double> warm, cold, naive, warmWall, coldWall, naiveWall, clearHistory;
  std::vector<double> setup, search, prefilter, distancesCold, distancesWarm, restCold, restWarm;
  std::vector<double> spheres, naiveDistances, perQueryCold, perQueryWarm, perQueryNaive;
  std::vector<double> damping;  ///< dampingForces after the warm call (lubricationContact)
  std::vector<double> paperWarm, paperCold;  ///< forces() with distanceMethod paper
  std::vector<double> fullFilmWarm;    ///< warm forces(), the A/B pair's model as `warm`
  std::vector<double> normalFilmWarm;  ///< warm forces() without the film's tangential terms
};

/// Sums over the timed rounds.
struct Counts {
  long candidates = 0, rejected = 0, boxRejected = 0, queries = 0, coldIterations = 0, warmIterations = 0,
       coldNotConverged = 0, warmNotConverged = 0, contacts = 0, lubricated = 0, damped = 0,
       dampingSweeps = 0;
  long paperQueries = 0, paperColdIterations = 0, paperWarmIterations = 0, paperNotConverged = 0;
  PeerStatistics peer;
};

const char* kColumns =
    "machine,nproc,date,compiler,quick,seed,bodies,volumeFraction,boxLength,aspectRatio,mode,"
    "viscosity,rounds,states,"
    "coldUs,coldQ1Us,coldQ3Us,warmUs,warmQ1Us,warmQ3Us,naiveUs,naiveQ1Us,naiveQ3Us,"
    "coldWallUs,warmWallUs,naiveWallUs,clearHistoryUs,loadAverage,"
    "setupUs,searchUs,prefilterUs,distancesColdUs,distancesWarmUs,restColdUs,restWarmUs,"
    "naiveSpheresUs,naiveDistancesUs,"
    "naiveOverCold,naiveOverWarm,coldOverWarm,naiveOverPipelineCold,naiveOverPipelineWarm,"
    "coldUsPerQuery,warmUsPerQuery,naiveUsPerQuery,"
    "candidatePairs,prefilterRejected,boxRejected,distanceQueries,coldMeanIterations,warmMeanIterations,"
    "coldNotConverged,warmNotConverged,contacts,lubricated,dampingUs,dampedPairs,dampingSweeps,"
    "naivePairsTested,naiveSphereOverlaps,naiveQueries,naiveMeanIterations,naiveNotConverged,"
    "paperColdUs,paperColdQ1Us,paperColdQ3Us,paperWarmUs,paperWarmQ1Us,paperWarmQ3Us,"
    "paperOverDualCold,paperOverDualWarm,paperQueries,paperColdMeanIterations,paperWarmMeanIterations,"
    "paperNotConverged,fullFilmWarmUs,normalFilmWarmUs,fullFilmOverNormalFilm\n";

/// One (Ar, mode): warm-up rounds, then the timed rounds, interleaved.
void measure(Scene& scene, CollisionMode mode, int warmupRounds, int rounds, Timings& tm, Counts& n) {
  using clock = std::chrono::steady_clock;
  const Settings settings = settingsFor(mode);
  CollisionModel warmModel = modelFor(settings), coldModel = modelFor(settings);
  Settings paperSettings = settings;
  paperSettings.distanceMethod = "paper";
  CollisionModel paperWarmModel = modelFor(paperSettings), paperColdModel = modelFor(paperSettings);
  Settings normalFilmSettings = settings;
  normalFilmSettings.laws.lubrication.tangential = false;
  CollisionModel fullFilmModel = modelFor(settings), normalFilmModel = modelFor(normalFilmSettings);
  StagedReplica replica;
  const ellipsoids::DualNewton dual;
  Spheres sp;
  std::vector<std::pair<int, int>> overlapping;
  std::vector<Vec3> force, torque, endVelocity, endAngularVelocity;
  volatile Scalar sink = 0;
  scene.next = 0;
  for (int r = 0; r < warmupRounds + rounds; ++r) {
    const std::vector<CollisionBody>& bodies = scene.advance();

    warmModel.resetStatistics();
    const auto w0 = clock::now();
    const double wc0 = cpuNow();
    warmModel.forces(bodies, kContactTime, kSubDt, force, torque);
    const double wc1 = cpuNow();
    const auto w1 = clock::now();
    const collision::CollisionStatistics ws = warmModel.statistics();

    // the implicit damping solve of the pairs the warm call recorded, with
    // the bodies' velocities as the end velocities of the sub-step
    double dampingSeconds = 0;
    if (!warmModel.dampedPairs().empty()) {
      endVelocity.resize(bodies.size());
      endAngularVelocity.resize(bodies.size());
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        endVelocity[i] = bodies[i].velocity;
        endAngularVelocity[i] = bodies[i].angularVelocity;
      }
      const double d0 = cpuNow();
      warmModel.dampingForces(bodies, endVelocity, endAngularVelocity, {}, {}, kSubDt, force, torque);
      dampingSeconds = cpuNow() - d0;
    }
    const long damped = long(warmModel.dampedPairs().size());
    const long dampingSweeps = warmModel.statistics().dampingSweeps;

    const double h0 = cpuNow();
    coldModel.clearHistory();
    const double h1 = cpuNow();
    coldModel.resetStatistics();
    const auto c0 = clock::now();
    const double cc0 = cpuNow();
    coldModel.forces(bodies, kContactTime, kSubDt, force, torque);
    const double cc1 = cpuNow();
    const auto c1 = clock::now();
    const collision::CollisionStatistics cs = coldModel.statistics();

    const StagedReplica::Result st = replica.run(bodies, settings);

    PeerStatistics ps;
    const auto n0 = clock::now();
    const double nc0 = cpuNow();
    sink = sink + naiveDistances(bodies, settings, sp, dual, overlapping, ps);
    const double nc1 = cpuNow();
    const auto n1 = clock::now();
    const long overlaps = ps.sphereOverlaps;

    // the same call with the paper's distance methods, warm then cold
    paperWarmModel.resetStatistics();
    const double pw0 = cpuNow();
    paperWarmModel.forces(bodies, kContactTime, kSubDt, force, torque);
    const double pw1 = cpuNow();
    paperColdModel.clearHistory();
    paperColdModel.resetStatistics();
    const double pc0 = cpuNow();
    paperColdModel.forces(bodies, kContactTime, kSubDt, force, torque);
    const double pc1 = cpuNow();
    const collision::CollisionStatistics pws = paperWarmModel.statistics();
    const collision::CollisionStatistics pcs = paperColdModel.statistics();

    // the warm call with and without the film's tangential terms (the same
    // pairs), back to back, the order alternating from round to round
    normalFilmModel.resetStatistics();
    fullFilmModel.resetStatistics();
    const auto timedWarmCall = [&](CollisionModel& model) {
      const double t0 = cpuNow();
      model.forces(bodies, kContactTime, kSubDt, force, torque);
      return cpuNow() - t0;
    };
    double fullFilmSeconds = 0, normalFilmSeconds = 0;
    if (r % 2 == 0) {
      fullFilmSeconds = timedWarmCall(fullFilmModel);
      normalFilmSeconds = timedWarmCall(normalFilmModel);
    } else {
      normalFilmSeconds = timedWarmCall(normalFilmModel);
      fullFilmSeconds = timedWarmCall(fullFilmModel);
    }
    const collision::CollisionStatistics nfs = normalFilmModel.statistics();

    // the replicas must do what the model does
    if (st.candidates != cs.candidatePairs || st.rejected != cs.prefilterRejected ||
        st.queries != cs.distanceQueries || overlaps != cs.candidatePairs ||
        ps.sphereOverlaps != cs.candidatePairs || ws.candidatePairs != cs.candidatePairs ||
        ws.distanceQueries != cs.distanceQueries || pcs.contacts != cs.contacts ||
        pcs.prefilterRejected != cs.prefilterRejected || nfs.lubricated != ws.lubricated ||
        nfs.distanceQueries != ws.distanceQueries) {
      throw std::logic_error(
          "the benchmark's replica of the model's steps disagrees with CollisionModel "
          "(candidate pairs: model " + std::to_string(cs.candidatePairs) + ", replica " +
          std::to_string(st.candidates) + ", naive " + std::to_string(overlaps) +
          "; rejected: model " + std::to_string(cs.prefilterRejected) + ", replica " +
          std::to_string(st.rejected) + "; queries: model " + std::to_string(cs.distanceQueries) +
          ", replica " + std::to_string(st.queries) + "; contacts: dual " + std::to_string(cs.contacts) +
          ", paper " + std::to_string(pcs.contacts) + "; lubricated: with the tangential terms " +
          std::to_string(ws.lubricated) + ", without " + std::to_string(nfs.lubricated) +
          "): update Spheres/StagedReplica in collisionCost.cpp to follow CollisionModel.cpp");
    }
    if (r < warmupRounds) continue;
    tm.warm.push_back(wc1 - wc0);
    if (damped > 0) tm.damping.push_back(dampingSeconds);
    n.damped += damped;
    n.dampingSweeps += dampingSweeps;
    tm.cold.push_back(cc1 - cc0);
    tm.naive.push_back(nc1 - nc0);
    tm.paperWarm.push_back(pw1 - pw0);
    tm.paperCold.push_back(pc1 - pc0);
    tm.fullFilmWarm.push_back(fullFilmSeconds);
    tm.normalFilmWarm.push_back(normalFilmSeconds);
    n.paperQueries += pcs.distanceQueries;
    n.paperColdIterations += pcs.distanceIterations;
    n.paperWarmIterations += pws.distanceIterations;
    n.paperNotConverged += pcs.distanceNotConverged + pws.distanceNotConverged;
    tm.clearHistory.push_back(h1 - h0);
    const double stages = st.setup + st.search + st.prefilter;
    tm.restCold.push_back(tm.cold.back() - stages - st.distancesCold);
    tm.restWarm.push_back(tm.warm.back() - stages - st.distancesWarm);
    tm.warmWall.push_back(seconds(w0, w1));
    tm.coldWall.push_back(seconds(c0, c1));
    tm.naiveWall.push_back(seconds(n0, n1));
    tm.spheres.push_back(ps.spheresSeconds);
    tm.naiveDistances.push_back(ps.distancesSeconds);
    if (ps.queries > 0) tm.perQueryNaive.push_back(ps.distancesSeconds / double(ps.queries));
    tm.setup.push_back(st.setup);
    tm.search.push_back(st.search);
    tm.prefilter.push_back(st.prefilter);
    tm.distancesCold.push_back(st.distancesCold);
    tm.distancesWarm.push_back(st.distancesWarm);
    if (st.queries > 0) {
      tm.perQueryCold.push_back(st.distancesCold / double(st.queries));
      tm.perQueryWarm.push_back(st.distancesWarm / double(st.queries));
    }
    n.candidates += cs.candidatePairs;
    n.rejected += cs.prefilterRejected;
    n.boxRejected += cs.boxRejected;  // of which by the boxes (cold model)
    n.queries += cs.distanceQueries;
    n.coldIterations += cs.distanceIterations;
    n.warmIterations += ws.distanceIterations;
    n.coldNotConverged += cs.distanceNotConverged;
    n.warmNotConverged += ws.distanceNotConverged;
    n.contacts += cs.contacts;
    n.lubricated += cs.lubricated;
    n.peer.pairsTested += ps.pairsTested;
    n.peer.sphereOverlaps += ps.sphereOverlaps;
    n.peer.queries += ps.queries;
    n.peer.iterations += ps.iterations;
    n.peer.notConverged += ps.notConverged;
  }
}

void runTable(const TableOptions& t) {
  const int rounds = t.repetitions > 0 ? t.repetitions : (t.quick ? 5 : 201);
  const int warmupRounds = t.quick ? 2 : 5;
  const int stateCount = t.quick ? 8 : 32;

  // open the output first: a bad path fails now, not after the run
  std::ofstream f(t.out);
  if (!f) throw std::runtime_error("cannot write '" + t.out + "' (does its folder exist?)");
  const std::string machine = cpuModel(), date = utcNow();
  const int nproc = processorCount();
  f << kColumns << std::setprecision(6);

  const auto start = std::chrono::steady_clock::now();
  for (const Case& c : kCases) {
    const auto t0 = std::chrono::steady_clock::now();
    std::unique_ptr<Scene> scene = makeScene(c, t.seed, stateCount);
    std::cerr << "collisionCost: Ar " << c.name << ": packing and " << stateCount << " states in "
              << std::fixed << std::setprecision(1) << seconds(t0, std::chrono::steady_clock::now())
              << " s" << std::defaultfloat << std::endl;
    for (CollisionMode mode : kModes) {
      const auto t1 = std::chrono::steady_clock::now();
      Timings tm;
      Counts n;
      measure(*scene, mode, warmupRounds, rounds, tm, n);

      const double us = 1e6, R = rounds;
      const auto med = [&](const std::vector<double>& v) { return v.empty() ? 0.0 : quantile(v, 0.5) * us; };
      const auto q1 = [&](const std::vector<double>& v) { return quantile(v, 0.25) * us; };
      const auto q3 = [&](const std::vector<double>& v) { return quantile(v, 0.75) * us; };
      const auto ratio = [](long a, long b) { return b > 0 ? double(a) / double(b) : 0.0; };
      const double cold = med(tm.cold), warm = med(tm.warm), naive = med(tm.naive);
      const double setup = med(tm.setup), search = med(tm.search), prefilter = med(tm.prefilter),
                   dCold = med(tm.distancesCold), dWarm = med(tm.distancesWarm),
                   spheres = med(tm.spheres);
      const double naiveQueries = n.peer.queries / R;
      f << csvText(machine) << ',' << nproc << ',' << date << ',' << csvText("GCC " __VERSION__) << ','
        << (t.quick ? 1 : 0) << ',' << t.seed << ',' << kBodies << ',' << kVolumeFraction << ','
        << scene->boxLength << ',' << c.name << ',' << toString(mode) << ','
        << settingsFor(mode).viscosity << ',' << rounds << ',' << stateCount << ','
        << cold << ',' << q1(tm.cold) << ',' << q3(tm.cold) << ','
        << warm << ',' << q1(tm.warm) << ',' << q3(tm.warm) << ','
        << naive << ',' << q1(tm.naive) << ',' << q3(tm.naive) << ','
        << med(tm.coldWall) << ',' << med(tm.warmWall) << ',' << med(tm.naiveWall) << ','
        << med(tm.clearHistory) << ',' << loadAverage() << ','
        << setup << ',' << search << ',' << prefilter << ',' << dCold << ',' << dWarm << ','
        << med(tm.restCold) << ',' << med(tm.restWarm) << ',' << spheres << ','
        << med(tm.naiveDistances) << ','
        << naive / cold << ',' << naive / warm << ',' << cold / warm << ','
        << naive / (setup + search + prefilter + dCold) << ','
        << naive / (setup + search + prefilter + dWarm) << ','
        << med(tm.perQueryCold) << ',' << med(tm.perQueryWarm) << ','
        << med(tm.perQueryNaive) << ','
        << n.candidates / R << ',' << n.rejected / R << ',' << n.boxRejected / R << ',' << n.queries / R << ','
        << ratio(n.coldIterations, n.queries) << ',' << ratio(n.warmIterations, n.queries) << ','
        << n.coldNotConverged << ',' << n.warmNotConverged << ','
        << n.contacts / R << ',' << n.lubricated / R << ',' << med(tm.damping) << ','
        << n.damped / R << ',' << ratio(n.dampingSweeps, long(tm.damping.size())) << ','
        << n.peer.pairsTested / R << ',' << n.peer.sphereOverlaps / R << ',' << naiveQueries << ','
        << ratio(n.peer.iterations, n.peer.queries) << ',' << n.peer.notConverged << ','
        << med(tm.paperCold) << ',' << q1(tm.paperCold) << ',' << q3(tm.paperCold) << ','
        << med(tm.paperWarm) << ',' << q1(tm.paperWarm) << ',' << q3(tm.paperWarm) << ','
        << med(tm.paperCold) / cold << ',' << med(tm.paperWarm) / warm << ',' << n.paperQueries / R << ','
        << ratio(n.paperColdIterations, n.paperQueries) << ',' << ratio(n.paperWarmIterations, n.paperQueries)
        << ',' << n.paperNotConverged << ',' << med(tm.fullFilmWarm) << ','
        << med(tm.normalFilmWarm) << ',' << med(tm.fullFilmWarm) / med(tm.normalFilmWarm) << '\n';
      f.flush();
      if (!f) throw std::runtime_error("writing '" + t.out + "' failed");
      std::cerr << "collisionCost: Ar " << c.name << ' ' << toString(mode) << ": cold "
                << std::fixed << std::setprecision(0) << cold << " us, warm " << warm
                << " us, naive " << naive << " us, paper " << med(tm.paperCold) << " / "
                << med(tm.paperWarm) << " us per call (" << n.queries / R << " distances; "
                << std::setprecision(1) << seconds(t1, std::chrono::steady_clock::now()) << " s)"
                << std::defaultfloat << std::endl;
    }
  }
  std::cerr << "collisionCost: wrote " << t.out << " in " << std::fixed << std::setprecision(1)
            << seconds(start, std::chrono::steady_clock::now()) << " s" << std::endl;
}

// ---------------------------------------------------------------------------------------------
// Google Benchmark mode

Scene& cachedScene(const Case& c) {
  static std::map<std::string, std::unique_ptr<Scene>> cache;
  auto& s = cache[c.name];
  if (!s) s = makeScene(c, 1, 32);
  return *s;
}

void setQueryCounters(benchmark::State& state, const collision::CollisionStatistics& s) {
  const double calls = double(state.iterations());
  state.counters["queries"] = double(s.distanceQueries) / calls;
  state.counters["candidates"] = double(s.candidatePairs) / calls;
  state.counters["iterations"] =
      s.distanceQueries > 0 ? double(s.distanceIterations) / double(s.distanceQueries) : 0.0;
  state.counters["notConverged"] = double(s.distanceNotConverged);
}

void forcesBenchmark(benchmark::State& state, Case c, CollisionMode mode, bool warm,
                     bool tangentialFilm) {
  Scene& scene = cachedScene(c);
  Settings settings = settingsFor(mode);
  settings.laws.lubrication.tangential = tangentialFilm;
  CollisionModel model = modelFor(settings);
  std::vector<Vec3> force, torque;
  scene.next = 0;
  model.forces(scene.advance(), kContactTime, kSubDt, force, torque);  // history of a first call
  model.resetStatistics();
  for (auto _ : state) {
    if (!warm) model.clearHistory();
    model.forces(scene.advance(), kContactTime, kSubDt, force, torque);
    benchmark::DoNotOptimize(force.data());
  }
  setQueryCounters(state, model.statistics());
}

void naiveBenchmark(benchmark::State& state, Case c, CollisionMode mode) {
  Scene& scene = cachedScene(c);
  const Settings settings = settingsFor(mode);
  const ellipsoids::DualNewton dual;
  Spheres sp;
  std::vector<std::pair<int, int>> overlapping;
  PeerStatistics st;
  scene.next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(naiveDistances(scene.advance(), settings, sp, dual, overlapping, st));
  }
  const double calls = double(state.iterations());
  state.counters["queries"] = double(st.queries) / calls;
  state.counters["iterations"] = st.queries > 0 ? double(st.iterations) / double(st.queries) : 0.0;
}

void searchBenchmark(benchmark::State& state, Case c, CollisionMode mode) {
  Scene& scene = cachedScene(c);
  const Settings settings = settingsFor(mode);
  collision::PairSearch search;
  Spheres sp;
  long pairs = 0;
  scene.next = 0;
  for (auto _ : state) pairs += searchOnly(scene.advance(), settings, sp, search);
  state.counters["candidates"] = double(pairs) / double(state.iterations());
}

void registerBenchmarks() {
  for (const Case& c : kCases) {
    for (CollisionMode mode : kModes) {
      const std::string suffix = std::string("/") + toString(mode) + "/Ar:" + c.name;
      benchmark::RegisterBenchmark(("cold" + suffix).c_str(), forcesBenchmark, c, mode, false, true)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("warm" + suffix).c_str(), forcesBenchmark, c, mode, true, true)
          ->Unit(benchmark::kMillisecond);
      if (mode == CollisionMode::lubricationContact) {
        benchmark::RegisterBenchmark(("warmNormalFilm" + suffix).c_str(), forcesBenchmark, c, mode,
                                     true, false)
            ->Unit(benchmark::kMillisecond);
      }
      benchmark::RegisterBenchmark(("naive" + suffix).c_str(), naiveBenchmark, c, mode)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("pairSearch" + suffix).c_str(), searchBenchmark, c, mode)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

// ---------------------------------------------------------------------------------------------

bool parseUnsigned(const std::string& s, std::uint64_t& v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

int main(int argc, char** argv) {
  bool table = false, ownOption = false;
  TableOptions t;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const std::string& what) -> std::string {
      if (i + 1 >= argc) usageError("option " + a + " needs " + what);
      return argv[++i];
    };
    if (a == "--help" || a == "-help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--table") {
      table = true;
      t.out = value("a CSV file name");
      if (t.out.empty() || t.out.rfind("--", 0) == 0) {
        usageError("option --table needs a CSV file name, not '" + t.out + "'");
      }
    } else if (a == "--quick") {
      t.quick = ownOption = true;
    } else if (a == "--repetitions") {
      ownOption = true;
      const std::string v = value("a number of rounds (>= 3)");
      std::uint64_t n = 0;
      if (!parseUnsigned(v, n) || n < 3 || n > 100000) {
        usageError("option --repetitions: '" + v + "' is not an integer in [3, 100000]");
      }
      t.repetitions = static_cast<int>(n);
    } else if (a == "--seed") {
      ownOption = true;
      const std::string v = value("a seed (0 .. 2^64-1)");
      if (!parseUnsigned(v, t.seed)) {
        usageError("option --seed: '" + v + "' is not an integer in [0, 2^64-1]");
      }
    } else if (a.rfind("--benchmark_", 0) == 0) {
      if (table) usageError("--benchmark_* flags are for the Google Benchmark mode, not with --table");
    } else {
      usageError("unknown argument '" + a + "'");
    }
  }
  if (ownOption && !table) usageError("--quick, --repetitions and --seed need --table FILE");

  if (table) {
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]).rfind("--benchmark_", 0) == 0) {
        usageError("--benchmark_* flags are for the Google Benchmark mode, not with --table");
      }
    }
    try {
      runTable(t);
    } catch (const std::exception& e) {
      std::cerr << "collisionCost: " << e.what() << std::endl;
      return 1;
    }
    return 0;
  }

  registerBenchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  try {
    if (benchmark::RunSpecifiedBenchmarks() == 0) {
      std::cerr << "collisionCost: no benchmark ran (--benchmark_list_tests lists them)" << std::endl;
      benchmark::Shutdown();
      return 2;
    }
  } catch (const std::exception& e) {
    std::cerr << "collisionCost: " << e.what() << std::endl;
    benchmark::Shutdown();
    return 1;
  }
  benchmark::Shutdown();
  return 0;
}
