#include "collision/SubStepper.hpp"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>

namespace collision {

namespace {

/// the body index that starts the record at k of a gather (records of `size`
/// numbers, the index first), checked
/// @throws std::runtime_error on a short record or an index not below n
std::size_t receivedBody(const std::vector<Scalar>& received, std::size_t k, std::size_t size,
                         std::size_t n) {
  const Scalar i = k + size <= received.size() ? received[k] : Scalar(-1);
  if (!(i >= 0 && i < Scalar(n))) {
    throw std::runtime_error("collision: a process sent a short record or body " + std::to_string(i) +
                             " of " + std::to_string(n));
  }
  return static_cast<std::size_t>(i);
}

}  // namespace

void SubStepper::step(BodySet& bodies, std::vector<BodyState>& states, CollisionModel* model,
                      Scalar contactTime, Scalar t, Scalar dt,
                      const std::vector<BodyState>& referenceStates,
                      const std::vector<char>* active, const std::vector<char>* evaluated,
                      const std::vector<char>* advanced) {
  const std::size_t n = bodies.size();
  if (states.size() != n) {
    throw std::invalid_argument("SubStepper::step: " + std::to_string(states.size()) +
                                " states for " + std::to_string(n) + " bodies");
  }
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  auto on = [active](std::size_t i) { return !active || (*active)[i]; };
  // the bodies whose trial states this process builds (with a work share:
  // those its pairs use; the collision forces of the others come from the
  // processes that own their pairs)
  auto built = [&](std::size_t i) { return on(i) && (!evaluated || (*evaluated)[i]); };

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
        if (built(i)) start_[i] = bodies.collisionBody(i, states[i]);
      }
    }
    // the start of the sub-step: the time of the last corrector (elapsed 0)
    model->forces(start_, contactTime, dt, force_, torque_, true, 0, active, evaluated);  // records the damped pairs

    for (std::size_t i = 0; i < n; ++i) {
      if (!built(i)) continue;
      trial_[i] = states[i];
      bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
      predicted_[i] = bodies.collisionBody(i, trial_[i]);
    }
    model->forces(predicted_, contactTime, dt, force1_, torque1_, false, dt, active, evaluated);
    for (std::size_t i = 0; i < n; ++i) {
      force_[i] = 0.5 * (force_[i] + force1_[i]);
      torque_[i] = 0.5 * (torque_[i] + torque1_[i]);
    }

    if (!model->dampedPairs().empty()) {
      // the end velocities under every other force, then the damping forces
      // implicit in them (an explicit damping c >> m/dt would be unstable);
      // the solve covers every process's damped pairs: their bodies' start
      // states too
      damped_.assign(n, 0);
      for (const DampedPair& p : model->dampedPairs()) {
        damped_[p.first] = 1;
        if (p.second >= 0) damped_[p.second] = 1;
      }
      endVelocity_.resize(n, Vec3::Zero());
      endAngularVelocity_.resize(n, Vec3::Zero());
      const bool reference = referenceStates.size() == n;
      referenceVelocity_.resize(reference ? n : 0, Vec3::Zero());
      referenceAngularVelocity_.resize(reference ? n : 0, Vec3::Zero());
      for (std::size_t i = 0; i < n; ++i) {
        if (!damped_[i] || !on(i)) continue;  // (only the active bodies' pairs are solved)
        if (reference) {
          referenceVelocity_[i] = referenceStates[i].velocity;
          referenceAngularVelocity_[i] = referenceStates[i].angularVelocity;
        }
        if (advanced && !(*advanced)[i]) continue;  // (its owner's: gathered below)
        if (!built(i)) start_[i] = bodies.collisionBody(i, states[i]);
        trial_[i] = states[i];
        bodies.advance(i, trial_[i], t, dt, force_[i], torque_[i]);
        endVelocity_[i] = trial_[i].velocity;
        endAngularVelocity_[i] = trial_[i].angularVelocity;
      }
      if (advanced && model->workShare()) gatherDampedBodies(*model->workShare(), *advanced, on);
      model->dampingForces(start_, endVelocity_, endAngularVelocity_, referenceVelocity_,
                           referenceAngularVelocity_, dt, force1_, torque1_, active);
      for (std::size_t i = 0; i < n; ++i) {
        force_[i] += force1_[i];
        torque_[i] += torque1_[i];
      }
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (!on(i) || (advanced && !(*advanced)[i])) continue;
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
  // (filled in place: the vectors keep their memory from step to step)
  if (start_.size() != n) {
    start_ = bodies.collisionBodies(states);
  } else {
    for (std::size_t i = 0; i < n; ++i) start_[i] = bodies.collisionBody(i, states[i]);
  }
  islands_ = model.islands(start_, dt, contactTime);
  const WorkShare* share = model.workShare();
  const std::vector<char>* evaluated = share ? &model.evaluatedBodies() : nullptr;
  if (share) {
    owned_.resize(n);
    for (std::size_t i = 0; i < n; ++i) owned_[i] = share->ownsBody(static_cast<int>(i));
  }
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
           referenceStates, &active_, evaluated, share ? &owned_ : nullptr);
      if (share) gatherStates(*share, states);
      for (std::size_t i = 0; i < n; ++i) {
        if (!active_[i]) continue;
        meanForce_[i] += force_[i] / steps;
        meanTorque_[i] += torque_[i] / steps;
        bodySubSteps_[i] = steps;
      }
    }
  }
  // (predicted_ holds the bodies at the end of the step for the check)
  for (std::size_t i = 0; i < n; ++i) predicted_[i] = bodies.collisionBody(i, states[i]);
  model.checkIslands(predicted_, islands_);
}

