"""`ergocell-edge detect`: videos to OpenPose-layout JSON folders, offline."""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, List, Optional, Sequence

from . import EdgeError
from .openpose import is_ours, write_keypoints, write_sidecar
from .stop import StopFlag
from .video import SourceSpec, check_file, open_capture, probe_file, split_side_by_side


@dataclass
class CameraOutput:
    """One camera's output folder: a whole video, or one half of a side-by-side video."""

    name: str  # folder name, and the prefix of its file names
    folder: Path
    half: Optional[str] = None  # None, "left" or "right"
    frames: int = 0
    with_person: int = 0
    inference_ms: float = 0.0
    width: int = 0
    height: int = 0

    @property
    def ms_per_frame(self) -> float:
        return self.inference_ms / self.frames if self.frames else 0.0


@dataclass
class VideoJob:
    video: Path
    outputs: List[CameraOutput]
    width: int = 0
    height: int = 0
    fps: Optional[float] = None
    frame_count: Optional[int] = None
    wall_s: float = 0.0
    interrupted: bool = False


def _same_or_inside(path: Path, other: Path) -> bool:
    return path == other or other in path.parents


def plan_jobs(videos: Sequence[str], out: str, side_by_side: bool = False,
              side_by_side_ids: Optional[Sequence[str]] = None) -> List[VideoJob]:
    """Checks the inputs and the output names (nothing is written)."""
    if not videos:
        raise EdgeError("no video given")
    if side_by_side_ids is not None:
        if not side_by_side:
            raise EdgeError("--side-by-side-ids needs --side-by-side")
        if len(side_by_side_ids) != 2 or not all(side_by_side_ids) or side_by_side_ids[0] == side_by_side_ids[1]:
            raise EdgeError("--side-by-side-ids takes two different names, LEFT,RIGHT")
        if len(videos) != 1:
            raise EdgeError("--side-by-side-ids names the two cameras of one video: give one video")
        for n in side_by_side_ids:
            _check_name(n)
    out_dir = Path(out).resolve()
    inputs = [(v, check_file(v).resolve()) for v in videos]
    for v, path in inputs:
        if _same_or_inside(out_dir, path):
            raise EdgeError(f"--out {out}: is the input {v} (or inside it)")
    if out_dir.exists() and not out_dir.is_dir():
        raise EdgeError(f"--out {out}: exists and is not a directory")
    jobs, names = [], {}
    for v, path in inputs:
        stem = path.stem
        if side_by_side:
            pairs = list(zip(side_by_side_ids or (f"{stem}_left", f"{stem}_right"), ("left", "right")))
        else:
            pairs = [(stem, None)]
        outputs = []
        for name, half in pairs:
            if name in names:
                raise EdgeError(f"two outputs would be named {name!r} ({names[name]} and {v}): rename a video")
            names[name] = v
            folder = out_dir / name
            if _same_or_inside(path, folder):
                raise EdgeError(f"the input {v} is inside its own output folder {folder}")
            outputs.append(CameraOutput(name=name, folder=folder, half=half))
        jobs.append(VideoJob(video=path, outputs=outputs))
    # An input inside any output folder is refused too (--force would clean that folder).
    for job in jobs:
        for other in jobs:
            for o in other.outputs:
                if _same_or_inside(job.video, o.folder):
                    raise EdgeError(f"the input {job.video} is inside the output folder {o.folder}")
    return jobs


def _check_name(name: str) -> None:
    if "/" in name or "\\" in name or name in (".", "..") or name.strip() != name:
        raise EdgeError(f"{name!r}: not a usable camera name")


def check_outputs(jobs: Sequence[VideoJob], force: bool) -> None:
    """Refuses existing non-empty output folders unless force; with force, removes the files a
    previous run wrote there (keypoint files and video.json; other files are left)."""
    busy = []
    for job in jobs:
        for o in job.outputs:
            if o.folder.exists():
                if not o.folder.is_dir():
                    raise EdgeError(f"{o.folder}: exists and is not a directory")
                if any(o.folder.iterdir()):
                    busy.append(o.folder)
    if busy and not force:
        raise EdgeError("output folder(s) not empty: " + ", ".join(str(b) for b in busy)
                        + " (use --force to replace their results)")
    for folder in busy:
        left = []
        for f in folder.iterdir():
            if f.is_file() and is_ours(f.name):
                f.unlink()
            else:
                left.append(f.name)
        if left:
            print(f"note: {folder}: kept {len(left)} file(s) that are not detection results", file=sys.stderr)


