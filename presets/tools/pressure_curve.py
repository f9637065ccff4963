#!/usr/bin/env python3
"""Synthesize in-cylinder pressure tables for torsim presets (plain Python 3, stdlib only).

A single-zone, closed-cycle model with a polytropic exponent and a Wiebe heat-release law,
plus a simple gas-exchange loop. It is not a measured curve: it stands in for the
manufacturer's measured pressures of seed 000 (§4.1, "loading forces are based on
in-cylinder pressure measurement") and seed 001 (eq. 3, P_i "estimated by experimental
measurements"), which the papers do not publish.

Model, per crank angle phi (deg, 0 = firing TDC, cycle -360..360):

* Volume V(phi) = Vc + A*s(phi), exact slider-crank piston travel s, Vc = Vd/(eps - 1).
* Valve overlap around gas-exchange TDC: p ramps linearly over OVERLAP_DEG from the
  exhaust pressure to the mean of intake and exhaust pressure at 360 = -360 deg and on to
  the intake pressure, so that the table's first and last points (-360 and 360, one
  cycle apart) are equal, as torsim requires of a table spanning exactly one cycle.
* Intake stroke (-360..-180): p = p_int (boost pressure, abs).
* Compression and combustion/expansion (-180..EVO): the first law with a polytropic
  exponent n in place of the ratio of specific heats,
      dp/dphi = (n - 1)/V * dQ/dphi - n * p/V * dV/dphi,
  Q(phi) = Q_tot * x_b(phi), Wiebe x_b = 1 - exp(-a*((phi - phi0)/dphi)^(m+1)).
* Blowdown: from EVO to BDC (180) p falls linearly to p_exh; exhaust stroke (180..360)
  at p_exh.
* Output: gauge pressure p - p_amb in bar, the quantity torsim's `pressure` tables hold.

Q_tot is scaled (bisection) so that the cycle-mean crank torque that torsim computes from
the table -- linear interpolation of the tabulated points, gas torque p*A*r_v with the
first-order r_v = r(sin phi + lambda/2 sin 2phi) of seed 001 eq. 4 -- equals the target.
The script prints, per load, the target and achieved mean torque, the IMEP of the fine
curve (closed integral of p dV over Vd) and the peak pressure, and then the TOML lines.

Usage:
    python3 presets/tools/pressure_curve.py cng      # CNG genset (seed 000), loads 0.3, 0.6, 1
    python3 presets/tools/pressure_curve.py rig      # 4-cyl. gasoline test-rig engine (seed 001)
    python3 presets/tools/pressure_curve.py bench    # the same engine at loads 0.3, 0.6, 1

Everything below `ENGINES` is the chosen input; each number's reason is beside it.
"""

import math
import sys

P_AMB_BAR = 1.0  # ambient, bar abs: gauge pressure = abs - 1 bar
OVERLAP_DEG = 30.0  # valve overlap half-width around gas-exchange TDC (+-360 deg)

