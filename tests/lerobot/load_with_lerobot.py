#!/usr/bin/env python3
"""Loads a dataset folder with LeRobot itself, offline, and reads every frame:
`LeRobotDataset(repo_id, root=DATASET_ROOT)`, then each item of it, checking what LeRobot
hands a training loop (the task string, the shapes, the per-episode frame order). Prints the
totals, the features and one frame. Usage: load_with_lerobot.py DATASET_ROOT [REPO_ID].
Run by `make check-lerobot` in a venv with `lerobot[dataset]`.
"""

import logging
import os
import sys

os.environ.setdefault("HF_HUB_OFFLINE", "1")
os.environ.setdefault("HF_DATASETS_OFFLINE", "1")
# Without FFmpeg's shared libraries LeRobot warns at import, at length, that torchcodec (its
# video decoder) cannot load: this dataset has no video.
logging.getLogger("lerobot.utils.import_utils").setLevel(logging.ERROR)

import lerobot  # noqa: E402
import torch  # noqa: E402
from lerobot.datasets.lerobot_dataset import LeRobotDataset  # noqa: E402


def main(argv):
    root = argv[1]
    repo_id = argv[2] if len(argv) > 2 else "bsv/so101-practice"
    ds = LeRobotDataset(repo_id=repo_id, root=root)
    meta = ds.meta
    print(f"lerobot {lerobot.__version__}, torch {torch.__version__}")
    info = meta.info  # a dict before LeRobot 0.5, a DatasetInfo after
    version = info["codebase_version"] if isinstance(info, dict) else info.codebase_version
    print(f"{repo_id} at {root}: codebase {version}, robot {meta.robot_type}, "
          f"{meta.fps} fps")
    print(f"episodes {ds.num_episodes}, frames {ds.num_frames}, tasks {meta.total_tasks}: "
          f"{list(meta.tasks.index)}")
    for key, ft in meta.features.items():
        print(f"  {key}: {ft['dtype']} {tuple(ft['shape'])} {ft['names']}")
    seen = 0
    last = {}
    for i in range(len(ds)):
        item = ds[i]
        e = int(item["episode_index"])
        k = int(item["frame_index"])
        assert k == last.get(e, -1) + 1, f"frame {i}: episode {e} frame {k} after {last.get(e)}"
        last[e] = k
        assert int(item["index"]) == i, f"frame {i}: index {int(item['index'])}"
        for key in ("observation.state", "action", "observation.environment_state"):
            assert tuple(item[key].shape) == (6,), f"frame {i}: {key} shape {tuple(item[key].shape)}"
            assert item[key].dtype == torch.float32, f"frame {i}: {key} {item[key].dtype}"
        assert isinstance(item["task"], str) and item["task"], f"frame {i}: task {item['task']!r}"
        seen += 1
    assert seen == ds.num_frames == meta.total_frames
    lengths = [last[e] + 1 for e in sorted(last)]
    print(f"read every frame: {seen} (episode lengths {lengths})")
    stats = meta.stats
    print("stats: " + ", ".join(f"{k} mean {[round(float(x), 3) for x in stats[k]['mean']]}"
                                for k in ("observation.state",)))
    item = ds[lengths[0] - 1]
    print("last frame of episode 0:")
    for key, value in item.items():
        if isinstance(value, torch.Tensor):
            value = [round(float(x), 4) for x in value.flatten()] if value.numel() > 1 else value.item()
        print(f"  {key}: {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
