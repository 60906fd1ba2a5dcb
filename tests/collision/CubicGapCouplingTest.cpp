// The coupling of normal and tangential motion from the gap's cubic terms
// (CubicGapCoupling.hpp): zero where the closest points are vertices; for a
// prolate tilted 45 degrees to a plane the coefficients of the Reynolds
// equation solved on the exact gap (validation/squeezeFilm, cubicCoupling.md);
// no load under a rigid motion of the pair; the same loads with the labels
// exchanged; one symmetric resistance, dissipative together with the squeeze
// film; and the terms as CollisionModel applies them to a tilted prolate
// approaching a wall.
#include "collision/CubicGapCoupling.hpp"
#include "collision/GapParaboloid.hpp"
#include "collision/RigidBody.hpp"
#include "collision/RigidBodyStep.hpp"
#include "collision/TangentialLubrication.hpp"
#include "ellipsoids/Ellipsoid.hpp"
#include "FilmLawSupport.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace collision;

namespace {

constexpr Scalar mu = 0.01, L = 2.5;
const Tensor3 kFlat{Mat3::Zero(), Mat3::Zero(), Mat3::Zero()};

/// Two spheroids touching at the origin, the normal d from the first to the second.
struct Pair {
  Touching first, second;
  Vec3 d;
};
Pair spheroidPair(const Vec3& d, const Vec3& e1, const Vec3& e2) {
  const Vec3 n = d.normalized();
  return {spheroidAt(2.5e-3, 1e-3, e1, n), spheroidAt(1.2e-3, 0.8e-3, e2, -n), n};
}
/// closest points away from the vertices on both bodies
const Pair kPairs[] = {
    spheroidPair(Vec3(0.3, -0.5, 0.8), Vec3(1, 0.2, 0), Vec3(0, 1, 0.4)),
    spheroidPair(Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, -1)),
    spheroidPair(Vec3(1, 1, 0.2), Vec3(0.2, 1, 1), Vec3(1, -0.7, 0.3)),
};

CubicGapCoupling couplingOf(const Pair& p) {
  return CubicGapCoupling(p.first.curvature, p.second.curvature, p.first.third, p.second.third,
                          p.d, mu);
}

}  // namespace

TEST(CubicGapCoupling, VanishesWhereTheClosestPointsAreVertices) {
  const Vec3 z = Vec3::UnitZ();
  const Touching sphere = spheroidAt(1e-3, 1e-3, Vec3(1, 2, 3), z);
  const Touching broadside = spheroidAt(2e-3, 1e-3, Vec3::UnitX(), z);
  const Touching tip = spheroidAt(2e-3, 1e-3, z, z);
  const Touching below = spheroidAt(1.5e-3, 1e-3, Vec3::UnitY(), -z);
  for (const Touching* t : {&sphere, &broadside, &tip}) {
    for (const bool plane : {true, false}) {
      const CubicGapCoupling c(t->curvature, plane ? Mat3::Zero() : below.curvature, t->third,
                               plane ? kFlat : below.third, z, mu);
      EXPECT_LT(c.approachForce().norm(), 1e-15);
      EXPECT_LT(c.approachMoment().norm(), 1e-18) << "no twist: the axes of S1 are K's";
    }
  }
  // bad input: a viscosity that is not positive, two planes (no film)
  EXPECT_THROW(CubicGapCoupling(sphere.curvature, Mat3::Zero(), sphere.third, kFlat, z, 0),
               std::invalid_argument);
  EXPECT_THROW(CubicGapCoupling(Mat3::Zero(), Mat3::Zero(), kFlat, kFlat, z, mu),
               std::invalid_argument);
}

