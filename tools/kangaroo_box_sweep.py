#!/usr/bin/env python3
"""How reliably the kangaroo jumps a box (Raibert & Hodgins 1991,
"Results": the jump's extra states): one run per box position, the box
0.2 m high and 0.3 m deep with its near face AT metres from the start, at
the desired SPEED (with the speed ramp, boxes further on are met faster).
Prints one character per position ('.' cleared and still up after SECONDS,
'F' fell, blew up or was refused) and the count cleared, for each preset
given.

Usage: python3 tools/kangaroo_box_sweep.py [PRESET ...] [--speed 5]
       [--seconds 20] [--at 3,5,...,25] [--gaitlab PATH]
(PRESET defaults to raibert-kangaroo; PATH to target/release/gaitlab,
built with `cargo build --release -p gaitlab-cli`.)"""
import argparse
import json

from gaitlab_run import run


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("presets", nargs="*", default=["raibert-kangaroo"])
    ap.add_argument("--speed", type=float, default=5.0)
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--at", default=",".join(str(a) for a in range(3, 27, 2)))
    ap.add_argument("--gaitlab", default="target/release/gaitlab")
    args = ap.parse_args()
    positions = [float(a) for a in args.at.split(",")]
    for preset in args.presets:
        marks = ""
        for at in positions:
            box = json.dumps([{"at_m": at, "height_m": 0.2, "depth_m": 0.3}])
            r = run(args.gaitlab, preset, [
                "--speed", str(args.speed), "--seconds", str(args.seconds),
                "--set", f"scenario.physics.obstacles={box}"])
            fell = r.get("error") or r.get("fell") or r.get("blow_up")
            marks += "F" if fell else "."
        cleared = marks.count(".")
        print(f"{preset}: {marks} · {cleared} of {len(positions)} cleared "
              f"(boxes at {args.at} m, {args.speed} m/s, {args.seconds} s)")


if __name__ == "__main__":
    main()
