#!/usr/bin/env python3
"""Time Pose2Sim's triangulation step on a set of per-camera OpenPose JSON folders.

    python triangulate_timing.py --calibration CALIB.toml --pose DIR [options]

DIR holds one sub-folder per camera, each with one OpenPose-layout JSON per frame
({"people":[{"pose_keypoints_2d":[x,y,c,...]}]}), e.g. DIR/cam_0/frame_000000000000_keypoints.json.

Pose2Sim wants a project folder (Config.toml, calibration/*.toml, pose/<name containing
"json">/*.json, frame index = last number in the file name, counted from 0, cameras paired
with calibration sections by sort order only). This script builds one in a temporary folder
with symlinks, writes a Config.toml with the settings below, runs Pose2Sim.triangulation()
and prints ONE JSON line on stdout (Pose2Sim's own log goes to stderr):

  {"tool":"pose2sim","version":...,"frames":N,"cameras":M,"seconds":S,"frames_per_s":...,
   "core_seconds":..., "core_frames_per_s":..., "load_seconds":..., ...}

seconds        wall time of Pose2Sim.triangulation() (config read, file listing and per-frame
               file matching, JSON parsing, triangulation, pandas, TRC writing, recap log);
               the Python import of Pose2Sim is reported apart (import_seconds).
core_seconds   Pose2Sim's own per-keypoint robust triangulation
               (Pose2Sim.triangulation.triangulation_from_best_cameras) over all frames, on
               arrays loaded beforehand: no file I/O, no pandas, no TRC (--no-core skips it).
load_seconds   Pose2Sim's JSON reader (extract_files_frame_f) over all frames, for reference.
"""
import argparse
import json
import logging
import os
import re
import shutil
import sys
import tempfile
import time
from pathlib import Path

T_START = time.perf_counter()

BLAZEPOSE_33_NAMES = [
    "Nose", "LEyeInner", "LEye", "LEyeOuter", "REyeInner", "REye", "REyeOuter",
    "LEar", "REar", "LMouth", "RMouth", "LShoulder", "RShoulder", "LElbow",
    "RElbow", "LWrist", "RWrist", "LPinky", "RPinky", "LIndex", "RIndex",
    "LThumb", "RThumb", "LHip", "RHip", "LKnee", "RKnee", "LAnkle", "RAnkle",
    "LHeel", "RHeel", "LBigToe", "RBigToe",
]
# Sections of a calibration TOML that Pose2Sim does not treat as cameras.
NON_CAMERA_KEYS = ("metadata", "capture_volume", "charuco", "checkerboard")


def last_number(s):
    nums = re.findall(r"\d+", s)
    return int(nums[-1]) if nums else None


def natural_key(s):
    return [int(c) if c.isdigit() else c.lower() for c in re.split(r"(\d+)", s)]


def log(msg):
    print(f"[triangulate_timing] {msg}", file=sys.stderr, flush=True)


