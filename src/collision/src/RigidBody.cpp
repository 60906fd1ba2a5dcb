#include "collision/RigidBody.hpp"

#include <cmath>

namespace collision {

namespace {
constexpr Scalar kPi = 3.14159265358979323846;

Quat rotation(const Vec3& angle) {
  const Scalar a = angle.norm();
  if (a == 0) return Quat::Identity();
  return Quat(Eigen::AngleAxis<Scalar>(a, angle / a));
}
}  // namespace

Scalar RigidBody::volume() const { return 4 * kPi / 3 * semiAxes.prod(); }

Vec3 RigidBody::bodyInertia() const {
  const Vec3 s = semiAxes.cwiseAbs2();
  return mass() / 5 * Vec3(s.y() + s.z(), s.x() + s.z(), s.x() + s.y());
}

Mat3 RigidBody::worldInertia(const Quat& q) const {
  const Mat3 R = q.toRotationMatrix();
  return R * bodyInertia().asDiagonal() * R.transpose();
}

Vec3 RigidBody::angularMomentum() const {
  return centre.cross(linearMomentum()) + worldInertia(orientation) * angularVelocity;
}

Scalar RigidBody::kineticEnergy() const {
  return 0.5 * mass() * velocity.squaredNorm() +
         0.5 * angularVelocity.dot(worldInertia(orientation) * angularVelocity);
}

CollisionBody RigidBody::collisionBody() const {
  CollisionBody b{ellipsoids::Ellipsoid(semiAxes, centre, orientation)};
  b.velocity = velocity;
  b.angularVelocity = angularVelocity;
  b.mass = mass();
  b.movable = movable;
  if (movable) b.inverseInertia = worldInertia(orientation).inverse();
  return b;
}

void RigidBody::advance(const Vec3& force, const Vec3& torque, Scalar dt) {
  if (!movable) return;
  const Vec3 u1 = velocity + force * dt / mass();
  centre += 0.5 * dt * (velocity + u1);
  velocity = u1;
  const Vec3 l0 = worldInertia(orientation) * angularVelocity;
  const Vec3 l1 = l0 + torque * dt;
  Quat half = (rotation(0.5 * dt * angularVelocity) * orientation).normalized();
  const Vec3 omegaHalf = worldInertia(half).inverse() * (l0 + 0.5 * dt * torque);
  orientation = (rotation(dt * omegaHalf) * orientation).normalized();
  angularVelocity = worldInertia(orientation).inverse() * l1;
}

void collisionSubStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                      Scalar dt) {
  std::vector<CollisionBody> cb;
  cb.reserve(bodies.size());
  for (const RigidBody& b : bodies) cb.push_back(b.collisionBody());
  std::vector<Vec3> f0, t0, f1, t1;
  model.forces(cb, contactTime, dt, f0, t0);  // records the damped pairs
  std::vector<RigidBody> predicted = bodies;
  std::vector<CollisionBody> cbPredicted;
  cbPredicted.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    predicted[i].advance(f0[i], t0[i], dt);
    cbPredicted.push_back(predicted[i].collisionBody());
  }
  model.forces(cbPredicted, contactTime, dt, f1, t1, false);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    f0[i] = 0.5 * (f0[i] + f1[i]);
    t0[i] = 0.5 * (t0[i] + t1[i]);
  }
  if (!model.dampedPairs().empty()) {
    // the end velocities under the contact forces, then the lubrication
    // forces implicit in them (in vacuum there is no flow: no film pairs)
    std::vector<Vec3> vEnd(bodies.size()), wEnd(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      RigidBody trial = bodies[i];
      trial.advance(f0[i], t0[i], dt);
      vEnd[i] = trial.velocity;
      wEnd[i] = trial.angularVelocity;
    }
    model.dampingForces(cb, vEnd, wEnd, {}, {}, dt, f1, t1);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      f0[i] += f1[i];
      t0[i] += t1[i];
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].advance(f0[i], t0[i], dt);
}

int collisionStep(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar contactTime,
                  Scalar dt) {
  std::vector<CollisionBody> cb;
  cb.reserve(bodies.size());
  for (const RigidBody& b : bodies) cb.push_back(b.collisionBody());
  const int n = model.subSteps(cb, dt, contactTime);
  for (int k = 0; k < n; ++k) collisionSubStep(bodies, model, contactTime, dt / n);
  return n;
}

}  // namespace collision