TEST(CubicGapCoupling, ATiltedProlateOnAPlaneGivesTheReynoldsCoefficients) {
  // validation/squeezeFilm: the prolate (2, 1, 1), its axis 45 degrees to the
  // normal z, touching the tangent plane z = 0 at the origin, a plane above;
  // mu = 1, unit approach speed: the ln(1/h0) coefficients of the tangential
  // force (along x, +5.1655) and of the torque about the centre (along y,
  // -16.3619, the reciprocal of the normal force under a rotation about y),
  // from the Reynolds equation on the exact gap (slidingFilm.py, slope
  // between h0 = 1e-4 and 1e-5)
  const ellipsoids::Ellipsoid prolate(
      Vec3(2, 1, 1), Vec3::Zero(), Quat::FromTwoVectors(Vec3::UnitX(), Vec3(1, 0, 1).normalized()));
  const Vec3 p1 = prolate.support(Vec3::UnitZ());
  const CubicGapCoupling c(prolate.curvatureTensor(p1), Mat3::Zero(),
                           prolate.surfaceThirdDerivative(p1), kFlat, Vec3::UnitZ(), 1);
  const FilmLoads l = c.loads(1, {p1, Vec3::UnitZ(), Vec3::Zero()}, {});
  EXPECT_NEAR(l.force1.x(), 5.1655, 0.002 * 5.1655);
  EXPECT_NEAR(l.force1.y(), 0, 1e-12);
  EXPECT_NEAR(l.force1.z(), 0, 1e-12) << "the approach has no normal force of its own";
  EXPECT_NEAR(l.torque1.y(), -16.3619, 0.002 * 16.3619);
  EXPECT_NEAR(l.torque1.x(), 0, 1e-12);
  EXPECT_NEAR(l.torque1.z(), 0, 1e-12);
  // reciprocity: a rotation about y through the centre gives the normal force -16.36
  const FilmLoads r = c.loads(1, {p1, Vec3::Zero(), Vec3::UnitY()}, {});
  EXPECT_NEAR(r.force1.z(), l.torque1.y(), 1e-12);
}

TEST(CubicGapCoupling, TwoBodiesAndTheTwistGiveTheReynoldsCoefficients) {
  // validation/squeezeFilm (slidingFilm.py, cubicCoupling.md): two bodies
  // touching at the origin, normal z from body 1 (below) to body 2; mu = 1,
  // body 1 approaching at unit speed; the ln(1/h0) coefficients of the
  // Reynolds equation on the exact gap (slope between h0 = 1e-4 and 1e-5)
  // along the frame e1, e2 of those runs, moments about the contact point
  const Vec3 z = Vec3::UnitZ();
  struct Case {
    const char* name;
    Touching first, second;
    Vec3 e1, e2;
    Scalar Fe1, Fe2, Me1, Me2, Mn;
  };
  const Scalar s = std::sqrt(0.5), c8 = std::cos(kPi / 8), s8 = std::sin(kPi / 8);
  const Vec3 tilted(s, 0, s);
  const Case cases[] = {
      {"prolates side by side, 45 deg (twist only)", spheroidAt(2, 1, Vec3::UnitX(), z),
       spheroidAt(2, 1, Vec3(s, s, 0), -z), Vec3(-s8, c8, 0), Vec3(-c8, -s8, 0), 0, 0, 0, 0,
       -2.9208},
      {"prolate 45 deg / sphere a = 2", spheroidAt(2, 1, tilted, z), spheroidAt(2, 2, z, -z),
       Vec3(0, 1, 0), Vec3(1, 0, 0), 0, -1.0267, -5.8110, 0, 0},
      {"prolate 45 deg / oblate 45 deg turned about n", spheroidAt(2, 1, tilted, z),
       spheroidAt(1, 2, Vec3(0.5, 0.5, -s), -z), Vec3(s8, c8, 0), Vec3(-c8, s8, 0), -2.3946,
       1.2647, -2.8121, 0.7509, 0.2329},
  };
  for (const Case& k : cases) {
    const CubicGapCoupling c(k.first.curvature, k.second.curvature, k.first.third,
                             k.second.third, z, 1);
    const FilmLoads l = c.loads(1, {k.first.arm, z, Vec3::Zero()}, {k.second.arm, Vec3::Zero(), Vec3::Zero()});
    const Vec3 moment = l.torque1 - k.first.arm.cross(l.force1);  // about the contact point
    const Scalar measured[5] = {k.Fe1, k.Fe2, k.Me1, k.Me2, k.Mn};
    const Scalar model[5] = {l.force1.dot(k.e1), l.force1.dot(k.e2), moment.dot(k.e1),
                             moment.dot(k.e2), moment.dot(z)};
    for (int i = 0; i < 5; ++i) {
      // 0.5 % where the coefficient is there, 1e-3 of the largest where it vanishes
      EXPECT_NEAR(model[i], measured[i], measured[i] != 0 ? 0.005 * std::abs(measured[i]) : 3e-3)
          << k.name << ", component " << i;
    }
    EXPECT_NEAR(l.force1.dot(z), 0, 1e-12) << k.name;
  }
}

