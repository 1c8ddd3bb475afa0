#!/usr/bin/env python3
"""Issue 42's robustness lines for the quadruped's bound, as one battery:
one upper leg 1 % heavier (front-left, 1.515 kg) at 1.5, 2.3 and 2.8 m/s
for 60 s; a far waypoint 0.8 rad off the heading at the same speeds for
60 s (the bound turns toward it at the steering's rate); and eight steps of
the desired speed at 20 s of 40-s runs (±10 % from 1.5, 2.3 and 2.8 m/s,
and 1.5 → 2.3, 2.3 → 2.8). A case holds when the run neither falls nor is
put back. Prints each case and the count held per kind.

Usage: python3 tools/bound_robustness.py [PRESET] [--paper-alone]
       [--gaitlab PATH]
(PRESET defaults to raibert-quadruped; PATH to target/release/gaitlab,
built with `cargo build --release -p gaitlab-cli`.)"""
import argparse
import json
import math
from concurrent.futures import ThreadPoolExecutor

from gaitlab_run import run

SPEEDS = [1.5, 2.3, 2.8]
STEPS = [(1.5, 1.65), (1.5, 1.35), (2.3, 2.53), (2.3, 2.07),
         (2.8, 3.08), (2.8, 2.52), (1.5, 2.3), (2.3, 2.8)]
TURN_RAD = 0.8


def cases():
    """`(kind, label, args)` of every case of the battery."""
    out = []
    for v in SPEEDS:
        out.append(("one leg 1 % heavier", f"{v} m/s", [
            "--speed", str(v), "--seconds", "60",
            "--set", "scenario.physics.bodies[0].mass_kg=1.515"]))
    far = [[100.0 * math.sin(TURN_RAD), 100.0 * math.cos(TURN_RAD)]]
    for v in SPEEDS:
        out.append((f"turning {TURN_RAD} rad", f"{v} m/s", [
            "--speed", str(v), "--seconds", "60",
            "--set", f"scenario.physics.waypoints={json.dumps(far)}"]))
    for v0, v1 in STEPS:
        out.append(("speed steps", f"{v0} → {v1} m/s", [
            "--speed", str(v0), "--seconds", "40",
            "--edit", f"20:speed_mps={v1}"]))
    return out


def verdict(m):
    """`held`, `fell`, the first put-back's second, or the refusal."""
    if "error" in m:
        return m["error"]
    backs = m.get("put_backs") or []
    if backs:
        return f"put back at {backs[0]['run_time_s']:.1f} s"
    return "fell" if m.get("fell") else "held"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("preset", nargs="?", default="raibert-quadruped")
    ap.add_argument("--paper-alone", action="store_true")
    ap.add_argument("--gaitlab", default="target/release/gaitlab")
    args = ap.parse_args()
    extra = ["--gait", "bound"] + (["--paper-alone"] if args.paper_alone else [])
    battery = cases()
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(
            lambda c: run(args.gaitlab, args.preset, [*extra, *c[2]]), battery))
    tally = {}
    for (kind, label, _), m in zip(battery, results):
        v = verdict(m)
        held, total = tally.get(kind, (0, 0))
        tally[kind] = (held + (v == "held"), total + 1)
        print(f"{kind}, {label}: {v}")
    print(" · ".join(f"{k}: {h} of {t}" for k, (h, t) in tally.items()))


if __name__ == "__main__":
    main()
