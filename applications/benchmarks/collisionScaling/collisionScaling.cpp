/**
 * collisionScaling: each rank's share of the body and collision work of the
 * collision sub-steps (collision::SubStepper::stepIslands, the path of every
 * coupled run) when P ranks share it through a WorkShare, threads standing in
 * for the ranks (collision::ThreadWorkShare: a waiting thread sleeps, so a
 * thread's CPU time is its own work; the collectives' data is copied, not
 * sent over a network).
 *
 *   collisionScaling [--bodies "1000 10000"] [--ranks "1 2 4 8"] [--steps 10]
 *                    [--out table.csv]
 *   collisionScaling --help
 *
 * Scene (the scaling benchmark's suspension, docs/scaling.md): N prolate
 * spheroids (Ar 2, D_eq 4 mm, density 1500 kg/m^3) placed by random
 * sequential addition (seed 1) in a triply periodic cube at solid fraction
 * 0.1, in a fluid of density 1000 kg/m^3 and viscosity 0.02 Pa s; the
 * lubricationContact laws (restitution 0.9, lubrication and film correction
 * with the cell size D/8 of 8 cells per D). The flow is replaced by a linear
 * drag that gives each body the terminal speed 2 cm/s under its buoyant
 * weight (and the same relaxation time for its rotation): the bodies start
 * with random velocities of 2 cm/s and 5 rad/s and keep moving, meeting and
 * squeezing films as in a settling suspension. Fluid steps of 2 ms (the
 * scaling benchmark's), contact time 10 steps.
 *
 * Each thread holds its own model, states and sub-stepper and calls
 * stepIslands once per step; after the steps the states of every rank are
 * compared with rank 0's (they must be equal bit for bit) and with the run
 * on one rank. Timed: each thread's CPU time over the steps after the first
 * two. The run on one rank is two identical serial runs at once (their mean
 * CPU time), so that every P keeps both cores busy: a thread's CPU time
 * grows by up to half when the other core works (shared caches and memory),
 * and the ratios compare like with like. Printed (and written to --out): per N and P the busiest rank's CPU
 * time per step, its ratio to one rank's, the mean over the ranks, the
 * distances of the busiest rank over all, the sub-steps and evaluations; and
 * the heap bytes per body that one rank's sub-steps hold (glibc's mallinfo2
 * around a separate 3-step serial run: every rank holds these for every body).
 */
#include "collision/FilmCorrection.hpp"
#include "collision/PairModel.hpp"
#include "collision/RigidBody.hpp"
#include "collision/SubStepper.hpp"
#include "collision/ThreadWorkShare.hpp"
#include "collision/WallModel.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace collision;

