#!/usr/bin/env python3
"""Tabulates the misses of a `benchtruth bench` run (issue 14): for every case whose
verdict is wrong, the truth (class and form), the verdict, and the held-out χ²/N (and the
fitted one) of the user's model, the plain recalibration and the best candidate of the
truth's own class, with why that candidate was not the verdict (rejected, set aside, not
verified, or short of the margin).

Usage: scripts/bench-misses.py OUT_DIR [--all]

Reads OUT_DIR/case-*/report.json and truth.toml, so it works on a run still going or
stopped before its results.csv; a case counts as right when the verdict names the truth's
class (a control: `none` or `parameter_error`), whatever the place. Writes nothing.
`--all` lists the right cases too. Standard library only.
"""

import json
import sys
import tomllib
from pathlib import Path


def fmt(x):
    return "—" if x is None else f"{x:.3g}"


def row_of(cands, effect):
    rows = [c for c in cands if c.get("effect") == effect]
    return rows[0] if rows else None


def why_not(c, plain_score):
    if c is None:
        return "not tried"
    if c.get("rejected"):
        return "rejected: " + str(c["rejected"])[:60]
    if c.get("set_aside"):
        return "set aside: " + str(c["set_aside"])[:60]
    if not c.get("verified", True):
        return "not verified"
    if plain_score:
        gain = 1 - c["score"] / plain_score
        return f"gain {gain:+.0%} on the plain score"
    return ""


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    show_all = "--all" in sys.argv
    cases = sorted(out.glob("**/case-*"), key=lambda p: int(p.name[5:]) if p.name[5:].isdigit() else 0)
    print("| seed | truth (form) | verdict | user held/fitted | plain held/fitted |"
          " truth's class held/fitted | why not |")
    print("|---|---|---|---|---|---|---|")
    n = right_n = 0
    for case in cases:
        try:
            truth = tomllib.loads((case / "truth.toml").read_text())
        except (OSError, ValueError):
            continue
        r = {"seed": case.name[5:], "truth": truth.get("effect", "?")}
        form = truth.get("form", "")
        try:
            rep = json.loads((case / "report.json").read_text())
        except (OSError, ValueError):
            print(f"| {r['seed']} | {r['truth']} ({form}) | no report | | | | |")
            continue
        verdict = rep.get("verdict", {}).get("effect")
        controls = ("none", "parameter_error")
        right = verdict == r["truth"] or (r["truth"] in controls and verdict in controls)
        n += 1
        right_n += right
        if right and not show_all:
            continue
        cands = rep.get("candidates", [])
        none_row = row_of(cands, "none")
        plain = row_of(cands, "parameter_error")
        own = row_of(cands, r.get("truth"))
        swapped = " (swapped)" if rep.get("fit", {}).get("swapped_because") else ""

        def pair(c):
            if c is None:
                return "—"
            return f"{fmt(c.get('residual_after'))} / {fmt(c.get('residual_fitted'))}"

        print(f"| {r['seed']} | {r.get('truth')} ({form}) |"
              f" {verdict}{swapped} | {pair(none_row)} |"
              f" {pair(plain)} | {pair(own)} |"
              f" {why_not(own, plain and plain.get('score'))} |")
    print(f"\n{right_n}/{n} right (class only; the bench also scores the place)")


if __name__ == "__main__":
    main()
