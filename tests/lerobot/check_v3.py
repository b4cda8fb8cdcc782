#!/usr/bin/env python3
"""Checks a LeRobot dataset folder against format v3.0 as LeRobot 0.6.1 writes and reads it,
with pyarrow and the standard library only (no LeRobot, no numpy):

- the layout: meta/info.json, meta/stats.json, meta/tasks.parquet, meta/episodes/ and data/
  parquet files named chunk-XXX/file-YYY.parquet;
- info.json: exactly DatasetInfo's keys, codebase_version v3.0, the totals, splits;
- the data files: one column per feature, of the arrow type LeRobot's features give
  (shape (1,): the scalar; (n,): fixed_size_list<n>), `index` contiguous from 0,
  `frame_index` 0.. in each episode, `timestamp == frame_index / fps` (float32);
- the episodes table: `episode_index`, `length`, `dataset_from_index`/`dataset_to_index`
  contiguous, `data/chunk_index`/`data/file_index` naming the file that holds the episode's
  rows, `tasks` known, `meta/episodes/*` naming its own file;
- tasks.parquet: pandas' metadata making `task` the index, task_index 0..T-1, every frame's
  task_index the one of its episode's task;
- the statistics, recomputed from the data as compute_stats.py does them (per episode:
  RunningQuantileStats' min, max, mean, std, count and the quantiles from a 5000-bin
  histogram with numpy's float32 edges for float32 and bool features; for the dataset:
  min of minima, max of maxima, count-weighted mean, pooled std, count-weighted quantiles),
  equal to the episodes table's stats/<feature>/<stat> columns and to stats.json (min, max
  and count exactly; mean and std to 1e-5 of the feature's scale; quantiles to one bin).

Usage: check_v3.py DATASET_ROOT. Exit 0 and one line when every check passes, exit 1 listing
the failures.
"""

import bisect
import json
import math
import re
import struct
import sys
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

INFO_KEYS = {
    "codebase_version", "fps", "features", "total_episodes", "total_frames", "total_tasks",
    "chunks_size", "data_files_size_in_mb", "video_files_size_in_mb", "data_path",
    "video_path", "robot_type", "splits",
}
STAT_KEYS = ["min", "max", "mean", "std", "count", "q01", "q10", "q50", "q90", "q99"]
QUANTILES = [0.01, 0.10, 0.50, 0.90, 0.99]
BINS = 5000
ARROW_SCALARS = {"float32": pa.float32(), "int64": pa.int64(), "bool": pa.bool_()}
FILE_NAME = re.compile(r"chunk-(\d{3})/file-(\d{3})\.parquet$")


def f32(x):
    """x rounded to float32, as a Python float."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def arrow_type(ft):
    shape = list(ft["shape"])
    scalar = ARROW_SCALARS[ft["dtype"]]
    if shape == [1]:
        return scalar
    return pa.list_(scalar, shape[0])


def edges(lo, hi, single):
    """np.linspace(min - 1e-10, max + 1e-10, 5001) in the data's precision."""
    if single:
        start, stop = f32(lo - f32(1e-10)), f32(hi + f32(1e-10))
        step = f32((stop - start) / BINS)
        out = [f32(f32(i * step) + start) for i in range(BINS + 1)]
    else:
        start, stop = lo - 1e-10, hi + 1e-10
        step = (stop - start) / BINS
        out = [i * step + start for i in range(BINS + 1)]
    out[-1] = stop
    return out


def quantile(counts, e, target):
    """compute_stats._compute_single_quantile."""
    cumsum, total = [], 0.0
    for c in counts:
        total += c
        cumsum.append(total)
    idx = next((i for i, c in enumerate(cumsum) if c >= target), len(cumsum))
    if idx == 0:
        return e[0]
    if idx >= len(cumsum):
        return e[-1]
    before = cumsum[idx - 1]
    in_bin = cumsum[idx] - before
    if in_bin == 0:
        return e[idx]
    return e[idx] + (target - before) / in_bin * (e[idx + 1] - e[idx])


