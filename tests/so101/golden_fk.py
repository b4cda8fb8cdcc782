#!/usr/bin/env python3
"""Golden forward kinematics of the SO-101's tool frame, computed by MuJoCo.

Reads tests/golden/so101/so101_new_calib.xml (TheRobotStudio/SO-ARM100, Apache-2.0,
Simulation/SO101/so101_new_calib.xml at commit fda892cba81032c46c40976a48c9ceadbf40a9ca),
removes its mesh assets and mesh geoms (they carry no kinematics: bodies, joints and sites
stay as written) and writes tests/golden/so101/fk.csv: for each joint vector, the pose of the
site `gripperframe` (the URDF's `gripper_frame_link`) in the world: position and rotation
matrix (row major), every float as Python's repr (round-trips exactly).

Joint vectors: zeros; each joint at its lower and upper limit with the others zero; all at
the lower, all at the upper limit; then random vectors uniform within the limits from
numpy's default_rng(101) until there are 256 rows.

With --boxes ASSETS_DIR (the repository's Simulation/SO101/assets), also prints for each body
the axis-aligned box (in the body's frame) around the vertices of its collision meshes, as
the Rust data of src/so101/model.rs; with --parts ASSETS_DIR, the drawn parts of
src/so101/model.rs: a box (in the body's frame) around each collision mesh (the base: each
visual mesh), the meshes of SPLIT cut in two across one of their axes, boxes inside another
of the same body left out.

    python3 -m pip install mujoco   # 3.x or later
    python3 tests/so101/golden_fk.py
"""
import os
import struct
import sys
import xml.etree.ElementTree as ET

import mujoco
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
MJCF = os.path.join(ROOT, "tests", "golden", "so101", "so101_new_calib.xml")
OUT = os.path.join(ROOT, "tests", "golden", "so101", "fk.csv")
JOINTS = ["shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll"]
ROWS = 256


def stripped_model():
    tree = ET.parse(MJCF)
    root = tree.getroot()
    for parent in root.iter():
        for child in list(parent):
            if child.tag == "geom" and child.get("type") == "mesh":
                parent.remove(child)
            elif child.tag == "asset":
                parent.remove(child)
    return mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))


def joint_vectors(model):
    ids = [model.joint(name).id for name in JOINTS]
    lo = np.array([model.jnt_range[i][0] for i in ids])
    hi = np.array([model.jnt_range[i][1] for i in ids])
    qs = [np.zeros(5)]
    for j in range(5):
        for bound in (lo, hi):
            q = np.zeros(5)
            q[j] = bound[j]
            qs.append(q)
    qs.append(lo.copy())
    qs.append(hi.copy())
    rng = np.random.default_rng(101)
    while len(qs) < ROWS:
        qs.append(lo + (hi - lo) * rng.random(5))
    return ids, qs


