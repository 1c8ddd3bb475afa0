#!/usr/bin/env python3
"""Issue 42's take-over table: every ordered pair of the quadruped's trot,
bound and gallop, switched at 7, 10, 13.3 and 20 s at 1.5, 2.3 and 2.8 m/s
(the twelve cases of each pair), 50-s runs by the paper's laws alone
(`--paper-alone`) and without `switch_to_start`, so the new gait's
controller takes over at the next flight from the state it finds. A cell is
`·` where the run held (no fall, no put-back), `✗` where it fell (`run
--json`'s `fell`), or the second of its first put-back (a blow-up) where
it was put back. Prints a Markdown table and the number held.

Usage: python3 tools/physics_switch_sweep.py [--preset FILE] [--set KEY=VALUE]
       [--speeds 1.5,2.3,2.8] [--times 7,10,13.3,20 | --times FROM:TO:STEP]
       [--jobs N] [--gaitlab PATH]
(FILE defaults to the bundled raibert-quadruped, a candidate from `gaitlab
tune` is measured by naming it; PATH defaults to target/release/gaitlab; `--set` is passed to every run,
e.g. `--set scenario.physics.lab_additions.hop_integrator=true` to keep the
trot's hop integrator, its default. `--times 7:20.3:0.7` switches at 7,
7.7, … 20.3 s, a denser sample of the hand-over's phase than the twelve
cases.)"""
import argparse
from concurrent.futures import ThreadPoolExecutor

from gaitlab_run import run

GAITS = ["trot", "bound", "gallop"]
SPEEDS = [1.5, 2.3, 2.8]
TIMES = [7.0, 10.0, 13.3, 20.0]
SECONDS = 50.0


def cell(m):
    """`·` where the run held, else `✗` or the first put-back's second."""
    if "error" in m:
        return "error"
    backs = m.get("put_backs") or []
    if backs:
        return f"{backs[0]['run_time_s']:.1f}"
    return "✗" if m.get("fell") else "·"


def case(args, a, b, speed, at):
    extra = ["--set", "scenario.physics.switch_to_start=[]"]
    for s in args.set:
        extra += ["--set", s]
    m = run(args.gaitlab, args.preset, [
        "--gait", a, "--switch", f"{at}:{b}", "--speed", str(speed),
        "--seconds", str(SECONDS), "--paper-alone", *extra])
    c = cell(m)
    return c, c == "·"


def times_arg(text):
    """`a,b,c` or `FROM:TO:STEP` (seconds) as a list."""
    if ":" in text:
        start, stop, step = (float(x) for x in text.split(":"))
        count = int(round((stop - start) / step)) + 1
        return [round(start + i * step, 3) for i in range(count)]
    return [float(x) for x in text.split(",")]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--preset", default="raibert-quadruped")
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--speeds", type=lambda t: [float(x) for x in t.split(",")],
                        default=SPEEDS)
    parser.add_argument("--times", type=times_arg, default=TIMES)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    args = parser.parse_args()
    pairs = [(a, b) for a in GAITS for b in GAITS if a != b]
    speeds, times = args.speeds, args.times
    jobs = [(a, b, v, t) for a, b in pairs for v in speeds for t in times]
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda j: case(args, *j), jobs))
    by = dict(zip(jobs, results))
    at = " / ".join(f"{t:g}" for t in times) if len(times) <= 6 else \
        f"{times[0]:g} … {times[-1]:g} s ({len(times)} times)"
    print("| pair | " + " | ".join(f"{v} m/s at {at}" + (" s" if len(times) <= 6 else "")
                                    for v in speeds) + " | held |")
    print("| --- |" + " --- |" * len(speeds) + " ---: |")
    total = 0
    for a, b in pairs:
        cells, held = [], 0
        for v in speeds:
            row = [by[(a, b, v, t)] for t in times]
            if len(times) <= 6:
                cells.append(" ".join(c for c, _ in row))
            else:
                cells.append(f"{sum(ok for _, ok in row)} of {len(row)}")
            held += sum(ok for _, ok in row)
        total += held
        print(f"| {a} → {b} | " + " | ".join(cells) + f" | {held} |")
    print(f"\n{total} of {len(jobs)} hold")


if __name__ == "__main__":
    main()
