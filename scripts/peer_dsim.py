"""OpenTorsion's time domain on torsim's linear 3-DOF benchmark job (issue 15, item 2).

The same driveline as `benches/transient.rs` (LINEAR_3DOF): inertias 0.5, 0.02 and
0.01 kg·m² on shafts of 2e5 and 1e4 N·m/rad (damping 2 and 1.5 N·m·s/rad), the last
inertia on a 1e4 N·m/rad, 1.5 N·m·s/rad spring to ground; torques 100·cos(Ωt) and
40·cos(2Ωt) N·m at the first inertia, Ω = 3000 rpm; 20 s at 10240 Hz. OpenTorsion's
`Assembly.dsim` discretizes the state space exactly for a zero-order-held input and
loops over the samples in numpy.

`dsim` reduces the state to twists (its "minimal representation"), which drops the
spring to ground of this driveline: its order-1 amplitude is then 10 % off. The same
loop on the full state (`state_space(minimal_representation=False)`, OpenTorsion's own
discretization) is timed beside it and is the one that solves torsim's job.

Prints one JSON line: per variant the median and best in-process time over `--repeat`
runs, s, and the order-1 speed amplitude of the first inertia over the last second, rpm
(the check that both tools ran the same job; torsim gives 6.435 rpm).
"""

import argparse
import json
import statistics
import time

import numpy as np
import opentorsion as ot


def assembly():
    disks = [
        ot.Disk(0, I=0.5),
        ot.Disk(1, I=0.02),
        ot.Disk(2, I=0.01, k=1.0e4, c=1.5),
    ]
    shafts = [
        ot.Shaft(0, 1, k=2.0e5, c=2.0),
        ot.Shaft(1, 2, k=1.0e4, c=1.5),
    ]
    return ot.Assembly(shaft_elements=shafts, disk_elements=disks)


def excitation(speed_rpm, duration_s, rate_hz):
    times = np.arange(int(round(duration_s * rate_hz))) / rate_hz
    omega = speed_rpm * 2.0 * np.pi / 60.0
    torque = 100.0 * np.cos(omega * times) + 40.0 * np.cos(2.0 * omega * times)
    exc = ot.TransientExcitation(3, times)
    exc.add_transient(0, torque)
    return exc, omega, times


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--speed-rpm", type=float, default=3000.0)
    parser.add_argument("--duration-s", type=float, default=20.0)
    parser.add_argument("--rate-hz", type=float, default=10240.0)
    args = parser.parse_args()
    model = assembly()
    exc, omega, times = excitation(args.speed_rpm, args.duration_s, args.rate_hz)
    out = {"samples": len(times)}
    for name, run in (("dsim", model.dsim), ("full_state", lambda e: full_state(model, e))):
        seconds = []
        for _ in range(args.repeat):
            start = time.perf_counter()
            speeds = run(exc)[1]
            seconds.append(time.perf_counter() - start)
        out[name] = {
            "median_s": statistics.median(seconds),
            "best_s": min(seconds),
            "order1_rpm": order1_rpm(speeds[0], times, omega),
        }
    print(json.dumps(out))


def full_state(model, exc):
    """`Assembly.dsim`'s loop on the full state: angles then speeds of every disk."""
    a, b, _, _ = model.state_space(minimal_representation=False)
    ad, bd = model.continuous_2_discrete(a, b, exc.ts)
    u = exc.excitation_matrix()
    x = np.zeros((a.shape[0], len(exc.times)))
    for i in range(len(exc.times) - 1):
        x[:, i + 1] = ad @ x[:, i] + bd @ u[:, i]
    n = model.M.shape[0]
    return x[:n, :], x[n:, :], exc.times


def order1_rpm(speed_rad_s, times, omega):
    """Order-1 amplitude over the last second (the start transient gone), rpm."""
    tail = times >= times[-1] - 1.0
    w, t = speed_rad_s[tail], times[tail]
    return 2.0 * abs(np.sum(w * np.exp(-1j * omega * t))) / len(w) * 60.0 / (2.0 * np.pi)


if __name__ == "__main__":
    main()
