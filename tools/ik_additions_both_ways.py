#!/usr/bin/env python3
"""Each lab addition of the bundled IK presets measured both ways (issue 41
item 2, docs/parameters.md "Both ways").

For each preset (default: `human` and `ik-quadruped`), each motion (walk,
run, wounded-walk, wounded-run), each of She 2006's four methods (transpose,
pinv, dls, sdls) and each lab addition of the IK engine, it runs

    gaitlab run PRESET --json --seconds S --mode MODE --method METHOD --set KEY=ON
    gaitlab run PRESET --json --seconds S --mode MODE --method METHOD --set KEY=OFF

on top of the preset as bundled (or, with `--base paper`, on top of
`--paper-alone`), so that only that one addition differs between the two
runs. The additions and their settings:

| addition | key | on | off (the thesis) |
| --- | --- | --- | --- |
| `lab_script` | scenario.thesis.script | lab | listing (§5.2.2) |
| `posture_pull` | scenario.thesis.posture_gain | 0.1 | 0 |
| `start_ramp` | scenario.thesis.start_ramp_s | 1 | 0 |
| `limit_re_solve` | scenario.ik.limit_passes | 4 | 1 (§6.1.1.1's clamp) |
| `step_wounds` | scenario.thesis.wound_form | step | angle (§5.1.1) |
| `clamp_every_method` | scenario.ik.clamp_every_method | true | false (§4.4.2) |
| `buss_alpha` | scenario.ik.transpose_alpha | buss | thesis (§4.4.1) |
| λ (not an addition) | scenario.ik.lambda | 0.05 | 0.2 |

An addition that does not act with a method or motion (`buss_alpha` off the
transpose, `clamp_every_method` off transpose and DLS, λ off DLS,
`step_wounds` off the wounded motions) is not run there.

Figures per run (feet and hands averaged over left and right; feet and hands
are the thesis' roles, so ik-quadruped's hind and front feet; "other" is any
other effector with a target, ik-quadruped's head): mean and max error (mm),
the fraction of frames with the target within reach, the mean error over
those frames, oscillation (Hz) and jitter (mrad/frame²) as defined in
docs/ik-metrics.md, `within_limits` and `restored_frames`.

Claims checked, fixed before measuring (She 2006):

- `L` (§5.1.1, §6.1.1.1): every joint stays within its limits, and no frame
  is undone as unstable: `within_limits` and `restored_frames == 0`. Every
  motion; the others walking and running only (§5.3 compares those; §5.2.3's
  wounded motions come with no claim on the errors, and §5.1.1's weights put
  the shown effectors off the IK's targets by design).
- `R` (§5.3, Fig. 5.10): walking, the two foot targets are reachable (≥ 99 %
  of frames) and the hands' are not (≤ 1 %); running, none are.
- `T` (§5.3, "the end effectors track the movement of target positions";
  SDLS "has the best performance … for reachable target positions"): walking,
  the feet's targets are reachable (≥ 99 %) and SDLS holds the feet on them
  (mean error ≤ 1 mm).
- Across the four methods, the same settings (§5.3): `S` SDLS's walking feet
  miss by no more than any other method's (+0.1 mm); `D` DLS's walking feet
  miss by less than pinv's and the transpose's ("substantially better");
  `P` pinv's hands oscillate ≥ 1.5 × DLS's and SDLS's where the hands are out
  of reach ("unreachable target positions caused the rigid body to
  oscillate"); `J` walking, the transpose's hands oscillate ≥ 1.5 × DLS's and
  SDLS's ("jerky and oscillates"; issue 18's factor).

It prints §5.3's comparisons per preset, motion and addition, each way,
and last, per preset and addition, each claim that fails with the addition
off and holds with it on ("rescues": the rule lets a bundled preset keep it)
and each that holds off and fails on ("breaks"), with the figures.

Run after `cargo build --release -p gaitlab-cli`:

    python3 tools/ik_additions_both_ways.py [--seconds 30] [--base bundled|paper]
        [--modes walk,run,wounded-walk,wounded-run] [--methods transpose,pinv,dls,sdls]
        [--additions lab_script,posture_pull,...] [--full] [PRESET ...]

`--full` also prints every run's figures (one row per preset, motion, method,
addition and way).
"""

