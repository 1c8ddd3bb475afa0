#!/usr/bin/env python3
"""The exported quadruped standing on stairs, in MuJoCo (issue 45 item 5):
gaitlab writes the creature on the third of five 0.1 m steps as MJCF
(`crates/physics/examples/stand_on_stairs.rs`) and settles it in its own
simulation held still — its leg springs as the gait set them at the start,
its hips and knees servoed to their start angles, no thrust. MuJoCo loads
the file, gets the same servo as passive joint springs on those joints, and
settles it from the same state for as long. The trunk's rest heights must
agree within 1 mm.

Run from the repository root (needs `pip install mujoco numpy`):
    python3 tools/stairs_mujoco_check.py [PRESET]
"""
import json
import subprocess
import sys
import tempfile

import mujoco
import numpy as np

TOLERANCE_M = 1e-3
preset = sys.argv[1] if len(sys.argv) > 1 else "raibert-quadruped"
out = tempfile.mkdtemp()
s = json.loads(subprocess.check_output(
    ["cargo", "run", "--quiet", "--release", "-p", "gaitlab-physics", "--example", "stand_on_stairs", "--", preset, out]))
m = mujoco.MjModel.from_xml_path(s["xml"])
d = mujoco.MjData(m)
q0 = np.array(s["q0"])
free = m.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
off_q, off_v = (7, 6) if free else (0, 0)
if free:
    d.qpos[:3] = s["start_base_m"]
    d.qpos[3:7] = s["start_quat_wxyz"]
d.qpos[off_q:] = q0
# The held joints: the example's servo as passive springs about their start angles.
for k in s["held"]:
    j = m.dof_jntid[off_v + k]
    m.jnt_stiffness[j] = s["hip_kp"]
    m.dof_damping[off_v + k] = s["hip_kv"]
    m.qpos_spring[m.jnt_qposadr[j]] = q0[k]
d.ctrl[:] = 0
steps = int(round(s["settle_s"] / m.opt.timestep))
for _ in range(steps):
    mujoco.mj_step(m, d)
mujoco_height = d.qpos[1]
gaitlab_height = s["gaitlab_rest_height_m"]
difference = abs(mujoco_height - gaitlab_height)
print(f"{preset} on a {s['tread_m']:.3f} m tread after {s['settle_s']} s: trunk at {gaitlab_height:.5f} m in gaitlab, "
      f"{mujoco_height:.5f} m in MuJoCo {mujoco.__version__}: {difference * 1e3:.3f} mm apart (tolerance {TOLERANCE_M * 1e3:.0f} mm)")
print(f"gaitlab on the floor: {s['gaitlab_flat_rest_height_m']:.5f} m (+ the tread: "
      f"{s['gaitlab_flat_rest_height_m'] + s['tread_m']:.5f} m); feet "
      + ", ".join(f"{h * 1e3:+.2f}" for h in s["gaitlab_feet_above_ground_m"]) + " mm above the tread in gaitlab")
sys.exit(1 if difference > TOLERANCE_M or not np.isfinite(mujoco_height) else 0)
