#!/usr/bin/env python3
"""Issue 20's speed check: every physics gait at three speeds for SECONDS
(default 60) with the lab's additions three ways: "paper" (every addition
off), "default" (the bundled presets' own `lab_additions`, each gait's
defaults where they name none) and "all on". For each run it prints whether the creature fell,
the mean speed after 3 s against the desired one, the additions used, the
friction needed and the peak vertical ground force (× weight), as a
Markdown table; a row fails when it falls or its mean speed is more than
10 % off (the paper's claim).

Usage: python3 tools/physics_speed_sweep.py [--seconds S] [--only WAY]
       [--preset P] [--set KEY=VALUE] [--gaitlab PATH]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`.) Exits 1 when a "default" row
fails."""
import argparse
import json
import sys

from gaitlab_run import run

GAITS = [
    ("raibert-biped", "run", [1.0, 1.6, 2.5]),
    ("raibert-biped", "gallop", [1.0, 1.5, 2.0]),
    ("raibert-biped", "gallop_alternate", [1.0, 1.5, 2.0]),
    ("raibert-quadruped", "trot", [1.0, 1.9, 2.3]),
    ("raibert-quadruped", "bound", [1.5, 2.3, 2.8]),
    ("raibert-quadruped", "gallop", [1.5, 2.3, 2.8]),
    ("raibert-quadruped", "pace", [1.3, 1.6, 2.0]),
    ("raibert-kangaroo", "hop", [2.0, 3.5, 5.0]),
]

NAMES = ["speed_trim", "unloading_posture", "speed_ramp", "tail_feedback",
         "hop_integrator"]

# None: the preset's own `lab_additions`, as bundled.
WAYS = {
    "paper": {name: False for name in NAMES},
    "default": None,
    "all on": {name: True for name in NAMES},
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--only", choices=list(WAYS), action="append")
    parser.add_argument("--preset", action="append",
                        help="only these presets (repeatable)")
    parser.add_argument("--set", action="append", default=[],
                        help="passed to every run (repeatable)")
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    args = parser.parse_args()
    ways = args.only or list(WAYS)
    print("| way | preset | gait | desired (m/s) | fell | mean (m/s) | error | "
          "additions used | friction needed | peak force (× weight) |")
    print("|---|---|---|---:|---|---:|---:|---|---:|---:|")
    failed_default = 0
    for way in ways:
        additions = WAYS[way]
        # A way that names the additions names them for every gait: one
        # gait's choice in the preset (`lab_additions_by_gait`) would win.
        chosen = [] if additions is None else [
            "--set", f"scenario.physics.lab_additions={json.dumps(additions)}",
            "--set", "scenario.physics.lab_additions_by_gait={}"]
        for preset, gait, speeds in GAITS:
            if args.preset and preset not in args.preset:
                continue
            for v in speeds:
                m = run(args.gaitlab, preset, [
                    "--gait", gait, "--speed", str(v),
                    "--seconds", str(args.seconds), *chosen,
                    *[a for kv in args.set for a in ("--set", kv)]])
                if "error" in m:
                    print(f"| {way} | {preset} | {gait} | {v} | error: "
                          f"{m['error']} | | | | | |")
                    failed_default += way == "default"
                    continue
                error = m["speed_mean_mps"] / v - 1.0
                bad = m["fell"] or abs(error) > 0.10
                failed_default += bad and way == "default"
                mark = " ✗" if bad else ""
                used = ", ".join(m["lab_additions"]) or "none"
                print(f"| {way} | {preset} | {gait} | {v} | {m['fell']} | "
                      f"{m['speed_mean_mps']:.3f} | {error * 100:+.1f} %{mark} | "
                      f"{used} | {m['friction_needed_max']:.2f} | "
                      f"{m['peak_vertical_force_bw']:.1f} |")
                sys.stdout.flush()
    if failed_default:
        print(f"{failed_default} default rows fell or missed 10 %",
              file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
