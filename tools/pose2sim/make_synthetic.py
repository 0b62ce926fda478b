#!/usr/bin/env python3
"""Synthetic multi-camera BlazePose-33 data set for triangulation benchmarks.

Writes, under --out:
  calibration.toml                  Pose2Sim/Anipose-style calibration (one [cam_N] table per camera)
  pose/cam_N/frame_%012d_keypoints.json   OpenPose-layout JSON, 33 BlazePose points per frame
  ground_truth.npy                  (frames, 33, 3) float64, world metres, Z up
  meta.json                         generator settings

Cameras: --cams cameras on a ring of --radius metres around the origin at
--cam-height metres, all looking at (0, 0, 0.9); 1280x720, fx = fy = 700,
no distortion. The body walks slowly on a small circle and swings its limbs.
Needs numpy and opencv (cv2.projectPoints) only.
"""
import argparse
import json
import math
import os
from pathlib import Path

import cv2
import numpy as np

# BlazePose 33 landmark names (MediaPipe order), Pose2Sim-style spelling: the timing script's list
# (this script's folder is on sys.path when it runs).
from triangulate_timing import BLAZEPOSE_33_NAMES  # noqa: E402


def body_pose(t):
    """33 BlazePose points (metres, body frame: x forward, y left, z up) at time t (s)."""
    s = 0.9 * math.sin(2 * math.pi * 0.8 * t)      # gait phase
    arm = 0.5 * s
    p = {}
    head_z = 1.62
    p["Nose"] = (0.10, 0.0, head_z)
    for side, y in (("L", 1), ("R", -1)):
        p[f"{side}EyeInner"] = (0.09, 0.015 * y, head_z + 0.035)
        p[f"{side}Eye"] = (0.085, 0.033 * y, head_z + 0.037)
        p[f"{side}EyeOuter"] = (0.08, 0.048 * y, head_z + 0.035)
        p[f"{side}Ear"] = (0.0, 0.075 * y, head_z + 0.01)
        p[f"{side}Mouth"] = (0.09, 0.025 * y, head_z - 0.045)
        sh = np.array([0.0, 0.19 * y, 1.42])
        # arms swing opposite to the legs of the same side
        a = -arm * y
        elbow = sh + np.array([0.28 * math.sin(a), 0.02 * y, -0.28 * math.cos(a)])
        wrist = elbow + np.array([0.26 * math.sin(a + 0.3), 0.0, -0.26 * math.cos(a + 0.3)])
        p[f"{side}Shoulder"] = tuple(sh)
        p[f"{side}Elbow"] = tuple(elbow)
        p[f"{side}Wrist"] = tuple(wrist)
        p[f"{side}Pinky"] = tuple(wrist + np.array([0.03, 0.03 * y, -0.07]))
        p[f"{side}Index"] = tuple(wrist + np.array([0.06, 0.01 * y, -0.07]))
        p[f"{side}Thumb"] = tuple(wrist + np.array([0.05, -0.01 * y, -0.04]))
        hip = np.array([0.0, 0.10 * y, 0.95])
        g = s * y * 0.45
        knee = hip + np.array([0.45 * math.sin(g), 0.0, -0.45 * math.cos(g)])
        kb = max(0.0, -g) * 0.8
        ankle = knee + np.array([0.45 * math.sin(g - kb), 0.0, -0.45 * math.cos(g - kb)])
        p[f"{side}Hip"] = tuple(hip)
        p[f"{side}Knee"] = tuple(knee)
        p[f"{side}Ankle"] = tuple(ankle)
        p[f"{side}Heel"] = tuple(ankle + np.array([-0.06, 0.0, -0.05]))
        p[f"{side}BigToe"] = tuple(ankle + np.array([0.17, 0.01 * y, -0.06]))
    return np.array([p[n] for n in BLAZEPOSE_33_NAMES], dtype=np.float64)


def world_points(f, fps):
    t = f / fps
    yaw = 0.25 * t                                # slow walk on a 0.3 m circle
    c, s = math.cos(yaw), math.sin(yaw)
    rot = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    centre = np.array([0.3 * math.cos(yaw) - 0.3, 0.3 * math.sin(yaw), 0.0])
    return body_pose(t) @ rot.T + centre