TEST(CubicGapCoupling, NoLoadUnderARigidMotionOfThePair) {
  for (const Pair& p : kPairs) {
    const CubicGapCoupling c = couplingOf(p);
    ASSERT_GT(c.approachForce().norm(), 0) << "closest points away from the vertices";
    expectNoLoadUnderRigidMotion(
        [&](const FilmSide& one, const FilmSide& two) { return c.loads(L, one, two); },
        p.first.arm, p.second.arm, 6 * kPi * mu * 1e-3 * L, 3);
  }
}

TEST(CubicGapCoupling, ExchangingTheBodiesGivesTheSameLoads) {
  for (const Pair& p : kPairs) {
    const CubicGapCoupling c = couplingOf(p);
    const CubicGapCoupling exchanged(p.second.curvature, p.first.curvature, p.second.third,
                                     p.first.third, -p.d, mu);
    expectSameLoadsExchanged(
        [&](const FilmSide& one, const FilmSide& two) { return c.loads(L, one, two); },
        [&](const FilmSide& one, const FilmSide& two) { return exchanged.loads(L, one, two); },
        p.first.arm, p.second.arm, 1e-3, 5);
  }
}

TEST(CubicGapCoupling, OneSymmetricResistanceDissipativeWithTheSqueezeFilm) {
  // at the gap h = 1e-3 a_min the film's ln(1/h) terms (the paraboloid law
  // and the coupling) and the squeeze film 6 pi mu R*^2/h: one symmetric
  // resistance; the coupling alone feeds some motions, the whole film none
  const Scalar h = 0.8e-6;
  for (const Pair& p : kPairs) {
    const CubicGapCoupling c = couplingOf(p);
    const TangentialLubrication t(p.first.curvature, p.second.curvature, p.d, mu);
    const Scalar squeeze =
        6 * kPi * mu *
        std::pow(GapParaboloid::fromCurvatureTensors(p.first.curvature, p.second.curvature, p.d)
                     .squeezeRadius(),
                 2) /
        h;
    const Vec3 n = p.d;
    const FilmLaw coupling = [&](const FilmSide& a, const FilmSide& b) { return c.loads(L, a, b); };
    const FilmLaw whole = [&](const FilmSide& a, const FilmSide& b) {
      FilmLoads l = c.loads(L, a, b);
      const FilmLoads tl = t.loads(L, a, b);
      const Vec3 relative = a.velocity + a.angularVelocity.cross(a.arm) - b.velocity -
                            b.angularVelocity.cross(b.arm);
      const Vec3 f = tl.force1 - squeeze * relative.dot(n) * n;
      l.force1 += f;
      l.torque1 += tl.torque1 + a.arm.cross(f - tl.force1);
      l.torque2 += tl.torque2 - b.arm.cross(f - tl.force1);
      return l;
    };
    const Mat12 Rc = loadMatrix(coupling, p.first.arm, p.second.arm);
    const Mat12 R = loadMatrix(whole, p.first.arm, p.second.arm);
    const Scalar scale = largestEntry(Rc);
    for (int row = 0; row < 12; ++row)
      for (int col = 0; col < row; ++col)
        EXPECT_NEAR(Rc[row][col], Rc[col][row], 1e-12 * scale) << row << " " << col;
    std::mt19937 rng(7);
    std::normal_distribution<Scalar> normal;
    Scalar largestFed = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      std::array<Scalar, 12> q;
      Scalar qq = 0;
      for (Scalar& v : q) {
        v = normal(rng);
        qq += v * v;
      }
      EXPECT_LE(power(R, q), 1e-12 * largestEntry(R) * qq);
      largestFed = std::max(largestFed, power(Rc, q));
    }
    EXPECT_GT(largestFed, 0) << "the coupling alone is not dissipative";
  }
}