def probe(job: VideoJob) -> None:
    """Opens the video and decodes its first frame (so that undecodable inputs fail before any output)."""
    info = probe_file(job.video)
    job.width, job.height = info.width, info.height
    job.fps = info.fps
    job.frame_count = info.frame_count
    if job.outputs[0].half is not None and job.width < 2:
        raise EdgeError(f"{job.video}: {job.width} px wide, cannot split side by side")


def sidecar(job: VideoJob, o: CameraOutput, model: str) -> dict:
    info = {
        "source": job.video.name,
        "width": o.width,
        "height": o.height,
        "fps": job.fps,
        "frames": o.frames,
        "frames_with_person": o.with_person,
        "model": model,
        "ms_per_frame": round(o.ms_per_frame, 3),
    }
    if o.half is not None:
        info["side_by_side"] = o.half
        info["source_width"] = job.width
        info["x_offset_px"] = 0 if o.half == "left" else job.width // 2
    if job.interrupted:
        info["interrupted"] = True
    return info


def run_video(job: VideoJob, detector_factory: Callable, model: str, max_frames: Optional[int],
              stop: StopFlag, progress: bool = True) -> VideoJob:
    from tqdm import tqdm

    t0 = time.perf_counter()
    cap = open_capture(SourceSpec("file", str(job.video)))
    if cap is None:
        raise EdgeError(f"{job.video}: cannot open it as a video")
    detectors = []
    try:
        for o in job.outputs:
            o.folder.mkdir(parents=True, exist_ok=True)
            detectors.append(detector_factory())
        total = job.frame_count
        if max_frames is not None:
            total = min(total, max_frames) if total else max_frames
        bar = tqdm(total=total, desc=job.video.stem, unit="frame", file=sys.stderr,
                   disable=None if progress else True, leave=False)
        i = 0
        try:
            while max_frames is None or i < max_frames:
                if stop:
                    job.interrupted = True
                    break
                ok, frame = cap.read()
                if not ok or frame is None:
                    break
                if frame.shape[:2] != (job.height, job.width):
                    raise EdgeError(f"{job.video}: frame {i} is {frame.shape[1]}x{frame.shape[0]}, "
                                    f"the first was {job.width}x{job.height}")
                images = split_side_by_side(frame) if job.outputs[0].half else (frame,)
                for o, det, img in zip(job.outputs, detectors, images):
                    landmarks, ms = det.detect(img)
                    o.height, o.width = img.shape[:2]
                    write_keypoints(o.folder, o.name, i, landmarks)
                    o.frames += 1
                    o.with_person += landmarks is not None
                    o.inference_ms += ms
                i += 1
                bar.update(1)
        finally:
            bar.close()
            for o in job.outputs:
                if o.frames == 0:
                    o.height, o.width = (job.height, job.width // 2) if o.half else (job.height, job.width)
                write_sidecar(o.folder, sidecar(job, o, model))
    finally:
        for det in detectors:
            det.close()
        cap.release()
        job.wall_s = time.perf_counter() - t0
    return job


def summary_line(job: VideoJob, o: CameraOutput) -> str:
    pct = 100.0 * o.with_person / o.frames if o.frames else 0.0
    return (f"{o.name}: {o.frames} frames, {o.with_person} with a person ({pct:.1f} %), "
            f"{o.ms_per_frame:.1f} ms/frame inference, wall {job.wall_s:.1f} s -> {o.folder}")


def run_detect(videos: Sequence[str], out: str, force: bool = False, max_frames: Optional[int] = None,
               side_by_side: bool = False, side_by_side_ids: Optional[Sequence[str]] = None,
               detector_factory: Optional[Callable] = None, model: Optional[str] = None,
               stop: Optional[StopFlag] = None, progress: bool = True) -> List[VideoJob]:
    if max_frames is not None and max_frames < 1:
        raise EdgeError("--max-frames must be at least 1")
    jobs = plan_jobs(videos, out, side_by_side, side_by_side_ids)
    for job in jobs:
        probe(job)
    check_outputs(jobs, force)
    if detector_factory is None:
        from .pose import PoseDetector, model_description
        detector_factory = PoseDetector
        model = model or model_description()
    model = model or "unknown"
    stop = stop if stop is not None else StopFlag()
    done = []
    for job in jobs:
        if stop:
            break
        done.append(job)
        run_video(job, detector_factory, model, max_frames, stop, progress)
        if job.interrupted:
            break
    return done
