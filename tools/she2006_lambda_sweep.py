#!/usr/bin/env python3
"""She 2006 §4.4.3's damping constant λ, measured: runs `gaitlab run she-2006
--mode M --method dls --set scenario.ik.lambda=L --json` for walking and
running over a range of λ and prints the markdown table of docs/she-2006.md
("Choosing λ"): the feet's error (reachable walking, unreachable running),
the hands' error, oscillation and jitter (unreachable in both motions).

Usage: python3 tools/she2006_lambda_sweep.py [--seconds S] [--gaitlab PATH]
       [--lambdas 0.01,0.05,...] [--set KEY=VALUE ...] [--json]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`)."""
import argparse
import json

from she2006_table import fmt, group, run

LAMBDAS = [0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 1.0]


def sweep(gaitlab, lambdas, seconds, extra):
    rows = []
    for mode in ("walk", "run"):
        for lam in lambdas:
            m = run(gaitlab, mode, "dls", seconds,
                    [*extra, "--set", f"scenario.ik.lambda={lam}"])
            feet = group(m, ("left_foot", "right_foot"))
            hands = group(m, ("left_hand", "right_hand"))
            rows.append({"mode": mode, "lambda": lam, "feet": feet, "hands": hands,
                         "lab_additions": m["lab_additions"]})
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    parser.add_argument("--lambdas", default=",".join(str(x) for x in LAMBDAS))
    parser.add_argument("--set", action="append", default=[],
                        help="passed on as --set KEY=VALUE")
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    args = parser.parse_args()
    extra = [x for kv in args.set for x in ("--set", kv)]
    lambdas = [float(x) for x in args.lambdas.split(",")]
    rows = sweep(args.gaitlab, lambdas, args.seconds, extra)
    if args.json:
        print(json.dumps(rows, indent=1))
        return
    print("| motion | λ (m) | feet error (mm) | feet oscillation (Hz) | hands error (mm) "
          "| hands oscillation (Hz) | hands jitter (mrad/frame²) |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        feet, hands = r["feet"], r["hands"]
        err = feet["err_r"] if r["mode"] == "walk" else feet["err_u"]
        print(f"| {r['mode']} | {r['lambda']:g} | {fmt(err, 1e3)} | {fmt(feet['osc'], 1, 2)} "
              f"| {fmt(hands['err_u'], 1e3)} | {fmt(hands['osc'], 1, 2)} "
              f"| {fmt(hands['jit'], 1e3, 3)} |")


if __name__ == "__main__":
    main()
