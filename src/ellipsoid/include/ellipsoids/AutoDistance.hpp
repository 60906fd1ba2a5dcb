/**
 * @file AutoDistance.hpp
 * @brief Method choice per pair, always with a certified stop.
 *
 * A table maps (largest elongation of the pair = max/min semi-axis, requested
 * accuracy relative to the smaller equal-volume radius) to a method; the
 * chosen method runs with StopRule::certified. If its answer is not certified
 * within epsD (status max-iterations or failed, or a bracket wider than epsD),
 * auto falls back to the next method of the fallback chain (dual, gjk,
 * movingBalls), so an auto answer with status converged or overlapping is
 * within the requested tolerance, always; if every method fails the status says so.
 *
 * Unsigned: an overlapping pair gives distance 0, status overlapping and the
 * bracket [0, upper] of the method that answered ([0, 0] when it found a
 * certain common point; call DualNewton for the penetration depth).
 *
 * The default table is the measured one (docs/benchmarks.md). paper() is the
 * founding paper's design under the name "paper": its table (Moving Balls for
 * 1/3 < Ar < 3, GJK otherwise, paperTable()), its two methods as the fallback
 * chain, the certified stop as every AutoDistance.
 */
#ifndef ELLIPSOIDS_AUTODISTANCE_HPP
#define ELLIPSOIDS_AUTODISTANCE_HPP

#include "ellipsoids/DistanceMethod.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ellipsoids {

class AutoDistance : public DistanceMethod {
 public:
  /// One row: pairs with elongation <= maxElongation and epsD/R_eq <= maxRelativeEps use method.
  /// Rows are scanned in order; the first match wins (the last row should match all).
  struct Rule {
    Scalar maxElongation;
    Scalar maxRelativeEps;
    std::string method;
  };

  /// The measured default table.
  static std::vector<Rule> defaultTable();
  /// The founding paper's rule: GJK for Ar <= 1/3 or >= 3, Moving Balls otherwise.
  static std::vector<Rule> paperTable();

  /// "auto": the default table, fallback chain dual, gjk, movingBalls.
  AutoDistance();
  /// @throws std::invalid_argument on an empty table or an unknown method name
  explicit AutoDistance(const std::vector<Rule>& table);
  /**
   * @param name what name() returns
   * @param fallback the methods tried, in order, after the table's choice fails
   * @throws std::invalid_argument on an empty table, an unknown method name, or
   *         a table row or fallback naming auto or paper
   */
  AutoDistance(const std::vector<Rule>& table, const std::string& name,
               const std::vector<std::string>& fallback);

  /// The founding paper's design, named "paper" (see the file comment).
  static std::unique_ptr<AutoDistance> paper();

  std::string name() const override { return name_; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;

  /// The method the table picks for this pair and accuracy (before any fallback).
  const DistanceMethod& choose(const Ellipsoid& e1, const Ellipsoid& e2, Scalar epsD) const;

 private:
  std::string name_;
  std::vector<Rule> table_;
  std::vector<std::unique_ptr<DistanceMethod>> tableMethods_;  // one per row
  std::vector<std::unique_ptr<DistanceMethod>> fallback_;
};

}  // namespace ellipsoids

#endif
