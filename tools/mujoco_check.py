#!/usr/bin/env python3
"""Cross-check gaitlab's dynamics and MJCF export against MuJoCo (an
independent engine): for every bundled physics preset, export the MJCF,
load it in MuJoCo, put both in the same 20 random states (springs, contact
and actuators off) and compare joint accelerations, kinetic energy and mass.

Run from the repository root (needs `pip install mujoco numpy`):
    cargo build --release -p gaitlab-cli -p gaitlab-physics --examples
    python3 tools/mujoco_check.py
"""
import os
import subprocess
import tempfile

import json

import mujoco
import numpy as np

out = tempfile.mkdtemp()
dump = "target/release/examples/dynamics_dump"
for preset in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"]:
    subprocess.check_call(["target/release/gaitlab", "export", preset, "--format", "mjcf", "--out", os.path.join(out, preset + ".xml")])
worst = {}
for preset in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"]:
    m = mujoco.MjModel.from_xml_path(f"{out}/{preset}.xml")
    m.jnt_stiffness[:] = 0; m.dof_damping[:] = 0; m.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    d = mujoco.MjData(m)
    errs = []
    for seed in range(1, 21):
        s = json.loads(subprocess.check_output([dump, preset, str(seed)]))
        q = np.array(s["q"]); qd = np.array(s["qd"])
        if s["free"]:
            rot = np.zeros(9); mujoco.mju_quat2Mat(rot, np.array(s["quat"])); rot = rot.reshape(3, 3)
            d.qpos[:3] = s["pos"]; d.qpos[3:7] = s["quat"]; d.qpos[7:] = q
            d.qvel[:3] = rot @ np.array(s["v_body"]); d.qvel[3:6] = s["w_body"]; d.qvel[6:] = qd
            off = 6
        else:
            d.qpos[:] = q; d.qvel[:] = qd; off = 0
        d.ctrl[:] = 0
        mujoco.mj_forward(m, d)
        M = np.zeros((m.nv, m.nv)); mujoco.mj_fullM(m, d, M)
        ke_mj = 0.5 * d.qvel @ M @ d.qvel
        qdd_mj = d.qacc[off:]
        scale = max(1.0, np.abs(qdd_mj).max())
        e = np.abs(qdd_mj - np.array(s["qdd"])).max() / scale
        if s["free"]:
            e = max(e, np.abs(d.qacc[3:6] - np.array(s["w_dot"])).max() / scale)
        errs.append((e, abs(ke_mj - s["ke"]) / max(1, s["ke"]), abs(m.body_mass.sum() - s["mass"])))
    worst[preset] = tuple(max(x[i] for x in errs) for i in range(3))
    print(preset, "nbody", m.nbody, "njnt", m.njnt, "nv", m.nv, "worst rel qacc err %.2e, KE err %.2e, mass err %.2e" % worst[preset])
