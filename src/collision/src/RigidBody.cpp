#include "collision/RigidBody.hpp"

#include "collision/RigidBodySet.hpp"
#include "collision/SubStepper.hpp"

namespace collision {

Vec3 RigidBody::angularMomentum() const {
  return centre.cross(linearMomentum()) + worldInertia(orientation) * angularVelocity;
}

Scalar RigidBody::kineticEnergy() const {
  return 0.5 * mass() * velocity.squaredNorm() +
         0.5 * angularVelocity.dot(worldInertia(orientation) * angularVelocity);
}

CollisionBody RigidBody::collisionBody(const BodyState& s) const {
  CollisionBody b{ellipsoids::Ellipsoid(semiAxes, s.centre, s.orientation.normalized())};
  b.velocity = s.velocity;
  b.angularVelocity = s.angularVelocity;
  b.mass = mass();
  b.movable = movable;
  if (movable) b.inverseInertia = inverseWorldInertia(s.orientation, bodyInertia());
  return b;
}

namespace {

/// n sub-steps of dt through the SubStepper, the states written back to the bodies
void subSteps(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
              Scalar dt, int n) {
  RigidBodySet set(bodies);
  std::vector<BodyState> states(bodies.begin(), bodies.end());
  SubStepper stepper;
  for (int k = 0; k < n; ++k) stepper.step(set, states, &model, contactTime, k * dt, dt);
  for (std::size_t i = 0; i < bodies.size(); ++i) static_cast<BodyState&>(bodies[i]) = states[i];
}

}  // namespace

void collisionSubStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                      Scalar dt) {
  subSteps(bodies, model, contactTime, dt, 1);
}

int collisionStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                  Scalar dt) {
  std::vector<CollisionBody> cb;
  cb.reserve(bodies.size());
  for (const RigidBody& b : bodies) cb.push_back(b.collisionBody());
  const int n = model.subSteps(cb, dt, contactTime);
  subSteps(bodies, model, contactTime, dt / n, n);
  return n;
}

}  // namespace collision