import argparse
import json
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parent))
from gaitlab_run import run  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
BIN = ROOT / "target" / "release" / "gaitlab"

MODES = ["walk", "run", "wounded-walk", "wounded-run"]
METHODS = ["transpose", "pinv", "dls", "sdls"]
# §5.3 compares the methods walking and running; the wounded motions (§5.2.3)
# come with no claim on the effectors' errors (§5.1.1's weights move the shown
# angles off the IK's own), so only `L` is checked there.
WALKING = {"walk"}
COMPARED = {"walk", "run"}

# name: (key, on, off, acts(mode, method))
ADDITIONS = {
    "lab_script": ("scenario.thesis.script", "lab", "listing", lambda mode, method: True),
    "posture_pull": ("scenario.thesis.posture_gain", "0.1", "0", lambda mode, method: True),
    "start_ramp": ("scenario.thesis.start_ramp_s", "1", "0", lambda mode, method: True),
    "limit_re_solve": ("scenario.ik.limit_passes", "4", "1", lambda mode, method: True),
    "step_wounds": ("scenario.thesis.wound_form", "step", "angle",
                    lambda mode, method: mode.startswith("wounded")),
    "clamp_every_method": ("scenario.ik.clamp_every_method", "true", "false",
                           lambda mode, method: method in ("transpose", "dls")),
    "buss_alpha": ("scenario.ik.transpose_alpha", "buss", "thesis",
                   lambda mode, method: method == "transpose"),
    "lambda_0.05": ("scenario.ik.lambda", "0.05", "0.2", lambda mode, method: method == "dls"),
}


def roles(preset):
    """The thesis' role (`left_foot` …) of each effector name of `preset`."""
    path = Path(preset) if preset.endswith(".json") else ROOT / "presets" / f"{preset}.json"
    named = {}
    try:
        named = json.loads(path.read_text())["scenario"]["thesis"].get("roles", {})
    except (OSError, KeyError, ValueError):
        pass
    out = {role: role for role in ("left_foot", "right_foot", "left_hand", "right_hand")}
    out.update(named)
    return {effector: role for role, effector in out.items()}


def group(m, which, by_role):
    """Averages (and the max error's max) over the effectors of one group."""
    es = []
    for e in m["effectors"]:
        role = by_role.get(e["name"], "")
        if (which == "other" and not role) or (which != "other" and role.endswith(which)):
            es.append(e)
    if not es:
        return None
    avg = lambda key: (sum(e[key] for e in es if e[key] is not None)
                       / max(1, sum(e[key] is not None for e in es))
                       if any(e[key] is not None for e in es) else None)
    return {
        "mean_mm": 1e3 * avg("mean_error_m"),
        "max_mm": 1e3 * max(e["max_error_m"] for e in es),
        "reach": avg("reachable"),
        "reach_mm": None if avg("mean_error_reachable_m") is None else 1e3 * avg("mean_error_reachable_m"),
        "osc_hz": avg("oscillation_hz"),
        "jitter": 1e3 * avg("jitter_rad"),
    }


def figures(m, by_role):
    if "error" in m:
        return {"error": m["error"]}
    return {
        "feet": group(m, "foot", by_role),
        "hands": group(m, "hand", by_role),
        "other": group(m, "other", by_role),
        "within_limits": m["within_limits"],
        "restored": m["restored_frames"],
        "additions": m.get("lab_additions", []),
    }


def run_claims(f, mode):
    """Per-run claims: name -> True / False / None (does not apply)."""
    if "error" in f:
        return {"L": False, "R": False, "T": False}
    feet, hands = f["feet"], f["hands"]
    walking = mode in WALKING
    out = {"L": f["within_limits"] and f["restored"] == 0}
    if mode not in COMPARED:
        return out
    if walking:
        out["R"] = feet["reach"] >= 0.99 and (hands is None or hands["reach"] <= 0.01)
    else:
        out["R"] = feet["reach"] <= 0.01 and (hands is None or hands["reach"] <= 0.01)
    return out


