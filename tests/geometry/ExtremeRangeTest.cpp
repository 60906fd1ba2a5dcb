// The supported range of the geometry core (SupportedRange): bodies outside it
// are rejected with a message naming the parameter and the allowed values;
// inside it every method's bracket contains the exact distance, checked
// against a long-double certified reference on random tangent pairs over
// Ar 1/100 to 100, gaps 1e-12 to 1e2 and scales 1e-30 to 1e30.
#include "LongDoubleReference.hpp"
#include "TestGeometry.hpp"
#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/DistanceMethod.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

using namespace ellipsoids;
using namespace testgeometry;

namespace {

/// The message of the constructor's exception ("" if it accepted the body).
std::string rejection(const Vec3& axes, const Vec3& centre) {
  try {
    Ellipsoid(axes, centre, Quat::Identity());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& text, const std::string& word) { return text.find(word) != std::string::npos; }

}  // namespace

TEST(ExtremeRange, BodiesOutsideTheSupportedRangeAreRejectedWithTheRange) {
  // the cases checked by hand against 60-digit arithmetic, and each bound
  for (const Vec3& axes : {Vec3(1e-300, 1e-300, 1e-300), Vec3(1e200, 1e200, 1e200), Vec3(1e80, 1e80, 1e80),
                           Vec3(1e-90, 1e-90, 1e-90), Vec3(1e-80, 2e-80, 1e-80), Vec3(1, 1, 3e-36),
                           Vec3(2e35, 1e35, 1e35)}) {
    const std::string what = rejection(axes, Vec3::Zero());
    EXPECT_TRUE(mentions(what, "semi-axes") && mentions(what, "[1e-35, 1e+35]")) << axes.transpose() << ": " << what;
  }
  for (const Vec3& axes : {Vec3(101, 1, 1), Vec3(1, 1, 0.0099), Vec3(3, 1, 0.02)}) {
    const std::string what = rejection(axes, Vec3::Zero());
    EXPECT_TRUE(mentions(what, "elongation") && mentions(what, "100")) << axes.transpose() << ": " << what;
  }
  for (const Vec3& centre : {Vec3(2e35, 0, 0), Vec3(0, -1e36, 0), Vec3(0, 0, std::nan(""))}) {
    const std::string what = rejection(Vec3(1, 1, 1), centre);
    EXPECT_TRUE(mentions(what, "centre") && mentions(what, "1e+35")) << centre.transpose() << ": " << what;
  }
  for (Scalar ar : {101.0, 1.0 / 101}) {
    try {
      Ellipsoid::spheroid(ar, 1, Vec3::Zero(), Quat::Identity());
      ADD_FAILURE() << "Ar " << ar << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(mentions(e.what(), "aspect ratio") && mentions(e.what(), "[1/100, 100]")) << e.what();
    }
  }
  // the bounds themselves are accepted
  EXPECT_EQ(rejection(Vec3(1e-35, 1e-35, 1e-35), Vec3::Constant(-1e35)), "");
  EXPECT_EQ(rejection(Vec3(1e35, 1e33, 1e35), Vec3::Constant(1e35)), "");
  EXPECT_NO_THROW(Ellipsoid::spheroid(100, 1, Vec3::Zero(), Quat::Identity()));
  EXPECT_NO_THROW(Ellipsoid::spheroid(0.01, 1, Vec3::Zero(), Quat::Identity()));
}

namespace {

/// One random tangent pair of the randomized test, with its inputs.
struct RandomPair {
  BodyInput b1, b2;
  Vec3 normal;  // the direction the pair was built along (body 1 to body 2)
  Scalar scale;
};

Scalar logUniform(std::mt19937_64& rng, Scalar lo, Scalar hi) {
  return std::pow(10.0, std::uniform_real_distribution<Scalar>(std::log10(lo), std::log10(hi))(rng));
}

/// Semi-axes of equal-volume diameter dEq: a spheroid of Ar in [1/100, 100] or a tri-axial body of elongation <= 100.
Vec3 randomShape(std::mt19937_64& rng, Scalar dEq) {
  if (std::uniform_int_distribution<int>(0, 3)(rng) == 0) {
    const Scalar b = logUniform(rng, 0.01, 1), c = logUniform(rng, 0.01, 1);
    const Vec3 s(1, b, c);
    return s * (dEq / 2 / std::cbrt(s.prod()));
  }
  const Scalar ar = logUniform(rng, 0.01, 100);
  return Ellipsoid::spheroid(ar, dEq, Vec3::Zero(), Quat::Identity()).semiAxes();
}

RandomPair randomPair(std::mt19937_64& rng) {
  RandomPair p;
  p.scale = logUniform(rng, 1e-30, 1e30);
  const Scalar gap = logUniform(rng, 1e-12, 1e2) * p.scale;
  // coordinates up to 1e4 sizes from the origin: their rounding enters the bracket
  const Vec3 centre1 = logUniform(rng, 1e-2, 1e4) * p.scale * randomUnit(rng);
  p.b1 = BodyInput{randomShape(rng, p.scale), centre1, randomRotation(rng)};
  const Vec3 axes2 = randomShape(rng, p.scale * logUniform(rng, 0.2, 5));
  const Quat q2 = randomRotation(rng);
  p.normal = randomUnit(rng);
  const Ellipsoid e1 = p.b1.body();
  const Ellipsoid atOrigin(axes2, Vec3::Zero(), q2);
  p.b2 = BodyInput{axes2, e1.support(p.normal) + atOrigin.support(p.normal) + gap * p.normal, q2};
  return p;
}

struct MethodCase {
  std::string label;
  std::unique_ptr<DistanceMethod> method;
  StopRule stop;
  int maxIterations;  // 0: the method's own
  bool certifiedStop;
  bool jiaFirst;  // the method starts with the Jia et al. test (the paper's Alg. 4-6)
};

}  // namespace

TEST(ExtremeRange, EveryMethodsBracketContainsTheLongDoubleReference) {
  std::vector<MethodCase> methods;
  auto add = [&](const std::string& label, const std::string& name, StopRule stop, int maxIterations,
                 bool certified) {
    const bool jiaFirst = name == "newtonCoulomb" || name == "exteriorPenalty" || name == "jain";
    methods.push_back({label, makeDistanceMethod(name), stop, maxIterations, certified, jiaFirst});
  };
  add("dual", "dual", StopRule::certified, 0, true);
  add("gjk", "gjk", StopRule::certified, 0, true);
  add("auto", "auto", StopRule::certified, 0, true);
  add("paper", "paper", StopRule::certified, 3000, true);
  add("movingBalls", "movingBalls", StopRule::certified, 3000, true);
  add("movingBalls (eps_theta)", "movingBalls", StopRule::paper, 3000, false);
  // the paper's fragile methods: only their brackets are at stake, on a short leash
  add("newtonCoulomb", "newtonCoulomb", StopRule::certified, 200, true);
  add("exteriorPenalty", "exteriorPenalty", StopRule::paper, 200, false);
  add("jain", "jain", StopRule::certified, 200, true);

  std::mt19937_64 rng(2201);
  const LongDoubleReference reference;
  const int pairs = 300;
  std::map<std::string, int> converged;
  double worstUse = 0;  // largest (reference error of a bound) / allowance seen: <= 1 is within it
  std::string worstWhat;
  for (int k = 0; k < pairs; ++k) {
    const RandomPair p = randomPair(rng);
    const Ellipsoid e1 = p.b1.body(), e2 = p.b2.body();
    const Scalar allow = roundingAllowance(e1, e2);
    const ReferenceBracket ref = reference.distance(p.b1, p.b2, p.normal, referenceTarget(e1, e2));
    ASSERT_TRUE(ref.tight) << "pair " << k << ": reference [" << double(ref.lower) << ", " << double(ref.upper)
                           << "] wider than the target " << double(referenceTarget(e1, e2));
    const Scalar epsD = logUniform(rng, 1e-12, 1e-4) * p.scale;
    for (const MethodCase& m : methods) {
      DistanceOptions o;
      o.epsD = epsD;
      o.stopRule = m.stop;
      o.maxIterations = m.maxIterations;
      const DistanceResult r = m.method->distance(e1, e2, o);
      const std::string what = m.label + ", pair " + std::to_string(k) + " (scale " + std::to_string(p.scale) +
                               ", elongations " + std::to_string(e1.elongation()) + " " +
                               std::to_string(e2.elongation()) + ", status " + toString(r.status) + ")";
      ASSERT_TRUE(std::isfinite(r.distance) && std::isfinite(r.lower) && std::isfinite(r.upper) &&
                  r.point1.allFinite() && r.point2.allFinite() && r.direction.allFinite())
          << what;
      EXPECT_LE(r.lower, r.upper) << what;
      EXPECT_LE(r.lower, r.distance) << what;
      EXPECT_GE(r.upper, r.distance) << what;
      EXPECT_LE(r.lower, ref.upper) << what << ": lower above the exact distance by " << double(r.lower - ref.upper);
      EXPECT_GE(r.upper, ref.lower) << what << ": upper below the exact distance by " << double(ref.lower - r.upper);
      if (m.certifiedStop && r.status == DistanceStatus::converged) {
        EXPECT_LE(r.bracketWidth(), epsD) << what;
      }
      // a clear gap is not called an overlap (Newton-Coulomb, exterior penalty
      // and Jain et al. run the Jia test first, as the paper: within its
      // touching band they answer overlapping, with the bracket [0, U])
      if (ref.lower > 2 * allow && !m.jiaFirst) {
        EXPECT_NE(r.status, DistanceStatus::overlapping) << what << ": apart by " << double(ref.lower);
      }
      converged[m.label] += r.status == DistanceStatus::converged;
      // how much of the allowance the bounds used: (bound's error) / allow, with
      // the bounds before their widening (lower + allow, upper - allow; a lower
      // bound clamped to 0 says nothing)
      const long double exact = (ref.lower + ref.upper) / 2;
      const double use = std::max(r.lower > 0 ? double((r.lower + allow - exact) / allow) : -1.0,
                                  double((exact - (r.upper - allow)) / allow));
      if (use > worstUse) {
        worstUse = use;
        worstWhat = what;
      }
    }
  }
  std::cout << "[ info ] " << pairs << " pairs; converged per method:";
  for (const auto& [label, n] : converged) std::cout << " " << label << " " << n << ";";
  std::cout << " largest share of the rounding allowance used by a bound: " << worstUse << " (" << worstWhat
            << ")\n";
  // the robust certified methods answer (almost) every query within eps_d
  EXPECT_GE(converged["dual"], pairs * 9 / 10);
  EXPECT_GE(converged["auto"], pairs * 9 / 10);
}
