/**
 * @file WorkShare.hpp
 * @brief How the processes of a parallel run share CollisionModel's work:
 *        each pair (of bodies, or of a body and a wall) belongs to one
 *        process, and the processes' results are combined with one
 *        collective per evaluation.
 *
 * A body's owner is a hash of its index modulo the number of processes, a
 * pair's the owner of its first body (the smaller index; a body's for its
 * wall pairs): the same on every process and for the pair's whole life, so
 * its warm start and contact history stay on the process that uses them, the
 * pairs spread evenly whatever the bodies' positions, and a process finds its
 * pairs from its own bodies (PairSearch's first-body flags) and needs the
 * states of those and their neighbours only. The collision core has
 * no MPI: a solver supplies the collectives (the OpenFOAM module's
 * pstreamWorkShare). Every process calls them in the same order, with the
 * same bodies.
 *
 * See also: CollisionModel::setWorkShare.
 */
#ifndef COLLISION_WORKSHARE_HPP
#define COLLISION_WORKSHARE_HPP

#include "collision/Types.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace collision {

class WorkShare {
 public:
  virtual ~WorkShare() = default;

  /// this process, in [0, size())
  virtual int rank() const = 0;
  /// the number of processes, >= 1
  virtual int size() const = 0;
  /// every process's bytes, concatenated in process order, on every process (collective)
  virtual std::vector<char> allGather(const std::vector<char>& local) const = 0;
  /// each entry the smallest of the processes' values of it, on every process (collective)
  virtual void minimum(std::vector<Scalar>& values) const = 0;

  /// every process's values concatenated in process order, on every process
  /// (allGather of their bytes; values of a trivially copyable type)
  /// @throws std::runtime_error if the bytes received are not whole values
  template <class T>
  std::vector<T> allGatherValues(const std::vector<T>& local) const {
    static_assert(std::is_trivially_copyable<T>::value, "allGatherValues: values copied as bytes");
    std::vector<char> bytes(local.size() * sizeof(T));
    if (!local.empty()) std::memcpy(bytes.data(), local.data(), bytes.size());
    const std::vector<char> all = allGather(bytes);
    if (all.size() % sizeof(T) != 0) {
      throw std::runtime_error("collision: the processes sent " + std::to_string(all.size()) +
                               " bytes, not whole values of " + std::to_string(sizeof(T)));
    }
    std::vector<T> values(all.size() / sizeof(T));
    if (!values.empty()) std::memcpy(values.data(), all.data(), all.size());
    return values;
  }

  /// the process that owns body i (>= 0)
  int bodyOwner(int i) const;
  bool ownsBody(int i) const { return bodyOwner(i) == rank(); }
  /// the process that owns the pair with this key: its first body's
  int owner(std::uint64_t key) const;
  bool owns(std::uint64_t key) const { return owner(key) == rank(); }
};

}  // namespace collision

#endif
