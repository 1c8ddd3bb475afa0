#!/usr/bin/env python3
"""Cross-check the terrain's MJCF export against MuJoCo (issue 45 item 5):
every sample terrain (a floor, slopes, stairs up and down in three headings,
two height fields) is written by gaitlab, loaded in MuJoCo, and a ray cast
straight down at 100 points per terrain must meet the ground at gaitlab's
own height (`Terrain::height_m`) within 1 mm.

Run from the repository root (needs `pip install mujoco numpy`):
    python3 tools/terrain_mujoco_check.py
"""
import json
import subprocess
import sys
import tempfile

import mujoco
import numpy as np

TOLERANCE_M = 1e-3
out = tempfile.mkdtemp()
samples = json.loads(subprocess.check_output(
    ["cargo", "run", "--quiet", "--release", "-p", "gaitlab-core", "--example", "terrain_mjcf", "--", out]))
worst_all = 0.0
failed = False
for name, points in samples.items():
    m = mujoco.MjModel.from_xml_path(f"{out}/{name}.xml")
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    geomid = np.zeros(1, dtype=np.int32)
    worst = 0.0
    for x, z, h in points:
        top = 200.0
        dist = mujoco.mj_ray(m, d, np.array([x, top, z]), np.array([0.0, -1.0, 0.0]), None, 1, -1, geomid)
        if dist < 0:
            print(f"{name}: no ground under ({x:.3f}, {z:.3f})")
            failed = True
            continue
        worst = max(worst, abs((top - dist) - h))
    worst_all = max(worst_all, worst)
    print(f"{name}: {len(points)} points, {m.ngeom} geom(s), {m.nhfield} hfield(s): largest height difference {worst * 1e3:.6f} mm")
    failed |= worst > TOLERANCE_M
print(f"all: largest difference {worst_all * 1e3:.6f} mm (tolerance {TOLERANCE_M * 1e3:.0f} mm)")
sys.exit(1 if failed else 0)