def column_stats(values, single):
    """get_feature_stats of one dimension of one episode; also the bin width."""
    n = len(values)
    lo, hi = min(values), max(values)
    mean = math.fsum(values) / n
    if n < 2:
        std = 0.0
        qs = [mean] * len(QUANTILES)
        return {"min": lo, "max": hi, "mean": mean, "std": std, "qs": qs, "bin": 0.0}
    std = math.sqrt(max(0.0, math.fsum(v * v for v in values) / n - mean * mean))
    e = edges(lo, hi, single)
    counts = [0.0] * BINS
    for v in values:
        at = bisect.bisect_right(e, v) - 1
        counts[min(max(at, 0), BINS - 1)] += 1
    qs = [quantile(counts, e, q * n) for q in QUANTILES]
    return {"min": lo, "max": hi, "mean": mean, "std": std, "qs": qs, "bin": e[1] - e[0]}


class Checker:
    def __init__(self, root):
        self.root = Path(root)
        self.failures = []

    def fail(self, what):
        self.failures.append(what)

    def expect(self, ok, what):
        if not ok:
            self.fail(what)
        return ok

    def close(self, got, want, tol, what):
        if not (isinstance(got, (int, float)) and abs(got - want) <= tol):
            self.fail(f"{what}: {got!r}, recomputed {want!r} (tolerance {tol:.3g})")

    def run(self):
        root = self.root
        for rel in ["meta/info.json", "meta/stats.json", "meta/tasks.parquet"]:
            if not (root / rel).is_file():
                self.fail(f"{rel}: missing")
        if self.failures:
            return
        info = json.loads((root / "meta/info.json").read_text(encoding="utf-8"))
        self.check_info(info)
        if self.failures:
            return
        fps = info["fps"]
        features = info["features"]
        tasks = self.check_tasks(info)
        data, files = self.read_data(features)
        if self.failures:
            return
        episodes = self.read_episodes(info)
        if self.failures:
            return
        self.check_frames(info, data, files, episodes, tasks, fps)
        if self.failures:
            return
        self.check_stats(features, data, episodes)

    def check_info(self, info):
        keys = set(info)
        self.expect(keys == INFO_KEYS, f"info.json keys: extra {sorted(keys - INFO_KEYS)}, "
                    f"missing {sorted(INFO_KEYS - keys)}")
        if self.failures:
            return
        self.expect(info["codebase_version"] == "v3.0", "info.json: codebase_version is not v3.0")
        self.expect(isinstance(info["fps"], int) and info["fps"] > 0, "info.json: fps")
        self.expect(info["splits"] == {"train": f"0:{info['total_episodes']}"}, "info.json: splits")
        self.expect(info["data_path"] ==
                    "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet", "info.json: data_path")
        for key in ["chunks_size", "data_files_size_in_mb", "video_files_size_in_mb"]:
            self.expect(isinstance(info[key], int) and info[key] > 0, f"info.json: {key}")
        for key in ["timestamp", "frame_index", "episode_index", "index", "task_index"]:
            self.expect(key in info["features"], f"info.json: no feature {key}")
        for key, ft in info["features"].items():
            ok = (ft.get("dtype") in ARROW_SCALARS and isinstance(ft.get("shape"), list)
                  and len(ft["shape"]) == 1 and ft["shape"][0] >= 1 and "names" in ft)
            if self.expect(ok, f"info.json: feature {key}: dtype/shape/names"):
                names = ft["names"]
                self.expect(names is None or len(names) == ft["shape"][0],
                            f"info.json: feature {key}: {len(names or [])} names for shape {ft['shape']}")

    def check_tasks(self, info):
        f = pq.ParquetFile(self.root / "meta/tasks.parquet")
        meta = f.schema_arrow.metadata or {}
        pandas = json.loads(meta.get(b"pandas", b"{}"))
        self.expect(pandas.get("index_columns") == ["task"], "tasks.parquet: pandas index is not 'task'")
        t = f.read()
        self.expect(t.schema.field("task_index").type == pa.int64(), "tasks.parquet: task_index type")
        self.expect(pa.types.is_string(t.schema.field("task").type) or
                    pa.types.is_large_string(t.schema.field("task").type), "tasks.parquet: task type")
        rows = t.to_pylist()
        self.expect([r["task_index"] for r in rows] == list(range(len(rows))), "tasks.parquet: task_index")
        self.expect(len(rows) == info["total_tasks"], "info.json: total_tasks")
        return {r["task"]: r["task_index"] for r in rows}

    def read_data(self, features):
        paths = sorted((self.root / "data").glob("*/*.parquet"))
        if not self.expect(paths, "data/: no parquet file"):
            return None, []
        columns = {key: [] for key in features}
        files = []
        for path in paths:
            rel = path.relative_to(self.root / "data").as_posix()
            m = FILE_NAME.match(rel)
            self.expect(m, f"data/{rel}: not chunk-XXX/file-YYY.parquet")
            schema = pq.read_schema(path)
            for key, ft in features.items():
                if not self.expect(key in schema.names, f"data/{rel}: no column {key}"):
                    continue
                got = schema.field(key).type
                self.expect(got == arrow_type(ft), f"data/{rel}: {key} is {got}, not {arrow_type(ft)}")
            extra = set(schema.names) - set(features)
            self.expect(not extra, f"data/{rel}: columns outside info.json's features: {sorted(extra)}")
            if self.failures:
                return None, []
            t = pq.read_table(path)
            start = len(columns["index"])
            for key in features:
                columns[key].extend(t.column(key).to_pylist())
            files.append(((int(m.group(1)), int(m.group(2))) if m else None, start, len(columns["index"])))
        return columns, files

    def read_episodes(self, info):
        paths = sorted((self.root / "meta/episodes").glob("*/*.parquet"))
        if not self.expect(paths, "meta/episodes/: no parquet file"):
            return []
        rows = []
        for path in paths:
            rel = path.relative_to(self.root / "meta/episodes").as_posix()
            m = FILE_NAME.match(rel)
            for row in pq.read_table(path).to_pylist():
                row["_file"] = (int(m.group(1)), int(m.group(2))) if m else None
                rows.append(row)
        self.expect(len(rows) == info["total_episodes"], "info.json: total_episodes")
        need = ["episode_index", "tasks", "length", "data/chunk_index", "data/file_index",
                "dataset_from_index", "dataset_to_index", "meta/episodes/chunk_index",
                "meta/episodes/file_index"]
        for key in need:
            self.expect(all(key in r for r in rows), f"episodes: no column {key}")
        return rows

    def check_frames(self, info, data, files, episodes, tasks, fps):
        n = len(data["index"])
        self.expect(n == info["total_frames"], f"info.json: total_frames {info['total_frames']}, data has {n}")
        self.expect(data["index"] == list(range(n)), "data: index is not 0, 1, 2, ... over the files")
        at = 0
        for e, ep in enumerate(episodes):
            name = f"episode {e}"
            self.expect(ep["episode_index"] == e, f"{name}: episode_index {ep['episode_index']}")
            lo, hi, length = ep["dataset_from_index"], ep["dataset_to_index"], ep["length"]
            self.expect(lo == at and hi == lo + length and length > 0,
                        f"{name}: from {lo} to {hi}, length {length}; expected from {at}")
            at = hi
            self.expect(ep["_file"] == (ep["meta/episodes/chunk_index"], ep["meta/episodes/file_index"]),
                        f"{name}: meta/episodes indices are not its file's")
            holder = [f for f in files if f[0] == (ep["data/chunk_index"], ep["data/file_index"])]
            self.expect(holder and holder[0][1] <= lo and hi <= holder[0][2],
                        f"{name}: data/chunk_index, data/file_index do not name the file with its rows")
            self.expect(len(ep["tasks"]) >= 1 and all(t in tasks for t in ep["tasks"]),
                        f"{name}: tasks {ep['tasks']} not in tasks.parquet")
            task_ids = {tasks.get(t) for t in ep["tasks"]}
            for k in range(lo, min(hi, n)):
                if data["episode_index"][k] != e or data["frame_index"][k] != k - lo:
                    self.fail(f"{name}: frame {k} has episode_index {data['episode_index'][k]}, "
                              f"frame_index {data['frame_index'][k]}")
                    break
                if data["task_index"][k] not in task_ids:
                    self.fail(f"{name}: frame {k}: task_index {data['task_index'][k]} is not its task's")
                    break
                want = f32((k - lo) / fps)
                if abs(data["timestamp"][k] - want) > 1e-6:
                    self.fail(f"{name}: frame {k}: timestamp {data['timestamp'][k]}, not frame_index / fps")
                    break
        self.expect(at == n, f"episodes cover {at} frames of {n}")

    def check_stats(self, features, data, episodes):
        stats = json.loads((self.root / "meta/stats.json").read_text(encoding="utf-8"))
        self.expect(set(stats) == set(features),
                    f"stats.json: features {sorted(set(stats) ^ set(features))} differ from info.json's")
        for key, ft in features.items():
            width = ft["shape"][0]
            single = ft["dtype"] in ("float32", "bool")
            rows = [v if isinstance(v, list) else [v] for v in data[key]]
            rows = [[float(x) for x in r] for r in rows]
            per_episode = []
            for e, ep in enumerate(episodes):
                part = rows[ep["dataset_from_index"]:ep["dataset_to_index"]]
                dims = [column_stats([r[d] for r in part], single) for d in range(width)]
                per_episode.append((len(part), dims))
                for stat in STAT_KEYS:
                    got = ep.get(f"stats/{key}/{stat}")
                    self.compare(f"episode {e}: stats/{key}/{stat}", stat, got, len(part), dims)
            total = sum(n for n, _ in per_episode)
            agg = []
            for d in range(width):
                mean = math.fsum(n * dims[d]["mean"] for n, dims in per_episode) / total
                var = math.fsum(n * (dims[d]["std"] ** 2 + (dims[d]["mean"] - mean) ** 2)
                                for n, dims in per_episode) / total
                agg.append({
                    "min": min(dims[d]["min"] for _, dims in per_episode),
                    "max": max(dims[d]["max"] for _, dims in per_episode),
                    "mean": mean,
                    "std": math.sqrt(var),
                    "qs": [math.fsum(n * dims[d]["qs"][i] for n, dims in per_episode) / total
                           for i in range(len(QUANTILES))],
                    "bin": max(dims[d]["bin"] for _, dims in per_episode),
                })
            got = stats.get(key, {})
            self.expect(list(got) == STAT_KEYS or set(got) == set(STAT_KEYS),
                        f"stats.json: {key}: keys {sorted(got)}")
            for stat in STAT_KEYS:
                self.compare(f"stats.json: {key}/{stat}", stat, got.get(stat), total, agg)

    def compare(self, what, stat, got, count, dims):
        if stat == "count":
            self.expect(got == [count], f"{what}: {got}, expected [{count}]")
            return
        if not self.expect(isinstance(got, list) and len(got) == len(dims),
                           f"{what}: {got!r} is not a list of {len(dims)}"):
            return
        for d, (g, s) in enumerate(zip(got, dims)):
            scale = max(abs(s["min"]), abs(s["max"]), 1e-3)
            if stat in ("min", "max"):
                self.close(g, s[stat], 0.0, f"{what}[{d}]")
            elif stat in ("mean", "std"):
                self.close(g, s[stat], 1e-5 * scale, f"{what}[{d}]")
            else:
                i = STAT_KEYS.index(stat) - 5
                self.close(g, s["qs"][i], s["bin"] * 1.001 + 1e-9 * scale, f"{what}[{d}]")


def main(argv):
    if len(argv) != 2:
        print("usage: check_v3.py DATASET_ROOT", file=sys.stderr)
        return 2
    checker = Checker(argv[1])
    try:
        checker.run()
    except Exception as e:  # an unreadable file is a failure, named
        checker.fail(f"{type(e).__name__}: {e}")
    if checker.failures:
        print(f"check_v3: {argv[1]}: {len(checker.failures)} failure(s)", file=sys.stderr)
        for f in checker.failures[:40]:
            print(f"  {f}", file=sys.stderr)
        return 1
    info = json.loads((Path(argv[1]) / "meta/info.json").read_text(encoding="utf-8"))
    print(f"check_v3: {argv[1]}: LeRobot v3.0 layout, types, offsets, tasks and statistics ok: "
          f"{info['total_episodes']} episodes, {info['total_frames']} frames at {info['fps']} fps, "
          f"{info['total_tasks']} tasks, {len(info['features'])} features")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
