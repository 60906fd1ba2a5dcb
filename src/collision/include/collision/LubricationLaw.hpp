/**
 * @file LubricationLaw.hpp
 * @brief Normal lubrication of two spheres or of a sphere and a plane, the
 *        correction a resolved simulation adds below its activation gap.
 *
 * Stokes lubrication force on sphere 1 approaching sphere 2 (radii a1, a2,
 * gap h, normal approach speed u): F = -6 pi mu a1 lambda u, with, for two
 * spheres (Jeffrey & Onishi 1984, X11A to O(xi ln xi); beta = a2/a1,
 * xi = 2 h/(a1 + a2)),
 *     lambda = 2 beta^2/(1 + beta)^3 / xi
 *            + beta (1 + 7 beta + beta^2)/(5 (1 + beta)^3) ln(1/xi)
 *            + (1 + 18 beta - 29 beta^2 + 18 beta^3 + beta^4)/(42 (1 + beta)^3) xi ln(1/xi)
 * (equal spheres: 1/(4 xi) - (9/40) ln xi - (3/112) xi ln xi, the form of
 * physics-references.md 3), and for a sphere of radius a and a plane
 * (eps = h/a; Cox & Brenner 1967, Costa et al. 2015)
 *     lambda = 1/eps - (1/5) ln eps - (1/21) eps ln eps + 0.9713.
 * The resolved flow carries the force down to gaps of about a cell; the
 * correction adds the part it does not carry, in one of two forms:
 * - the ratio form (Costa et al. 2015): below the activation gap ratio
 *   (xi_act, eps_act) the flow is taken to carry lambda(x_act), and
 *       F = -6 pi mu a1 [lambda(x) - lambda(x_act)] u;
 * - the resolved-gap form: the flow carries the film force of the gap
 *   s = sqrt(x^2 + x_delta^2), widened in quadrature by a resolved gap
 *   delta = c x cell size (x_delta its ratio), so that the correction is the
 *   difference of the singular terms at x and at s,
 *       F = -6 pi mu a1 [A (1/x - 1/s) + (B/2) ln(1 + x_delta^2/x^2)
 *                        - (the same at x_act)] u,
 *   with A/x and B ln(1/x) the leading and logarithmic terms of lambda, and
 *   x_act = kActivationOverResolvedGap x_delta. c is fitted once on the
 *   resolved force of a sphere approaching a wall (LubricationParameters).
 * x is frozen below the saturation gap x_sat (surface roughness; the
 * founding paper's eps_1 = 1e-3), so that the force stays finite; off in
 * contact.
 * For spheroids a1, a2 are the Gaussian curvature radii of the bodies at their
 * closest points (a plane: infinite; Ardekani et al. 2016), and the leading
 * term, the squeeze force of the local gap, is that of the gap's paraboloid
 * (GapParaboloid.hpp): 6 pi mu R*^2 u/h in place of the two spheres'
 * 6 pi mu (a1 a2/(a1 + a2))^2 u/h (a plane: a^2), the logarithmic terms those
 * of the two spheres (LubricationGapLaw with a squeeze radius).
 */
#ifndef COLLISION_LUBRICATIONLAW_HPP
#define COLLISION_LUBRICATIONLAW_HPP

#include "collision/Range.hpp"
#include "collision/Types.hpp"