def tracks(f, mode, method):
    if method != "sdls" or mode not in WALKING:
        return None
    if "error" in f:
        return False
    feet = f["feet"]
    return feet["reach"] >= 0.99 and feet["reach_mm"] is not None and feet["reach_mm"] <= 1.0


def method_claims(by_method, mode):
    """§5.3's comparisons across the four methods run with the same settings."""
    if (any("error" in f for f in by_method.values()) or set(by_method) != set(METHODS)
            or mode not in COMPARED):
        return {}
    feet = {k: f["feet"]["mean_mm"] for k, f in by_method.items()}
    hands_osc = {k: f["hands"]["osc_hz"] for k, f in by_method.items()}
    out = {}
    if mode in WALKING:
        out["S"] = all(feet["sdls"] <= feet[k] + 0.1 for k in METHODS)
        out["D"] = feet["dls"] < feet["pinv"] and feet["dls"] < feet["transpose"]
        out["J"] = all(hands_osc["transpose"] >= 1.5 * hands_osc[k] for k in ("dls", "sdls"))
    if all(f["hands"]["reach"] <= 0.01 for f in by_method.values()):
        out["P"] = all(hands_osc["pinv"] >= 1.5 * hands_osc[k] for k in ("dls", "sdls"))
    return out


def across(claim, by_method):
    """The figure a comparison claim compares, per method."""
    if claim in ("S", "D"):
        return "feet " + ", ".join(f"{m} {fmt(f['feet']['mean_mm'])}" for m, f in by_method.items()) + " mm"
    return "hands " + ", ".join(f"{m} {fmt(f['hands']['osc_hz'], 2)}" for m, f in by_method.items()) + " Hz"


def fmt(x, digits=1):
    if x is None:
        return "—"
    return f"{x:.{digits}f}"


