#!/usr/bin/env python3
"""She 2006 §5.3 measured: runs `gaitlab run she-2006 --mode M --method K --json`
for the two motions and the four methods and prints the markdown table of
docs/she-2006.md (feet and hands averaged over left and right).

Usage: python3 tools/she2006_table.py [--seconds S] [--gaitlab PATH]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`)."""
import argparse
import json
import subprocess

METHODS = ["transpose", "pinv", "dls", "sdls"]
MODES = ["walk", "run"]


def run(gaitlab, mode, method, seconds, extra):
    out = subprocess.run(
        [gaitlab, "run", "she-2006", "--mode", mode, "--method", method,
         "--seconds", str(seconds), "--json", *extra],
        check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def mean(values):
    values = [v for v in values if v is not None]
    return sum(values) / len(values) if values else None


def fmt(value, scale=1.0, digits=1):
    return "—" if value is None else f"{value * scale:.{digits}f}"


def group(metrics, names):
    effs = [e for e in metrics["effectors"] if e["name"] in names]
    return {
        "reachable": mean([e["reachable"] for e in effs]),
        "err_r": mean([e["mean_error_reachable_m"] for e in effs]),
        "err_u": mean([e["mean_error_unreachable_m"] for e in effs]),
        "osc": mean([e["oscillation_hz"] for e in effs]),
        "jit": mean([e["jitter_rad"] for e in effs]),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    parser.add_argument("--set", action="append", default=[],
                        help="passed on as --set KEY=VALUE")
    args = parser.parse_args()
    extra = [x for kv in args.set for x in ("--set", kv)]
    print("| motion | method | feet reachable | feet error, reachable / unreachable (mm) "
          "| hands reachable | hands error, unreachable (mm) | feet oscillation (Hz) "
          "| hands oscillation (Hz) | hands jitter (mrad/frame²) | µs/frame |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for mode in MODES:
        for method in METHODS:
            m = run(args.gaitlab, mode, method, args.seconds, extra)
            feet = group(m, ("left_foot", "right_foot"))
            hands = group(m, ("left_hand", "right_hand"))
            print(f"| {mode} | {method} | {fmt(feet['reachable'], 100, 0)} % "
                  f"| {fmt(feet['err_r'], 1e3)} / {fmt(feet['err_u'], 1e3)} "
                  f"| {fmt(hands['reachable'], 100, 0)} % | {fmt(hands['err_u'], 1e3)} "
                  f"| {fmt(feet['osc'], 1, 2)} | {fmt(hands['osc'], 1, 2)} "
                  f"| {fmt(hands['jit'], 1e3, 3)} | {m['us_per_frame']:.0f} |")


if __name__ == "__main__":
    main()
