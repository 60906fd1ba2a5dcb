#!/usr/bin/python3
"""Published drag, lift and pitching torque of a sphere and of a prolate spheroid AR 2.5
in a uniform stream (validation/finiteReynoldsDrag). Re = U D_eq/nu; force coefficients
normalised by rho U^2/2 pi D_eq^2/4, the torque's by rho U^2/2 pi D_eq^2/4 D_eq/2, D_eq the
diameter of the equal-volume sphere."""
import math

# Johnson & Patel (1999, JFM 378, 19), body-fitted steady axisymmetric sphere wakes
JOHNSON_PATEL = {50: 1.57, 100: 1.08}


def schiller_naumann(re):
    """Schiller & Naumann (1933): C_D = 24/Re (1 + 0.15 Re^0.687), Re <= 1000."""
    return 24.0 / re * (1.0 + 0.15 * re ** 0.687)


def standard_drag_curve(re):
    """The standard drag curve of Clift, Grace & Weber (1978, Table 5.2) for
    20 <= Re <= 260: C_D = 24/Re (1 + 0.1935 Re^0.6305), a fit to accurate
    experiments and numerical solutions; it agrees with Johnson & Patel at Re 50
    and 100 within 0.7 %."""
    if not 20 <= re <= 260:
        raise ValueError(f"standard_drag_curve: Re {re} outside its range 20-260")
    return 24.0 / re * (1.0 + 0.1935 * re ** 0.6305)


def clift_low_re(re):
    """The standard drag curve of Clift, Grace & Weber (1978, Table 5.2) for
    0.01 < Re <= 20: C_D = 24/Re (1 + 0.1315 Re^(0.82 - 0.05 log10 Re))."""
    if not 0.01 < re <= 20:
        raise ValueError(f"clift_low_re: Re {re} outside its range 0.01-20")
    return 24.0 / re * (1.0 + 0.1315 * re ** (0.82 - 0.05 * math.log10(re)))


def clift(re):
    """Clift, Grace & Weber's standard drag curve over 0.01 < Re <= 260 (its two branches)."""
    return clift_low_re(re) if re <= 20 else standard_drag_curve(re)


def abraham(re):
    """Abraham (1970): C_D = 24/9.06^2 (1 + 9.06/sqrt(Re))^2, the correlation ten Cate et
    al. (2002) took their u_inf from."""
    return 24.0 / 9.06 ** 2 * (1.0 + 9.06 / math.sqrt(re)) ** 2


def terminal_speed(cd, rho_p, rho_f, mu, d, g=9.81, tolerance=1e-12):
    """(U, Re) of a sphere of diameter d whose drag C_D(Re) rho_f U^2/2 pi d^2/4 equals its
    net weight (rho_p - rho_f) g pi d^3/6, by bisection between 0.01 and 1 times the Stokes
    speed (a C_D at or above 24/Re, and below 100 times it, brackets it); raises if the
    correlation does not bracket it or the bisection does not reach the tolerance."""
    weight = (rho_p - rho_f) * g * math.pi * d ** 3 / 6.0
    stokes = (rho_p - rho_f) * g * d ** 2 / (18.0 * mu)

    def excess(u):
        re = rho_f * u * d / mu
        return cd(re) * 0.5 * rho_f * u * u * math.pi * d * d / 4.0 - weight

    lo, hi = 0.01 * stokes, stokes
    if not (excess(lo) < 0.0 <= excess(hi)):
        raise ValueError(f"terminal_speed: {cd.__name__} does not bracket the balance "
                         f"between {lo:.3g} and {hi:.3g} m/s")
    for _ in range(200):
        u = 0.5 * (lo + hi)
        lo, hi = (u, hi) if excess(u) < 0.0 else (lo, u)
        if hi - lo <= tolerance * hi:
            return hi, rho_f * hi * d / mu
    raise RuntimeError(f"terminal_speed: no convergence to {tolerance:g} in 200 bisections")


# Zastawny, Mallouppas, Zhao, van Wachem (2012, IJMF 39, 227), ellipsoid AR 2.5
# ("shape 1"): C_D = C_D0 + (C_D90 - C_D0) sin^a0(phi), C_D0 = a1/Re^a2 + a3/Re^a4,
# C_D90 = a5/Re^a6 + a7/Re^a8, fitted to their resolved simulations for
# 0.1 <= Re <= 300; phi the angle between the stream and the symmetry axis.
ZASTAWNY_AR25 = (2.0, 5.1, 0.48, 15.52, 1.05, 24.68, 0.98, 3.19, 0.21)


def zastawny_drag(re, phi_deg, a=ZASTAWNY_AR25):
    c0 = a[1] / re ** a[2] + a[3] / re ** a[4]
    c90 = a[5] / re ** a[6] + a[7] / re ** a[8]
    return c0 + (c90 - c0) * math.sin(math.radians(phi_deg)) ** a[0]


