/**
 * @file ThreadWorkShare.hpp
 * @brief The WorkShare of threads of one process standing in for the ranks
 *        of a parallel run: the same collectives as MPI's, on a shared
 *        exchange (the unit tests and benchmarks/collisionScaling).
 *
 * Each of P threads holds its own CollisionModel with a ThreadWorkShare of
 * one Group and its rank; a collective returns when every thread has called
 * it. A waiting thread sleeps (it uses no CPU time), so the CPU time of a
 * thread is its own share of the work.
 *
 * Usage:
 *     ThreadWorkShare::Group group(P);
 *     // in thread r:
 *     model.setWorkShare(std::make_shared<ThreadWorkShare>(group, r));
 * or, threads and group in one call:
 *     auto results = ThreadWorkShare::runRanks<Result>(P, [](auto share) { ...; return result; });
 *
 * See also: WorkShare, CollisionModel::setWorkShare.
 */
#ifndef COLLISION_THREADWORKSHARE_HPP
#define COLLISION_THREADWORKSHARE_HPP

#include "collision/WorkShare.hpp"

#include <condition_variable>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace collision {

class ThreadWorkShare : public WorkShare {
 public:
  /// The exchange of P threads: each deposits, waits for all, reads.
  class Group {
   public:
    /// @throws std::invalid_argument unless processes >= 1
    explicit Group(int processes);
    int processes() const { return processes_; }
    std::vector<char> allGather(int rank, const std::vector<char>& local);
    /// @throws std::runtime_error if the threads' vectors differ in size
    void minimum(int rank, std::vector<Scalar>& values);

   private:
    /// wait until every thread arrived (the generation changes)
    void arrive(std::unique_lock<std::mutex>& lock);

    int processes_;
    std::vector<std::vector<char>> bytes_;
    std::vector<std::vector<Scalar>> values_;
    std::mutex mutex_;
    std::condition_variable wake_;
    int arrived_ = 0;
    long generation_ = 0;
  };

  /// @throws std::invalid_argument unless 0 <= rank < group.processes()
  ThreadWorkShare(Group& group, int rank);

  /**
   * body(share) on P threads at once, thread r with the share of rank r of
   * one group; the results in rank order. A rank that throws while the others
   * wait in a collective leaves them waiting: body must fail on every rank
   * alike, as a parallel run must.
   * @throws std::runtime_error naming the first rank that threw and its message
   */
  template <class Result, class Body>
  static std::vector<Result> runRanks(int processes, const Body& body) {
    Group group(processes);
    std::vector<Result> results(processes);
    std::vector<std::string> errors(processes);
    std::vector<std::thread> threads;
    for (int r = 0; r < processes; ++r) {
      threads.emplace_back([&, r] {
        try {
          results[r] = body(std::make_shared<const ThreadWorkShare>(group, r));
        } catch (const std::exception& e) {
          errors[r] = e.what();
        }
      });
    }
    for (std::thread& t : threads) t.join();
    for (int r = 0; r < processes; ++r) {
      if (!errors[r].empty()) {
        throw std::runtime_error("rank " + std::to_string(r) + " of " + std::to_string(processes) +
                                 ": " + errors[r]);
      }
    }
    return results;
  }

  int rank() const override { return rank_; }
  int size() const override { return group_.processes(); }
  std::vector<char> allGather(const std::vector<char>& local) const override {
    return group_.allGather(rank_, local);
  }
  void minimum(std::vector<Scalar>& values) const override { group_.minimum(rank_, values); }

 private:
  Group& group_;
  int rank_;
};

}  // namespace collision

#endif
