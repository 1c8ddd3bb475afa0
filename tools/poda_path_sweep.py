#!/usr/bin/env python3
"""Issue 19's path sweep: planted-foot slip and the body's departure from
its path on tight paths, for every PODA preset and every gait it has.

Paths (x, z in metres):
- the issue's closed Catmull-Rom path [[0,0],[1,0.5],[2,-0.5],[3,1],[2,2],[0,1.5]]
  at scale 1, 2 and 4, and its plain 90-degree corner [[0,0],[0,3],[-3,3]];
- RANDOM closed Catmull-Rom paths (default 20, seed 19): 4 to 8 points at
  random angles around a circle of radius 0.5 to 3 m, each point's radius
  jittered by up to 50 %, so that the tightest bends are far tighter than
  any preset's legs can take.

Each case is `gaitlab run PRESET --gait G --path FILE --seconds S --json`,
with `turn_within_reach` and `yaw_toward_actual` as the preset sets them
(on, for the bundled PODA presets) and, with --both, again with both off
(`--set scenario.poda.turn_within_reach=false --set
scenario.poda.yaw_toward_actual=false`: how the presets ran before
2026-12-02). Prints per preset and setting the
cases, how many slip more than 1 mm, the worst slip and the largest
`path_error_max_m`.

Usage: python3 tools/poda_path_sweep.py [--presets P,...] [--random N]
       [--seconds S] [--seed K] [--both] [--jobs J] [--gaitlab PATH]"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import tempfile

from gaitlab_run import run

LIMIT_M = 1e-3
TIGHT = [[0, 0], [1, 0.5], [2, -0.5], [3, 1], [2, 2], [0, 1.5]]
CORNER = [[0, 0], [0, 3], [-3, 3]]


def paths(count, seed):
    rng = random.Random(seed)
    out = []
    for scale in (1, 2, 4):
        out.append((f"tight x{scale}", [[x * scale, z * scale] for x, z in TIGHT], True))
    out.append(("corner 90", CORNER, False))
    for k in range(count):
        n = rng.randint(4, 8)
        radius = rng.uniform(0.5, 3.0)
        angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
        points = []
        for a in angles:
            r = radius * rng.uniform(0.5, 1.5)
            points.append([round(r * math.cos(a), 4), round(r * math.sin(a), 4)])
        out.append((f"random {k} (n {n}, r {radius:.2f})", points, True))
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--presets", default="poda-quadruped,hexapod,insect-14,poda-biped")
    parser.add_argument("--random", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--seed", type=int, default=19)
    parser.add_argument("--both", action="store_true")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    args = parser.parse_args()
    tmp = tempfile.mkdtemp(prefix="poda-paths-")
    files = []
    for i, (name, points, closed) in enumerate(paths(args.random, args.seed)):
        file = os.path.join(tmp, f"path{i}.json")
        with open(file, "w") as f:
            json.dump({"kind": "catmull_rom", "points": points, "closed": closed}, f)
        files.append((name, file))
    settings = [("on", [])]
    if args.both:
        settings.append(("off, as before 2026-12-02", [
            "--set", "scenario.poda.turn_within_reach=false",
            "--set", "scenario.poda.yaw_toward_actual=false"]))
    for preset in args.presets.split(","):
        gaits = run(args.gaitlab, preset, ["--seconds", "0.1"])["gaits_available"]
        for label, extra in settings:
            jobs = []
            with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
                for gait in gaits:
                    for name, file in files:
                        cli = ["--gait", gait, "--path", file, "--seconds", str(args.seconds), *extra]
                        jobs.append((gait, name, pool.submit(run, args.gaitlab, preset, cli)))
            results = [(g, n, j.result()) for g, n, j in jobs]
            errors = [(g, n, r["error"]) for g, n, r in results if "error" in r]
            good = [(g, n, r) for g, n, r in results if "error" not in r]
            over = [x for x in good if x[2]["foot_slip_max_m"] > LIMIT_M]
            worst = max(good, key=lambda x: x[2]["foot_slip_max_m"])
            departs = max(good, key=lambda x: x[2]["path_error_max_m"])
            print(f"{preset} (turn_within_reach {label}): {len(good)} cases "
                  f"({len(gaits)} gaits x {len(files)} paths), {len(over)} slip more than 1 mm, "
                  f"worst {worst[2]['foot_slip_max_m'] * 1e3:.3f} mm ({worst[0]}, {worst[1]}); "
                  f"path_error_max_m up to {departs[2]['path_error_max_m']:.3f} m ({departs[0]}, {departs[1]})")
            for gait, name, error in errors[:5]:
                print(f"  error: {gait}, {name}: {error}")


if __name__ == "__main__":
    main()
