#!/usr/bin/env python3
"""Issue 19's sweep of live PODA changes: planted-foot slip after every gait
switch and every ±30 % gait-value edit, each made at 72 successive frames.

For each preset (default: poda-quadruped, hexapod, insect-14):
- every ordered pair of its gaits (`gaits_available`): `gaitlab run PRESET
  --gait A --switch T:B --seconds T+AFTER --json`, T = WARMUP + k/fps for
  k = 0..71 (72 frames: more than one cycle at the presets' periods), and
  AFTER = 18 s: long enough for the legs to take the change on (insect-14
  takes up to 17 s);
- edits of period_s, speed_mps, stroke_m, duty_factor and leg_force_n by
  ×0.7 and ×1.3 from the preset's own gait, at the same 72 frames:
  `gaitlab run PRESET --edit T:KEY=VALUE --seconds T+AFTER --json`.

Each run's `foot_slip_max_m` (the largest planted-foot slip of the whole
run) is the figure; an edit or switch the engine refuses counts as handled
and is listed with its reason. Prints per preset the number of cases, how
many slip more than 1 mm, the worst case, and the refusals.

Usage: python3 tools/poda_change_sweep.py [--presets P,...] [--frames N]
       [--jobs J] [--gaitlab PATH] [--only switch|edit] [--after S]
       [--set KEY=VALUE ...] [--list N]
(PATH defaults to target/release/gaitlab; build it with
`cargo build --release -p gaitlab-cli`.)"""
import argparse
import concurrent.futures
import sys

from gaitlab_run import run

WARMUP_S = 2.0
AFTER_S = 18.0
FPS = 60.0
EDIT_KEYS = {
    "period_s": "period_s_set",
    "speed_mps": "speed_mps_set",
    "stroke_m": "stroke_m",
    "duty_factor": "duty_factor_set",
    "leg_force_n": "leg_force_n_set",
}
LIMIT_M = 1e-3


def cases(gaitlab, preset, frames, only, after_s, extra):
    base = run(gaitlab, preset, ["--seconds", "1", *extra])
    if "error" in base:
        sys.exit(f"{preset}: {base['error']}")
    gaits = base["gaits_available"]
    out = []
    for k in range(frames):
        t = WARMUP_S + k / FPS
        seconds = f"{t + after_s:.6f}"
        if only in (None, "switch"):
            for a in gaits:
                for b in gaits:
                    if a != b:
                        out.append((f"{a} -> {b} at {t:.4f} s",
                                    ["--gait", a, "--switch", f"{t:.6f}:{b}",
                                     "--seconds", seconds, *extra]))
        if only in (None, "edit"):
            for key, field in EDIT_KEYS.items():
                for factor in (0.7, 1.3):
                    value = base[field] * factor
                    out.append((f"{key} x{factor} at {t:.4f} s",
                                ["--edit", f"{t:.6f}:{key}={value!r}",
                                 "--seconds", seconds, *extra]))
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--presets", default="poda-quadruped,hexapod,insect-14")
    parser.add_argument("--frames", type=int, default=72)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--gaitlab", default="target/release/gaitlab")
    parser.add_argument("--only", choices=["switch", "edit"])
    parser.add_argument("--list", type=int, default=10,
                        help="how many of the worst cases to print")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a preset value for every run (gaitlab run --set)")
    parser.add_argument("--after", type=float, default=AFTER_S,
                        help="seconds run after each change (default %(default)s)")
    args = parser.parse_args()
    worst_all = 0.0
    for preset in args.presets.split(","):
        extra = [a for kv in args.set for a in ("--set", kv)]
        todo = cases(args.gaitlab, preset, args.frames, args.only, args.after, extra)
        over, refused, errors = [], {}, []
        worst = (0.0, "")
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = pool.map(lambda c: (c[0], run(args.gaitlab, preset, c[1])), todo)
            for name, m in results:
                if "error" in m:
                    errors.append(f"{name}: {m['error']}")
                    continue
                for change in m.get("changes", []):
                    if "refused" in change:
                        refused.setdefault(change["refused"], []).append(name)
                slip = m["foot_slip_max_m"]
                if slip > worst[0]:
                    worst = (slip, name)
                if slip > LIMIT_M:
                    over.append((slip, name))
        worst_all = max(worst_all, worst[0])
        print(f"{preset}: {len(todo)} cases, {len(over)} slip more than 1 mm, "
              f"worst {worst[0] * 1e3:.3f} mm ({worst[1]})")
        for slip, name in sorted(over, reverse=True)[:args.list]:
            print(f"  {slip * 1e3:8.3f} mm  {name}")
        for reason, names in refused.items():
            print(f"  refused ×{len(names)}: {reason} (e.g. {names[0]})")
        for error in errors[:5]:
            print(f"  error: {error}")
    return 0 if worst_all <= LIMIT_M else 1


if __name__ == "__main__":
    sys.exit(main())
