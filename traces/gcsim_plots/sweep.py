"""gcsim plot --sweep: simulated time, speedup and communication share against node count, with
the thesis's measured curve overlaid when the sweep reproduces one of its tables.
Expected columns (traces/README.md): nodes, simulated_s, comm_s; optional speedup, wall_s,
thesis_s, thesis_speedup, thesis_comm_s, and scene / broadcast (or algo) naming a thesis table."""

import csv
import math
import os
import re

import numpy as np

from .errors import PlotError, checked_csv_rows, reads_file
from .style import DPI
from .thesis_tables import thesis_curve

# Canonical column -> accepted spellings (compared after lower-casing and turning spaces,
# dashes and dots into underscores).
SYNONYMS = {
    "nodes": ("nodes", "node", "n", "processors", "procs", "node_count", "n_nodes", "num_nodes"),
    "simulated_s": ("simulated_s", "simulated", "sim_s", "simulated_time_s", "simulated_seconds", "time_s",
                    "simulated_total_s", "total_s"),
    "speedup": ("speedup", "speed_up", "simulated_speedup"),
    "comm_s": ("comm_s", "communication_s", "comm", "comm_time_s", "communication", "simulated_comm_s",
               "communication_time_s", "comm_s_mean", "mean_comm_s"),
    # Of comm_s, the time blocked before the peer sent or asked (docs/run-records.md); gcsim sweep writes it.
    "waiting_s": ("waiting_s", "waiting_s_mean", "waiting", "wait_s"),
    "wall_s": ("wall_s", "wall", "wall_time_s", "wall_seconds", "wall_total_s", "host_s"),
    "thesis_s": ("thesis_s", "thesis_time_s", "paper_s", "thesis", "measured_s"),
    "thesis_speedup": ("thesis_speedup", "paper_speedup", "measured_speedup"),
    "thesis_comm_s": ("thesis_comm_s", "paper_comm_s", "thesis_communication_s", "measured_comm_s"),
    "scene": ("scene",),
    # One series per value; gcsim sweep mpi's "machine" (calibrated, published) is such a variant.
    "broadcast": ("broadcast", "bcast", "algo", "algorithm", "variant", "machine"),
}
REQUIRED = ("nodes", "simulated_s", "comm_s")


def normalise(name):
    return re.sub(r"[\s\-.]+", "_", name.strip().lower())


def number(text):
    text = (text or "").strip()
    if text in ("", "-", "nan", "NaN", "NA"):
        return math.nan
    value = float(text)
    if not math.isfinite(value) or abs(value) > 1e100:  # a plot axis cannot hold it
        raise ValueError(f"{text!r} is not a finite number of plausible size")
    return value


@reads_file("sweep CSV")
def read_sweep(path):
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file (expected a sweep CSV from gcsim sweep radiosity|raytrace)")
    try:
        with open(path, newline="", encoding="utf-8", errors="replace") as f:
            rows = checked_csv_rows(path, (line for line in f if line.strip() and not line.startswith("#")))
    except OSError as e:
        raise PlotError(f"{path}: cannot read: {e.strerror}")
    if not rows:
        raise PlotError(f"{path}: empty; expected a CSV with a header line and one row per node count")
    header = [normalise(h) for h in rows[0]]
    where = {}
    for canonical, spellings in SYNONYMS.items():
        for s in spellings:
            if s in header:
                where[canonical] = header.index(s)
                break
    missing = [c for c in REQUIRED if c not in where]
    if missing:
        raise PlotError(f"{path}: missing column{'s' if len(missing) > 1 else ''} {', '.join(missing)} "
                        f"(found: {', '.join(rows[0])}; expected at least {', '.join(REQUIRED)}, "
                        "optionally speedup, wall_s, thesis_s, thesis_speedup, thesis_comm_s, scene, broadcast)")
    body = rows[1:]
    if not body:
        raise PlotError(f"{path}: has a header but no rows")
    data = {}
    for canonical, i in where.items():
        column = [r[i] if i < len(r) else "" for r in body]
        if canonical in ("scene", "broadcast"):
            data[canonical] = column
            continue
        try:
            data[canonical] = np.array([number(v) for v in column])
        except ValueError:
            bad = next(v for v in column if not _is_number(v))
            raise PlotError(f"{path}: column {rows[0][i]!r} should hold numbers, found {bad!r}")
    if np.isnan(data["nodes"]).any() or (data["nodes"] <= 0).any():
        raise PlotError(f"{path}: column {rows[0][where['nodes']]!r} should hold positive node counts")
    return data


def _is_number(v):
    try:
        number(v)
        return True
    except ValueError:
        return False


def present(data, column, idx):
    """The column's values for these rows, or None when the file lacks it or leaves it empty."""
    if column not in data or np.isnan(data[column][idx]).all():
        return None
    return data[column][idx]


def series(data):
    """One series per (scene, broadcast) found in the file, each sorted by node count."""
    n = len(data["nodes"])
    keys = list(zip(data.get("scene", [""] * n), data.get("broadcast", [""] * n)))
    out = []
    for key in dict.fromkeys(keys):
        idx = [i for i in range(n) if keys[i] == key]
        idx.sort(key=lambda i: data["nodes"][i])
        out.append((key, np.array(idx)))
    return out




def read_meta(path):
    """What the sweep ran, from its comment rows: '# gcsim sweep APP; scene S; machine M; model X'
    gives {'app': APP, 'scene': S, 'machine': M, 'model': X}. CSVs written before these rows (or by
    hand) give {}."""
    meta = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            comments = [line[1:].strip() for line in f if line.startswith("#")]
    except OSError:
        return meta
    for line in comments:
        parts = [p.strip() for p in line.split(";")]
        if not parts[0].startswith("gcsim sweep"):
            continue
        meta["app"] = parts[0][len("gcsim sweep"):].strip()
        for part in parts[1:]:
            key, _, value = part.partition(" ")
            if key and value:
                meta[key] = value.strip()
    return meta


def describe_sweep(meta, path):
    """The figure's title and machine line, from the comment rows (or the file's name)."""
    what = " ".join(v for v in (meta.get("app"), "sweep") if v)
    if meta.get("scene"):
        what += f", scene {meta['scene']}"
    if not meta.get("app"):
        what = f"{os.path.basename(path)}: node-count sweep"
    if meta.get("machine"):
        machine = f"{meta['machine']}; network model {meta.get('model', 'not recorded')}"
    else:
        machine = "machine and network model not recorded in this CSV (written before gcsim sweep named them)"
    return what, machine