void SubStepper::gatherDampedBodies(const WorkShare& share, const std::vector<char>& advanced,
                                    const std::function<bool(std::size_t)>& on) {
  // the damping solve reads of each body of a damped pair its end velocities,
  // mass, world inverse inertia and mobility: the owner's, to every process
  constexpr std::size_t kNumbers = 19;
  std::vector<Scalar> mine;
  for (std::size_t i = 0; i < damped_.size(); ++i) {
    if (!damped_[i] || !on(i) || !advanced[i]) continue;
    const CollisionBody& b = start_[i];
    const Mat3& J = b.inverseInertia;
    mine.insert(mine.end(),
                {Scalar(i), endVelocity_[i].x(), endVelocity_[i].y(), endVelocity_[i].z(),
                 endAngularVelocity_[i].x(), endAngularVelocity_[i].y(), endAngularVelocity_[i].z(),
                 b.mass, J(0, 0), J(0, 1), J(0, 2), J(1, 0), J(1, 1), J(1, 2), J(2, 0), J(2, 1),
                 J(2, 2), Scalar(b.movable), Scalar(b.stationary)});
  }
  const std::vector<Scalar> numbers = share.allGatherValues(mine);
  for (std::size_t k = 0; k < numbers.size(); k += kNumbers) {
    const Scalar* x = &numbers[k];
    const std::size_t i = receivedBody(numbers, k, kNumbers, damped_.size());
    if (advanced[i]) continue;  // (this process's own)
    endVelocity_[i] = Vec3(x[1], x[2], x[3]);
    endAngularVelocity_[i] = Vec3(x[4], x[5], x[6]);
    CollisionBody& b = start_[i];  // (its shape is not read by the solve)
    b.mass = x[7];
    b.inverseInertia << x[8], x[9], x[10], x[11], x[12], x[13], x[14], x[15], x[16];
    b.movable = x[17] != 0;
    b.stationary = x[18] != 0;
  }
}

void SubStepper::gatherStates(const WorkShare& share, std::vector<BodyState>& states) {
  // each process's active bodies it owns: index and the 13 numbers of the state
  constexpr std::size_t kNumbers = 13;
  std::vector<Scalar> mine;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!active_[i] || !owned_[i]) continue;
    const BodyState& b = states[i];
    mine.insert(mine.end(), {Scalar(i), b.centre.x(), b.centre.y(), b.centre.z(),
                             b.orientation.w(), b.orientation.x(), b.orientation.y(),
                             b.orientation.z(), b.velocity.x(), b.velocity.y(), b.velocity.z(),
                             b.angularVelocity.x(), b.angularVelocity.y(), b.angularVelocity.z()});
  }
  const std::vector<Scalar> numbers = share.allGatherValues(mine);
  for (std::size_t k = 0; k < numbers.size(); k += kNumbers + 1) {
    const Scalar* x = &numbers[k];
    BodyState& b = states[receivedBody(numbers, k, kNumbers + 1, states.size())];
    b.centre = Vec3(x[1], x[2], x[3]);
    b.orientation = Quat(x[4], x[5], x[6], x[7]);
    b.velocity = Vec3(x[8], x[9], x[10]);
    b.angularVelocity = Vec3(x[11], x[12], x[13]);
  }
}

}  // namespace collision
