// The logarithmic tangential lubrication terms (TangentialLubrication.hpp):
// the ln(a/h) coefficients of Goldman, Cox and Brenner (1967) for a sphere and
// a plane and of Jeffrey and Onishi (1984) for two spheres, no load under a
// rigid motion of the pair, one symmetric dissipative resistance matrix, and
// the terms as CollisionModel applies them to a sphere sliding over a wall.
#include "collision/LubricationLaw.hpp"
#include "collision/RigidBody.hpp"
#include "collision/TangentialLubrication.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace collision;

namespace {

constexpr Scalar kInf = std::numeric_limits<Scalar>::infinity();
constexpr Scalar mu = 0.01, L = 2.5;

/// The 12 x 12 resistance matrix R: (F1, T1, F2, T2) = R (U1, Omega1, U2, Omega2).
/// The 12 x 12 resistance matrix R (row-major): (F1, T1, F2, T2) = R (U1, Omega1, U2, Omega2).
/// Plain arrays: the product q.R q is all the tests need.
using Mat12 = std::array<std::array<Scalar, 12>, 12>;

Mat12 resistance(const TangentialLubrication& law, const Vec3& d) {
  Mat12 R{};
  for (int k = 0; k < 12; ++k) {
    Vec3 motion[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    motion[k / 3](k % 3) = 1;
    const TangentialLubricationLoads l = law.loads(L, d, motion[0], motion[1], motion[2], motion[3]);
    const Vec3 loads[4] = {l.force1, l.torque1, -l.force1, l.torque2};
    for (int row = 0; row < 12; ++row) R[row][k] = loads[row / 3](row % 3);
  }
  return R;
}

Scalar largestEntry(const Mat12& R) {
  Scalar m = 0;
  for (const auto& row : R)
    for (const Scalar v : row) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

TEST(TangentialLubrication, SphereAndPlaneGiveGoldmanCoxBrenner) {
  // sphere of radius a above a floor (d = -z, from the sphere to the plane)
  const Scalar a = 2e-3;
  const TangentialLubrication law(a, kInf, mu);
  const Vec3 d(0, 0, -1);
  const Scalar f0 = 6 * kPi * mu * a * L, t0 = 8 * kPi * mu * a * a * L;
  // translation U along x: drag (8/15) ln(a/h), torque (1/10) ln(a/h) in the rolling sense (+y)
  TangentialLubricationLoads l = law.loads(L, d, Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  EXPECT_NEAR(l.force1.x(), -f0 * 8 / 15, 1e-15);
  EXPECT_NEAR(l.torque1.y(), t0 / 10, 1e-15);
  EXPECT_NEAR(l.force1.y() + l.force1.z() + l.torque1.x() + l.torque1.z(), 0, 1e-18);
  // rotation Omega about y (bottom surface moving along -x): force (2/15) a ln(a/h)
  // along +x, torque -(2/5) a ln(a/h) against the rotation
  l = law.loads(L, d, Vec3::Zero(), Vec3(0, 1, 0), Vec3::Zero(), Vec3::Zero());
  EXPECT_NEAR(l.force1.x(), f0 * a * 2 / 15, 1e-18);
  EXPECT_NEAR(l.torque1.y(), -t0 * a * 2 / 5, 1e-18);
  // rotation about the normal, motion along the normal: no logarithmic term
  l = law.loads(L, d, Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3::Zero(), Vec3::Zero());
  EXPECT_EQ(l.force1.norm() + l.torque1.norm(), 0);
  EXPECT_EQ(law.loads(0, d, Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3::Zero(), Vec3::Zero()).force1.norm(), 0);
}

TEST(TangentialLubrication, TwoSpheresGiveJeffreyOnishi) {
  // the ln(1/xi) coefficients of Y^A_11 (force), Y^C_11 and Y^C_12 (torques)
  // and -Y^B_11/2 (torque of a translation); the forces of the rotations
  // against the closed forms of Simeonov & Calantoni (2012)
  const Vec3 d(1, 0, 0);
  for (const Scalar beta : {0.3, 1.0, 2.0, 5.0}) {
    const Scalar a1 = 1e-3, a2 = beta * a1, b1 = 1 + beta;
    const TangentialLubrication law(a1, a2, mu);
    const Scalar YA = 4.0 / 15 * beta * (2 + beta + 2 * beta * beta) / (b1 * b1 * b1);
    const Scalar YB = -1.0 / 5 * beta * (4 + beta) / (b1 * b1);
    const Scalar YC11 = 2.0 / 5 * beta / b1, YC12 = beta * beta / (10 * b1);
    const Scalar f0 = 6 * kPi * mu * a1 * L, t0 = 8 * kPi * mu * a1 * a1 * L;
    TangentialLubricationLoads l = law.loads(L, d, Vec3(0, 1, 0), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
    EXPECT_NEAR(l.force1.y(), -f0 * YA, 1e-15 * f0) << beta;
    EXPECT_NEAR(l.torque1.z(), t0 * YB / 2, 1e-15 * t0) << "d x u = +z: T1 = -t0 E z" << beta;
    l = law.loads(L, d, Vec3::Zero(), Vec3(0, 0, 1), Vec3::Zero(), Vec3::Zero());
    EXPECT_NEAR(l.torque1.z(), -t0 * a1 * YC11, 1e-15 * t0 * a1) << beta;
    EXPECT_NEAR(l.force1.y(), f0 * a1 * YB * 2 / 3, 1e-15 * f0 * a1) << "Omega1 x d = +y" << beta;
    l = law.loads(L, d, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, 1));
    EXPECT_NEAR(l.torque1.z(), -t0 * a1 * YC12, 1e-15 * t0 * a1) << beta;
    EXPECT_NEAR(l.force1.y(), -f0 * a1 * 2 * beta * beta * (1 + 4 * beta) / (15 * b1 * b1),
                1e-15 * f0 * a1)
        << beta;
  }
  // equal spheres: Y^A_11 = (1/6) ln(1/xi)
  const TangentialLubrication equal(1, 1, 1);
  EXPECT_NEAR(equal.loads(1, d, Vec3(0, 0, 1), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()).force1.z(),
              -kPi, 1e-14);
}

TEST(TangentialLubrication, NoLoadUnderARigidMotionOfThePair) {
  // the pair translating and rotating as one rigid body about any point
  std::mt19937 rng(3);
  std::uniform_real_distribution<Scalar> u(-1, 1);
  const Vec3 d = Vec3(0.3, -0.5, 0.8).normalized();
  const Scalar a1 = 1.5e-3, a2 = 0.7e-3;
  const TangentialLubrication law(a1, a2, mu);
  const Vec3 contact(0.2, 0.1, -0.3);
  const Vec3 c1 = contact - a1 * d, c2 = contact + a2 * d;
  for (int k = 0; k < 5; ++k) {
    const Vec3 V(u(rng), u(rng), u(rng)), W(u(rng), u(rng), u(rng)), x0(u(rng), u(rng), u(rng));
    const TangentialLubricationLoads l =
        law.loads(L, d, V + W.cross(c1 - x0), W, V + W.cross(c2 - x0), W);
    const Scalar scale = 6 * kPi * mu * a1 * L * (V.norm() + W.norm());
    EXPECT_LT(l.force1.norm(), 1e-13 * scale);
    EXPECT_LT(l.torque1.norm(), 1e-13 * scale);
    EXPECT_LT(l.torque2.norm(), 1e-13 * scale);
  }
}

TEST(TangentialLubrication, OneSymmetricDissipativeResistance) {
  const Vec3 d = Vec3(1, 2, -2).normalized();
  for (const Scalar a2 : {0.5e-3, 1e-3, 3e-3}) {
    const Mat12 R = resistance(TangentialLubrication(1e-3, a2, mu), d);
    const Scalar scale = largestEntry(R);
    ASSERT_GT(scale, 0) << a2;
    for (int row = 0; row < 12; ++row)
      for (int col = 0; col < row; ++col)
        EXPECT_NEAR(R[row][col], R[col][row], 1e-12 * scale) << a2 << " " << row << " " << col;
    // loads oppose the motion: the power q.R q is never positive, and some motions dissipate
    std::mt19937 rng(7);
    std::normal_distribution<Scalar> normal;
    Scalar largestDissipation = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      std::array<Scalar, 12> q;
      Scalar qq = 0;
      for (Scalar& v : q) {
        v = normal(rng);
        qq += v * v;
      }
      Scalar power = 0;
      for (int row = 0; row < 12; ++row)
        for (int col = 0; col < 12; ++col) power += q[row] * R[row][col] * q[col];
      EXPECT_LE(power, 1e-12 * scale * qq) << a2;
      largestDissipation = std::max(largestDissipation, -power);
    }
    EXPECT_GT(largestDissipation, 0) << a2;
  }
}

TEST(TangentialLubrication, RateAndBadArguments) {
  const TangentialLubrication law(1e-3, kInf, mu);
  const Mat3 I = Mat3::Identity() * 1e6;
  EXPECT_EQ(law.rate(0, 1, I, 0, Mat3::Zero()), 0);
  EXPECT_NEAR(law.rate(L, 1, Mat3::Zero(), 0, Mat3::Zero()), 6 * kPi * mu * 1e-3 * L * 8 / 15, 1e-15);
  EXPECT_NEAR(law.rate(L, 0, I, 0, Mat3::Zero()), 8 * kPi * mu * 1e-9 * L * 2 / 5 * I.norm(), 1e-12);
  EXPECT_THROW(TangentialLubrication(0, 1, mu), std::invalid_argument);
  EXPECT_THROW(TangentialLubrication(1, -1, mu), std::invalid_argument);
  EXPECT_THROW(TangentialLubrication(1, 1, 0), std::invalid_argument);
}

TEST(TangentialLubrication, LogFactorOfTheGapLaw) {
  LubricationParameters p;  // walls: activation 0.075 a, saturation 1e-3
  const Scalar a = 2e-3;
  const LubricationGapLaw law(a, kInf, mu, p);
  EXPECT_NEAR(law.logFactor(0.01 * a), std::log(7.5), 1e-14);
  EXPECT_NEAR(law.logFactor(1e-5 * a), std::log(75.0), 1e-14) << "frozen below saturation";
  EXPECT_NEAR(law.logFactor(0), std::log(75.0), 1e-14);
  EXPECT_EQ(law.logFactor(0.075 * a), 0);
  EXPECT_EQ(law.logFactor(-1e-6), 0) << "off in contact";
  EXPECT_EQ(LubricationGapLaw().logFactor(1e-6), 0);
}

TEST(TangentialLubrication, ASphereSlidingOverAWallIsHeldBackAndSpunUp) {
  // a sphere 0.01 a above the floor sliding along x: the collision model adds
  // the sphere-plane terms scaled by 1/(1 + dt rate), drag along -x and torque
  // along +y (rolling), with the wall's log factor ln(0.075/0.01)
  const Scalar a = 2e-3, dt = 1e-4, gap = 0.01 * a;
  RigidBody b;
  b.semiAxes = Vec3::Constant(a);
  b.centre = Vec3(0, 0, a + gap);
  b.velocity = Vec3(0.05, 0, 0);
  b.density = 2500;
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = mu;
  for (const bool tangential : {true, false}) {
    s.laws.lubrication.tangential = tangential;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    std::vector<Vec3> F, T;
    model.forces({b.collisionBody()}, 10 * dt, dt, F, T);
    if (!tangential) {
      EXPECT_EQ(F[0].norm() + T[0].norm(), 0);
      continue;
    }
    const TangentialLubrication law(a, kInf, mu);
    const Scalar Lw = std::log(7.5);
    const CollisionBody cb = b.collisionBody();
    const Scalar relax = 1 / (1 + dt * law.rate(Lw, 1 / cb.mass, cb.inverseInertia, 0, Mat3::Zero()));
    EXPECT_GT(relax, 0.5) << "a case where the terms are resolved by the sub-step";
    EXPECT_LT(relax, 1);
    EXPECT_NEAR(F[0].x(), -relax * 6 * kPi * mu * a * Lw * 8 / 15 * 0.05, 1e-12 * std::abs(F[0].x()));
    EXPECT_NEAR(T[0].y(), relax * 8 * kPi * mu * a * a * Lw / 10 * 0.05, 1e-12 * std::abs(T[0].y()));
    EXPECT_NEAR(F[0].z(), 0, 1e-18) << "the normal term is dampingForces()'s";
  }
}
