// dryCollisions: dry collisions in vacuum through the collision core
// (CollisionModel in the sub-steps of SubStepper and the rigid-body step of
// RigidBodyStep, the ones coupled runs use), measured against the input restitution and
// the conservation laws, and pushed to the extremes (README.md).
//
//   dryCollisions [--quick] [--out DIR] [--only PART] [--approach-scale F]
//
// --approach-scale F: CollisionSettings::approachContactTimeScale of every run
// (default 1), for the sensitivity to the approach check's bound.
//
// Units: the equal-volume diameter D_eq = 1, the nominal contact time T_c = 1,
// density 1. Fluid steps dt = T_c/5 (N_c = 5), each split into the sub-steps
// CollisionModel::subSteps asks for (exactly as collisionStep does; the loop
// is written out here only to look at the bodies after every sub-step).
// Writes CSVs and checks.md to DIR (default: validation/dryCollisions/results)
// and exits 1 if any check fails, 2 on a usage error.
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "collision/RigidBody.hpp"
#include "ellipsoids/DualNewton.hpp"

#ifndef DRYCOLLISIONS_RESULTS
#define DRYCOLLISIONS_RESULTS "results"
#endif

using namespace collision;

namespace {

constexpr Scalar kInf = std::numeric_limits<Scalar>::infinity();
constexpr Scalar kDeq = 1;  // length unit
constexpr Scalar kTc = 1;   // nominal contact time, time unit
constexpr int kNc = 5;      // fluid steps per nominal contact time
constexpr Scalar kDt = kTc / kNc;
constexpr Scalar kMaxOverlap = 0.1;  // the model's default cap, fraction of a_min

// ---------------------------------------------------------------------------
// Tolerances (README.md: where each comes from)
// |e_measured - e| (rebound speed error over the impact speed) of a contact
// resolved by N sub-steps, any phase of the first touch in the sub-step grid
// and any e in [0.1, 0.97]: the measured worst is 0.139 at N = 5 and
// 0.34/N to 0.37/N at N = 10, 20, 50 (README.md)
Scalar restitutionTolerance(int n) { return n < 10 ? 0.15 : 0.4 / n; }
// tilted spheroid on a wall: the contact point moves while the body turns;
// |e_measured - e| <= restitutionTolerance(N) + kTurnAllowance theta_c
// (theta_c the angle turned during the contact), for uncapped contacts
constexpr Scalar kTurnAllowance = 1.0;
constexpr Scalar kSpinTolerance = 0.01;  // |omega - omega_rigid| / |omega_rigid|, uncapped contacts
constexpr Scalar kMomentumTolerance = 1e-13;  // |dp| / sum |p_i|
// |dL| / (sum |x_i - P| |p_i| + |I_i w_i|): second order in the sub-step
Scalar angularMomentumTolerance(int n) { return 1e-3 / (Scalar(n) * n); }
constexpr Scalar kEnergyTolerance = 1e-9;   // KE(t) <= KE(0) (1 + tol)
constexpr Scalar kOverlapTolerance = 0.15;  // max overlap / a_min (cap 0.1)

// ---------------------------------------------------------------------------
// Checks: each named check keeps its worst value and where it occurred.
struct Check {
  std::string name;
  std::string rule;   // e.g. "<= 0.01"
  bool upper = true;  // the value must be <= tol (else >= tol)
  Scalar tol = 0;
  Scalar worst = 0;
  std::string worstCase;
  long count = 0;
  long failed = 0;
  std::string firstFailure;
};

class Checks {
 public:
  void atMost(const std::string& name, Scalar value, Scalar tol, const std::string& where) {
    add(name, true, value, tol, where);
  }
  void atLeast(const std::string& name, Scalar value, Scalar tol, const std::string& where) {
    add(name, false, value, tol, where);
  }
  /// ok must be true; the value shown is the number of failures
  void require(const std::string& name, bool ok, const std::string& where) {
    add(name, true, ok ? 0 : 1, 0, where);
  }
  void note(const std::string& text) { notes_.push_back(text); }
  bool allPassed() const {
    for (const Check& c : list_) {
      if (c.failed > 0) return false;
    }
    return true;
  }
  void report(std::ostream& os) const {
    // '|' in a name would end a markdown table cell
    auto cell = [](const std::string& text) {
      std::string t;
      for (char ch : text) t += ch == '|' ? std::string("\\|") : std::string(1, ch);
      return t;
    };
    os << "| check | rule | worst | worst case | cases | failed |\n|---|---|---|---|---|---|\n";
    for (const Check& c : list_) {
      std::ostringstream v;
      v << std::setprecision(3) << c.worst;
      os << "| " << cell(c.name) << " | " << c.rule << " | " << v.str() << " | " << c.worstCase
         << " | " << c.count << " | " << c.failed << " |\n";
    }
    os << "\n";
    for (const std::string& n : notes_) os << "- " << n << "\n";
    for (const Check& c : list_) {
      if (c.failed > 0) os << "\nFAILED " << c.name << ": first at " << c.firstFailure << "\n";
    }
  }

