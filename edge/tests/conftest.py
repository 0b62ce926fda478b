import sys
from pathlib import Path

import pytest

EDGE = Path(__file__).resolve().parents[1]
REPO = EDGE.parent
# The demo videos live beside the repository: /work/main -> /work/shared/data/...
DATA = REPO.parent / "shared" / "data" / "pose2sim-demo-videos"

sys.path.insert(0, str(Path(__file__).resolve().parent))


def demo_video(name="cam03.mp4", folder="videos"):
    path = DATA / folder / name
    if not path.is_file():
        pytest.skip(f"demo data not present: {path}")
    return path


@pytest.fixture
def repo():
    return REPO
