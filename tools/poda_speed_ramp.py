#!/usr/bin/env python3
"""Issue 19's speed ramp with gait by speed: the PODA quadruped (or PRESET)
runs with `scenario.poda.gait_by_speed=true` while `--edit T:speed_mps=V`
raises its speed from FROM to TO m/s over SECONDS (one edit every STEP s),
then holds it for HOLD s. Prints the gaits it went through with the time and
speed of each change, the planted feet's largest slip (`foot_slip_max_m`),
the measured body speed, and any refused edit.

Usage: python3 tools/poda_speed_ramp.py [--preset P] [--from V] [--to V]
       [--seconds S] [--step S] [--hold S] [--gaitlab PATH]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`.) Exits 1 when a planted foot slips
more than 1 mm or the gait changes fewer than twice."""
import argparse
import sys

from gaitlab_run import run

LIMIT_M = 1e-3


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--preset", default="poda-quadruped")
    parser.add_argument("--from", dest="start", type=float, default=0.2)
    parser.add_argument("--to", type=float, default=5.0)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--step", type=float, default=0.25)
    parser.add_argument("--hold", type=float, default=5.0)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    args = parser.parse_args()
    steps = round(args.seconds / args.step)
    edits = []
    for k in range(steps + 1):
        t = k * args.step
        v = args.start + (args.to - args.start) * k / steps
        edits += ["--edit", f"{t:.6f}:speed_mps={v:.6f}"]
    m = run(args.gaitlab, args.preset,
            ["--set", "scenario.poda.gait_by_speed=true",
             "--seconds", f"{args.seconds + args.hold:.6f}", *edits])
    if "error" in m:
        sys.exit(m["error"])
    gait, switches = None, []
    for change in m["changes"]:
        if "refused" in change:
            print(f"refused: {change['change']}: {change['refused']}")
            continue
        if change.get("gait") != gait:
            gait = change.get("gait")
            speed = change["change"].split("=")[1]
            switches.append(gait)
            print(f"{change['applied_at_s']:7.3f} s  {float(speed):5.2f} m/s  {gait}")
    slip = m["foot_slip_max_m"]
    print(f"gaits: {' -> '.join(switches)} ({len(switches) - 1} changes); "
          f"foot_slip_max_m {slip * 1e3:.3f} mm; final gait {m['gait']}, "
          f"period {m['period_s_set']:.3f} s, stroke {m['stroke_m']:.3f} m, "
          f"speed set {m['speed_mps_set']:.2f} m/s, measured over the run "
          f"{m['body_speed_mps']:.2f} m/s")
    return 0 if slip <= LIMIT_M and len(switches) >= 3 else 1


if __name__ == "__main__":
    sys.exit(main())
