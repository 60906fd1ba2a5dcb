#include "collision/SubStepper.hpp"

#include <stdexcept>
#include <string>

namespace collision {

void SubStepper::step(BodySet& bodies, std::vector<BodyState>& states, CollisionModel* model,
                      Scalar contactTime, Scalar t, Scalar dt,
                      const std::vector<BodyState>& referenceStates) {
  const std::size_t n = bodies.size();
  if (states.size() != n) {
    throw std::invalid_argument("SubStepper::step: " + std::to_string(states.size()) +
                                " states for " + std::to_string(n) + " bodies");
  }
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());

  if (model) {
    start_.clear();
    for (std::size_t i = 0; i < n; ++i) start_.push_back(bodies.collisionBody(i, states[i]));
    // the start of the sub-step: the time of the last corrector (elapsed 0)
    model->forces(start_, contactTime, dt, force_, torque_, true, 0);  // records the damped pairs

    trial_ = states;
    predicted_.clear();
    for (std::size_t i = 0; i < n; ++i) {
      bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
      predicted_.push_back(bodies.collisionBody(i, trial_[i]));
    }
    model->forces(predicted_, contactTime, dt, force1_, torque1_, false, dt);
    for (std::size_t i = 0; i < n; ++i) {
      force_[i] = 0.5 * (force_[i] + force1_[i]);
      torque_[i] = 0.5 * (torque_[i] + torque1_[i]);
    }

    if (!model->dampedPairs().empty()) {
      // the end velocities under every other force, then the damping forces
      // implicit in them (an explicit damping c >> m/dt would be unstable)
      trial_ = states;
      endVelocity_.resize(n);
      endAngularVelocity_.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
        endVelocity_[i] = trial_[i].velocity;
        endAngularVelocity_[i] = trial_[i].angularVelocity;
      }
      referenceVelocity_.clear();
      referenceAngularVelocity_.clear();
      for (const BodyState& r : referenceStates) {
        referenceVelocity_.push_back(r.velocity);
        referenceAngularVelocity_.push_back(r.angularVelocity);
      }
      model->dampingForces(start_, endVelocity_, endAngularVelocity_, referenceVelocity_,
                           referenceAngularVelocity_, dt, force1_, torque1_);
      for (std::size_t i = 0; i < n; ++i) {
        force_[i] += force1_[i];
        torque_[i] += torque1_[i];
      }
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    const BodyState start = states[i];
    bodies.advance(i, states[i], t, dt, force_[i], torque_[i]);
    bodies.accept(i, start, states[i], dt, force_[i], torque_[i]);
  }
}

}  // namespace collision
