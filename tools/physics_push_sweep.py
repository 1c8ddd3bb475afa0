#!/usr/bin/env python3
"""Issue 42's pushes: every physics gait, by the paper's laws alone
(`--paper-alone`) at its bundled speed, pushed 0.3 m/s forward, backward and
sideways (`gaitlab run … --push T:VX,VZ`) at four phases of its stride (a
quarter stride apart, from T0 = 8 s), one run per push. A push is recovered
when the creature does not fall in the next 5 s and its forward speed over
the last of them is within 10 % of the desired (`run --json`'s
`recovered`). Prints a Markdown table: per gait and direction, how many of
the four recovered, and for each failure whether it fell or missed its
speed (and the speed). The kangaroo is planar: it has no sideways push.

Usage: python3 tools/physics_push_sweep.py [--dv 0.3] [--only GAIT]
       [--set KEY=VALUE] [--defaults] [--gaitlab PATH]
(`--defaults`: each preset's own lab additions instead of `--paper-alone`.)
(PATH defaults to target/release/gaitlab.)"""
import argparse

from gaitlab_run import run

GAITS = [
    ("raibert-biped", "run"),
    ("raibert-biped", "gallop"),
    ("raibert-biped", "gallop_alternate"),
    ("raibert-quadruped", "trot"),
    ("raibert-quadruped", "bound"),
    ("raibert-quadruped", "gallop"),
    ("raibert-quadruped", "pace"),
    ("raibert-kangaroo", "hop"),
]

# Gaits pushed at a speed other than their preset's (m/s): the pace's tested
# speeds are 1.3–2.0 m/s, the bundled quadruped's 2.3 m/s is above them.
SPEEDS = {"pace": 1.6}

T0 = 8.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--dv", type=float, default=0.3)
    parser.add_argument("--only", action="append", help="only these gaits")
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    parser.add_argument("--defaults", action="store_true",
                        help="the bundled presets' own additions, not the paper alone")
    args = parser.parse_args()
    extra = [] if args.defaults else ["--paper-alone"]
    for s in args.set:
        extra += ["--set", s]
    dv = args.dv
    directions = [("forward", (0.0, dv)), ("backward", (0.0, -dv)),
                  ("sideways", (dv, 0.0))]
    print("| preset | gait | speed (m/s) | forward | backward | sideways | failures |")
    print("|---|---|---:|---|---|---|---|")
    total = recovered_total = 0
    for preset, gait in GAITS:
        if args.only and gait not in args.only:
            continue
        if gait in SPEEDS:
            extra_gait = [*extra, "--speed", str(SPEEDS[gait])]
        else:
            extra_gait = extra
        base = run(args.gaitlab, preset, ["--gait", gait, "--seconds", "10", *extra_gait])
        if "error" in base:
            print(f"| {preset} | {gait} | | error: {base['error']} | | | |")
            continue
        stride = base["stride_duration_s"] or 0.4
        speed = base["speed_desired_mps"]
        cells = []
        failures = []
        for name, (vx, vz) in directions:
            if preset == "raibert-kangaroo" and vx != 0.0:
                cells.append("n/a (planar)")
                continue
            ok = 0
            for k in range(4):
                at = T0 + k * stride / 4.0
                seconds = at + 5.5
                r = run(args.gaitlab, preset,
                        ["--gait", gait, "--seconds", f"{seconds:.3f}",
                         "--push", f"{at:.4f}:{vx},{vz}", *extra_gait])
                total += 1
                if "error" in r:
                    failures.append(f"{name} {k}/4: error {r['error']}")
                    continue
                if r.get("recovered"):
                    ok += 1
                    recovered_total += 1
                    continue
                push = (r.get("pushes") or [{}])[0]
                if push.get("fell") or r.get("fell"):
                    failures.append(f"{name} {k}/4 fell")
                else:
                    after = push.get("speed_after_mps")
                    failures.append(f"{name} {k}/4 slow ({after:.2f})" if after is not None
                                    else f"{name} {k}/4 no verdict")
            cells.append(f"{ok}/4")
        print(f"| {preset} | {gait} | {speed:.2f} | {' | '.join(cells)} | "
              f"{'; '.join(failures) or '—'} |")
    print()
    print(f"{recovered_total} of {total} pushes recovered.")


if __name__ == "__main__":
    main()
