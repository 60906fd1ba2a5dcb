#include "collision/ThreadWorkShare.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace collision {

ThreadWorkShare::Group::Group(int processes)
    : processes_(processes), bytes_(std::max(processes, 0)), values_(std::max(processes, 0)) {
  if (processes < 1) {
    throw std::invalid_argument("ThreadWorkShare: a group needs at least one thread, given " +
                                std::to_string(processes));
  }
}

std::vector<char> ThreadWorkShare::Group::allGather(int rank, const std::vector<char>& local) {
  std::unique_lock<std::mutex> lock(mutex_);
  bytes_[rank] = local;
  arrive(lock);
  std::vector<char> all;
  for (const std::vector<char>& b : bytes_) all.insert(all.end(), b.begin(), b.end());
  arrive(lock);  // every thread has read before the next deposit
  return all;
}

void ThreadWorkShare::Group::minimum(int rank, std::vector<Scalar>& values) {
  std::unique_lock<std::mutex> lock(mutex_);
  values_[rank] = values;
  arrive(lock);
  for (const std::vector<Scalar>& other : values_) {
    if (other.size() != values.size()) {
      throw std::runtime_error("ThreadWorkShare: minimum over vectors of different sizes (" +
                               std::to_string(other.size()) + ", " +
                               std::to_string(values.size()) + ")");
    }
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = std::min(values[k], other[k]);
  }
  arrive(lock);
}

void ThreadWorkShare::Group::arrive(std::unique_lock<std::mutex>& lock) {
  const long generation = generation_;
  if (++arrived_ == processes_) {
    arrived_ = 0;
    ++generation_;
    wake_.notify_all();
  } else {
    wake_.wait(lock, [&] { return generation_ != generation; });
  }
}

ThreadWorkShare::ThreadWorkShare(Group& group, int rank) : group_(group), rank_(rank) {
  if (rank < 0 || rank >= group.processes()) {
    throw std::invalid_argument("ThreadWorkShare: rank " + std::to_string(rank) + " not in [0, " +
                                std::to_string(group.processes()) + ")");
  }
}

}  // namespace collision