def cell(f):
    """One way's figures in a table cell."""
    if "error" in f:
        return "refused: " + f["error"].splitlines()[-1]
    feet, hands, other = f["feet"], f["hands"], f["other"]
    s = (f"feet {fmt(feet['mean_mm'])}/{fmt(feet['max_mm'], 0)} mm "
         f"({fmt(100 * feet['reach'], 0)} % reach, {fmt(feet['osc_hz'], 2)} Hz, {fmt(feet['jitter'], 3)})")
    if hands:
        s += (f"; hands {fmt(hands['mean_mm'])}/{fmt(hands['max_mm'], 0)} mm "
              f"({fmt(100 * hands['reach'], 0)} %, {fmt(hands['osc_hz'], 2)} Hz, {fmt(hands['jitter'], 3)})")
    if other:
        s += f"; other {fmt(other['mean_mm'])} mm"
    if not f["within_limits"] or f["restored"]:
        s += f"; **within limits {f['within_limits']}, restored {f['restored']}**"
    return s


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=30)
    parser.add_argument("--base", choices=["bundled", "paper"], default="bundled",
                        help="run each addition on top of the preset as bundled, or of --paper-alone")
    parser.add_argument("--modes", default=",".join(MODES))
    parser.add_argument("--methods", default=",".join(METHODS))
    parser.add_argument("--additions", default=",".join(ADDITIONS))
    parser.add_argument("--full", action="store_true", help="print every run's figures")
    parser.add_argument("--jobs", type=int, default=8)
    parser.add_argument("presets", nargs="*", default=["human", "ik-quadruped"])
    args = parser.parse_args()
    modes = args.modes.split(",")
    methods = args.methods.split(",")
    additions = args.additions.split(",")
    base = ["--paper-alone"] if args.base == "paper" else []

    jobs = {}
    for preset in args.presets:
        for mode in modes:
            for method in methods:
                for name in additions:
                    key, on, off, _ = ADDITIONS[name]
                    for way, value in (("on", on), ("off", off)):
                        jobs[(preset, mode, method, name, way)] = [
                            "--seconds", str(args.seconds), "--mode", mode, "--method", method,
                            *base, "--set", f"{key}={value}"]
    distinct = {tuple(a) + (k[0],) for k, a in jobs.items()}
    with ThreadPoolExecutor(args.jobs) as pool:
        done = dict(zip(distinct, pool.map(
            lambda a: run(str(BIN), a[-1], list(a[:-1])), distinct)))
    by_role = {p: roles(p) for p in args.presets}
    figs = {k: figures(done[tuple(a) + (k[0],)], by_role[k[0]]) for k, a in jobs.items()}

    print(f"`python3 tools/ik_additions_both_ways.py --seconds {args.seconds:g} --base {args.base}`; "
          "per cell: mean/max error, reachable share, oscillation, jitter (mrad/frame²).\n")
    if args.full:
        print("| preset | motion | method | addition | on | off | claims on | claims off |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    verdicts, crosses = {}, {}
    for preset in args.presets:
        for name in additions:
            acts = ADDITIONS[name][3]
            for mode in modes:
                cross = {}
                for way in ("on", "off"):
                    cross[way] = method_claims(
                        {m: figs[(preset, mode, m, name, way)] for m in METHODS if m in methods}, mode)
                if mode in COMPARED and any(acts(mode, m) for m in methods):
                    crosses[(preset, mode, name)] = cross
                for method in methods:
                    if not acts(mode, method):
                        continue
                    on, off = figs[(preset, mode, method, name, "on")], figs[(preset, mode, method, name, "off")]
                    claims = {}
                    for way, f in (("on", on), ("off", off)):
                        c = run_claims(f, mode)
                        t = tracks(f, mode, method)
                        if t is not None:
                            c["T"] = t
                        claims[way] = c
                    for claim in claims["on"]:
                        a, b = claims["on"][claim], claims["off"][claim]
                        if a != b:
                            verdicts.setdefault((preset, name), []).append(
                                ("rescues" if a else "breaks", claim, mode, method, on, off))
                    if args.full:
                        show = lambda c: " ".join(k if v else f"**¬{k}**" for k, v in sorted(c.items()))
                        print(f"| {preset} | {mode} | {method} | `{name}` | {cell(on)} | {cell(off)} | "
                              f"{show(claims['on'])} | {show(claims['off'])} |")
                for claim in cross["on"]:
                    a, b = cross["on"].get(claim), cross["off"].get(claim)
                    if b is not None and a != b and any(acts(mode, m) for m in methods):
                        verdicts.setdefault((preset, name), []).append(
                            ("rescues" if a else "breaks", claim, mode, "across methods",
                             *(across(claim, {m: figs[(preset, mode, m, name, way)] for m in METHODS})
                               for way in ("on", "off"))))
        sys.stdout.flush()

    print("\n§5.3's comparisons across the four methods (walking and running; "
          "**¬X**: fails), each addition on and off:\n")
    print("| preset | motion | addition | on | off |")
    print("| --- | --- | --- | --- | --- |")
    for (preset, mode, name), cross in sorted(crosses.items()):
        show = lambda c: " ".join(k if v else f"**¬{k}**" for k, v in sorted(c.items())) or "—"
        print(f"| {preset} | {mode} | `{name}` | {show(cross['on'])} | {show(cross['off'])} |")

    print("\n| preset | addition | rescues (claim fails off, holds on) | breaks (holds off, fails on) |")
    print("| --- | --- | --- | --- |")
    for preset in args.presets:
        for name in additions:
            found = verdicts.get((preset, name), [])
            show = lambda f: f if isinstance(f, str) else cell(f)
            say = lambda kind: "; ".join(
                f"{claim} {mode} {method}: on {show(on)} / off {show(off)}"
                for k, claim, mode, method, on, off in found if k == kind) or "none"
            print(f"| {preset} | `{name}` | {say('rescues')} | {say('breaks')} |")


if __name__ == "__main__":
    main()