def main():
    model = stripped_model()
    data = mujoco.MjData(model)
    ids, qs = joint_vectors(model)
    site = model.site("gripperframe").id
    head = ["q1", "q2", "q3", "q4", "q5", "x", "y", "z"]
    head += [f"r{i}{j}" for i in range(1, 4) for j in range(1, 4)]
    lines = [",".join(head)]
    for q in qs:
        data.qpos[:] = 0.0
        for k, jid in enumerate(ids):
            data.qpos[model.jnt_qposadr[jid]] = q[k]
        mujoco.mj_kinematics(model, data)
        cells = list(q) + list(data.site_xpos[site]) + list(data.site_xmat[site])
        lines.append(",".join(repr(float(c)) for c in cells))
    with open(OUT, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {OUT}: {len(qs)} rows, mujoco {mujoco.__version__}")
    if len(sys.argv) == 3 and sys.argv[1] == "--boxes":
        print_boxes(sys.argv[2])
    if len(sys.argv) == 3 and sys.argv[1] == "--parts":
        print_parts(sys.argv[2])


def stl_vertices(path):
    with open(path, "rb") as f:
        data = f.read()
    (n,) = struct.unpack_from("<I", data, 80)
    tris = np.frombuffer(data, dtype=np.uint8, count=n * 50, offset=84).reshape(n, 50)
    return tris[:, 12:48].copy().view("<f4").reshape(-1, 3).astype(np.float64)


def quat_mat(q):
    w, x, y, z = np.array(q) / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def print_boxes(assets):
    root = ET.parse(MJCF).getroot()
    for body in root.iter("body"):
        pts = []
        for g in body.findall("geom"):
            if g.get("class") != "collision" and g.get("class") != "visual":
                continue
            if body.get("name") != "base" and g.get("class") != "collision":
                continue
            if body.get("name") == "base" and g.get("class") != "visual":
                continue
            v = stl_vertices(os.path.join(assets, g.get("mesh") + ".stl"))
            pos = np.array([float(x) for x in g.get("pos").split()])
            rot = quat_mat([float(x) for x in g.get("quat").split()])
            pts.append(v @ rot.T + pos)
        if not pts:
            continue
        p = np.vstack(pts)
        lo, hi = p.min(axis=0), p.max(axis=0)
        c, h = (lo + hi) / 2, (hi - lo) / 2
        print(f'    ("{body.get("name")}", [{c[0]:.4f}, {c[1]:.4f}, {c[2]:.4f}], '
              f"[{h[0]:.4f}, {h[1]:.4f}, {h[2]:.4f}]),")


# Meshes drawn as two boxes: the mesh's axis and where (in the mesh's frame, m) to cut it.
# The fixed jaw's mount and finger; the moving jaw's hinge and finger; the base's housing and
# its raised back.
SPLIT = {
    "wrist_roll_follower_so101_v1": (2, 0.0527),
    "moving_jaw_so101_v1": (1, -0.036),
    "base_so101_v2": (2, 0.042),
}


def surface_points(path, n=6):
    """Points on every triangle of the STL (a barycentric grid of n per edge)."""
    tri = stl_vertices(path).reshape(-1, 3, 3)
    pts = []
    for i in range(n + 1):
        for j in range(n + 1 - i):
            a, b = i / n, j / n
            pts.append(tri[:, 0] * (1 - a - b) + tri[:, 1] * a + tri[:, 2] * b)
    return np.vstack(pts)


def print_parts(assets):
    root = ET.parse(MJCF).getroot()
    names = [b.get("name") for b in root.iter("body")]
    for body in root.iter("body"):
        name = body.get("name")
        want = "visual" if name == "base" else "collision"
        boxes = []
        for g in body.findall("geom"):
            if g.get("class") != want:
                continue
            p = surface_points(os.path.join(assets, g.get("mesh") + ".stl"))
            pieces = [p]
            if g.get("mesh") in SPLIT:
                axis, cut = SPLIT[g.get("mesh")]
                pieces = [p[p[:, axis] <= cut], p[p[:, axis] >= cut]]
            pos = np.array([float(x) for x in g.get("pos").split()])
            rot = quat_mat([float(x) for x in g.get("quat").split()])
            for piece in pieces:
                w = piece @ rot.T + pos
                boxes.append((w.min(axis=0), w.max(axis=0)))
        kept = [
            (lo, hi) for k, (lo, hi) in enumerate(boxes)
            if not any(
                j != k and np.all(lo >= lo2 - 1e-4) and np.all(hi <= hi2 + 1e-4)
                for j, (lo2, hi2) in enumerate(boxes)
            )
        ]
        for lo, hi in kept:
            c, h = (lo + hi) / 2, (hi - lo) / 2
            print(f"    part({names.index(name)}, [{c[0]:.4f}, {c[1]:.4f}, {c[2]:.4f}], "
                  f"[{h[0]:.4f}, {h[1]:.4f}, {h[2]:.4f}]),")


if __name__ == "__main__":
    main()
