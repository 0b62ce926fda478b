"""The `ergocell-edge` command: `detect` (offline, JSON files) and `publish` (live, ROS 2)."""

from __future__ import annotations

import argparse
import logging
import signal
import sys
from typing import List, Optional

from . import EdgeError, __version__
from .stop import StopFlag

EXIT_USER_ERROR = 2


def _positive_int(s: str) -> int:
    try:
        v = int(s)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: {s!r}") from None
    if v < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {v}")
    return v


def _complexity(s: str) -> int:
    try:
        return int(s)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: {s!r}") from None


def _two_ids(s: str) -> List[str]:
    parts = [p.strip() for p in s.split(",")]
    if len(parts) != 2 or not all(parts):
        raise argparse.ArgumentTypeError(f"expected LEFT,RIGHT, got {s!r}")
    return parts


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="ergocell-edge",
        description="ergocell's edge camera node: MediaPipe BlazePose-33 body landmarks from video.")
    p.add_argument("--version", action="version", version=f"ergocell-edge {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="{detect,publish}")

    d = sub.add_parser(
        "detect", help="offline: videos to OpenPose-layout JSON files, one folder per video",
        description="Runs the detector on every frame of each video and writes DIR/<stem>/<stem>_<frame, "
                    "12 digits>_keypoints.json (OpenPose layout, 33 BlazePose points in pixels, c = "
                    "visibility; \"people\": [] when nobody is found) and DIR/<stem>/video.json.")
    d.add_argument("videos", nargs="+", metavar="VIDEO")
    d.add_argument("--out", required=True, metavar="DIR", help="output directory (one folder per camera in it)")
    d.add_argument("--force", action="store_true",
                   help="replace the results in existing non-empty output folders")
    d.add_argument("--max-frames", type=_positive_int, metavar="N", help="only the first N frames of each video")
    d.add_argument("--side-by-side", action="store_true",
                   help="each video is a stereo camera's side-by-side frames: the left and right halves are "
                        "two cameras, written to <stem>_left and <stem>_right")
    d.add_argument("--side-by-side-ids", type=_two_ids, metavar="LEFT,RIGHT",
                   help="with --side-by-side and one video: the two cameras' names (folders and file prefixes)")
    d.add_argument("--model-complexity", type=_complexity, default=1, metavar="1",
                   help="MediaPipe pose model: only 1 (full, bundled in the wheel) is supported")
    d.add_argument("--no-progress", action="store_true", help="no progress bar")
    d.add_argument("--verbose", action="store_true", help="show MediaPipe's native start-up log lines")

    u = sub.add_parser(
        "publish", help="live: frames to ergocell_msgs/msg/CameraLandmarks over ROS 2",
        description="Publishes one CameraLandmarks message per frame on the cell's [ros] camera_topic "
                    "(domain [ros] domain_id; QoS best effort, keep last 5). Needs rclpy and ergocell_msgs "
                    "(not pip dependencies; see README.md).")
    u.add_argument("--camera", required=True, metavar="ID", help="camera id (must be in the rig)")
    u.add_argument("--source", required=True, metavar="SRC",
                   help="a video file, /dev/videoN or N (a camera device), or a GStreamer pipeline (with '!')")
    u.add_argument("--right-camera", metavar="ID",
                   help="the source is a side-by-side stereo camera: its left half is --camera, its right "
                        "half this camera (both published, same stamp)")
    u.add_argument("--rig", metavar="FILE",
                   help="ergocell rig TOML ([[camera]] id) or Qualisys .qca.txt (camera serial); default: "
                        "config/rig.toml in the current directory or a parent")
    u.add_argument("--cell", metavar="FILE",
                   help="cell TOML with the [ros] section; default: config/cell.toml in the current "
                        "directory or a parent")
    u.add_argument("--max-frames", type=_positive_int, metavar="N",
                   help="stop after N source frames (file: frames consumed, dropped ones included)")
    u.add_argument("--loop", action="store_true", help="file source: play it again at its end")
    u.add_argument("--realtime", action=argparse.BooleanOptionalAction, default=True,
                   help="file source: pace at the file's fps, stamps start + index/fps, late frames "
                        "dropped (default); --no-realtime: as fast as possible, stamped when read")
    u.add_argument("--fps", type=float, metavar="HZ", help="the file's frame rate when it does not say it")
    u.add_argument("--start-at", type=float, metavar="UNIX_S",
                   help="file source, realtime: start playback at this wall time (seconds since the epoch), "
                        "so that several nodes playing a multi-camera recording share one time base")
    u.add_argument("--wait-for-subscriber", type=float, default=0.0, metavar="S",
                   help="wait up to S seconds for a subscriber before the first frame")
    u.add_argument("--stats-every", type=float, default=10.0, metavar="S",
                   help="log counts every S seconds (0: only at the end)")
    u.add_argument("--model-complexity", type=_complexity, default=1, metavar="1",
                   help="MediaPipe pose model: only 1 (full, bundled in the wheel) is supported")
    u.add_argument("--verbose", action="store_true", help="debug logging and MediaPipe's native log lines")
    return p


def _detect(args, stop: StopFlag) -> int:
    from .detect import run_detect, summary_line
    from .pose import check_complexity
    check_complexity(args.model_complexity)
    detector_factory = None
    if args.verbose:
        from .pose import PoseDetector
        detector_factory = lambda: PoseDetector(quiet=False)  # noqa: E731
    jobs = run_detect(args.videos, args.out, force=args.force, max_frames=args.max_frames,
                      side_by_side=args.side_by_side, side_by_side_ids=args.side_by_side_ids,
                      detector_factory=detector_factory, stop=stop, progress=not args.no_progress)
    for job in jobs:
        for o in job.outputs:
            print(summary_line(job, o), flush=True)
    if stop:
        written = sum(o.frames for j in jobs for o in j.outputs)
        where = ", ".join(f"{o.name}: {o.frames}" for j in jobs for o in j.outputs)
        print(f"ergocell-edge: stopped by {stop.signal_name}: {written} frame file(s) written ({where}); "
              "the last folder is incomplete (its video.json says \"interrupted\": true)", file=sys.stderr)
        return 128 + (signal.SIGTERM if stop.signal_name == "SIGTERM" else signal.SIGINT)
    return 0


def _publish(args, stop: StopFlag) -> int:
    from .publish import PublishOptions, run_publish
    opts = PublishOptions(
        camera=args.camera, source=args.source, right_camera=args.right_camera, rig=args.rig,
        cell=args.cell, max_frames=args.max_frames, loop=args.loop, realtime=args.realtime, fps=args.fps,
        start_at=args.start_at, wait_for_subscriber=args.wait_for_subscriber, stats_every_s=args.stats_every,
        model_complexity=args.model_complexity, verbose=args.verbose)
    if args.model_complexity != 1:
        from .pose import check_complexity
        check_complexity(args.model_complexity)
    run_publish(opts, stop)
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    args = build_parser().parse_args(argv)
    logging.basicConfig(level=logging.DEBUG if getattr(args, "verbose", False) else logging.INFO,
                        format="%(asctime)s ergocell-edge: %(message)s", stream=sys.stderr)
    stop = StopFlag().install()
    try:
        if args.command == "detect":
            return _detect(args, stop)
        return _publish(args, stop)
    except EdgeError as e:
        print(f"ergocell-edge: error: {e}", file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        print("ergocell-edge: interrupted", file=sys.stderr)
        return 130
    finally:
        stop.restore()


if __name__ == "__main__":
    sys.exit(main())
