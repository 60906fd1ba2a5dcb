#include "collision/CollisionModel.hpp"
#include "collision/ContactLaw.hpp"
#include "collision/PlaneWall.hpp"
#include "collision/SpringDashpotContact.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace collision;

TEST(ContactLaw, EffectiveMassOfAHeadOnPairIsTheReducedMass) {
  ContactSide s1{true, 1 / 2.0, Mat3::Identity(), Vec3(0.5, 0, 0)};
  ContactSide s2{true, 1 / 3.0, Mat3::Identity(), Vec3(-0.5, 0, 0)};
  EXPECT_NEAR(1 / inverseEffectiveMass(s1, s2, Vec3::UnitX()), 2.0 * 3.0 / 5.0, 1e-15);
  ContactSide wall;  // immovable
  EXPECT_NEAR(1 / inverseEffectiveMass(s1, wall, Vec3::UnitX()), 2.0, 1e-15);
  // off the centre line the rotation lowers the effective mass
  s1.arm = Vec3(0.5, 0.3, 0);
  EXPECT_LT(1 / inverseEffectiveMass(s1, wall, Vec3::UnitX()), 2.0);
}

TEST(ContactLaw, DampedOscillatorLeavesWithTheRestitution) {
  // the analytic damped oscillator of the law: exit speed / impact speed = e
  for (Scalar e : {1.0, 0.97, 0.5, 0.1}) {
    const Scalar m = 2, tc = 1e-3;
    const SpringDashpot law = springDashpot(m, e, tc);
    const Scalar w0 = std::sqrt(law.stiffness / m), z = law.damping / (2 * m);
    const Scalar wd = std::sqrt(w0 * w0 - z * z);
    EXPECT_NEAR(M_PI / wd, tc, 1e-12 * tc) << e;       // the contact lasts T_c
    EXPECT_NEAR(std::exp(-z * M_PI / wd), e, 1e-12) << e;  // and returns e
  }
}

TEST(ContactLaw, FrictionOpposesSlipAndNeverReversesItInAStep) {
  ContactSide s1{true, 1.0, Mat3::Identity() * 2.5, Vec3(0, 0, -1)};
  ContactSide wall;
  const SpringDashpot law{1e4, 0};
  const Vec3 n = -Vec3::UnitZ();  // from body 1 to the wall below
  const Vec3 relative(-1e-3, 0, 0);  // wall relative to body: body slides along +x
  // on the wall (body 2) the friction acts along the body's slip, on the body against it
  const Vec3 f = contactForce(law.stiffness * 1e-3, n, relative, law, s1, wall, 0.5, 1e-3);
  EXPECT_NEAR(f.z(), -10, 1e-12);
  EXPECT_GT(f.x(), 0);
  const Scalar wt = inverseEffectiveMass(s1, wall, Vec3::UnitX());
  EXPECT_NEAR(f.x(), std::min(0.5 * 10, 1e-3 / (wt * 1e-3)), 1e-12);
}

TEST(ContactLaw, DashpotPullsOnlyWhileTheSpringStillPushes) {
  // the linear law's short tensile end (separating, spring nearly relaxed)
  // stays; once the elastic force is spent (a spring stiffened in the
  // contact) the dashpot may push but not pull
  const ContactSide s1{true, 1.0, Mat3::Identity(), Vec3::Zero()};
  const ContactSide wall;
  const SpringDashpot law{1e4, 10};
  const Vec3 n = Vec3::UnitZ();
  const Vec3 separating(0, 0, 0.5), approaching(0, 0, -0.5);
  EXPECT_NEAR(contactForce(1.0, n, separating, law, s1, wall, 0, 1e-3).z(), 1.0 - 5.0, 1e-12);
  EXPECT_EQ(contactForce(0.0, n, separating, law, s1, wall, 0, 1e-3).z(), 0.0);
  EXPECT_NEAR(contactForce(0.0, n, approaching, law, s1, wall, 0, 1e-3).z(), 5.0, 1e-12);
}

namespace {
/// a contact of mass 1 kg at its first touch with T_c 1 ms, made 2 %
/// into a cap of 1 mm, then evaluated approaching at u_n (m/s) with the
/// effective mass m (a turning spheroid's contact point moves, and with it
/// m_eff) at the overlap x cap, the sub-step resolving exactly its T_c
struct ApproachCheck {
  ContactState state;
  long stiffened = 0;
};
ApproachCheck approachAt(Scalar overlapOverCap, Scalar un, Scalar m, Scalar shortestContactTime) {
  const SpringDashpotContact contact(0.97);
  const Scalar cap = 1e-3;
  ApproachCheck r;
  r.state = contact.firstTouch(1e-3, -0.01, cap);
  ContactLoading l;
  l.overlap = 0.02 * cap;
  l.normalSpeed = -0.01;
  l.inverseMass = 1;
  l.cap = cap;
  l.shortestContactTime = 1e-3;
  contact.force(r.state, l, r.stiffened);
  r.stiffened = 0;
  l.overlap = overlapOverCap * cap;
  l.normalSpeed = un;
  l.inverseMass = 1 / m;
  l.shortestContactTime = shortestContactTime;
  contact.force(r.state, l, r.stiffened);
  return r;
}
}  // namespace

