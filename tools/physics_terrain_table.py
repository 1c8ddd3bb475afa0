#!/usr/bin/env python3
"""Issue 45 item 3's figures (docs/terrain.md, "Physics on terrain"): the
biped run up and down a 5° slope (and 10°), the quadruped trot up 5° and
the kangaroo hop over rough ground at difficulty 0.25 (and 0.5, 1), each for SECONDS (default 60) with
the lab's `ground_ahead` off (the paper's laws) and on, beside each
creature's run on the floor. Prints a Markdown table: whether it fell (and
how many times it was put back), the mean horizontal speed against the
desired one, the friction needed (max, mid-support, first and last 10 ms,
in the surface's frame), the trunk's height range above the ground and the
metres climbed and made good by the centre of mass.

Usage: python3 tools/physics_terrain_table.py [--seconds S] [--only TEXT]
       [--gaitlab PATH]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`.)"""
import argparse
import json

from gaitlab_run import run

UP = {"kind": "plane", "slope_deg": 5, "direction_deg": 90}
DOWN = {"kind": "plane", "slope_deg": -5, "direction_deg": 90}
UP10 = {"kind": "plane", "slope_deg": 10, "direction_deg": 90}
DOWN10 = {"kind": "plane", "slope_deg": -10, "direction_deg": 90}
ROUGH = {"kind": "rough", "seed": 1, "difficulty": 0.25, "size_m": [6, 400]}
ROUGH_05 = dict(ROUGH, difficulty=0.5)
ROUGH_1 = dict(ROUGH, difficulty=1.0)
FLAT = {"kind": "flat"}
CASES = [
    ("biped run", "raibert-biped", "floor", FLAT),
    ("biped run", "raibert-biped", "up 5°", UP),
    ("biped run", "raibert-biped", "down 5°", DOWN),
    ("biped run", "raibert-biped", "up 10°", UP10),
    ("biped run", "raibert-biped", "down 10°", DOWN10),
    ("quadruped trot", "raibert-quadruped", "floor", FLAT),
    ("quadruped trot", "raibert-quadruped", "up 5°", UP),
    ("kangaroo hop", "raibert-kangaroo", "floor", FLAT),
    ("kangaroo hop", "raibert-kangaroo", "rough 0.25", ROUGH),
    ("kangaroo hop", "raibert-kangaroo", "rough 0.5", ROUGH_05),
    ("kangaroo hop", "raibert-kangaroo", "rough 1", ROUGH_1),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seconds", type=float, default=60.0)
    ap.add_argument("--only", default="")
    ap.add_argument("--gaitlab", default="target/release/gaitlab")
    a = ap.parse_args()
    print("| creature, gait | ground | `ground_ahead` | fell (put back) | speed m/s (desired) "
          "| speed error | friction needed max / mid / edges | trunk above ground m "
          "| climbed m (made good m) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for what, preset, ground, terrain in CASES:
        if a.only not in preset + " " + ground:
            continue
        for on in (["off"] if ground == "floor" else ["off", "on"]):
            d = run(a.gaitlab, preset, [
                "--seconds", str(a.seconds),
                "--set", "scenario.terrain=" + json.dumps(terrain, separators=(",", ":")),
                "--set", "scenario.physics.lab_additions.ground_ahead="
                + ("true" if on == "on" else "false")])
            if "error" in d:
                print(f"| {what} | {ground} | {on} | {d['error']} |")
                continue
            t = d.get("terrain") or {}
            want = d["speed_desired_mps"]
            err = (d["speed_mean_mps"] - want) / want * 100 if want else 0.0
            th = t.get("trunk_height_range_m")
            trunk = f"{th[0]:.2f}–{th[1]:.2f}" if th else "—"
            climbed = f"{t['climbed_m']:+.2f} ({t['made_good_m']:.1f})" if t else "—"
            print(f"| {what} | {ground} | {on} | {'yes' if d['fell'] else 'no'} "
                  f"({len(d['put_backs'])}) | {d['speed_mean_mps']:.3f} ({want}) | {err:+.1f} % "
                  f"| {d['friction_needed_max']:.2f} / {d['friction_needed_mid']:.2f} / "
                  f"{d['friction_needed_edges']:.2f} | {trunk} | {climbed} |")


if __name__ == "__main__":
    main()
