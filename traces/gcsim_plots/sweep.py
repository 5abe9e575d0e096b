"""gcsim plot --sweep: simulated time, speedup and communication share against node count, with
the thesis's measured curve overlaid when the sweep reproduces one of its tables.
Expected columns (traces/README.md): nodes, simulated_s, comm_s; optional speedup, wall_s,
thesis_s, thesis_speedup, thesis_comm_s, and scene / broadcast (or algo) naming a thesis table."""

import csv
import math
import os
import re

import numpy as np

from .errors import PlotError
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
    "wall_s": ("wall_s", "wall", "wall_time_s", "wall_seconds", "wall_total_s", "host_s"),
    "thesis_s": ("thesis_s", "thesis_time_s", "paper_s", "thesis", "measured_s"),
    "thesis_speedup": ("thesis_speedup", "paper_speedup", "measured_speedup"),
    "thesis_comm_s": ("thesis_comm_s", "paper_comm_s", "thesis_communication_s", "measured_comm_s"),
    "scene": ("scene",),
    "broadcast": ("broadcast", "bcast", "algo", "algorithm", "variant"),
}
REQUIRED = ("nodes", "simulated_s", "comm_s")


def normalise(name):
    return re.sub(r"[\s\-.]+", "_", name.strip().lower())


def number(text):
    text = (text or "").strip()
    if text in ("", "-", "nan", "NaN", "NA"):
        return math.nan
    return float(text)


def read_sweep(path):
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file (expected a sweep CSV from gcsim sweep radiosity|raytrace)")
    try:
        with open(path, newline="", encoding="utf-8", errors="replace") as f:
            rows = list(csv.reader(line for line in f if line.strip() and not line.startswith("#")))
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


def plot_sweep(plt, path, out_path, title=None):
    data = read_sweep(path)
    fig, (ax_time, ax_speedup, ax_comm) = plt.subplots(1, 3, figsize=(17, 5.4), dpi=DPI)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    overlays = []
    all_nodes = sorted(set(data["nodes"].tolist()))
    for k, ((scene, broadcast), idx) in enumerate(series(data)):
        color = colors[k % len(colors)]
        nodes = data["nodes"][idx]
        sim = data["simulated_s"][idx]
        comm = data["comm_s"][idx]
        name = " ".join(v for v in (scene, broadcast) if v)
        suffix = f" ({name})" if name else ""
        label = f"gcsim simulated{suffix}"
        ax_time.plot(nodes, sim, "o-", color=color, label=label)
        if "wall_s" in data:
            ax_time.plot(nodes, data["wall_s"][idx], "x:", color=color, alpha=0.7, label=f"host wall-clock{suffix}")
        if "speedup" in data and not np.isnan(data["speedup"][idx]).all():
            speedup = data["speedup"][idx]
        else:
            speedup = sim[0] / sim  # relative to the smallest node count of the series
        ax_speedup.plot(nodes, speedup, "o-", color=color, label=label)
        ax_comm.plot(nodes, 100.0 * comm / sim, "o-", color=color, label=label)

        # The thesis's measurements: from the file's thesis_* columns, else from its tables.
        thesis = None
        if "thesis_s" in data and not np.isnan(data["thesis_s"][idx]).all():
            t_time = data["thesis_s"][idx]
            t_speedup = present(data, "thesis_speedup", idx)
            if t_speedup is None:
                t_speedup = t_time[0] / t_time
            t_comm = present(data, "thesis_comm_s", idx)
            thesis = (f"thesis measured{suffix} (the file's thesis_* columns)", nodes, t_time, t_speedup, t_comm)
        else:
            curve = thesis_curve(scene, broadcast)
            if curve:
                tn = np.array(sorted(curve["time"]))
                t_time = np.array([curve["time"][n] for n in tn])
                t_speedup = np.array([curve["speedup"].get(n, math.nan) for n in tn]) if curve["speedup"] else None
                t_comm = np.array([curve["comm"].get(n, math.nan) for n in tn]) if curve["comm"] else None
                thesis = (curve["label"], tn, t_time, t_speedup, t_comm)
        if thesis:
            label_t, tn, t_time, t_speedup, t_comm = thesis
            overlays.append(label_t)
            all_nodes = sorted(set(all_nodes) | set(float(n) for n in tn))
            ax_time.plot(tn, t_time, "s--", color=color, alpha=0.55, label=label_t)
            if t_speedup is not None:
                ax_speedup.plot(tn, t_speedup, "s--", color=color, alpha=0.55, label=label_t)
            if t_comm is not None:
                ax_comm.plot(tn, 100.0 * t_comm / t_time, "s--", color=color, alpha=0.55, label=label_t)

    sweep_nodes = sorted(set(data["nodes"].tolist()))
    ideal = np.array(sweep_nodes) / sweep_nodes[0]
    top = ax_speedup.get_ylim()[1]
    ax_speedup.plot(sweep_nodes, ideal, color="#999999", linewidth=0.8, linestyle="-.", label="ideal (linear)")
    ax_speedup.set_ylim(0, max(top, 1.2))
    for ax in (ax_time, ax_speedup, ax_comm):
        ax.set_xscale("log", base=2)
        ax.set_xticks(all_nodes)
        ax.set_xticklabels([f"{int(n)}" for n in all_nodes])
        ax.set_xlabel("nodes")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    values = data["simulated_s"][~np.isnan(data["simulated_s"])]
    if values.size and values.max() / max(values.min(), 1e-12) > 30:
        ax_time.set_yscale("log")
    ax_time.set_ylabel("time (s)")
    ax_time.set_title("simulated time against node count")
    ax_speedup.set_ylabel("speedup (time on fewest nodes / time)")
    ax_speedup.set_title("speedup")
    ax_comm.set_ylabel("communication share of the time (%)")
    ax_comm.set_ylim(0, 105)
    ax_comm.set_title("communication share (comm_s / simulated_s)")
    note = "; overlaid: " + "; ".join(overlays) if overlays else "; no thesis table matches (no overlay)"
    fig.suptitle(f"{title or os.path.basename(path)}{note}", fontsize=11)
    print(note.lstrip("; "))
    fig.tight_layout()
    fig.savefig(out_path)
    plt.close(fig)
