#include "collision/SubStepper.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace collision {

void SubStepper::step(BodySet& bodies, std::vector<BodyState>& states, CollisionModel* model,
                      Scalar contactTime, Scalar t, Scalar dt,
                      const std::vector<BodyState>& referenceStates,
                      const std::vector<char>* active) {
  const std::size_t n = bodies.size();
  if (states.size() != n) {
    throw std::invalid_argument("SubStepper::step: " + std::to_string(states.size()) +
                                " states for " + std::to_string(n) + " bodies");
  }
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  auto on = [active](std::size_t i) { return !active || (*active)[i]; };

  if (model) {
    // the bodies as the model sees them (of the active ones only, when the
    // others were set by an earlier sub-step of the same bodies)
    if (!active || start_.size() != n) {
      start_.clear();
      for (std::size_t i = 0; i < n; ++i) start_.push_back(bodies.collisionBody(i, states[i]));
      predicted_ = start_;
      trial_ = states;
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        if (on(i)) start_[i] = bodies.collisionBody(i, states[i]);
      }
    }
    // the start of the sub-step: the time of the last corrector (elapsed 0)
    model->forces(start_, contactTime, dt, force_, torque_, true, 0, active);  // records the damped pairs

    for (std::size_t i = 0; i < n; ++i) {
      if (!on(i)) continue;
      trial_[i] = states[i];
      bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
      predicted_[i] = bodies.collisionBody(i, trial_[i]);
    }
    model->forces(predicted_, contactTime, dt, force1_, torque1_, false, dt, active);
    for (std::size_t i = 0; i < n; ++i) {
      force_[i] = 0.5 * (force_[i] + force1_[i]);
      torque_[i] = 0.5 * (torque_[i] + torque1_[i]);
    }

    if (!model->dampedPairs().empty()) {
      // the end velocities under every other force, then the damping forces
      // implicit in them (an explicit damping c >> m/dt would be unstable)
      endVelocity_.resize(n, Vec3::Zero());
      endAngularVelocity_.resize(n, Vec3::Zero());
      const bool reference = referenceStates.size() == n;
      referenceVelocity_.resize(reference ? n : 0, Vec3::Zero());
      referenceAngularVelocity_.resize(reference ? n : 0, Vec3::Zero());
      for (std::size_t i = 0; i < n; ++i) {
        if (!on(i)) continue;  // (only the active bodies' pairs are solved)
        trial_[i] = states[i];
        bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
        endVelocity_[i] = trial_[i].velocity;
        endAngularVelocity_[i] = trial_[i].angularVelocity;
        if (reference) {
          referenceVelocity_[i] = referenceStates[i].velocity;
          referenceAngularVelocity_[i] = referenceStates[i].angularVelocity;
        }
      }
      model->dampingForces(start_, endVelocity_, endAngularVelocity_, referenceVelocity_,
                           referenceAngularVelocity_, dt, force1_, torque1_, active);
      for (std::size_t i = 0; i < n; ++i) {
        force_[i] += force1_[i];
        torque_[i] += torque1_[i];
      }
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (!on(i)) continue;
    const BodyState start = states[i];
    bodies.advance(i, states[i], t, dt, force_[i], torque_[i]);
    bodies.accept(i, start, states[i], dt, force_[i], torque_[i]);
  }
}

void SubStepper::stepIslands(BodySet& bodies, std::vector<BodyState>& states, CollisionModel& model,
                             Scalar contactTime, Scalar t, Scalar dt, int minSubSteps,
                             const std::vector<BodyState>& referenceStates) {
  const std::size_t n = bodies.size();
  if (states.size() != n) {
    throw std::invalid_argument("SubStepper::stepIslands: " + std::to_string(states.size()) +
                                " states for " + std::to_string(n) + " bodies");
  }
  start_ = bodies.collisionBodies(states);
  islands_ = model.islands(start_, dt, contactTime);
  predicted_ = start_;
  trial_ = states;
  meanForce_.assign(n, Vec3::Zero());
  meanTorque_.assign(n, Vec3::Zero());
  bodySubSteps_.assign(n, 1);
  // the numbers of sub-steps of the step: those of the interacting islands,
  // and the islands without interaction (no collision forces)
  std::vector<int> counts;
  for (const Island& island : islands_) {
    counts.push_back(island.interacts ? std::max(minSubSteps, island.subSteps) : -std::max(1, minSubSteps));
  }
  std::vector<int> distinct(counts);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  for (const int count : distinct) {
    active_.assign(n, 0);
    for (std::size_t k = 0; k < islands_.size(); ++k) {
      if (counts[k] != count) continue;
      for (const int b : islands_[k].bodies) active_[b] = 1;
    }
    const int steps = std::abs(count);
    const Scalar subDt = dt / steps;
    for (int s = 0; s < steps; ++s) {
      step(bodies, states, count > 0 ? &model : nullptr, contactTime, t + s * subDt, subDt,
           referenceStates, &active_);
      for (std::size_t i = 0; i < n; ++i) {
        if (!active_[i]) continue;
        meanForce_[i] += force_[i] / steps;
        meanTorque_[i] += torque_[i] / steps;
        bodySubSteps_[i] = steps;
      }
    }
  }
  model.checkIslands(bodies.collisionBodies(states), islands_);
}

}  // namespace collision