namespace {

constexpr Scalar kDiameter = 4e-3;
constexpr Scalar kAspectRatio = 2;
constexpr Scalar kSolidFraction = 0.1;
constexpr Scalar kDensity = 1500, kFluidDensity = 1000, kViscosity = 0.02;
constexpr Scalar kCell = kDiameter / 8;
constexpr Scalar kTerminalSpeed = 0.02, kStartSpin = 5;
constexpr Scalar kDt = 2e-3, kContactSteps = 10;
constexpr int kUntimedSteps = 2;
const Vec3 kGravity(0, 0, -9.81);

double threadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// Settling bodies with a linear drag standing in for the flow.
class DraggedBodies : public BodySet {
 public:
  explicit DraggedBodies(const std::vector<RigidBody>& bodies) : bodies_(bodies) {}
  std::size_t size() const override { return bodies_.size(); }
  CollisionBody collisionBody(std::size_t i, const BodyState& s) const override {
    CollisionBody b = bodies_[i].collisionBody(s);
    b.externalForce = weight(i) - drag(i) * s.velocity;
    b.filmGap = kCell;
    b.cellSize = kCell;
    return b;
  }
  void advance(std::size_t i, BodyState& s, Scalar, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override {
    const RigidBody& b = bodies_[i];
    // the drag's relaxation time m/c for the rotation too
    const Vec3 spinDrag = -(drag(i) / b.mass()) * (b.worldInertia(s.orientation) * s.angularVelocity);
    advanceRigidBody(s, dt, (weight(i) - drag(i) * s.velocity + fc) * dt, (tc + spinDrag) * dt,
                     b.mass(), b.bodyInertia());
  }

 private:
  Vec3 weight(std::size_t i) const {
    return (1 - kFluidDensity / kDensity) * bodies_[i].mass() * kGravity;
  }
  Scalar drag(std::size_t i) const { return weight(i).norm() / kTerminalSpeed; }

  const std::vector<RigidBody>& bodies_;
};

struct Scene {
  std::vector<RigidBody> bodies;
  PeriodicBox box;
};

Scene scene(int count) {
  packing::RsaOptions o;
  o.aspectRatio = kAspectRatio;
  o.volumeFraction = kSolidFraction;
  o.equivalentDiameter = kDiameter;
  o.boxLengthRelative = std::cbrt(count * kPi / (6 * kSolidFraction));
  o.seed = 1;
  const packing::Packing p = packing::randomSequentialAddition(o);
  Scene s;
  s.box = PeriodicBox(Vec3::Zero(), Vec3::Constant(p.boxLength), {true, true, true});
  std::mt19937_64 rng(7);
  std::normal_distribution<Scalar> g;
  auto randomDirection = [&] {
    Vec3 v(g(rng), g(rng), g(rng));
    return Vec3(v / v.norm());
  };
  for (const ellipsoids::Ellipsoid& e : p.bodies) {
    RigidBody b;
    b.semiAxes = e.semiAxes();
    b.centre = e.centre();
    b.orientation = e.orientation();
    b.density = kDensity;
    b.velocity = kTerminalSpeed * randomDirection();
    b.angularVelocity = kStartSpin * randomDirection();
    s.bodies.push_back(b);
  }
  return s;
}

CollisionModel makeModel(const PeriodicBox& box) {
  InteractionParameters p;
  p.contact.restitution = 0.9;
  p.viscosity = kViscosity;
  CollisionModel model(CollisionSettings(), PairModel::New("lubricatedSpringDashpot", p),
                       WallModel::New("lubricatedSpringDashpot", p), {},
                       std::make_unique<FilmCorrection>(kViscosity, 1));
  model.setPeriodicBox(box);
  return model;
}

struct RankRun {
  std::vector<BodyState> states;
  double cpu = 0;  ///< over the timed steps
  long distances = 0;
  long evaluations = 0;
  long subSteps = 0;  ///< the largest count of a step, summed over the steps
  double evaluated = 0;  ///< the mean fraction of the bodies whose trial states the rank built
};

RankRun run(const Scene& s, int steps, std::shared_ptr<const WorkShare> share) {
  DraggedBodies set(s.bodies);
  CollisionModel model = makeModel(s.box);
  if (share) model.setWorkShare(share);
  SubStepper stepper;
  RankRun r;
  r.states.assign(s.bodies.begin(), s.bodies.end());
  double cpu0 = 0;
  for (int k = 0; k < steps; ++k) {
    if (k == kUntimedSteps) {
      cpu0 = threadCpuSeconds();
      model.resetStatistics();
    }
    const std::vector<BodyState> reference(r.states);
    stepper.stepIslands(set, r.states, model, kContactSteps * kDt, k * kDt, kDt, 1, reference);
    if (k >= kUntimedSteps) {
      std::vector<int> counts;
      for (const Island& island : stepper.islands()) {
        if (island.interacts) counts.push_back(island.subSteps);
      }
      std::sort(counts.begin(), counts.end());
      counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
      for (const int c : counts) r.evaluations += 2 * c;
      r.subSteps += counts.empty() ? 1 : counts.back();
      const std::vector<char>& e = model.evaluatedBodies();
      r.evaluated += (e.empty() ? 1.0 : double(std::count(e.begin(), e.end(), 1)) / e.size()) /
                     (steps - kUntimedSteps);
    }
  }
  r.cpu = threadCpuSeconds() - cpu0;
  r.distances = model.statistics().distanceQueries;
  return r;
}

/// The heap bytes a rank's collision sub-steps hold per body (glibc's
/// mallinfo2: the bytes in use after three steps less those before the
/// model, sub-stepper and states were made; one thread, nothing else allocating).
double bytesPerBody(const Scene& s) {
  const auto inUse = [] {
    const struct mallinfo2 m = mallinfo2();
    return double(m.uordblks) + double(m.hblkhd);
  };
  const double before = inUse();
  double after = 0;
  {
    DraggedBodies set(s.bodies);
    CollisionModel model = makeModel(s.box);
    SubStepper stepper;
    std::vector<BodyState> states(s.bodies.begin(), s.bodies.end());
    for (int k = 0; k < 3; ++k) {
      const std::vector<BodyState> reference(states);
      stepper.stepIslands(set, states, model, kContactSteps * kDt, k * kDt, kDt, 1, reference);
    }
    after = inUse();
  }
  return (after - before) / s.bodies.size();
}

std::vector<int> integers(const std::string& list, const std::string& option) {
  std::istringstream in(list);
  std::vector<int> out;
  std::string word;
  while (in >> word) {
    try {
      std::size_t used = 0;
      const int v = std::stoi(word, &used);
      if (used != word.size() || v < 1) throw std::invalid_argument(word);
      out.push_back(v);
    } catch (const std::exception&) {
      throw std::invalid_argument("option " + option + ": '" + word +
                                  "' is not a positive integer");
    }
  }
  if (out.empty()) throw std::invalid_argument("option " + option + " needs at least one integer");
  return out;
}

Scalar maxDifference(const std::vector<BodyState>& a, const std::vector<BodyState>& b) {
  Scalar d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max({d, (a[i].centre - b[i].centre).norm() / kDiameter,
                  (a[i].velocity - b[i].velocity).norm() / kTerminalSpeed});
  }
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  std::string bodyList = "1000 10000", rankList = "1 2 4 8", out;
  int steps = 10;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value");
        return argv[++i];
      };
      if (a == "--help" || a == "-h") {
        std::cout << "collisionScaling [--bodies \"1000 10000\"] [--ranks \"1 2 4 8\"] "
                     "[--steps 10] [--out table.csv]\n";
        return 0;
      } else if (a == "--bodies") {
        bodyList = value();
      } else if (a == "--ranks") {
        rankList = value();
      } else if (a == "--steps") {
        steps = integers(value(), "--steps").front();
        if (steps <= kUntimedSteps) throw std::invalid_argument("option --steps must be > 2");
      } else if (a == "--out") {
        out = value();
      } else {
        throw std::invalid_argument("unknown argument '" + a +
                                    "' (allowed: --bodies, --ranks, --steps, --out, --help)");
      }
    }
    const std::vector<int> counts = integers(bodyList, "--bodies");
    const std::vector<int> ranks = integers(rankList, "--ranks");
    std::ostringstream csv, memory;
    memory << "\nHeap bytes per body of one rank's collision sub-steps (mallinfo2, after 3 steps):\n\n"
              "| bodies | bytes per body |\n|---|---|\n";
    csv << "bodies,ranks,rank,cpu_per_step_s,distances,evaluated_fraction,evaluations,sub_steps\n";
    std::cout << "| bodies | P | busiest rank CPU s/step | over 1 rank | mean over ranks | "
                 "busiest rank's distances | bodies evaluated (busiest) | evaluations/step | "
                 "sub-steps/step | max difference to 1 rank |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const int n : counts) {
      const Scene s = scene(n);
      memory << "| " << n << " | " << std::lround(bytesPerBody(s)) << " |\n";
      const int timed = steps - kUntimedSteps;
      RankRun serial;
      double serialCpu = 0;
      for (const int P : ranks) {
        // one rank runs as two independent copies at once, so that every
        // run keeps both cores of the machine busy (the CPU time of a thread
        // grows when the other core works: shared caches and memory)
        std::vector<RankRun> runs = ThreadWorkShare::runRanks<RankRun>(
            P == 1 ? 2 : P, [&](std::shared_ptr<const WorkShare> share) {
              return run(s, steps, P > 1 ? share : nullptr);
            });
        if (P == 1) {
          if (maxDifference(runs[1].states, runs[0].states) != 0) {
            throw std::runtime_error("two serial runs ended with different states");
          }
          runs[0].cpu = 0.5 * (runs[0].cpu + runs[1].cpu);
          runs.resize(1);
        }
        for (int r = 0; r < P; ++r) {
          if (maxDifference(runs[r].states, runs[0].states) != 0) {
            throw std::runtime_error("rank " + std::to_string(r) + " of " + std::to_string(P) +
                                     " ended with other states than rank 0");
          }
        }
        double busiest = 0, mean = 0, evaluated = 0;
        long distances = 0, busiestDistances = 0;
        for (int r = 0; r < P; ++r) {
          busiest = std::max(busiest, runs[r].cpu / timed);
          mean += runs[r].cpu / timed / P;
          distances += runs[r].distances;
          busiestDistances = std::max(busiestDistances, runs[r].distances);
          evaluated = std::max(evaluated, runs[r].evaluated);
          csv << n << "," << P << "," << r << "," << runs[r].cpu / timed << "," << runs[r].distances
              << "," << runs[r].evaluated << "," << runs[r].evaluations << "," << runs[r].subSteps << "\n";
        }
        if (P == 1 || serial.states.empty()) {
          serial = runs[0];
          serialCpu = busiest;
        }
        char line[400];
        std::snprintf(line, sizeof line, "| %d | %d | %.4g | %.3f | %.4g | %.3f | %.3f | %.1f | %.2f | %.1e |\n",
                      n, P, busiest, busiest / serialCpu, mean,
                      distances > 0 ? double(busiestDistances) / distances : 0.0, evaluated,
                      double(runs[0].evaluations) / timed, double(runs[0].subSteps) / timed,
                      maxDifference(runs[0].states, serial.states));
        std::cout << line << std::flush;
      }
    }
    std::cout << memory.str();
    if (!out.empty()) {
      std::ofstream f(out);
      f << csv.str();
      if (!f) throw std::runtime_error("cannot write " + out);
    }
  } catch (const std::exception& e) {
    std::cerr << "collisionScaling: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
