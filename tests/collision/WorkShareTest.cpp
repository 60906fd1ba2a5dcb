// WorkShare: the pairs shared among processes (threads standing in for MPI
// ranks, with the same collectives) give every process the same bodies, the
// serial model's motion to round-off, and each process a share of the
// distance work; histories are kept and restored per owner.
#include "collision/RigidBody.hpp"
#include "collision/SubStepper.hpp"
#include "collision/ThreadWorkShare.hpp"
#include "collision/WorkShare.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <tuple>

using namespace collision;

namespace {


/// Bodies under their buoyant weight in a viscous fluid: the load rule, the
/// lubrication and the film correction all act.
class SettlingBodies : public BodySet {
 public:
  SettlingBodies(const std::vector<RigidBody>& bodies, const Vec3& g, Scalar cell)
      : bodies_(bodies), g_(g), cell_(cell) {}
  std::size_t size() const override { return bodies_.size(); }
  CollisionBody collisionBody(std::size_t i, const BodyState& s) const override {
    ++builds;
    CollisionBody b = bodies_[i].collisionBody(s);
    b.externalForce = bodies_[i].mass() * g_;
    b.filmGap = cell_;
    b.cellSize = cell_;
    return b;
  }
  void advance(std::size_t i, BodyState& s, Scalar, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override {
    ++advances;
    const RigidBody& b = bodies_[i];
    advanceRigidBody(s, dt, (b.mass() * g_ + fc) * dt, tc * dt, b.mass(), b.bodyInertia());
  }

  /// the calls of collisionBody() and advance() (a process's per-body work)
  mutable long builds = 0, advances = 0;

 private:
  const std::vector<RigidBody>& bodies_;
  Vec3 g_;
  Scalar cell_;
};

constexpr Scalar kSize = 1e-3;  // equivalent diameter
constexpr Scalar kCell = kSize / 8;
const Vec3 kGravity(0, 0, -9.81 * 0.5);  // (1 - rho_f/rho_p) g

/// 18 spheroids (Ar 2, 1 and 1/2) in a column over a floor, close enough to
/// touch and squeeze films as they land on it and on each other.
std::vector<RigidBody> column() {
  std::mt19937_64 rng(23);
  std::normal_distribution<Scalar> g;
  std::vector<RigidBody> bodies;
  for (int k = 0; k < 18; ++k) {
    RigidBody b;
    const Scalar ar = k % 3 == 0 ? 2.0 : (k % 3 == 1 ? 1.0 : 0.5);
    b.semiAxes = Vec3(std::cbrt(ar * ar), 1 / std::cbrt(ar), 1 / std::cbrt(ar)) * 0.5 * kSize;
    b.centre = kSize * Vec3(1.15 * (k % 3), 1.15 * ((k / 3) % 2), 0.75 + 1.1 * (k / 6)) +
               0.05 * kSize * Vec3(g(rng), g(rng), g(rng));
    b.orientation = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
    b.velocity = Vec3(0, 0, -0.05) + 0.02 * Vec3(g(rng), g(rng), g(rng));
    b.density = 2000;
    bodies.push_back(b);
  }
  return bodies;
}

ModelSetup setup() {
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = 1e-3;
  s.laws.contact.friction = 0.3;
  s.filmViscosity = 1e-3;
  return s;
}

struct Settled {
  std::vector<BodyState> states;
  CollisionStatistics statistics;
  std::vector<PairRecord> history;
  long contactSteps = 0;  ///< steps with a contact
  std::size_t islands = 0;  ///< the most islands of a step
};

constexpr Scalar kDt = 2e-4;  // the fluid step
constexpr int kSteps = 150;

/// kSteps fluid steps of the column on one process of a share (nullptr: alone)
Settled settle(std::shared_ptr<const WorkShare> share) {
  const std::vector<RigidBody> bodies = column();
  const SettlingBodies set(bodies, kGravity, kCell);
  SettlingBodies stepped = set;
  CollisionModel model = makeModel(setup(), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  model.setWorkShare(share);
  Settled run;
  for (const RigidBody& b : bodies) run.states.push_back(b);
  SubStepper stepper;
  for (int step = 0; step < kSteps; ++step) {
    // as a coupled run steps: island by island
    const std::vector<BodyState> reference = run.states;
    stepper.stepIslands(stepped, run.states, model, 10 * kDt, step * kDt, kDt, 1, reference);
    run.contactSteps += model.activeContacts() > 0;
    run.islands = std::max(run.islands, stepper.islands().size());
  }
  run.statistics = model.statistics();
  run.history = model.history();
  return run;
}

std::tuple<int, int, std::array<int, 3>> id(const PairRecord& r) { return {r.first, r.second, r.image}; }

}  // namespace

TEST(WorkShare, ProcessesAgreeWithEachOtherAndWithOneProcessAndShareTheDistances) {
  const Settled alone = settle(nullptr);
  ASSERT_GT(alone.statistics.contacts, 50);
  ASSERT_GT(alone.statistics.wallContacts, 10);
  ASSERT_GT(alone.statistics.lubricated, 50);
  ASSERT_GT(alone.statistics.dampingSolves, 50);
  ASSERT_GT(alone.islands, 1u);  // the islands differ in their sub-steps

  constexpr int P = 3;
  const std::vector<Settled> runs = ThreadWorkShare::runRanks<Settled>(P, settle);

  // every process ends with the same bodies, bit for bit
  for (int r = 1; r < P; ++r) {
    for (std::size_t i = 0; i < alone.states.size(); ++i) {
      EXPECT_EQ(runs[r].states[i].centre, runs[0].states[i].centre) << "process " << r << ", body " << i;
      EXPECT_EQ(runs[r].states[i].velocity, runs[0].states[i].velocity) << "process " << r << ", body " << i;
      EXPECT_EQ(runs[r].states[i].angularVelocity, runs[0].states[i].angularVelocity)
          << "process " << r << ", body " << i;
    }
  }
  // and the motion of one process to round-off (sums in another order)
  Scalar speed = 0;
  for (const BodyState& s : alone.states) speed = std::max(speed, s.velocity.norm());
  Scalar dx = 0, du = 0;
  for (std::size_t i = 0; i < alone.states.size(); ++i) {
    dx = std::max(dx, (runs[0].states[i].centre - alone.states[i].centre).norm());
    du = std::max(du, (runs[0].states[i].velocity - alone.states[i].velocity).norm());
  }
  std::cout << "[ info ] " << P << " processes against one: centres " << dx / kSize << " D, velocities "
            << du / speed << " of the largest speed\n";
  EXPECT_LT(dx, 1e-9 * kSize);
  EXPECT_LT(du, 1e-7 * speed);

  // each process computed a share of the distances, together all of them
  // (a process computes the pairs of its own bodies as first bodies: with
  // 18 bodies the shares come in lumps about a third)
  long total = 0;
  for (int r = 0; r < P; ++r) {
    const long q = runs[r].statistics.distanceQueries;
    std::cout << "[ info ] process " << r << ": " << q << " distances of " << alone.statistics.distanceQueries
              << ", " << runs[r].statistics.contacts + runs[r].statistics.wallContacts << " contacts\n";
    EXPECT_GT(q, 0.2 * alone.statistics.distanceQueries) << "process " << r;
    EXPECT_LT(q, 0.6 * alone.statistics.distanceQueries) << "process " << r;
    total += q;
  }
  EXPECT_NEAR(double(total), double(alone.statistics.distanceQueries), 0.01 * alone.statistics.distanceQueries);

  // the histories: each pair on one process; together the pairs of one process
  std::set<std::tuple<int, int, std::array<int, 3>>> together, single;
  for (const PairRecord& r : alone.history) single.insert(id(r));
  for (int r = 0; r < P; ++r) {
    for (const PairRecord& rec : runs[r].history) {
      EXPECT_TRUE(together.insert(id(rec)).second) << "pair (" << rec.first << " " << rec.second << ") twice";
    }
  }
  EXPECT_EQ(together, single);
}

TEST(WorkShare, EachProcessBuildsAndAdvancesAboutItsShareOfTheBodies) {
  // 24 pairs of spheres in a periodic box, each pair closing in head-on and
  // far from the others (24 islands): a process builds trial states only of
  // the bodies its own pairs use and advances only its own bodies, so each of
  // 3 processes does about a third of the per-body work of one process
  // (besides one build per body at the start and the end of each step), and
  // all end with the states of one process
  constexpr int kPairs = 24;
  constexpr Scalar kSide = 4 * kPairs * kSize;
  std::vector<RigidBody> bodies;
  for (int k = 0; k < kPairs; ++k) {
    for (const int side : {-1, 1}) {
      RigidBody b;
      b.semiAxes = Vec3::Constant(0.5 * kSize);
      b.centre = Vec3(4 * k * kSize + 2 * kSize, (1.5 + 0.01 * k) * kSize, 0.5 * kSide) +
                 side * Vec3(0, 0.52 * kSize, 0);
      b.velocity = Vec3(0, -side * 0.05, 0);
      b.density = 2000;
      bodies.push_back(b);
    }
  }
  const PeriodicBox box(Vec3::Zero(), Vec3::Constant(kSide), {true, true, true});
  struct Run {
    std::vector<BodyState> states;
    long builds = 0, advances = 0, contacts = 0;
  };
  auto run = [&](std::shared_ptr<const WorkShare> share) {
    SettlingBodies set(bodies, Vec3::Zero(), kCell);
    CollisionModel model = makeModel(setup(), {});
    model.setPeriodicBox(box);
    model.setWorkShare(share);
    Run r;
    r.states.assign(bodies.begin(), bodies.end());
    SubStepper stepper;
    for (int step = 0; step < 40; ++step) {
      const std::vector<BodyState> reference = r.states;
      stepper.stepIslands(set, r.states, model, 10 * kDt, step * kDt, kDt, 1, reference);
    }
    r.builds = set.builds;
    r.advances = set.advances;
    r.contacts = model.statistics().contacts;
    return r;
  };
  const Run alone = run(nullptr);
  ASSERT_GT(alone.contacts, 10 * kPairs);  // every pair met
  constexpr int P = 3;
  const std::vector<Run> runs = ThreadWorkShare::runRanks<Run>(P, run);
  const long perStep = 2 * static_cast<long>(bodies.size()) * 40;  // the builds of islands and checks
  for (int r = 0; r < P; ++r) {
    const double builds = double(runs[r].builds - perStep) / (alone.builds - perStep);
    const double advances = double(runs[r].advances) / alone.advances;
    std::cout << "[ info ] process " << r << " of " << P << ": trial-state builds " << builds
              << ", advances " << advances << " of one process's\n";
    EXPECT_GT(builds, 0.1) << "process " << r;
    EXPECT_LT(builds, 0.6) << "process " << r;
    EXPECT_GT(advances, 0.1) << "process " << r;
    EXPECT_LT(advances, 0.6) << "process " << r;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      EXPECT_EQ(runs[r].states[i].centre, runs[0].states[i].centre) << "process " << r << ", body " << i;
      EXPECT_LT((runs[r].states[i].velocity - alone.states[i].velocity).norm(), 1e-12) << "body " << i;
    }
  }
}

TEST(WorkShare, EachProcessKeepsTheRestoredHistoryOfItsOwnPairs) {
  // a history of pairs and wall pairs, restored on 4 processes: each keeps
  // its own, the union is the whole, and a damping force is reported once
  std::vector<PairRecord> records;
  for (int i = 0; i < 40; ++i) {
    PairRecord r;
    r.first = i;
    r.second = i % 5 == 0 ? -1 : i + 1 + i % 3;
    r.warm = r.second >= 0;
    r.direction = Vec3(0, 0, 1);
    r.contactTime = i % 2 ? 1e-3 : 0;
    r.stiffness = 1;
    r.dampingForce = Vec3(0, 0, i % 4 == 0 ? 1e-6 : 0);
    records.push_back(r);
  }
  constexpr int P = 4;
  ThreadWorkShare::Group exchange(P);  // (no collective is called: one thread suffices)
  std::set<std::tuple<int, int, std::array<int, 3>>> together;
  int damping = 0;
  for (int r = 0; r < P; ++r) {
    CollisionModel model =
        makeModel(setup(), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    model.setWorkShare(std::make_shared<ThreadWorkShare>(exchange, r));
    model.setHistory(records);
    const std::vector<PairRecord> own = model.history();
    EXPECT_LT(own.size(), records.size()) << "process " << r;
    for (const PairRecord& rec : own) {
      EXPECT_TRUE(together.insert(id(rec)).second);
      damping += rec.dampingForce.squaredNorm() > 0;
    }
  }
  std::set<std::tuple<int, int, std::array<int, 3>>> whole;
  int wholeDamping = 0;
  for (const PairRecord& rec : records) {
    if (rec.warm || rec.contactTime > 0 || rec.dampingForce.squaredNorm() > 0) whole.insert(id(rec));
    wholeDamping += rec.dampingForce.squaredNorm() > 0;
  }
  EXPECT_EQ(together, whole);
  EXPECT_EQ(damping, wholeDamping);
}

TEST(WorkShare, TheOwnersSpreadTheBodiesEvenlyAndAPairGoesWithItsFirstBody) {
  // 20000 bodies: each process's count within 4 standard deviations of a
  // random equal share (binomial) on 2, 3, 8 and 64 processes; the pairs of a
  // body with its next 6 neighbours and a wall belong to its owner
  ThreadWorkShare::Group exchange(1);
  for (const int P : {2, 3, 8, 64}) {
    struct Sized : ThreadWorkShare {
      Sized(ThreadWorkShare::Group& e, int p) : ThreadWorkShare(e, 0), p_(p) {}
      int size() const override { return p_; }
      int p_;
    } share(exchange, P);
    constexpr int kBodies = 20000;
    std::vector<long> count(P, 0);
    for (int i = 0; i < kBodies; ++i) {
      const int owner = share.bodyOwner(i);
      ASSERT_TRUE(owner >= 0 && owner < P);
      ++count[owner];
      for (int d = 1; d <= 6; ++d) EXPECT_EQ(share.owner(PairKey::encode(i, i + d)), owner);
      EXPECT_EQ(share.owner(PairKey::encode(i, -1)), owner);
    }
    const double mean = double(kBodies) / P;
    const double sd = std::sqrt(mean * (1 - 1.0 / P));
    for (int r = 0; r < P; ++r) {
      EXPECT_NEAR(count[r], mean, 4 * sd) << P << " processes, process " << r;
    }
  }
}