# Zastawny et al.'s lift for the same ellipsoid: |C_L| = (b1/Re^b2 + b3/Re^b4)
# sin(phi)^(b5 + b6 Re^b7) cos(phi)^(b8 + b9 Re^b10). The paper could not be read on this
# machine: b1..b10 as transcribed in the spheroid utilities of a public Basilisk sandbox
# (myspheroid.h, "Correlations for the drag, lift and pitching torque coefficients of a
# spheroid"), whose drag coefficients for this shape are ZASTAWNY_AR25 digit for digit,
# with the same normalisation (pi D_eq^2/4) and Re = U D_eq/nu.
ZASTAWNY_LIFT_AR25 = (6.079, 0.898, 0.704, -0.028, 1.067, 0.0025, 0.818, 1.049, 0.0, 0.0)


def zastawny_lift(re, phi_deg, b=ZASTAWNY_LIFT_AR25):
    p = math.radians(phi_deg)
    return ((b[0] / re ** b[1] + b[2] / re ** b[3])
            * math.sin(p) ** (b[4] + b[5] * re ** b[6])
            * math.cos(p) ** (b[7] + b[8] * re ** b[9]))


# Zastawny et al.'s pitching torque for the same ellipsoid, the form of their lift:
# C_T = (c1/Re^c2 + c3/Re^c4) sin(phi)^(c5 + c6 Re^c7) cos(phi)^(c8 + c9 Re^c10), with
# C_T = T_z/(rho U^2/2 pi D_eq^2/4 D_eq/2): the torque about the centre over the drag's
# reference force times the equal-volume sphere's radius, Re = U D_eq/nu, valid for
# 0.1 <= Re <= 300 and 0 <= phi <= 90 degrees. c1..c10 for AR 2.5 ("gamma = 5/2") and the
# normalisation from the same transcription as ZASTAWNY_LIFT_AR25: the Basilisk sandbox
# file myspheroid.h ("Utility functions for spheroids", section "Correlations for the drag,
# lift and pitching torque coefficients of a spheroid", function torque_Zastawny2012); the
# public-code index that holds the file gives its text but not its repository or path.
# The form is positive for 0 < phi < 90 and that source states no sign convention for T_z,
# so the magnitude is compared (validation/finiteReynoldsDrag/plotDrag.torque_table).
ZASTAWNY_TORQUE_AR25 = (2.078, 0.279, 0.372, 0.018, 0.98, 0.0, 0.0, 1.0, 0.0, 0.0)


def zastawny_torque(re, phi_deg, c=ZASTAWNY_TORQUE_AR25):
    p = math.radians(phi_deg)
    return ((c[0] / re ** c[1] + c[2] / re ** c[3])
            * math.sin(p) ** (c[4] + c[5] * re ** c[6])
            * math.cos(p) ** (c[7] + c[8] * re ** c[9]))


def linear_resistance_lift(re, phi_deg):
    """|C_L| = (C_D90 - C_D0) sin(phi) cos(phi) with Zastawny's C_D0 and C_D90: exact
    for Stokes flow (the force is linear in the velocity, so the drag varies as
    sin^2 phi and the lift follows from the same two coefficients); at finite Re an
    estimate, not a fit to lift data."""
    c0, c90 = zastawny_drag(re, 0.0), zastawny_drag(re, 90.0)
    p = math.radians(phi_deg)
    return (c90 - c0) * math.sin(p) * math.cos(p)


def stokes_prolate_k(ar):
    """(K_along, K_across): the Stokes drag of a prolate spheroid of aspect ratio ar moving
    along and across its axis, divided by that of the equal-volume sphere (Oberbeck 1876;
    Happel & Brenner 1965, eccentricity e, semi-major axis a)."""
    a = 0.5 * ar ** (2.0 / 3.0)
    e = math.sqrt(1.0 - 1.0 / ar ** 2)
    log = math.log((1 + e) / (1 - e))
    along = 16 * math.pi * a * e ** 3 / ((1 + e * e) * log - 2 * e)
    across = 32 * math.pi * a * e ** 3 / ((3 * e * e - 1) * log + 2 * e)
    return along / (3 * math.pi), across / (3 * math.pi)


def zastawny_stokes_check(ar=2.5, re=0.1, re_scale=1.0):
    """Zastawny's C_D0 and C_D90 at Re 0.1 (the lower end of their range) divided by the
    exact Stokes values 24/Re K: how far the correlation is from the exact low-Re limit.
    re_scale: the correlation evaluated at re_scale Re (another reading of its Re)."""
    k_along, k_across = stokes_prolate_k(ar)
    return (zastawny_drag(re * re_scale, 0.0) / (24 / re * k_along),
            zastawny_drag(re * re_scale, 90.0) / (24 / re * k_across))