ENGINES = {
    # Seed 000 §4: in-line 6-cyl. turbocharged CNG engine, 11.9 l, 250 kW at 1800 rpm.
    "cng": {
        "cylinders": 6,
        "bore": 0.130,  # m (chosen with crank radius 0.075 m to give 11.9 l)
        "crank_radius": 0.075,  # m
        "conrod": 0.250,  # m
        "eps": 11.5,  # compression ratio, typical of lean-burn/stoichiometric CNG engines
        "n": 1.35,  # polytropic exponent
        "wiebe_a": 5.0,  # Wiebe efficiency parameter (99.3 % burnt at the end)
        "wiebe_m": 2.0,  # Wiebe form factor
        # per load: target mean torque (N.m), intake and exhaust pressure (bar abs),
        # start of combustion and burn duration (deg)
        "loads": [
            # 30 %: throttled, no boost; later, slower burn of a leaner charge
            {"load": 0.3, "torque": 0.3 * 1326.3, "p_int": 0.90, "p_exh": 1.10,
             "soc": -20.0, "dur": 58.0},
            {"load": 0.6, "torque": 0.6 * 1326.3, "p_int": 1.40, "p_exh": 1.45,
             "soc": -20.0, "dur": 52.0},
            # full load: 250 kW at 1800 rpm -> 250e3 / (1800*2*pi/60) = 1326.3 N.m
            # (IMEP about 14 bar), boost about 2 bar abs
            {"load": 1.0, "torque": 1326.3, "p_int": 2.00, "p_exh": 1.85,
             "soc": -20.0, "dur": 48.0},
        ],
        "evo": 140.0,  # exhaust valve opening, deg after firing TDC (blowdown to BDC)
    },
    # Seed 001: four-cylinder engine of the test rig (data confidential). Chosen: a
    # 1.9 l naturally aspirated gasoline engine, bore 82 mm, stroke 90 mm, about 170 N.m
    # at full load (IMEP about 11.5 bar), peak pressure about 70 bar.
    "rig": {
        "cylinders": 4,
        "bore": 0.082,
        "crank_radius": 0.045,
        "conrod": 0.140,
        "eps": 10.5,
        "n": 1.33,
        "wiebe_a": 5.0,
        "wiebe_m": 2.0,
        "loads": [
            {"load": 1.0, "torque": 170.0, "p_int": 0.98, "p_exh": 1.15,
             "soc": -24.0, "dur": 45.0},
        ],
        "evo": 130.0,
    },
    # The diagnosis bench (presets/diagnosis-bench.toml): the rig engine above with two
    # throttled part loads for torsim synth's part-load regimes. Chosen: at 30 % and 60 %
    # of the full-load torque the throttle holds the intake at 0.38 / 0.64 bar abs, and the
    # leaner, slower charge starts burning later.
    "bench": {
        "cylinders": 4,
        "bore": 0.082,
        "crank_radius": 0.045,
        "conrod": 0.140,
        "eps": 10.5,
        "n": 1.33,
        "wiebe_a": 5.0,
        "wiebe_m": 2.0,
        "loads": [
            {"load": 0.3, "torque": 0.3 * 170.0, "p_int": 0.38, "p_exh": 1.05,
             "soc": -28.0, "dur": 55.0},
            {"load": 0.6, "torque": 0.6 * 170.0, "p_int": 0.64, "p_exh": 1.10,
             "soc": -26.0, "dur": 50.0},
            {"load": 1.0, "torque": 170.0, "p_int": 0.98, "p_exh": 1.15,
             "soc": -24.0, "dur": 45.0},
        ],
        "evo": 130.0,
    },
}


def kinematics(e):
    r, l, b = e["crank_radius"], e["conrod"], e["bore"]
    area = math.pi * b * b / 4.0
    vd = area * 2.0 * r
    vc = vd / (e["eps"] - 1.0)

    def volume(phi_deg):
        p = math.radians(phi_deg)
        s = r * (1.0 - math.cos(p)) + l - math.sqrt(l * l - (r * math.sin(p)) ** 2)
        return vc + area * s

    return area, vd, volume


def fine_curve(e, case, q_tot, step=0.1):
    """Absolute pressure (bar) on a fine grid from -360 to 360 deg."""
    _, _, volume = kinematics(e)
    n, a, m = e["n"], e["wiebe_a"], e["wiebe_m"]
    soc, dur = case["soc"], case["dur"]

    def burnt(phi):
        if phi <= soc:
            return 0.0
        return 1.0 - math.exp(-a * ((phi - soc) / dur) ** (m + 1.0))

    count = int(round(720.0 / step))
    angles = [-360.0 + i * step for i in range(count + 1)]
    p = []
    pa = case["p_int"] * 1e5
    p_evo = None
    p_overlap = 0.5 * (case["p_int"] + case["p_exh"])
    for phi in angles:
        if phi <= -360.0 + OVERLAP_DEG:
            t = (phi + 360.0) / OVERLAP_DEG
            p.append(p_overlap + t * (case["p_int"] - p_overlap))
            continue
        if phi <= -180.0:
            p.append(case["p_int"])
            continue
        if phi <= e["evo"]:
            # integrate the first law from the previous point (midpoint rule)
            prev = phi - step
            v0, v1 = volume(prev), volume(phi)
            vm = 0.5 * (v0 + v1)
            dq = q_tot * (burnt(phi) - burnt(prev))
            # predictor-corrector on p
            dp1 = (n - 1.0) / vm * dq - n * pa / vm * (v1 - v0)
            pm = pa + 0.5 * dp1
            dp = (n - 1.0) / vm * dq - n * pm / vm * (v1 - v0)
            pa = pa + dp
            p.append(pa / 1e5)
            p_evo = pa / 1e5
            continue
        if phi <= 180.0:
            t = (phi - e["evo"]) / (180.0 - e["evo"])
            p.append(p_evo + t * (case["p_exh"] - p_evo))
            continue
        if phi < 360.0 - OVERLAP_DEG:
            p.append(case["p_exh"])
            continue
        t = (phi - (360.0 - OVERLAP_DEG)) / OVERLAP_DEG
        p.append(case["p_exh"] + t * (p_overlap - case["p_exh"]))
    return angles, p