TEST(CubicGapCoupling, ATiltedProlateApproachingAWallIsPushedSideways) {
  // a prolate (Ar 2) tilted 45 degrees in the xz plane, 0.005 b above the
  // floor, moving straight down: no sliding, so the paraboloid law gives
  // nothing and the model's tangential force and torque are the coupling's,
  // L V (f, m + arm x f) times one factor; then, free in the film with its
  // spin, it never gains kinetic energy
  const Scalar b = 1e-3;
  const Quat q = Quat::FromTwoVectors(Vec3::UnitX(), Vec3(1, 0, 1).normalized());
  const ellipsoids::Ellipsoid shape(Vec3(2 * b, b, b), Vec3::Zero(), q);
  const Vec3 lowest = shape.support(-Vec3::UnitZ());
  RigidBody body;
  body.semiAxes = Vec3(2 * b, b, b);
  body.orientation = q;
  body.centre = Vec3(0, 0, -lowest.z() + 0.005 * b);
  body.velocity = Vec3(0, 0, -0.01);
  body.density = 1200;
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = 0.05;
  CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  const Scalar dt = 1e-4;
  std::vector<Vec3> F, T;
  model.forces({body.collisionBody()}, 10 * dt, dt, F, T);
  // body 1 the prolate, n = -z towards the wall; its closest point at `lowest`
  const CubicGapCoupling c(shape.curvatureTensor(lowest), Mat3::Zero(),
                           shape.surfaceThirdDerivative(lowest), kFlat, -Vec3::UnitZ(), 0.05);
  ASSERT_GT(F[0].norm(), 0);
  const Scalar factor = F[0].x() / c.approachForce().x();  // relax L V
  EXPECT_GT(factor, 0) << "the approach speed is positive";
  EXPECT_LT((F[0] - factor * c.approachForce()).norm(), 1e-9 * F[0].norm());
  const Vec3 expectedTorque = factor * (c.approachMoment() + lowest.cross(c.approachForce()));
  EXPECT_LT((T[0] - expectedTorque).norm(), 1e-9 * T[0].norm());

  // free in the film, spinning and sliding: the kinetic energy never grows
  body.angularVelocity = Vec3(3, -20, 5);
  body.velocity = Vec3(0.02, -0.01, -0.01);
  const Scalar mass = body.mass();
  Scalar previous = body.kineticEnergy();
  int filmSteps = 0;
  for (int step = 0; step < 200; ++step) {
    const std::vector<CollisionBody> cb{body.collisionBody()};
    model.forces(cb, 10 * dt, dt, F, T);
    std::vector<Vec3> v{body.velocity + F[0] * dt / mass};
    std::vector<Vec3> w{body.angularVelocity + cb[0].inverseInertia * T[0] * dt};
    std::vector<Vec3> Fl, Tl;
    model.dampingForces(cb, v, w, {}, {}, dt, Fl, Tl);
    filmSteps += !model.dampedPairs().empty();
    advanceRigidBody(body, dt, (F[0] + Fl[0]) * dt, (T[0] + Tl[0]) * dt, mass,
                     body.bodyInertia());
    const Scalar now = body.kineticEnergy();
    ASSERT_TRUE(std::isfinite(now));
    EXPECT_LE(now, previous * (1 + 1e-9)) << "step " << step;
    previous = now;
  }
  EXPECT_GT(filmSteps, 50);
}
