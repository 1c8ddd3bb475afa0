#!/usr/bin/env python3
"""The physics panel's tested bands (issue 21 item 3: each slider's validated
range shown as a band): every gait at the middle of its tested speeds
(tools/physics_speed_sweep.py) for SECONDS (default 60) with the presets' own
lab additions, once per value of the dynamic scale L (Table 1) and of the
desired hop height, the other at the preset's. A value passes when the
creature does not fall and its mean speed after 3 s is within 10 % of the
desired one (the paper's claim, the speed sweep's test). Prints a Markdown
table per slider (the mean speed over the desired one, or "fell") and, for
the scale, the passing span around L = 1: the band
`crates/physics/src/control/tested_speeds.rs` records. The hop heights are a
report only: their passing values are scattered (a bound holds 0.02–0.05 m,
the kangaroo only 0.1 m), no band to draw.

Usage: python3 tools/physics_band_sweep.py [--seconds S] [--gaitlab PATH]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`.)"""
import argparse

from gaitlab_run import run
from physics_speed_sweep import GAITS

SCALES = [0.25, 0.5, 1.0, 2.0, 4.0]
HOP_HEIGHTS_M = [0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4]


def passes(metrics):
    if "error" in metrics or metrics.get("fell") or metrics.get("blow_up"):
        return False
    desired = metrics["speed_desired_mps"]
    return abs(metrics["speed_mean_mps"] - desired) <= 0.1 * abs(desired)


def span(values, ok, around):
    """The passing values next to one another around `around`: (low, high) or None."""
    if around not in values or not ok[values.index(around)]:
        return None
    i = j = values.index(around)
    while i > 0 and ok[i - 1]:
        i -= 1
    while j + 1 < len(values) and ok[j + 1]:
        j += 1
    return values[i], values[j]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    args = parser.parse_args()
    for slider, values, key, banded in [
        ("scale L", SCALES, "scenario.physics.scale", True),
        ("hop height (m)", HOP_HEIGHTS_M, "scenario.physics.hop_height_m", False),
    ]:
        print(f"\n### {slider}\n")
        tail = " band |" if banded else ""
        print("| preset | gait | speed (m/s) | " + " | ".join(str(v) for v in values) + " |" + tail)
        print("|---|---|---|" + "---|" * len(values) + ("---|" if banded else ""))
        for preset, gait, speeds in GAITS:
            speed = speeds[1]
            base = [f"--gait={gait}", f"--speed={speed}", f"--seconds={args.seconds}"]
            ok, cells = [], []
            for v in values:
                m = run(args.gaitlab, preset, base + ["--set", f"{key}={v}"])
                good = passes(m)
                ok.append(good)
                if "error" in m:
                    cells.append("refused")
                else:
                    mark = "fell" if m.get("fell") else f"{m['speed_mean_mps'] / m['speed_desired_mps']:.2f}"
                    cells.append(mark + ("" if good else " ✗"))
            band = f" {span(values, ok, 1.0)} |" if banded else ""
            print(f"| {preset} | {gait} | {speed} | " + " | ".join(cells) + " |" + band)


if __name__ == "__main__":
    main()
