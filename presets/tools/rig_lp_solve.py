#!/usr/bin/env python3
"""Stiffnesses of seed 001's 3-DOF LP test-rig model (eq. 6) for given natural frequencies.

Plain Python 3, stdlib only. Used for presets/test-rig-70sh.toml: with the chosen
inertias (in the transmission shaft's own units; the crank's is multiplied by 9 for the
1/3 gearbox), it finds k_a (shaft), k_b, k_c (rubber stages, c to the frame) whose modes
are 9.0 / 49.8 / 116.4 Hz (Table 8(c): 4.5 / 24.9 / 58.2 % of the chosen f_max = 200 Hz).

Method: the characteristic polynomial of M^-1 K has coefficients
  c1 = ka/J1 + (ka+kb)/J2 + (kb+kc)/J3,
  c2 = ka kb/(J1 J2) + ka (kb+kc)/(J1 J3) + (ka kb + ka kc + kb kc)/(J2 J3),
  c3 = ka kb kc/(J1 J2 J3),
which must equal the elementary symmetric functions of w_i^2. Newton's method in
log k from a grid of starts; every distinct solution is printed. Pick the one whose
mode 2 is dominated by the middle flange (seed 001 Fig. 12); verify with `torsim modes`.

Usage: python3 presets/tools/rig_lp_solve.py [J_crank J_es J_mf]   (defaults 0.15 0.2 0.1)
"""
import itertools
import math
import sys

TARGET_HZ = (9.0, 49.8, 116.4)
RATIO = 1.0 / 3.0  # gearbox: transmission shaft speed / crank speed
J_GEARBOX_OUT = 0.005  # kg m2, own shaft
# engine: 4 cylinders x 0.6 kg, r = 0.045 m, l = 0.14 m: mean reciprocating inertia
J_RECIP = 4 * 0.6 * 0.045**2 * (0.5 + (0.045 / 0.14) ** 2 / 8)


def coefficients(j, k):
    j1, j2, j3 = j
    ka, kb, kc = k
    return (
        ka / j1 + (ka + kb) / j2 + (kb + kc) / j3,
        ka * kb / (j1 * j2) + ka * (kb + kc) / (j1 * j3) + (ka * kb + ka * kc + kb * kc) / (j2 * j3),
        ka * kb * kc / (j1 * j2 * j3),
    )


def targets(freqs):
    w2 = [(2 * math.pi * f) ** 2 for f in freqs]
    return (sum(w2), w2[0] * w2[1] + w2[0] * w2[2] + w2[1] * w2[2], w2[0] * w2[1] * w2[2])


def residual(j, x, t):
    return [math.log(a / b) for a, b in zip(coefficients(j, [math.exp(v) for v in x]), t)]


def solve3(a, b):
    """Gaussian elimination with pivoting for a 3x3 system."""
    m = [row[:] + [bi] for row, bi in zip(a, b)]
    for c in range(3):
        p = max(range(c, 3), key=lambda i: abs(m[i][c]))
        m[c], m[p] = m[p], m[c]
        if abs(m[c][c]) < 1e-300:
            return None
        for i in range(3):
            if i != c:
                f = m[i][c] / m[c][c]
                m[i] = [u - f * v for u, v in zip(m[i], m[c])]
    return [m[i][3] / m[i][i] for i in range(3)]


def newton(j, freqs, start):
    t = targets(freqs)
    x = [math.log(v) for v in start]
    for _ in range(200):
        r = residual(j, x, t)
        if max(abs(v) for v in r) < 1e-13:
            return [math.exp(v) for v in x]
        jac = [[0.0] * 3 for _ in range(3)]
        for col in range(3):
            xp = list(x)
            xp[col] += 1e-6
            rp = residual(j, xp, t)
            for row in range(3):
                jac[row][col] = (rp[row] - r[row]) / 1e-6
        step = solve3(jac, [-v for v in r])
        if step is None:
            return None
        scale = min(1.0, 1.0 / max(abs(v) for v in step))
        x = [u + scale * v for u, v in zip(x, step)]
    return None


def main():
    j_crank, j_es, j_mf = (float(v) for v in sys.argv[1:4]) if len(sys.argv) >= 4 else (0.15, 0.2, 0.1)
    j = ((j_crank + J_RECIP) / RATIO**2 + J_GEARBOX_OUT, j_es, j_mf)
    print(f"inertias referred to the transmission shaft: {j[0]:.4f}, {j[1]:.4f}, {j[2]:.4f} kg m2")
    found = set()
    for start in itertools.product((3e3, 1e4, 3e4, 1e5), repeat=3):
        k = newton(j, TARGET_HZ, start)
        if k:
            found.add(tuple(round(v, 1) for v in k))
    if not found:
        print("no solution: these inertias cannot give the target frequencies")
    for ka, kb, kc in sorted(found):
        print(f"k_a = {ka} N m/rad, k_b = {kb} N m/rad, k_c = {kc} N m/rad")


if __name__ == "__main__":
    main()
