#!/usr/bin/env python3
"""Draws a Campbell diagram as SVG from `torsim campbell MODEL --json` (stdin) — Python
stdlib only. Usage:
    torsim campbell presets/cng-genset.toml --json | scripts/campbell_svg.py \
        --orders 1.5,3,4.5,6,7.5,9 --max-hz 250 > assets/campbell-cng-genset.svg
Modes are horizontal lines (blue), order lines grey with their label, crossings red dots,
the operating range shaded."""
import argparse, json, sys

ap = argparse.ArgumentParser()
ap.add_argument("--orders", default="")
ap.add_argument("--max-hz", type=float, default=None)
ap.add_argument("--title", default="")
a = ap.parse_args()
d = json.load(sys.stdin)
speeds = d["speeds_rpm"]
orders = [float(x) for x in a.orders.split(",")] if a.orders else d["orders"]
n0, n1 = speeds[0], speeds[-1]
fmax = a.max_hz or max(max(m["frequency_hz"]) for m in d["modes"]) * 1.1
W, H, L, R, T, B = 720, 420, 60, 20, 30, 45
x = lambda n: L + (n - n0) / (n1 - n0) * (W - L - R)
y = lambda f: H - B - f / fmax * (H - T - B)
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
op = d.get("operating_range_rpm")
if op:
    out.append(f'<rect x="{x(max(op[0], n0)):.1f}" y="{T}" width="{x(min(op[1], n1)) - x(max(op[0], n0)):.1f}" height="{H - T - B}" fill="#e8f4e8"/>')
    out.append(f'<text x="{x(max(op[0], n0)) + 4:.1f}" y="{T + 12}" fill="#3a7a3a">operating range</text>')
for i in range(6):
    f = fmax * i / 5
    out.append(f'<line x1="{L}" x2="{W - R}" y1="{y(f):.1f}" y2="{y(f):.1f}" stroke="#eee"/><text x="{L - 6}" y="{y(f) + 4:.1f}" text-anchor="end">{f:.0f}</text>')
for i in range(5):
    n = n0 + (n1 - n0) * i / 4
    out.append(f'<text x="{x(n):.1f}" y="{H - B + 16}" text-anchor="middle">{n:.0f}</text>')
for q in orders:
    n_end = min(n1, fmax * 60 / q)
    out.append(f'<line x1="{x(n0):.1f}" y1="{y(q * n0 / 60):.1f}" x2="{x(n_end):.1f}" y2="{y(q * n_end / 60):.1f}" stroke="#999"/>')
    out.append(f'<text x="{x(n_end) - 4:.1f}" y="{y(q * n_end / 60) + (12 if n_end < n1 else -4):.1f}" text-anchor="end" fill="#555">{q:g}</text>')
for m in d["modes"]:
    f = m["frequency_hz"][0]
    if f <= fmax:
        out.append(f'<line x1="{L}" x2="{W - R}" y1="{y(f):.1f}" y2="{y(f):.1f}" stroke="#1f5fbf" stroke-width="2"/>')
        out.append(f'<text x="{W - R - 2}" y="{y(f) - 4:.1f}" text-anchor="end" fill="#1f5fbf">mode {m["mode"]}: {f:.1f} Hz</text>')
for c in d["crossings"]:
    if c["order"] in orders and c["frequency_hz"] <= fmax:
        out.append(f'<circle cx="{x(c["rpm"]):.1f}" cy="{y(c["frequency_hz"]):.1f}" r="4" fill="#d62728"/>')
        out.append(f'<text x="{x(c["rpm"]) + 6:.1f}" y="{y(c["frequency_hz"]) + 14:.1f}" fill="#d62728">{c["rpm"]:.0f} rpm</text>')
out.append(f'<line x1="{L}" y1="{H - B}" x2="{W - R}" y2="{H - B}" stroke="black"/><line x1="{L}" y1="{T}" x2="{L}" y2="{H - B}" stroke="black"/>')
out.append(f'<text x="{(L + W - R) / 2}" y="{H - 8}" text-anchor="middle">engine speed [rpm]</text>')
out.append(f'<text transform="translate(16,{(T + H - B) / 2}) rotate(-90)" text-anchor="middle">frequency [Hz]</text>')
out.append(f'<text x="{L}" y="{T - 10}" font-size="13">{a.title}</text></svg>')
print("\n".join(out))