namespace collision {

/// The defaults are the member initialisers, the allowed values the k... constants.
struct LubricationParameters {
  /// xi_act = 2 h/(a1 + a2) below which the pair correction acts, in activationRange()
  Scalar pairActivation = 0.025;
  /// eps_act = h/a below which the wall correction acts, in activationRange()
  Scalar wallActivation = 0.075;
  /// > 0: the resolved-gap form for pairs, with delta = pairResolvedGapCells
  /// x the bodies' cell size (CollisionBody::cellSize), in place of the ratio
  /// pairActivation; 0: the ratio form. In kCellsRange.
  Scalar pairResolvedGapCells = 0;
  /// > 0: the resolved-gap form for walls (wallResolvedGapCells x cellSize),
  /// in place of wallActivation; 0: the ratio form. In kCellsRange.
  Scalar wallResolvedGapCells = 0;
  static constexpr Range kCellsRange{0, 8, true, false};
  /// The resolved gap in cells of the module's flow solver (its defaults):
  /// fitted once on the resolved film force of a sphere approaching a wall at
  /// 8 cells/d (least squares over eleven gaps, 2 d to 1e-3 d) and checked at
  /// 12 and 16 (validation/lubricationResolution, docs/collisions.md).
  static constexpr Scalar kWallResolvedGapCells = 0.62;
  /// Pairs: two diffuse surfaces, each leaving the wall's unresolved layer,
  /// combined in quadrature (sqrt(2) x the wall's value; predicted from the
  /// wall's fit, not fitted; checked on two spheres approaching each other at
  /// 8 and 12 cells/d, validation/lubricationResolution --shape spherePair).
  static constexpr Scalar kPairResolvedGapCells = 1.41421356237309505 * kWallResolvedGapCells;
  /// The resolved-gap form acts below this many resolved gaps delta: beyond,
  /// its correction, about delta^2/(2 h^2) of the force, is at most 1/32.
  static constexpr Scalar kActivationOverResolvedGap = 4;
  /// xi_sat, eps_sat: the correction is frozen below this gap ratio, in kSaturationRange
  Scalar saturation = 1e-3;
  static constexpr Range kSaturationRange{0, 1, true, true};
  /// the logarithmic tangential and rotational terms too (TangentialLubrication.hpp)
  bool tangential = true;
  /// the largest activation gap ratio
  static constexpr Scalar kMaxActivation = 1;

  /// (saturation, kMaxActivation]: the allowed activation gap ratios
  Range activationRange() const { return Range{saturation, kMaxActivation, true, false}; }

  /// @throws std::invalid_argument naming the parameter and its allowed range
  void validate() const;

  /// Whether the law of a wall (true) or a pair is of the resolved-gap form.
  bool resolvedGapForm(bool wall) const {
    return (wall ? wallResolvedGapCells : pairResolvedGapCells) > 0;
  }

  /**
   * The resolved gap ratio x_delta of the resolved-gap form (delta/a1 for a
   * wall, a2 = infinity; 2 delta/(a1 + a2) for a pair), 0 in the ratio form.
   * @throws std::invalid_argument in the resolved-gap form with cellSize <= 0
   */
  Scalar resolvedGapRatio(Scalar a1, Scalar a2, Scalar cellSize) const;

  /**
   * The activation gap ratio of a law (x_act: h_act/a1 for a wall, a2 =
   * infinity; 2 h_act/(a1 + a2) for a pair) for the curvature radii a1, a2
   * and the cell size: the ratio keyword's, or kActivationOverResolvedGap
   * x_delta, at most kMaxActivation (the asymptotic laws hold below it) and
   * at least the saturation ratio (there the law no longer acts).
   * Nondecreasing in a1 and a2, so that the radii's upper bounds bound the
   * activation gap.
   * @throws std::invalid_argument in the resolved-gap form with cellSize <= 0
   */
  Scalar activationRatio(Scalar a1, Scalar a2, Scalar cellSize) const;