 private:
  void add(const std::string& name, bool upper, Scalar value, Scalar tol,
           const std::string& where) {
    auto it = index_.find(name);
    if (it == index_.end()) {
      Check c;
      c.name = name;
      c.upper = upper;
      c.tol = tol;
      std::ostringstream r;
      r << (upper ? "<= " : ">= ") << tol;
      c.rule = r.str();
      c.worst = upper ? -kInf : kInf;
      it = index_.emplace(name, list_.size()).first;
      list_.push_back(c);
    }
    Check& c = list_[it->second];
    ++c.count;
    const bool ok = upper ? value <= tol : value >= tol;  // NaN fails
    const bool worse = std::isnan(value) || (upper ? value > c.worst : value < c.worst);
    if (worse && !std::isnan(c.worst)) {
      c.worst = value;
      c.worstCase = where;
    }
    if (!ok) {
      if (c.failed == 0) {
        std::ostringstream f;
        f << where << " (value " << value << ")";
        c.firstFailure = f.str();
      }
      ++c.failed;
    }
  }
  std::vector<Check> list_;
  std::vector<std::string> notes_;
  std::map<std::string, std::size_t> index_;
};

// ---------------------------------------------------------------------------
// Bodies and helpers

RigidBody makeBody(const Vec3& semiAxes, const Vec3& centre, const Quat& q, const Vec3& u) {
  RigidBody b;
  b.semiAxes = semiAxes;
  b.centre = centre;
  b.orientation = q;
  b.velocity = u;
  b.density = 1;
  return b;
}

Vec3 spheroidAxes(Scalar ar) {
  return ellipsoids::Ellipsoid::spheroid(ar, kDeq, Vec3::Zero(), Quat::Identity()).semiAxes();
}

ellipsoids::Ellipsoid shapeOf(const RigidBody& b) {
  return ellipsoids::Ellipsoid(b.semiAxes, b.centre, b.orientation);
}

bool finite(const std::vector<RigidBody>& bodies) {
  for (const RigidBody& b : bodies) {
    if (!b.centre.allFinite() || !b.velocity.allFinite() || !b.angularVelocity.allFinite() ||
        !b.orientation.coeffs().allFinite()) {
      return false;
    }
  }
  return true;
}

Scalar kineticEnergy(const std::vector<RigidBody>& bodies) {
  Scalar k = 0;
  for (const RigidBody& b : bodies) k += b.kineticEnergy();
  return k;
}

Vec3 linearMomentum(const std::vector<RigidBody>& bodies) {
  Vec3 p = Vec3::Zero();
  for (const RigidBody& b : bodies) p += b.linearMomentum();
  return p;
}

/// Angular momentum about the fixed point P, and its scale sum |x_i - P| |p_i| + |I_i w_i|.
Vec3 angularMomentum(const std::vector<RigidBody>& bodies, const Vec3& P, Scalar* scale) {
  Vec3 l = Vec3::Zero();
  Scalar s = 0;
  for (const RigidBody& b : bodies) {
    const Vec3 spin = b.worldInertia(b.orientation) * b.angularVelocity;
    l += (b.centre - P).cross(b.linearMomentum()) + spin;
    s += (b.centre - P).norm() * b.linearMomentum().norm() + spin.norm();
  }
  if (scale) *scale = s;
  return l;
}

Vec3 pointVelocity(const RigidBody& b, const Vec3& x) {
  return b.velocity + b.angularVelocity.cross(x - b.centre);
}

const PlaneWall kFloor{"floor", Vec3::Zero(), Vec3::UnitZ()};

/// Normal speed (along +z) of the body point nearest the floor z = 0 (DryCollisionTest).
Scalar wallNormalSpeed(const RigidBody& b) {
  const WallDistance d = wallDistance(shapeOf(b), kFloor);
  return pointVelocity(b, d.bodyPoint).z();
}

/// Accurate signed distance (dual method, negative: penetration depth).
ellipsoids::DistanceResult signedDistance(const RigidBody& a, const RigidBody& b, Scalar epsD,
                                          const Vec3* warm = nullptr) {
  ellipsoids::DistanceOptions o;
  o.epsD = epsD;
  if (warm) {
    o.useInitialDirection = true;
    o.initialDirection = *warm;
  }
  return ellipsoids::DualNewton().distance(shapeOf(a), shapeOf(b), o);
}

std::string fmt(Scalar x, int precision = 4) {
  std::ostringstream s;
  s << std::setprecision(precision) << x;
  return s.str();
}

/**
 * Fluid steps dt = T_c/5, each in the sub-steps the model asks for (as
 * collisionStep), until after() returns true or the time reaches tMax.
 * after(h, n) is called after each sub-step (h its length, n the sub-steps of
 * the fluid step). Returns true if after() ended the run.
 */
template <class After>
bool advance(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar tMax, Scalar& time,
             After&& after) {
  std::vector<CollisionBody> cb;
  while (time < tMax) {
    cb.clear();
    for (const RigidBody& b : bodies) cb.push_back(b.collisionBody());
    const int n = model.subSteps(cb, kDt, kTc);
    const Scalar h = kDt / n;
    for (int k = 0; k < n; ++k) {
      collisionSubStep(bodies, model, kTc, h);
      time += h;
      if (after(h, n)) return true;
    }
  }
  return false;
}

/// CollisionSettings::approachContactTimeScale of every run (--approach-scale,
/// the sensitivity of the results to the approach check's bound)
Scalar approachContactTimeScale = CollisionSettings().approachContactTimeScale;

/// The numerical settings and the laws' parameters of a dry run (model springDashpot).
struct DrySettings {
  CollisionSettings settings;
  InteractionParameters laws;
};

DrySettings contactSettings(Scalar e, int n, Scalar friction = 0) {
  DrySettings s;
  s.laws.contact.restitution = e;
  s.laws.contact.friction = friction;
  s.settings.subStepsPerContact = n;
  s.settings.maxOverlap = kMaxOverlap;
  s.settings.approachContactTimeScale = approachContactTimeScale;
  return s;
}

/// The collision model of a dry run: springDashpot pairs and walls, no film correction.
CollisionModel dryModel(const DrySettings& s, std::vector<PlaneWall> walls) {
  return CollisionModel(s.settings, PairModel::New("springDashpot", s.laws),
                        WallModel::New("springDashpot", s.laws), std::move(walls));
}

struct Options {
  bool quick = false;
  std::string out = DRYCOLLISIONS_RESULTS;
  std::string only;  // run only the parts whose name starts with this
};

std::ofstream openCsv(const Options& o, const std::string& name, const std::string& header) {
  std::ofstream f(o.out + "/" + name);
  if (!f) throw std::runtime_error("cannot write " + o.out + "/" + name);
  f << std::setprecision(10) << header << "\n";
  return f;
}

// ---------------------------------------------------------------------------
// 1 and 2: head-on spheres, pair (1:1 and 1:8 masses) and wall

struct HeadOn {
  bool ok = false;  // the contact happened and ended, all finite
  std::string error;
  Scalar eMeasured = 0;
  Scalar momentumError = 0;
  Scalar energyLossError = 0;  // (KE0 - KE1)/(1/2 (1 - e^2) m_eff u0^2) - 1
  Scalar keMaxRatio = 0;       // max KE(t)/KE(0) - 1
  Scalar maxOverlapRatio = 0;
  int contactSubSteps = 0;
  int subStepsPerFluidStep = 0;
  Scalar spin = 0;  // |omega| after (spheres: must stay 0)
};

/// kind: "1:1", "1:8" (a sphere of D 1/2 onto one of D 1 at rest) or "wall".
HeadOn headOn(const std::string& kind, Scalar e, int n, Scalar phase, Scalar u0) {
  const Scalar h = kTc / n;
  const Scalar g0 = u0 * h * (1 + phase);  // first touch at `phase` into the second sub-step
  std::vector<RigidBody> b;
  std::vector<PlaneWall> walls;
  Scalar mEff = 0;
  if (kind == "1:1") {
    b.push_back(makeBody(Vec3::Constant(0.5), Vec3(-0.5 - g0 / 2, 0, 0), Quat::Identity(),
                         Vec3(u0 / 2, 0, 0)));
    b.push_back(makeBody(Vec3::Constant(0.5), Vec3(0.5 + g0 / 2, 0, 0), Quat::Identity(),
                         Vec3(-u0 / 2, 0, 0)));
  } else if (kind == "1:8") {
    b.push_back(
        makeBody(Vec3::Constant(0.25), Vec3(-0.25 - g0, 0, 0), Quat::Identity(), Vec3(u0, 0, 0)));
    b.push_back(makeBody(Vec3::Constant(0.5), Vec3(0.5, 0, 0), Quat::Identity(), Vec3::Zero()));
  } else {
    b.push_back(
        makeBody(Vec3::Constant(0.5), Vec3(0, 0, 0.5 + g0), Quat::Identity(), Vec3(0, 0, -u0)));
    walls.push_back(kFloor);
  }
  if (b.size() == 2) {
    mEff = b[0].mass() * b[1].mass() / (b[0].mass() + b[1].mass());
  } else {
    mEff = b[0].mass();
  }
  CollisionModel model = dryModel(contactSettings(e, n), walls);
  const Vec3 p0 = linearMomentum(b);
  Scalar pScale = 0;
  for (const RigidBody& x : b) pScale += x.linearMomentum().norm();
  const Scalar ke0 = kineticEnergy(b);
  HeadOn r;
  bool touched = false;
  Scalar time = 0;
  try {
    const bool ended = advance(b, model, g0 / u0 + 10 * kTc, time, [&](Scalar, int sub) {
      r.keMaxRatio = std::max(r.keMaxRatio, kineticEnergy(b) / ke0 - 1);
      if (model.activeContacts() > 0) {
        touched = true;
        ++r.contactSubSteps;
        r.subStepsPerFluidStep = std::max(r.subStepsPerFluidStep, sub);
      }
      return touched && model.activeContacts() == 0;
    });
    if (!ended) r.error = "the contact did not end";
  } catch (const std::exception& ex) {
    r.error = ex.what();
  }
  if (!finite(b)) r.error = "non-finite state";
  r.ok = r.error.empty();
  if (b.size() == 2) {
    r.eMeasured = (b[1].velocity.x() - b[0].velocity.x()) / u0;  // u0 approaching
    r.momentumError = (linearMomentum(b) - p0).norm() / pScale;
    r.spin = b[0].angularVelocity.norm() + b[1].angularVelocity.norm();
  } else {
    r.eMeasured = b[0].velocity.z() / u0;
    r.momentumError = (b[0].velocity - Vec3(0, 0, r.eMeasured * u0)).norm() / u0;  // stays along z
    r.spin = b[0].angularVelocity.norm();
  }
  r.energyLossError = (ke0 - kineticEnergy(b)) / (0.5 * (1 - e * e) * mEff * u0 * u0) - 1;
  r.maxOverlapRatio = model.statistics().maxOverlapRatio;
  return r;
}

void headOnSet(const Options& o, Checks& checks, bool wall) {
  const std::vector<std::string> kinds =
      wall ? std::vector<std::string>{"wall"} : std::vector<std::string>{"1:1", "1:8"};
  const std::vector<Scalar> es =
      o.quick ? std::vector<Scalar>{0.97, 0.5, 0.1} : std::vector<Scalar>{0.97, 0.9, 0.5, 0.1};
  const std::vector<int> ns = o.quick ? std::vector<int>{5, 20} : std::vector<int>{5, 10, 20, 50};
  const std::vector<Scalar> phases =
      o.quick ? std::vector<Scalar>{0.0, 0.4, 0.8} : std::vector<Scalar>{0.0, 0.2, 0.4, 0.6, 0.8};
  // approach speed (D_eq/T_c): below the overlap cap's speed for every N (the
  // contact time is T_c and the sub-steps per fluid step N/5)
  const Scalar u0 = 0.02;
  std::ofstream csv =
      openCsv(o, wall ? "sphereWall.csv" : "sphereSphere.csv",
              "case,e,N,phase,eMeasured,relError,momentumError,energyLossError,"
              "keMaxRatio,maxOverlapRatio,contactSubSteps,subStepsPerFluidStep,spin");
  const std::string part = wall ? "2 sphere-wall" : "1 sphere-sphere";
  for (const std::string& kind : kinds) {
    for (Scalar e : es) {
      for (int n : ns) {
        for (Scalar phase : phases) {
          const HeadOn r = headOn(kind, e, n, phase, u0);
          const std::string where =
              kind + " e=" + fmt(e) + " N=" + std::to_string(n) + " phase=" + fmt(phase);
          checks.require(part + ": contact made and ended, finite", r.ok, where + " " + r.error);
          const Scalar rel = r.eMeasured / e - 1;
          csv << kind << "," << e << "," << n << "," << phase << "," << r.eMeasured << "," << rel
              << "," << r.momentumError << "," << r.energyLossError << "," << r.keMaxRatio << ","
              << r.maxOverlapRatio << "," << r.contactSubSteps << "," << r.subStepsPerFluidStep
              << "," << r.spin << "\n";
          checks.atMost(part + ": |e_meas - e|, N = " + std::to_string(n),
                        std::abs(r.eMeasured - e), restitutionTolerance(n), where);
          checks.atMost(part + (wall ? ": velocity off the normal / u0" : ": |dp| / sum |p_i|"),
                        r.momentumError, kMomentumTolerance, where);
          checks.atMost(part + ": max KE(t)/KE(0) - 1", r.keMaxRatio, kEnergyTolerance, where);
          checks.atMost(part + ": spin after (sphere, head-on)", r.spin, 0, where);
          // the sub-steps the model gives a contact: N, or N + 1 when the
          // touch or the release falls near a sub-step boundary
          if (n >= 10) {
            checks.require(part + ": contact sub-steps N or N + 1 (N >= 10)",
                           r.contactSubSteps == n || r.contactSubSteps == n + 1, where);
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// 3: spheroid on a wall, tilted

void spheroidWall(const Options& o, Checks& checks) {
  const std::vector<Scalar> ars =
      std::vector<Scalar>{1.0 / 6, 1.0 / 3, 3, 6};
  const std::vector<Scalar> tilts =
      o.quick ? std::vector<Scalar>{0, 15, 60, 75, 90} : std::vector<Scalar>{0, 15, 30, 45, 60, 75, 90};
  const std::vector<Scalar> es{0.97, 0.5};
  const std::vector<int> ns = o.quick ? std::vector<int>{10} : std::vector<int>{10, 20, 50};
  // slow, slower: contact time T_c (uncapped; the body turns through
  // ~0.01 and ~0.001 rad during the contact); fast: the overlap cap shortens
  // the contact to pi maxOverlap a_min / u (the overlap reaches ~0.1 a_min,
  // the body turns through up to ~0.25 rad)
  const std::vector<std::pair<std::string, Scalar>> speeds =
      o.quick ? std::vector<std::pair<std::string, Scalar>>{{"slow", 0.005}, {"fast", 1.0}}
              : std::vector<std::pair<std::string, Scalar>>{
                    {"slower", 0.0005}, {"slow", 0.005}, {"fast", 1.0}};
  std::ofstream csv =
      openCsv(o, "spheroidWall.csv",
              "ar,tiltDeg,e,N,speedCase,speed,eMeasured,relError,spinY,spinRigidY,spinError,"
              "vzMeasured,vzRigid,contactTime,contactTimeModel,thetaContact,maxOverlapRatio,"
              "energyLossError,keChange,contactSubSteps");
  for (Scalar ar : ars) {
    for (Scalar tilt : tilts) {
      for (Scalar e : es) {
        for (int n : ns) {
          for (const auto& [speedCase, u] : speeds) {
            RigidBody b = makeBody(spheroidAxes(ar), Vec3::Zero(),
                                   Quat(Eigen::AngleAxis<Scalar>(tilt * kPi / 180, Vec3::UnitY())),
                                   Vec3(0, 0, -u));
            // the contact point and arm, and the rigid-impact prediction
            // (frictionless, constant m_eff): J = (1 + e) m_eff u,
            // dv = J/m z, dw = I^-1 (r x z) J
            const Scalar support =
                std::sqrt(Vec3::UnitZ().dot(shapeOf(b).shapeMatrix() * Vec3::UnitZ()));
            const Scalar h0 = kTc / n;
            const Scalar g0 = u * h0 * 1.37;
            b.centre = Vec3(0, 0, support + g0);
            const WallDistance wd = wallDistance(shapeOf(b), kFloor);
            const Vec3 arm = wd.bodyPoint - b.centre;
            const Mat3 Iinv = b.worldInertia(b.orientation).inverse();
            const Vec3 rxn = arm.cross(Vec3::UnitZ());
            const Scalar mEff = 1 / (1 / b.mass() + rxn.dot(Iinv * rxn));
            const Scalar J = (1 + e) * mEff * u;
            const Vec3 spinRigid = Iinv * rxn * J;
            const Scalar vzRigid = -u + J / b.mass();
            const Scalar aMin = b.semiAxes.minCoeff();
            const Scalar tcModel = std::min(kTc, kPi * kMaxOverlap * aMin / u);

            std::vector<RigidBody> bodies{b};
            CollisionModel model = dryModel(contactSettings(e, n), {kFloor});
            const Scalar before = wallNormalSpeed(bodies[0]);
            const Scalar ke0 = kineticEnergy(bodies);
            bool touched = false;
            Scalar contactTime = 0, time = 0;
            int contactSubSteps = 0;
            std::string error;
            try {
              if (!advance(bodies, model, g0 / u + 20 * kTc, time, [&](Scalar h, int) {
                    if (model.activeContacts() > 0) {
                      touched = true;
                      contactTime += h;
                      ++contactSubSteps;
                    }
                    return touched && model.activeContacts() == 0;
                  })) {
                error = "the contact did not end";
              }
            } catch (const std::exception& ex) {
              error = ex.what();
            }
            if (!finite(bodies)) error = "non-finite state";
            const RigidBody& a = bodies[0];
            const Scalar after = wallNormalSpeed(a);
            const Scalar eMeasured = -after / before;
            const Scalar rel = eMeasured / e - 1;
            const Scalar spinError =
                (a.angularVelocity - spinRigid).norm() / std::max(spinRigid.norm(), 1e-300);
            const Scalar theta = a.angularVelocity.norm() * contactTime;
            const Scalar energyLossError =
                (ke0 - a.kineticEnergy()) / (0.5 * (1 - e * e) * mEff * u * u) - 1;
            csv << ar << "," << tilt << "," << e << "," << n << "," << speedCase << "," << u << ","
                << eMeasured << "," << rel << "," << a.angularVelocity.y() * kDeq / u << ","
                << spinRigid.y() * kDeq / u << "," << (spinRigid.norm() > 0 ? spinError : 0) << ","
                << a.velocity.z() / u << "," << vzRigid / u << "," << contactTime << "," << tcModel
                << "," << theta << "," << model.statistics().maxOverlapRatio << ","
                << energyLossError << "," << a.kineticEnergy() / ke0 - 1 << "," << contactSubSteps
                << "\n";
            const std::string where = "Ar=" + fmt(ar, 3) + " tilt=" + fmt(tilt) + " e=" + fmt(e) +
                                      " N=" + std::to_string(n) + " " + speedCase;
            checks.require("3 spheroid-wall: contact made and ended, finite", error.empty(),
                           where + " " + error);
            checks.atMost("3 spheroid-wall: max overlap / a_min",
                          model.statistics().maxOverlapRatio, kOverlapTolerance, where);
            checks.atMost("3 spheroid-wall: KE(end)/KE(0) - 1 (energy never gained)",
                          a.kineticEnergy() / ke0 - 1, kEnergyTolerance, where);
            const bool capped = tcModel < kTc;
            const bool tilted = spinRigid.norm() > 1e-6 * u / kDeq;
            if (!capped) {
              checks.atMost(
                  "3 spheroid-wall: |e_meas - e| - theta_c, uncapped, N = " + std::to_string(n),
                  std::abs(eMeasured - e) - kTurnAllowance * theta, restitutionTolerance(n), where);
              if (tilted) {
                checks.atMost("3 spheroid-wall: |w - w_rigid|/|w_rigid|, uncapped", spinError,
                              kSpinTolerance, where);
              }
            } else if (!tilted) {
              checks.atMost(
                  "3 spheroid-wall: |e_meas - e|, capped, untilted, N = " + std::to_string(n),
                  std::abs(eMeasured - e), restitutionTolerance(n), where);
            }
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// 4 and 5: two spheroids

/**
 * Place body b (orientation given) on the line c_b = c_a + s x + offset y at
 * the largest s where the signed distance is g0 (the bodies approach along x).
 * Returns false if the line never comes within g0 (a miss).
 */
bool placeOnApproach(const RigidBody& a, RigidBody& b, Scalar offset, Scalar g0) {
  const Scalar epsD = 1e-13;
  const Scalar far = a.semiAxes.maxCoeff() + b.semiAxes.maxCoeff() + 1;
  auto d = [&](Scalar s) {
    b.centre = a.centre + Vec3(s, offset, 0);
    return signedDistance(a, b, epsD).distance;
  };
  // the signed distance is convex along the line (that of the relative
  // position to the convex configuration obstacle): golden section for its
  // minimum, then bisection on the receding side
  const Scalar phi = (std::sqrt(5.0) - 1) / 2;
  Scalar lo = -far, hi = far;
  Scalar x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
  Scalar f1 = d(x1), f2 = d(x2);
  for (int i = 0; i < 80; ++i) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - phi * (hi - lo);
      f1 = d(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + phi * (hi - lo);
      f2 = d(x2);
    }
  }
  Scalar sMin = 0.5 * (lo + hi);
  if (d(sMin) > g0) return false;
  lo = sMin;
  hi = far;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * far; ++i) {
    const Scalar mid = 0.5 * (lo + hi);
    (d(mid) > g0 ? hi : lo) = mid;
  }
  d(hi);
  return true;
}

/// The lateral offset at which the approach along x just grazes (min signed distance 0).
Scalar grazingOffset(const RigidBody& a, RigidBody b) {
  Scalar lo = 0, hi = a.semiAxes.maxCoeff() + b.semiAxes.maxCoeff();
  for (int i = 0; i < 60; ++i) {
    const Scalar mid = 0.5 * (lo + hi);
    (placeOnApproach(a, b, mid, 0) ? lo : hi) = mid;
  }
  return lo;
}

struct PairRun {
  std::string error;
  bool touched = false;
  int episodes = 0;               // separate contacts (the model's view)
  Scalar maxOverlapRatio = 0;     // the model's statistics (predictor states included)
  Scalar maxDepthRatio = 0;       // monitor: max penetration depth / a_min at sub-step ends
  Scalar minCentreMargin = kInf;  // min over contacts of (c2 - c1).n0 / (a_min,1 + a_min,2)
  Scalar finalDistance = 0;
  bool apart = false;  // bounding spheres disjoint and receding at the end
  long notConverged = 0;
  long distanceQueries = 0;
  long subSteps = 0;
  Scalar time = 0;
  Scalar momentumError = 0;
  Scalar angularMomentumError = 0;
  Scalar keMaxRatio = 0;    // max KE(t)/KE(0) - 1
  Scalar keFinalRatio = 0;  // KE(end)/KE(0)
  Scalar eContact = -1;  // frictionless single contact: -u_n,after/u_n,before at the contact point
  Scalar impactSpeed = 0;  // -u_n before the first contact
  Scalar maxSpin = 0;
};

/**
 * Two bodies until they are certainly apart for good (bounding spheres
 * disjoint and their centres receding: in vacuum they never meet again) or tMax.
 */
PairRun runPair(std::vector<RigidBody>& b, const DrySettings& settings, Scalar tMax,
                const Vec3& P) {
  PairRun r;
  CollisionModel model = dryModel(settings, {});
  const Vec3 p0 = linearMomentum(b);
  Scalar pScale = 0;
  for (const RigidBody& x : b) pScale += x.linearMomentum().norm();
  Scalar lScale0 = 0;
  const Vec3 l0 = angularMomentum(b, P, &lScale0);
  const Scalar ke0 = kineticEnergy(b);
  const Scalar aSum = b[0].semiAxes.minCoeff() + b[1].semiAxes.minCoeff();
  const Scalar aMin = std::min(b[0].semiAxes.minCoeff(), b[1].semiAxes.minCoeff());
  const Scalar reach = b[0].semiAxes.maxCoeff() + b[1].semiAxes.maxCoeff();
  const Scalar epsD = 1e-10;

  bool inContact = false, modelContact = false;
  Vec3 n0 = Vec3::UnitX(), warm = Vec3::UnitX();
  bool haveWarm = false;
  Scalar unBefore = 0;
  int monitorEpisodes = 0;
  // the normal speed of the closest points' midpoint (from 1 to 2; < 0 approaching)
  auto normalSpeed = [&](const ellipsoids::DistanceResult& d) {
    const Vec3 x = 0.5 * (d.point1 + d.point2);
    return (pointVelocity(b[1], x) - pointVelocity(b[0], x)).dot(d.direction);
  };
  auto monitor = [&](bool first) {
    const Vec3 c = b[1].centre - b[0].centre;
    if (c.norm() > reach) {
      inContact = false;
      haveWarm = false;
      return c.norm() - reach;
    }
    const ellipsoids::DistanceResult d =
        signedDistance(b[0], b[1], epsD, haveWarm ? &warm : nullptr);
    if (d.direction.allFinite()) {
      warm = d.direction;
      haveWarm = true;
    }
    if (d.distance < 0) {
      if (!inContact) {
        inContact = true;
        ++monitorEpisodes;
        n0 = d.direction;
      }
      r.maxDepthRatio = std::max(r.maxDepthRatio, -d.distance / aMin);
      r.minCentreMargin = std::min(r.minCentreMargin, c.dot(n0) / aSum);
    } else {
      if (inContact && monitorEpisodes == 1) {
        r.eContact = unBefore < 0 ? -normalSpeed(d) / unBefore : -1;
      }
      inContact = false;
      if (monitorEpisodes == 0 || first) {
        unBefore = normalSpeed(d);
        r.impactSpeed = -unBefore;
      }
    }
    return d.distance;
  };
  try {
    monitor(true);
    const bool ended = advance(b, model, tMax, r.time, [&](Scalar, int) {
      ++r.subSteps;
      const Scalar ke = kineticEnergy(b);
      r.keMaxRatio = std::max(r.keMaxRatio, ke / ke0 - 1);
      for (const RigidBody& x : b) r.maxSpin = std::max(r.maxSpin, x.angularVelocity.norm());
      if (model.activeContacts() > 0) {
        r.touched = true;
        if (!modelContact) ++r.episodes;
        modelContact = true;
      } else {
        modelContact = false;
      }
      r.finalDistance = monitor(false);
      if (!finite(b)) throw std::runtime_error("non-finite state");
      const Vec3 c = b[1].centre - b[0].centre;
      return r.touched && !modelContact && c.norm() > reach &&
             c.dot(b[1].velocity - b[0].velocity) > 0;
    });
    r.apart = ended;
  } catch (const std::exception& ex) {
    r.error = ex.what();
  }
  if (monitorEpisodes != 1 || settings.laws.contact.friction > 0) r.eContact = -1;
  r.notConverged = model.statistics().distanceNotConverged;
  r.distanceQueries = model.statistics().distanceQueries;
  r.maxOverlapRatio = model.statistics().maxOverlapRatio;
  r.momentumError = (linearMomentum(b) - p0).norm() / pScale;
  r.angularMomentumError = (angularMomentum(b, P, nullptr) - l0).norm() / lScale0;
  r.keFinalRatio = kineticEnergy(b) / ke0;
  if (!finite(b) && r.error.empty()) r.error = "non-finite state";
  return r;
}

/// A deterministic pseudo-random unit quaternion (portable: no std distributions).
Quat randomRotation(std::uint64_t& state) {
  auto next = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return Scalar(state >> 11) / Scalar(1ULL << 53);
  };
  const Scalar u1 = next(), u2 = next(), u3 = next();
  return Quat(std::sqrt(1 - u1) * std::sin(2 * kPi * u2),
              std::sqrt(1 - u1) * std::cos(2 * kPi * u2), std::sqrt(u1) * std::sin(2 * kPi * u3),
              std::sqrt(u1) * std::cos(2 * kPi * u3));
}

void spheroidPairs(const Options& o, Checks& checks) {
  const std::vector<std::pair<Scalar, Scalar>> pairs =
      o.quick ? std::vector<std::pair<Scalar, Scalar>>{{3, 1.0 / 3}, {6, 1.0 / 6}}
              : std::vector<std::pair<Scalar, Scalar>>{
                    {3, 1.0 / 3}, {6, 1.0 / 6}, {3, 3}, {1.0 / 3, 1.0 / 3}, {6, 1}};
  const int orientations = o.quick ? 1 : 2;
  const std::vector<Scalar> offsets =
      o.quick ? std::vector<Scalar>{0, 0.6} : std::vector<Scalar>{0, 0.3, 0.6, 0.9};
  const std::vector<Scalar> frictions{0, 0.3};
  const std::vector<Scalar> es = o.quick ? std::vector<Scalar>{0.5} : std::vector<Scalar>{0.9, 0.5};
  // 10: the model's default sub-steps per contact; 20: the order of the L error
  const std::vector<int> ns = o.quick ? std::vector<int>{10} : std::vector<int>{10, 20};
  const Scalar u = 0.02;          // relative approach speed, D_eq/T_c
  const Vec3 where0(2, -1, 0.5);  // the collision happens here, L is about the origin
  std::ofstream csv = openCsv(
      o, "spheroidPairs.csv",
      "ar1,ar2,orientation,offset,friction,e,N,impactSpeed,eContact,momentumError,"
      "angularMomentumError,keMaxRatio,keFinalRatio,episodes,maxOverlapRatio,minCentreMargin,"
      "finalDistance,apart,notConverged,subSteps");
  int index = 0;
  std::vector<Scalar> eContactErrors;
  for (const auto& [ar1, ar2] : pairs) {
    for (int k = 0; k < orientations; ++k) {
      std::uint64_t seed = 12345 + 1000 * index++ + k;
      const Quat q1 = randomRotation(seed), q2 = randomRotation(seed);
      for (Scalar offset : offsets) {
        for (Scalar mu : frictions) {
          for (Scalar e : es) {
            for (int n : ns) {
              RigidBody a = makeBody(spheroidAxes(ar1), where0, q1, Vec3(u / 2, 0.05 * u, 0));
              RigidBody c =
                  makeBody(spheroidAxes(ar2), Vec3::Zero(), q2, Vec3(-u / 2, 0, 0.03 * u));
              a.angularVelocity = Vec3(0.1, 0.2, -0.3) * u / kDeq;
              c.angularVelocity = Vec3(-0.2, 0.1, 0.1) * u / kDeq;
              if (!placeOnApproach(a, c, offset, 0.02 * kDeq)) {
                csv << ar1 << "," << ar2 << "," << k << "," << offset << "," << mu << "," << e
                    << "," << n << ",miss\n";
                continue;
              }
              std::vector<RigidBody> b{a, c};
              const PairRun r = runPair(b, contactSettings(e, n, mu), 400 * kTc, Vec3::Zero());
              csv << ar1 << "," << ar2 << "," << k << "," << offset << "," << mu << "," << e << ","
                  << n << "," << r.impactSpeed << "," << r.eContact << "," << r.momentumError << ","
                  << r.angularMomentumError << "," << r.keMaxRatio << "," << r.keFinalRatio << ","
                  << r.episodes << "," << r.maxOverlapRatio << "," << r.minCentreMargin << ","
                  << r.finalDistance << "," << r.apart << "," << r.notConverged << "," << r.subSteps
                  << "\n";
              const std::string where = "Ar " + fmt(ar1, 3) + "/" + fmt(ar2, 3) + " q" +
                                        std::to_string(k) + " b=" + fmt(offset) + " mu=" + fmt(mu) +
                                        " e=" + fmt(e) + " N=" + std::to_string(n);
              checks.require("4 spheroid pairs: contact, no error, apart at the end",
                             r.error.empty() && r.touched && r.apart, where + " " + r.error);
              checks.atMost("4 spheroid pairs: |dp| / sum |p_i|", r.momentumError,
                            kMomentumTolerance, where);
              checks.atMost("4 spheroid pairs: |dL| / L scale (about a fixed point), N = " +
                                std::to_string(n),
                            r.angularMomentumError, angularMomentumTolerance(n), where);
              checks.atMost("4 spheroid pairs: max KE(t)/KE(0) - 1", r.keMaxRatio, kEnergyTolerance,
                            where);
              checks.atMost("4 spheroid pairs: max overlap / a_min", r.maxOverlapRatio,
                            kOverlapTolerance, where);
              if (r.eContact >= 0) eContactErrors.push_back(std::abs(r.eContact - e));
            }
          }
        }
      }
    }
  }
  if (!eContactErrors.empty()) {
    // not a check: the contact point of two turning bodies moves during the
    // contact, and the closest points before and after are not one material point
    std::sort(eContactErrors.begin(), eContactErrors.end());
    std::ostringstream note;
    note << "4 spheroid pairs, frictionless single contacts (" << eContactErrors.size()
         << "): |e_contact - e| median " << fmt(eContactErrors[eContactErrors.size() / 2], 3)
         << ", max " << fmt(eContactErrors.back(), 3)
         << " (normal speed of the closest points' midpoint, the sub-steps before and after)";
    checks.note(note.str());
  }
}

void extremes(const Options& o, Checks& checks) {
  // Ar 6 (prolate, body 1, moving +x) against Ar 1/6 (oblate, body 2, -x), D_eq 1.
  // alpha: angle between the approach direction and the oblate's flat faces
  // (0: the prolate slides along a face; 90: face-on). The prolate's axis:
  // along the approach (x), 45 degrees in the x-y plane, across it (y) or
  // out of it (z). The offset along y is f times the grazing offset b_g (the
  // approach then just touches): f = 0.999 is a grazing impact.
  const std::vector<Scalar> alphas =
      o.quick ? std::vector<Scalar>{1, 20, 90} : std::vector<Scalar>{0, 1, 5, 20, 90};
  const std::vector<std::string> axes = o.quick ? std::vector<std::string>{"x", "z"}
                                                : std::vector<std::string>{"x", "xy45", "y", "z"};
  const std::vector<Scalar> fractions =
      o.quick ? std::vector<Scalar>{0, 0.9, 0.999} : std::vector<Scalar>{0, 0.5, 0.9, 0.99, 0.999};
  const std::vector<Scalar> speeds =
      o.quick ? std::vector<Scalar>{0.01, 1, 100} : std::vector<Scalar>{0.01, 0.1, 1, 10, 100};
  const std::vector<Scalar> gaps =
      o.quick ? std::vector<Scalar>{1e-6, -1e-6} : std::vector<Scalar>{1e-6, 0, -1e-6};
  const std::vector<Scalar> frictions =
      o.quick ? std::vector<Scalar>{0.3} : std::vector<Scalar>{0, 0.3};
  const Scalar e = 0.9;
  const int n = 10;
  std::ofstream csv = openCsv(
      o, "extremes.csv",
      "prolateAxis,alphaDeg,fraction,offset,speed,gap,friction,maxOverlapRatio,maxDepthRatio,"
      "minCentreMargin,finalDistance,apart,episodes,notConverged,distanceQueries,subSteps,time,"
      "momentumError,angularMomentumError,keFinalRatio,keMaxRatio,maxSpin,error");
  const Vec3 prolate = spheroidAxes(6), oblate = spheroidAxes(1.0 / 6);
  long notConverged = 0, queries = 0, notApart = 0;
  for (const std::string& axis : axes) {
    Quat q1 = Quat::Identity();
    if (axis == "xy45") q1 = Quat(Eigen::AngleAxis<Scalar>(kPi / 4, Vec3::UnitZ()));
    if (axis == "y") q1 = Quat(Eigen::AngleAxis<Scalar>(kPi / 2, Vec3::UnitZ()));
    if (axis == "z") q1 = Quat(Eigen::AngleAxis<Scalar>(-kPi / 2, Vec3::UnitY()));
    for (Scalar alpha : alphas) {
      // oblate axis (sin alpha, cos alpha, 0): its faces make alpha with x
      const Quat q2(Eigen::AngleAxis<Scalar>(kPi / 2 - alpha * kPi / 180, Vec3::UnitZ()));
      const RigidBody a0 = makeBody(prolate, Vec3::Zero(), q1, Vec3::Zero());
      const RigidBody c0 = makeBody(oblate, Vec3::Zero(), q2, Vec3::Zero());
      const Scalar bGraze = grazingOffset(a0, c0);
      for (Scalar f : fractions) {
        for (Scalar gap : gaps) {
          RigidBody c = c0;
          if (!placeOnApproach(a0, c, f * bGraze, gap)) {
            checks.require("5 extremes: placement", false, axis + " alpha=" + fmt(alpha));
            continue;
          }
          for (Scalar speed : speeds) {
            for (Scalar mu : frictions) {
              RigidBody a = a0;
              RigidBody cc = c;
              a.velocity = Vec3(speed / 2, 0, 0);
              cc.velocity = Vec3(-speed / 2, 0, 0);
              std::vector<RigidBody> b{a, cc};
              // long enough to separate for good: ~40 contact times and 6 D_eq of travel
              const Scalar tcEff = std::min(kTc, kPi * kMaxOverlap * oblate.minCoeff() / speed);
              const PairRun r = runPair(b, contactSettings(e, n, mu), 40 * tcEff + 6 * kDeq / speed,
                                        Vec3::Zero());
              notConverged += r.notConverged;
              queries += r.distanceQueries;
              std::string err = r.error;
              for (char& ch : err) {
                if (ch == ',') ch = ';';
              }
              csv << axis << "," << alpha << "," << f << "," << f * bGraze << "," << speed << ","
                  << gap << "," << mu << "," << r.maxOverlapRatio << "," << r.maxDepthRatio << ","
                  << r.minCentreMargin << "," << r.finalDistance << "," << r.apart << ","
                  << r.episodes << "," << r.notConverged << "," << r.distanceQueries << ","
                  << r.subSteps << "," << r.time << "," << r.momentumError << ","
                  << r.angularMomentumError << "," << r.keFinalRatio << "," << r.keMaxRatio << ","
                  << r.maxSpin << "," << err << "\n";
              const std::string where = "axis " + axis + " alpha=" + fmt(alpha) + " f=" + fmt(f) +
                                        " u=" + fmt(speed) + " gap=" + fmt(gap) + " mu=" + fmt(mu);
              checks.require("5 extremes: no exception, finite (no NaN)", r.error.empty(),
                             where + " " + r.error);
              checks.require("5 extremes: touched", r.touched, where);
              checks.atMost("5 extremes: max overlap / a_min (model)", r.maxOverlapRatio,
                            kOverlapTolerance, where);
              checks.atMost("5 extremes: max depth / a_min (sub-step ends)", r.maxDepthRatio,
                            kOverlapTolerance, where);
              checks.atLeast("5 extremes: min (c2 - c1).n0 / (a_min1 + a_min2) in contact",
                             r.minCentreMargin, 0.5, where);
              checks.require("5 extremes: signed distance > 0 at the end (no tunnelling)",
                             r.finalDistance > 0, where);
              if (!r.apart) ++notApart;
              checks.atMost("5 extremes: KE(end)/KE(0) - 1 (energy never gained)",
                            r.keFinalRatio - 1, kEnergyTolerance, where);
              checks.atMost("5 extremes: |dp| / sum |p_i|", r.momentumError, kMomentumTolerance,
                            where);
            }
          }
        }
      }
    }
  }
  std::ostringstream note;
  note << "5 extremes: " << notConverged << " non-converged distances (model) in " << queries
       << " queries; " << notApart
       << " runs still within reach of each other at the end of the run (apart, not yet "
          "receding beyond the bounding spheres)";
  checks.note(note.str());
}

/// Head-on equal spheres from slow to fast: the overlap cap at work.
void capSweep(const Options& o, Checks& checks) {
  const std::vector<Scalar> speeds =
      o.quick ? std::vector<Scalar>{0.01, 100} : std::vector<Scalar>{0.01, 0.1, 1, 10, 100};
  const std::vector<Scalar> es{0.97, 0.5, 0.1};
  const int n = 10;
  std::ofstream csv = openCsv(o, "capSweep.csv",
                              "speed,e,N,eMeasured,relError,maxOverlapRatio,contactTime,"
                              "contactTimeModel,subStepsPerFluidStep,contactSubSteps");
  for (Scalar speed : speeds) {
    for (Scalar e : es) {
      std::vector<RigidBody> b{makeBody(Vec3::Constant(0.5), Vec3(-0.5 - 1e-6, 0, 0),
                                        Quat::Identity(), Vec3(speed / 2, 0, 0)),
                               makeBody(Vec3::Constant(0.5), Vec3(0.5 + 1e-6, 0, 0),
                                        Quat::Identity(), Vec3(-speed / 2, 0, 0))};
      CollisionModel model = dryModel(contactSettings(e, n), {});
      bool touched = false;
      Scalar time = 0, contactTime = 0;
      int maxSub = 0, contactSubSteps = 0;
      std::string error;
      try {
        if (!advance(b, model, 1e-6 / speed + 10 * kTc, time, [&](Scalar h, int sub) {
              if (model.activeContacts() > 0) {
                touched = true;
                contactTime += h;
                ++contactSubSteps;
                maxSub = std::max(maxSub, sub);
              }
              return touched && model.activeContacts() == 0;
            })) {
          error = "the contact did not end";
        }
      } catch (const std::exception& ex) {
        error = ex.what();
      }
      const Scalar eMeasured = (b[1].velocity.x() - b[0].velocity.x()) / speed;
      const Scalar tcModel = std::min(kTc, kPi * kMaxOverlap * 0.5 / speed);
      csv << speed << "," << e << "," << n << "," << eMeasured << "," << eMeasured / e - 1 << ","
          << model.statistics().maxOverlapRatio << "," << contactTime << "," << tcModel << ","
          << maxSub << "," << contactSubSteps << "\n";
      const std::string where = "u=" + fmt(speed) + " e=" + fmt(e);
      checks.require("5 cap sweep (spheres): contact ended, finite", error.empty() && finite(b),
                     where + " " + error);
      checks.atMost("5 cap sweep (spheres): max overlap / a_min",
                    model.statistics().maxOverlapRatio, kOverlapTolerance, where);
      checks.atMost("5 cap sweep (spheres): |e_meas - e|, N = 10", std::abs(eMeasured - e),
                    restitutionTolerance(n), where);
    }
  }
}


// ---------------------------------------------------------------------------
// 6: oblique sphere-wall impacts with Coulomb friction (the tangential spring)

/// The rigid-body impact theory of a sphere on a plane with Coulomb friction
/// (Maw, Barber & Fawcett 1976; Walton 1993), in the variables Joseph & Hunt
/// (2004) use: Psi = v_t / u_n, the tangential speed of the contact point over
/// the normal impact speed. Sliding throughout the contact (Psi_in above
/// Psi_c = 7/2 mu (1 + e)/(1 + beta0)): Psi_out = Psi_in - 7/2 mu (1 + e);
/// sticking: Psi_out = -beta0 Psi_in.
Scalar psiOutTheory(Scalar psiIn, Scalar mu, Scalar e, Scalar beta0) {
  const Scalar psiC = 3.5 * mu * (1 + e) / (1 + beta0);
  return psiIn > psiC ? psiIn - 3.5 * mu * (1 + e) : -beta0 * psiIn;
}

void obliqueSphereWall(const Options& o, Checks& checks) {
  const std::vector<Scalar> mus = o.quick ? std::vector<Scalar>{0.15} : std::vector<Scalar>{0.05, 0.1, 0.15, 0.3};
  const std::vector<Scalar> es = o.quick ? std::vector<Scalar>{0.97} : std::vector<Scalar>{0.97, 0.8};
  const std::vector<Scalar> psis =
      o.quick ? std::vector<Scalar>{0.1, 0.5, 2.0}
              : std::vector<Scalar>{0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7,
                                    0.8, 1.0, 1.2, 1.5, 2.0, 3.0, 4.0};
  const int n = 10;
  const Scalar un = 0.02;  // as the head-on wall impacts (uncapped contact time T_c)
  std::ofstream csv = openCsv(o, "obliqueSphereWall.csv",
                              "mu,e,N,psiIn,psiOut,psiOutTheory,eMeasured,muEffective,"
                              "reboundTangent,maxOverlapRatio");
  for (Scalar mu : mus) {
    for (Scalar e : es) {
      for (Scalar psi : psis) {
        const Scalar g0 = un * 1.4 * kTc / n;
        std::vector<RigidBody> b{makeBody(Vec3::Constant(0.5), Vec3(0, 0, 0.5 + g0),
                                          Quat::Identity(), Vec3(psi * un, 0, -un))};
        DrySettings s = contactSettings(e, n, mu);
        CollisionModel model = dryModel(s, {kFloor});
        bool touched = false;
        Scalar time = 0;
        std::string error;
        try {
          if (!advance(b, model, g0 / un + 10 * kTc, time, [&](Scalar, int) {
                if (model.activeContacts() > 0) touched = true;
                return touched && model.activeContacts() == 0;
              })) {
            error = "the contact did not end";
          }
        } catch (const std::exception& ex) {
          error = ex.what();
        }
        const Vec3 contact = b[0].centre - Vec3(0, 0, 0.5);
        const Scalar psiOut = pointVelocity(b[0], contact).x() / un;
        const Scalar eMeasured = b[0].velocity.z() / un;
        const Scalar muEff = (psi * un - b[0].velocity.x()) / ((1 + eMeasured) * un);
        // the theory with the measured normal restitution and beta0 = e (the
        // tangential spring has the normal one's period and damping)
        const Scalar theory = psiOutTheory(psi, mu, eMeasured, e);
        csv << mu << "," << e << "," << n << "," << psi << "," << psiOut << "," << theory << ","
            << eMeasured << "," << muEff << "," << b[0].velocity.x() / b[0].velocity.z() << ","
            << model.statistics().maxOverlapRatio << "\n";
        const std::string where = "mu=" + fmt(mu) + " e=" + fmt(e) + " Psi_in=" + fmt(psi);
        checks.require("6 oblique sphere-wall: contact made and ended, finite",
                       error.empty() && finite(b), where + " " + error);
        const Scalar psiC = 3.5 * mu * (1 + eMeasured) / (1 + e);
        // sliding: the impulse ratio is mu, less the short sticking phase at the start of the
        // contact and the partial slip at its end (the spring's elastic tangential compliance,
        // as in Maw, Barber & Fawcett's elastic theory), which fade as Psi_in grows
        if (psi >= 2 * psiC) {
          checks.atMost("6 oblique sphere-wall: sliding (Psi_in >= 2 Psi_c), |mu_eff/mu - 1|",
                        std::abs(muEff / mu - 1), 0.04, where);
        } else if (psi < 0.75 * psiC) {
          checks.atMost("6 oblique sphere-wall: sticking, |Psi_out/Psi_in + e|",
                        std::abs(psiOut / psi + e), 0.05, where);
        }
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--out" && i + 1 < argc) {
      o.out = argv[++i];
    } else if (arg == "--only" && i + 1 < argc) {
      o.only = argv[++i];
    } else if (arg == "--approach-scale" && i + 1 < argc) {
      approachContactTimeScale = std::strtod(argv[++i], nullptr);
      const Range& r = CollisionSettings::kApproachContactTimeScaleRange;
      if (!r.contains(approachContactTimeScale)) {
        std::cerr << "dryCollisions: --approach-scale " << argv[i] << " must be in " << r.str()
                  << "\n";
        return 2;
      }
    } else {
      std::cerr << "usage: dryCollisions [--quick] [--out DIR] [--only PART] [--approach-scale F]\n"
                   "  PART: 1 sphere-sphere, 2 sphere-wall, 3 spheroid-wall, 4 spheroid pairs,\n"
                   "        5 cap sweep and extremes, 6 oblique sphere-wall\n";
      return 2;
    }
  }
  mkdir(o.out.c_str(), 0755);
  Checks checks;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&]() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  struct Part {
    const char* name;
    void (*run)(const Options&, Checks&);
  };
  const Part parts[] = {
      {"1 sphere-sphere", [](const Options& op, Checks& c) { headOnSet(op, c, false); }},
      {"2 sphere-wall", [](const Options& op, Checks& c) { headOnSet(op, c, true); }},
      {"3 spheroid-wall", spheroidWall},
      {"4 spheroid pairs", spheroidPairs},
      {"5 cap sweep", capSweep},
      {"5 extremes", extremes},
      {"6 oblique sphere-wall", obliqueSphereWall},
  };
  std::ostringstream timing;
  try {
    for (const Part& p : parts) {
      if (std::string(p.name).rfind(o.only, 0) != 0) continue;
      const double t0 = elapsed();
      p.run(o, checks);
      std::cout << p.name << ": " << std::fixed << std::setprecision(1) << elapsed() - t0 << " s\n"
                << std::defaultfloat;
      timing << "- " << p.name << ": " << std::fixed << std::setprecision(1) << elapsed() - t0
             << " s\n"
             << std::defaultfloat;
    }
  } catch (const std::exception& ex) {
    std::cerr << "dryCollisions: " << ex.what() << "\n";
    return 1;
  }
  std::ostringstream report;
  report << "# dryCollisions checks" << (o.quick ? " (--quick)" : "");
  if (approachContactTimeScale != CollisionSettings().approachContactTimeScale) {
    report << " (approachContactTimeScale " << approachContactTimeScale << ")";
  }
  report << "\n\n";
  checks.report(report);
  report << "\nWall time " << std::fixed << std::setprecision(1) << elapsed() << " s\n"
         << timing.str();
  std::cout << "\n" << report.str();
  std::ofstream(o.out + "/checks.md") << report.str();
  const bool ok = checks.allPassed();
  std::cout << (ok ? "dryCollisions: all checks passed\n" : "dryCollisions: CHECKS FAILED\n");
  return ok ? 0 : 1;
}