def look_at(cam_pos, target):
    """World->camera rotation (OpenCV camera: x right, y down, z forward)."""
    z = target - cam_pos
    z /= np.linalg.norm(z)
    x = np.cross(z, np.array([0.0, 0.0, 1.0]))
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.stack([x, y, z])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=300)
    ap.add_argument("--cams", type=int, default=6)
    ap.add_argument("--radius", type=float, default=3.0)
    ap.add_argument("--cam-height", type=float, default=1.2)
    ap.add_argument("--fps", type=float, default=30.0)
    ap.add_argument("--noise-px", type=float, default=1.0, help="Gaussian pixel noise sigma")
    ap.add_argument("--outlier-rate", type=float, default=0.0,
                    help="fraction of 2D observations displaced by 30-80 px (exercises camera exclusion)")
    ap.add_argument("--conf", type=float, default=0.9, help="confidence written for every point")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()

    rng = np.random.default_rng(args.seed)
    out = Path(args.out)
    (out / "pose").mkdir(parents=True, exist_ok=True)
    W, H, fx, fy = 1280, 720, 700.0, 700.0
    K = np.array([[fx, 0, W / 2], [0, fy, H / 2], [0, 0, 1.0]])
    dist = np.zeros(5)
    target = np.array([0.0, 0.0, 0.9])

    cams = []
    for i in range(args.cams):
        a = 2 * math.pi * i / args.cams
        pos = np.array([args.radius * math.cos(a), args.radius * math.sin(a), args.cam_height])
        R = look_at(pos, target)
        t = -R @ pos
        rvec = cv2.Rodrigues(R)[0].ravel()
        cams.append((f"cam_{i}", rvec, t))

    with open(out / "calibration.toml", "w") as fh:
        for name, rvec, t in cams:
            fh.write(f"[{name}]\nname = \"{name}\"\nsize = [ {float(W)}, {float(H)}]\n")
            fh.write(f"matrix = [ [ {fx}, 0.0, {W / 2}], [ 0.0, {fy}, {H / 2}], [ 0.0, 0.0, 1.0]]\n")
            fh.write("distortions = [ 0.0, 0.0, 0.0, 0.0]\n")
            fh.write(f"rotation = [ {float(rvec[0])!r}, {float(rvec[1])!r}, {float(rvec[2])!r}]\n")
            fh.write(f"translation = [ {float(t[0])!r}, {float(t[1])!r}, {float(t[2])!r}]\n")
            fh.write("fisheye = false\n\n")
        fh.write("[metadata]\nadjusted = false\nerror = 0.0\n")

    truth = np.stack([world_points(f, args.fps) for f in range(args.frames)])
    np.save(out / "ground_truth.npy", truth)

    n_out = 0
    for name, rvec, t in cams:
        d = out / "pose" / name
        d.mkdir(exist_ok=True)
        for f in range(args.frames):
            uv = cv2.projectPoints(truth[f], rvec, t, K, dist)[0].reshape(-1, 2)
            uv = uv + rng.normal(0.0, args.noise_px, uv.shape)
            if args.outlier_rate > 0:
                m = rng.random(len(uv)) < args.outlier_rate
                n_out += int(m.sum())
                ang = rng.uniform(0, 2 * math.pi, m.sum())
                r = rng.uniform(30, 80, m.sum())
                uv[m] += np.stack([r * np.cos(ang), r * np.sin(ang)], axis=1)
            kp = np.concatenate([uv, np.full((len(uv), 1), args.conf)], axis=1).ravel()
            js = {"version": 1.3, "people": [{"person_id": [-1],
                                                "pose_keypoints_2d": [round(float(v), 3) for v in kp]}]}
            with open(d / f"frame_{f:012d}_keypoints.json", "w") as fh:
                json.dump(js, fh)

    meta = dict(vars(args), width=W, height=H, fx=fx, fy=fy, names=BLAZEPOSE_33_NAMES, outliers=n_out)
    with open(out / "meta.json", "w") as fh:
        json.dump(meta, fh, indent=1)
    print(json.dumps({"out": str(out), "frames": args.frames, "cameras": args.cams, "outliers": n_out}))


if __name__ == "__main__":
    main()