  /// The activation gap h_act itself (a length) for the radii and cell size.
  Scalar activationGap(Scalar a1, Scalar a2, Scalar cellSize) const;
};

/// lambda of two spheres of radii a1, a2 at the gap ratio xi = 2 h/(a1 + a2) > 0.
Scalar pairLubricationLambda(Scalar xi, Scalar a1, Scalar a2);

/// lambda of a sphere and a plane at eps = h/a > 0.
Scalar wallLubricationLambda(Scalar eps);

/**
 * The correction's coefficient c >= 0: the force on body 1 is F_1 = c u n and
 * on body 2 F_2 = -F_1, with n the unit normal from 1 to 2 and u = (v_2 - v_1).n
 * the normal relative speed at the closest points (negative when approaching:
 * the force then pushes the bodies apart; when separating it holds them).
 * Zero at and beyond the activation gap; a gap in [0, saturation gap) counts as
 * the saturation gap; zero in contact (gap < 0), where the spring-dashpot law
 * alone acts (as in Costa et al. 2015: a lubrication force held through the
 * contact would damp the rebound a second time).
 * @param gap  surface gap h (any sign)
 * @param a1, a2 the curvature radii (a2 = infinity for a plane)
 */
Scalar pairLubricationCoefficient(Scalar gap, Scalar a1, Scalar a2, Scalar viscosity,
                                  const LubricationParameters& p);
Scalar wallLubricationCoefficient(Scalar gap, Scalar a, Scalar viscosity,
                                  const LubricationParameters& p);

/**
 * The integral of the coefficient over the gap, I = int_{h0}^{h1} c(h) dh
 * (signed: negative for h1 < h0), in closed form. A pair whose gap goes from
 * h0 to h1 under the correction alone (Stokes: F dt = -c(h) dh) receives the
 * impulse -I along its normal whatever the time this takes: the correction's
 * logarithm is integrated exactly however coarse the time step (the body
 * sub-steps of a fluid step cross the gap range 1e-3 .. 0.075 a in a few
 * steps, and a coefficient sampled at their start gaps misses most of the
 * small gaps, where most of the logarithm is). c(h) as in pair/wallLubricationCoefficient: 0 in contact and beyond
 * the activation gap, frozen below the saturation gap.
 */
Scalar pairLubricationIntegral(Scalar h0, Scalar h1, Scalar a1, Scalar a2, Scalar viscosity,
                               const LubricationParameters& p);
Scalar wallLubricationIntegral(Scalar h0, Scalar h1, Scalar a, Scalar viscosity,
                               const LubricationParameters& p);

/**
 * One pair's correction as a function of its gap, with the constants of the
 * law computed once (the implicit solve evaluates it many times per pair):
 * coefficient(h) equals pairLubricationCoefficient(h, a1, a2, ...) and
 * primitive(h1) - primitive(h0) equals pairLubricationIntegral(h0, h1, ...).
 */
class LubricationGapLaw {
 public:
  LubricationGapLaw() = default;
  /// a2 = infinity: a sphere of radius a1 and a plane
  LubricationGapLaw(Scalar a1, Scalar a2, Scalar viscosity, const LubricationParameters& p);
  /// The same with the leading term 6 pi mu R*^2 u/h of the gap's paraboloid
  /// (squeezeRadius R* > 0; for spheres R* = a1 a2/(a1 + a2), a plane: a1)
  /// and the activation gap of the cell size cellSize (activationRatio; 0 with
  /// the ratio activation)
  LubricationGapLaw(Scalar a1, Scalar a2, Scalar viscosity, const LubricationParameters& p,
                    Scalar squeezeRadius, Scalar cellSize = 0);
  Scalar coefficient(Scalar gap) const;
  /// G(gap) = int_0^gap c(h) dh (0 for gap <= 0, constant beyond the activation gap)
  Scalar primitive(Scalar gap) const;
  /// L = ln(x_act/max(x, x_sat)) for a gap in [0, activation gap), 0 otherwise:
  /// the log factor of the tangential terms (TangentialLubrication.hpp)
  Scalar logFactor(Scalar gap) const;

 private:
  Scalar lambda(Scalar x) const;
  Scalar lambdaPrimitive(Scalar x) const;
  /// the resolved-gap form's correction (before the shift at x_act) and its primitive
  Scalar unresolved(Scalar x) const;
  Scalar unresolvedPrimitive(Scalar x) const;
  /// the correction's value at x > 0 below the activation gap, before the saturation
  Scalar correction(Scalar x) const;
  Scalar correctionPrimitive(Scalar x) const;
  bool wall_ = true;
  Scalar delta_ = 0;  ///< x_delta > 0: the resolved-gap form
  Scalar logB_ = 0;   ///< B of lambda's B ln(1/x)
  Scalar A_ = 0, B_ = 0, C_ = 0;  ///< the pair law's terms; walls: A_, the 1/eps term's
  Scalar scale_ = 0;              ///< gap ratio x = scale_ h
  Scalar force_ = 0;              ///< 6 pi mu a1: c = force_ (lambda(x) - lambda(x_act))
  Scalar act_ = 0, sat_ = 0, correctionSat_ = 0, primitiveSat_ = 0;
  Scalar lambdaAct_ = 0;      ///< ratio form: lambda(x_act)
  Scalar unresolvedAct_ = 0;  ///< resolved-gap form: unresolved(x_act)
};

}  // namespace collision

#endif