def table_angles():
    """10-degree steps, 5-degree steps from -40 to 80 deg around firing TDC."""
    out = [float(a) for a in range(-360, -40, 10)]
    out += [float(a) for a in range(-40, 80, 5)]
    out += [float(a) for a in range(80, 361, 10)]
    return out


def sample(angles, p, wanted):
    step = angles[1] - angles[0]
    return [p[int(round((w - angles[0]) / step))] for w in wanted]


def mean_torque_from_table(e, ang, bar_gauge, samples=7200):
    """As torsim does: periodic linear interpolation, T = p*A*r_v, first order in lambda."""
    area, _, _ = kinematics(e)
    r = e["crank_radius"]
    lam = r / e["conrod"]
    total = 0.0
    j = 0
    for i in range(samples):
        phi = -360.0 + 720.0 * i / samples
        while j + 1 < len(ang) - 1 and ang[j + 1] <= phi:
            j += 1
        t = (phi - ang[j]) / (ang[j + 1] - ang[j])
        pb = bar_gauge[j] + t * (bar_gauge[j + 1] - bar_gauge[j])
        x = math.radians(phi)
        rv = r * (math.sin(x) + 0.5 * lam * math.sin(2.0 * x))
        total += pb * 1e5 * area * rv
    return total / samples


def imep_bar(e, angles, p_abs):
    _, vd, volume = kinematics(e)
    work = 0.0
    for i in range(1, len(angles)):
        work += 0.5 * (p_abs[i] + p_abs[i - 1]) * 1e5 * (volume(angles[i]) - volume(angles[i - 1]))
    return work / vd / 1e5


def solve_case(e, case):
    wanted = table_angles()

    def torque_for(q):
        angles, p = fine_curve(e, case, q)
        gauge = [round(v - P_AMB_BAR, 2) for v in sample(angles, p, wanted)]
        return mean_torque_from_table(e, wanted, gauge), angles, p, gauge

    lo, hi = 0.0, 20000.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if torque_for(mid)[0] < case["torque"] / e["cylinders"]:
            lo = mid
        else:
            hi = mid
    t_cyl, angles, p, gauge = torque_for(0.5 * (lo + hi))
    return {
        "q_tot": 0.5 * (lo + hi),
        "torque": t_cyl * e["cylinders"],
        "imep": imep_bar(e, angles, p),
        "peak": max(p),
        "angles": wanted,
        "gauge": gauge,
    }


def fmt(values):
    return ", ".join(f"{v:g}" for v in values)


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "cng"
    e = ENGINES[which]
    results = [(case, solve_case(e, case)) for case in e["loads"]]
    for case, res in results:
        print(
            f"# load {case['load']}: target {case['torque']:.1f} N.m, table gives "
            f"{res['torque']:.1f} N.m; IMEP {res['imep']:.2f} bar; peak "
            f"{res['peak']:.1f} bar abs; heat released {res['q_tot']:.0f} J/cycle/cyl"
        )
    if len(results) == 1:
        res = results[0][1]
        print(
            f"pressure = {{ crank_angle_deg = [{fmt(res['angles'])}], "
            f"bar = [{fmt(res['gauge'])}] }}"
        )
        return
    print("pressure_by_load = [")
    for case, res in results:
        print(
            f"  {{ load = {case['load']}, crank_angle_deg = [{fmt(res['angles'])}], "
            f"bar = [{fmt(res['gauge'])}] }},"
        )
    print("]")


if __name__ == "__main__":
    main()