def flat_skeleton(names, ids=None):
    """Custom Pose2Sim skeleton (anytree dict) with every keypoint a child of a non-keypoint root."""
    ids = list(range(len(names))) if ids is None else ids
    return {"name": "Root", "id": "None",
            "children": [{"name": n, "id": int(i)} for n, i in zip(names, ids)]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--calibration", required=True, help="Pose2Sim/Anipose-style calibration .toml")
    ap.add_argument("--pose", required=True, help="folder with one sub-folder of JSON files per camera")
    ap.add_argument("--pose-model", default="auto",
                    help="'auto' (33 points -> BLAZEPOSE_33), 'BLAZEPOSE_33' (all 33 BlazePose points, "
                         "custom skeleton), 'FLAT' (every point in the JSON, custom skeleton), or any "
                         "Pose2Sim skeletons.py name: BLAZEPOSE (Pose2Sim's 22-point subset), BODY_25B, "
                         "BODY_25, HALPE_26, COCO_17, ...")
    ap.add_argument("--likelihood-threshold", type=float, default=0.3,
                    help="likelihood_threshold_triangulation (Pose2Sim default 0.3)")
    ap.add_argument("--reproj-threshold", type=float, default=15.0,
                    help="reproj_error_threshold_triangulation in px (Pose2Sim default 15)")
    ap.add_argument("--min-cameras", type=int, default=2,
                    help="min_cameras_for_triangulation (Pose2Sim default 2)")
    ap.add_argument("--undistort", action="store_true",
                    help="undistort_points = true (Pose2Sim default false: pinhole P = K[R|t], distortion ignored)")
    ap.add_argument("--lr-swap", action="store_true", help="handle_LR_swap = true (default false)")
    ap.add_argument("--interpolate", action="store_true",
                    help="Pose2Sim's default gap filling (linear, gaps < 20 frames, large gaps last value); "
                         "default here: no interpolation, gaps stay NaN")
    ap.add_argument("--fps", type=float, default=30.0, help="frame rate written to the TRC (no effect on timing)")
    ap.add_argument("--frames", type=int, default=0, help="use only the first N frames (0 = all)")
    ap.add_argument("--no-core", action="store_true", help="skip the core (no file I/O) timing")
    ap.add_argument("--out-trc", help="copy the TRC that Pose2Sim wrote to this path")
    ap.add_argument("--truth", help="ground_truth.npy (frames, points, 3; world metres, Z up) to check the TRC against")
    ap.add_argument("--keep", help="build the Pose2Sim project in this folder (kept) instead of a temporary one")
    ap.add_argument("--quiet", action="store_true", help="silence Pose2Sim's log and progress bar")
    args = ap.parse_args()

    calib_path = Path(args.calibration).resolve()
    pose_root = Path(args.pose).resolve()

    import rtoml  # light; Pose2Sim itself is imported later and timed apart
    calib = rtoml.load(calib_path)
    cal_keys = [k for k in calib if k not in NON_CAMERA_KEYS and isinstance(calib[k], dict)]
    cal_names = [calib[k].get("name") or k for k in cal_keys]
    if not cal_keys:
        sys.exit(f"no camera sections in {calib_path}")

    # ---- camera folders, paired with calibration sections -------------------------------------
    cam_dirs = sorted([d for d in pose_root.iterdir() if d.is_dir() and any(d.glob("*.json"))],
                      key=lambda d: natural_key(d.name))
    if len(cam_dirs) != len(cal_keys):
        sys.exit(f"{len(cam_dirs)} camera folders in {pose_root} but {len(cal_keys)} cameras in {calib_path}")

    def norm(name):  # "cam_01", "cam01_json", "Cam01" -> "cam01"
        return re.sub(r"[^0-9a-z]", "", re.sub(r"_?json$", "", name.lower()))

    by_name = {}
    for d in cam_dirs:
        hits = [i for i, (k, n) in enumerate(zip(cal_keys, cal_names)) if norm(d.name) in (norm(k), norm(n))]
        if len(hits) == 1:
            by_name[hits[0]] = d
    if len(by_name) == len(cal_keys):
        ordered_dirs = [by_name[i] for i in range(len(cal_keys))]
        pairing = "by name"
    else:
        ordered_dirs = cam_dirs
        pairing = "by sorted order"
        log(f"camera folders do not match calibration names {cal_names}: pairing by sorted order "
            f"{[d.name for d in cam_dirs]}")

    # ---- frames: union of frame numbers (last number in the file name), re-indexed from 0 ----
    cam_files = []
    for d in ordered_dirs:
        files = {}
        for p in d.glob("*.json"):
            n = last_number(p.name)
            if n is None:
                sys.exit(f"no frame number in file name {p}")
            if n in files:
                sys.exit(f"two files for frame {n} in {d}: {files[n].name}, {p.name}")
            files[n] = p
        cam_files.append(files)
    frame_ids = sorted(set().union(*[f.keys() for f in cam_files]))
    if args.frames:
        frame_ids = frame_ids[:args.frames]
    n_frames, n_cams = len(frame_ids), len(ordered_dirs)
    missing = sum(1 for files in cam_files for f in frame_ids if f not in files)

    # number of keypoints, from the first file found
    first = next(iter(cam_files[0].values()))
    with open(first) as fh:
        people = json.load(fh).get("people", [])
    n_kpts = len(people[0]["pose_keypoints_2d"]) // 3 if people else 0

    pose_model = args.pose_model
    custom = None
    if pose_model.lower() == "auto":
        if n_kpts == 33:
            pose_model = "BLAZEPOSE_33"
        else:
            sys.exit(f"{n_kpts} keypoints per person in {first}: pass --pose-model (FLAT, BODY_25B, HALPE_26, ...)")
    if pose_model.upper() == "BLAZEPOSE_33":
        pose_model, custom = "BLAZEPOSE_33", flat_skeleton(BLAZEPOSE_33_NAMES)
    elif pose_model.upper() == "FLAT":
        pose_model, custom = "FLAT", flat_skeleton([f"P{i}" for i in range(n_kpts)])

    # ---- Pose2Sim project ------------------------------------------------------------------
    if args.keep:
        parent = Path(args.keep).resolve()
        if parent.exists():
            shutil.rmtree(parent)
        parent.mkdir(parents=True)
        tmp = None
    else:
        tmp = tempfile.mkdtemp(prefix="p2s_timing_")
        parent = Path(tmp)
    # Pose2Sim looks for a folder whose name contains "calib" next to Config.toml, and for a
    # Config.toml one level up (batch mode): keep the project alone in its parent folder.
    proj = parent / "trial"
    (proj / "calibration").mkdir(parents=True)
    shutil.copy(calib_path, proj / "calibration" / "Calib.toml")
    width = max(6, len(str(n_frames)))
    for c, (d, files) in enumerate(zip(ordered_dirs, cam_files)):
        jd = proj / "pose" / f"cam{c + 1:02d}_json"  # must contain "json"; sorted by last number
        jd.mkdir(parents=True)
        for new_idx, f in enumerate(frame_ids):
            if f in files:
                os.symlink(files[f], jd / f"cam{c + 1:02d}_{new_idx:0{width}d}.json")

    import Pose2Sim as _p2s_pkg  # noqa: F401  (package __init__ is light)
    from importlib.metadata import version as _version
    p2s_version = _version("pose2sim")
    default_cfg = Path(_p2s_pkg.__file__).parent / "Demo_SinglePerson" / "Config.toml"
    cfg = rtoml.load(default_cfg)  # every key the code reads without a default is there
    cfg["project"].update({
        "project_dir": str(proj),
        "multi_person": False,
        "frame_rate": args.fps,
        "frame_range": [0, n_frames],
    })
    cfg["pose"]["pose_model"] = pose_model
    if custom is not None:
        cfg["pose"][pose_model] = custom
    tri = cfg["triangulation"]
    tri.update({
        "reproj_error_threshold_triangulation": args.reproj_threshold,
        "likelihood_threshold_triangulation": args.likelihood_threshold,
        "min_cameras_for_triangulation": args.min_cameras,
        "handle_LR_swap": bool(args.lr_swap),
        "undistort_points": bool(args.undistort),
        "remove_incomplete_frames": False,
        "sections_to_keep": "all",
        "min_chunk_size": 1,
        "show_interp_indices": False,
        "make_c3d": False,
    })
    if args.interpolate:
        tri.update({"interpolation": "linear", "interp_if_gap_smaller_than": 20, "fill_large_gaps_with": "last_value"})
    else:
        tri.update({"interpolation": "none", "fill_large_gaps_with": "nan"})
    cfg.setdefault("logging", {})["use_custom_logging"] = args.quiet
    with open(proj / "Config.toml", "w") as fh:
        rtoml.dump(cfg, fh)

    # ---- import Pose2Sim (timed apart) -----------------------------------------------------
    t0 = time.perf_counter()
    logging.getLogger().setLevel(logging.WARNING if args.quiet else logging.INFO)
    if args.quiet:
        os.environ["TQDM_DISABLE"] = "1"
    from Pose2Sim import Pose2Sim as p2s
    import Pose2Sim.triangulation as p2s_tri
    import numpy as np
    import_s = time.perf_counter() - t0

    # keypoints in Pose2Sim's order (pre-order walk of the skeleton tree), as in triangulate_all
    from anytree import RenderTree
    from anytree.importer import DictImporter
    from Pose2Sim import skeletons
    if custom is not None:
        model = DictImporter().import_(custom)
        model.id = None
    else:
        alias = {"BODY_WITH_FEET": "HALPE_26", "LOWER_BODY": "HALPE_26_LOWER", "WHOLE_BODY_WRIST": "COCO_133_WRIST",
                 "WHOLE_BODY": "COCO_133", "BODY": "COCO_17", "HAND": "HAND_21", "FACE": "FACE_106",
                 "ANIMAL": "ANIMAL2D_17"}
        model = getattr(skeletons, alias.get(pose_model.upper(), pose_model))
    kpt_ids = [n.id for _, _, n in RenderTree(model) if n.id is not None]
    kpt_names = [n.name for _, _, n in RenderTree(model) if n.id is not None]

    # ---- the step as a user runs it ----------------------------------------------------------
    cwd = os.getcwd()
    os.chdir(proj)  # as in Pose2Sim's docs: run from the trial folder
    try:
        t0 = time.perf_counter()
        p2s.triangulation(str(proj))
        seconds = time.perf_counter() - t0
    finally:
        os.chdir(cwd)
    trcs = sorted((proj / "pose-3d").glob("*.trc"))
    if len(trcs) != 1:
        sys.exit(f"expected one TRC in {proj / 'pose-3d'}, found {trcs}")
    trc = trcs[0]

    result = {
        "tool": "pose2sim",
        "version": p2s_version,
        "frames": n_frames,
        "cameras": n_cams,
        "seconds": round(seconds, 4),
        "frames_per_s": round(n_frames / seconds, 2),
    }

    # ---- core: Pose2Sim's robust triangulation alone, on preloaded arrays ----------------------
    if not args.no_core:
        from Pose2Sim.common import computeP, retrieve_calib_params
        idx = list(range(len(kpt_ids)))
        P = computeP(calib_path, undistort=args.undistort)
        calib_params = retrieve_calib_params(calib_path)
        jdirs = sorted((proj / "pose").iterdir(), key=lambda d: natural_key(d.name))
        t0 = time.perf_counter()
        frames_xyl = []
        for i in range(n_frames):
            paths = [d / f"{d.name[:-5]}_{i:0{width}d}.json" for d in jdirs]
            frames_xyl.append(p2s_tri.extract_files_frame_f(paths, kpt_ids, nb_persons_to_detect=1))
        load_s = time.perf_counter() - t0
        if args.undistort:
            log("core timing skips point undistortion (done once per frame in Pose2Sim's loop)")
        lt = args.likelihood_threshold
        swap = idx  # handle_LR_swap off unless --lr-swap
        if args.lr_swap:
            sw = [("L" + n[1:]) if n.startswith("R") else ("R" + n[1:]) if n.startswith("L") else n for n in kpt_names]
            swap = [kpt_names.index(n) if n in kpt_names else k for k, n in enumerate(sw)]
        t0 = time.perf_counter()
        core = np.full((n_frames, len(idx), 3), np.nan)
        for i, (x, y, l) in enumerate(frames_xyl):
            x, y, l = x[0].copy(), y[0].copy(), l[0].copy()
            with np.errstate(invalid="ignore"):
                bad = l < lt
            x[bad] = np.nan
            y[bad] = np.nan
            l[bad] = np.nan
            for k in idx:
                q, _, _, _ = p2s_tri.triangulation_from_best_cameras(
                    cfg, np.array((x[:, k], y[:, k], l[:, k])),
                    np.array((x[:, swap[k]], y[:, swap[k]], l[:, swap[k]])), P, calib_params)
                core[i, k] = q
        core_s = time.perf_counter() - t0
        result.update({
            "core_seconds": round(core_s, 4),
            "core_frames_per_s": round(n_frames / core_s, 2),
            "load_seconds": round(load_s, 4),
        })
    else:
        core = None

    # ---- TRC back to world (Pose2Sim writes Y-up: trc X,Y,Z = world Y,Z,X) --------------------
    import pandas as pd
    data = pd.read_csv(trc, sep="\t", skiprows=5, header=None).to_numpy()
    frames_out = data[:, 0].astype(int)
    xyz = data[:, 2:2 + 3 * (data.shape[1] - 2) // 3].astype(float)
    xyz = xyz.reshape(len(data), -1, 3)[:, :, [2, 0, 1]]  # back to world Z-up
    n_pts = xyz.shape[1]
    result.update({
        "keypoints": n_pts,
        "trc_frames": int(len(frames_out)),
        "valid_points": int(np.isfinite(xyz).all(axis=2).sum()),
        "total_points": int(n_frames * n_pts),
        "pose_model": pose_model,
        "camera_pairing": pairing,
        "missing_files": missing,
        "import_seconds": round(import_s, 3),
        "script_seconds": round(time.perf_counter() - T_START, 3),
    })
    if core is not None and len(frames_out):
        d = np.abs(core[frames_out] - xyz)
        result["core_vs_trc_max_abs_m"] = float(np.nanmax(d)) if np.isfinite(d).any() else None
    if args.truth:
        gt = np.load(args.truth)[np.array(frame_ids)][frames_out][:, kpt_ids]
        err = np.linalg.norm(xyz - gt, axis=2)
        result.update({"err_mean_m": round(float(np.nanmean(err)), 5),
                       "err_p95_m": round(float(np.nanpercentile(err, 95)), 5),
                       "err_max_m": round(float(np.nanmax(err)), 5)})
    if args.out_trc:
        shutil.copy(trc, args.out_trc)
    if tmp:
        shutil.rmtree(tmp, ignore_errors=True)
    print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