TEST(SpringDashpotContact, TheApproachCheckNeverAsksForMoreSubSteps) {
  // a fast approach near the cap, the sub-step resolving half the contact's
  // T_c: the spring is stiffened, but its contact time (what the island's
  // sub-steps follow) stays at or above the shortest one the sub-step
  // resolves, also when m_eff has grown since the first touch
  for (const Scalar m : {0.5, 1.0, 1.6}) {
    const ApproachCheck r = approachAt(0.9, -3.0, m, 0.5e-3);
    EXPECT_GT(r.stiffened, 0) << m;
    EXPECT_GE(r.state.contactTime, 0.5e-3 * (1 - 1e-12)) << m;
  }
  EXPECT_NEAR(approachAt(0.9, -3.0, 1.0, 0.5e-3).state.contactTime, 0.5e-3, 1e-15);
}

TEST(SpringDashpotContact, BeyondTheCapTheApproachCheckLeavesTheSpring) {
  // no spring meets the check beyond the cap; stiffening there at every
  // evaluation to the shortest contact time, which other contacts shorten,
  // would shrink the sub-steps step after step
  const ApproachCheck over = approachAt(1.005, -0.5, 1.0, 0.5e-3);
  EXPECT_EQ(over.stiffened, 0);
  EXPECT_NEAR(over.state.contactTime, 1e-3, 1e-15);
  // just below the cap the same approach stiffens it
  EXPECT_GT(approachAt(0.995, -0.5, 1.0, 0.5e-3).stiffened, 0);
}

TEST(PlaneWall, SpheroidDistanceMatchesSampling) {
  const Quat q(Eigen::AngleAxis<Scalar>(0.7, Vec3(1, 2, 3).normalized()));
  const ellipsoids::Ellipsoid e(Vec3(3, 1, 0.5), Vec3(0.2, -0.1, 4), q);
  PlaneWall w{"floor", Vec3(0, 0, 0.5), Vec3(0, 0.6, 0.8)};
  w.validate();
  const WallDistance d = wallDistance(e, w);
  Scalar best = 1e300;
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j < 800; ++j) {
      const Scalar th = M_PI * i / 400, ph = 2 * M_PI * j / 800;
      const Vec3 u(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      const Vec3 x = e.centre() + e.rotation() * e.semiAxes().cwiseProduct(u);
      best = std::min(best, w.normal.dot(x - w.point));
    }
  EXPECT_NEAR(d.distance, best, 1e-3);
  EXPECT_LE(d.distance, best + 1e-12);
  EXPECT_NEAR(e.levelSet(d.bodyPoint), 0, 1e-12);
  EXPECT_NEAR(w.normal.dot(d.wallPoint - w.point), 0, 1e-12);
  PlaneWall bad{"bad", Vec3::Zero(), Vec3(0, 0, 2)};
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

namespace {
/// The message of validate() on settings with one value out of range; empty if it passed.
std::string validateMessage(const ModelSetup& s) {
  try {
    s.settings.validate();
    s.laws.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return std::string();
}
}  // namespace

TEST(ContactLaw, OutOfRangeSettingsNameTheKeywordAndTheRangeOfTheConstants) {
  struct Case {
    const char* keyword;
    void (*set)(ModelSetup&);
    Range range;
  };
  const Case cases[] = {
      {"restitution", [](ModelSetup& s) { s.laws.contact.restitution = 1.5; },
       ContactParameters::kRestitutionRange},
      {"friction", [](ModelSetup& s) { s.laws.contact.friction = -0.1; },
       ContactParameters::kFrictionRange},
      {"rollingFriction", [](ModelSetup& s) { s.laws.contact.rollingFriction = 2; },
       ContactParameters::kRollingFrictionRange},
      {"sustainedLoadOverlap", [](ModelSetup& s) { s.laws.contact.sustainedLoadOverlap = 0; },
       ContactParameters::kSustainedLoadOverlapRange},
      {"maxOverlap", [](ModelSetup& s) { s.settings.maxOverlap = 0; },
       CollisionSettings::kMaxOverlapRange},
      {"subStepsPerContact", [](ModelSetup& s) { s.settings.subStepsPerContact = 3; },
       CollisionSettings::kSubStepsPerContactRange},
      {"distanceAccuracy", [](ModelSetup& s) { s.settings.distanceAccuracy = 0.5; },
       CollisionSettings::kDistanceAccuracyRange},
      {"maxSubSteps", [](ModelSetup& s) { s.settings.maxSubSteps = 0; },
       CollisionSettings::kMaxSubStepsRange},
      {"approachContactTimeScale", [](ModelSetup& s) { s.settings.approachContactTimeScale = 8; },
       CollisionSettings::kApproachContactTimeScaleRange},
      {"saturation", [](ModelSetup& s) { s.laws.lubrication.saturation = 1; },
       LubricationParameters::kSaturationRange},
      {"pairActivation", [](ModelSetup& s) { s.laws.lubrication.pairActivation = 2; },
       LubricationParameters().activationRange()},
  };
  // the defaults lie in their ranges
  EXPECT_EQ(validateMessage(ModelSetup()), "");
  for (const Case& c : cases) {
    ModelSetup s;
    c.set(s);
    const std::string what = validateMessage(s);
    EXPECT_NE(what.find(c.keyword), std::string::npos) << what;
    EXPECT_NE(what.find(c.range.str()), std::string::npos) << c.keyword << ": " << what;
  }
  EXPECT_EQ(ContactParameters::kRestitutionRange.str(), "(0, 1]");
  EXPECT_EQ(CollisionSettings::kMaxSubStepsRange.str(), "[1, 1e+09]");
}
