#!/usr/bin/env python3
"""Every bundled preset run as bundled and as its paper alone (`gaitlab run
--paper-alone`): the lab additions each way and the figures that say what
the additions buy (issue 41 item 2, docs/parameters.md "Both ways").

Run after `cargo build --release -p gaitlab-cli`:
    python3 tools/paper_alone_both_ways.py [--seconds 30] [PRESET ...]
"""

import argparse
import json
import subprocess
import sys
from pathlib import Path

BIN = Path(__file__).resolve().parent.parent / "target" / "release" / "gaitlab"


def run(preset, seconds, paper, extra=()):
    args = [str(BIN), "run", preset, "--json", "--seconds", str(seconds), *extra]
    if paper:
        args.append("--paper-alone")
    out = subprocess.run(args, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        return {"error": out.stderr.strip()}
    return json.loads(out.stdout)


def figures(m):
    if "error" in m:
        return m["error"]
    engine = m["engine"]
    if engine == "ik":
        feet = [e for e in m["effectors"] if "foot" in e["name"]]
        hands = [e for e in m["effectors"] if "hand" in e["name"]]
        mean = lambda es: 1e3 * sum(e["mean_error_m"] for e in es) / max(len(es), 1)
        worst = lambda es: 1e3 * max((e["max_error_m"] for e in es), default=0.0)
        return (f"feet mean {mean(feet):.1f} mm (max {worst(feet):.0f}), hands mean {mean(hands):.1f} mm, "
                f"within limits {m['within_limits']}, restored frames {m['restored_frames']}")
    if engine == "poda":
        first = lambda v: max(v) if isinstance(v, list) else v
        return (f"slip {1e3 * first(m['foot_slip_max_m']):.2f} mm, "
                f"path error {first(m['path_error_max_m']):.3f} m, "
                f"body speed {first(m['body_speed_mps']):.3f} m/s, "
                f"pitch range {first(m['body_pitch_range_deg']):.2f}°")
    t2 = [abs(r["diff_pct"]) for r in m.get("table2", []) if r.get("diff_pct") is not None]
    return (f"fell {m['fell']}, put back {len(m.get('put_backs', []))}×, speed {m['speed_mean_mps']:.2f}"
            f"/{m['speed_desired_mps']:.2f} m/s, Table 2 mean |diff| {sum(t2) / max(len(t2), 1):.0f} %")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=30)
    parser.add_argument("presets", nargs="*")
    args = parser.parse_args()
    names = args.presets or [l.split()[0] for l in subprocess.run(
        [str(BIN), "presets"], capture_output=True, text=True, check=True).stdout.splitlines() if l.strip()]
    print("| preset | additions as bundled | as bundled | paper alone |")
    print("| --- | --- | --- | --- |")
    for name in names:
        bundled, paper = run(name, args.seconds, False), run(name, args.seconds, True)
        adds = ", ".join(f"`{a}`" for a in bundled.get("lab_additions", [])) or "none"
        assert "error" in paper or paper.get("lab_additions") == [], (name, paper.get("lab_additions"))
        print(f"| {name} | {adds} | {figures(bundled)} | {figures(paper)} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
