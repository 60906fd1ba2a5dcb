// The pair and wall models built by name, and the film correction given or not.
#include "ModelSetup.hpp"
#include "collision/RigidBody.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

using namespace collision;

namespace {
/// The message of New(name); empty if it built a model.
template <class Model>
std::string newMessage(const std::string& name, const InteractionParameters& p) {
  try {
    Model::New(name, p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return std::string();
}
}  // namespace

TEST(ModelFactory, AnUnknownNameListsTheAllowedOnes) {
  const InteractionParameters p;
  for (const std::string& what :
       {newMessage<PairModel>("hertz", p), newMessage<WallModel>("hertz", p)}) {
    EXPECT_NE(what.find("hertz"), std::string::npos) << what;
    EXPECT_NE(what.find("springDashpot, lubricatedSpringDashpot"), std::string::npos) << what;
  }
}

TEST(ModelFactory, SpringDashpotHasNoLubricationReachTheLubricatedOneHas) {
  InteractionParameters p;
  p.viscosity = 1e-3;
  p.contact.friction = 0.2;
  const auto pair = PairModel::New("springDashpot", p);
  const auto wall = WallModel::New("springDashpot", p);
  EXPECT_EQ(pair->name(), "springDashpot");
  EXPECT_FALSE(pair->lubrication().acts());
  EXPECT_FALSE(wall->lubrication().acts());
  EXPECT_EQ(pair->lubrication().reach(1, 1), 0);
  EXPECT_EQ(pair->contact().restitution(), p.contact.restitution);

  const auto lubricatedPair = PairModel::New("lubricatedSpringDashpot", p);
  const auto lubricatedWall = WallModel::New("lubricatedSpringDashpot", p);
  const Scalar a = 1e-3;
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  EXPECT_TRUE(lubricatedPair->lubrication().acts());
  EXPECT_DOUBLE_EQ(lubricatedPair->lubrication().activationGap(a, a, 0),
                   p.lubrication.pairActivation * a);
  EXPECT_DOUBLE_EQ(lubricatedWall->lubrication().activationGap(a, inf, 0),
                   p.lubrication.wallActivation * a);
  // the law of a sphere at a wall inside its activation gap acts
  EXPECT_GT(lubricatedWall->lubrication().gapLaw(a, inf, a, 0).coefficient(0.01 * a), 0);
  // a lubricated model needs the viscosity from its caller
  EXPECT_THROW(PairModel::New("lubricatedSpringDashpot", InteractionParameters()),
               std::invalid_argument);
}

TEST(ModelFactory, WithoutAFilmCorrectionNoFilmPairsAreRecorded) {
  // a sphere resting a fifth of its film gap above the floor
  const Scalar a = 2e-3, cell = 6.7e-4;
  RigidBody sphere;
  sphere.semiAxes = Vec3::Constant(a);
  sphere.centre = Vec3(0, 0, a + 0.2 * cell);
  sphere.velocity = Vec3(0, 0, -1e-3);
  CollisionBody b = sphere.collisionBody();
  b.filmGap = cell;
  const PlaneWall floorWall{"floor", Vec3::Zero(), Vec3::UnitZ()};
  for (const bool film : {false, true}) {
    ModelSetup s;
    s.filmViscosity = film ? 0.07 : 0;
    CollisionModel model = makeModel(s, {floorWall});
    EXPECT_EQ(model.filmCorrection() != nullptr, film);
    std::vector<Vec3> F, T;
    model.forces({b}, 1e-2, 1e-3, F, T);
    EXPECT_EQ(model.dampedPairs().size(), film ? 1u : 0u);
    EXPECT_EQ(model.statistics().filmPairs, film ? 1 : 0);
  }
}
