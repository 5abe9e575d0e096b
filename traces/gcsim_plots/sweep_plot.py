"""gcsim plot --sweep: simulated time, speedup and communication share against node count, with
the thesis's measured curve overlaid when the sweep reproduces one of its tables.

Node counts double from point to point, so every panel's node axis is log 2; the speedup panel is
log-log, where ideal (linear) speedup is a straight line and every series stays in the frame."""

import math

import numpy as np
from matplotlib.ticker import FixedLocator, NullLocator

from .style import DPI
from .sweep import describe_sweep, present, read_meta, read_sweep, series
from .thesis_tables import thesis_curve

# gcsim's series and the thesis's overlays in two families of colours, with their own markers, so
# that an overlay never looks like a second gcsim series (nor in greyscale).
GCSIM_COLORS = ("#1f77b4", "#2ca02c", "#9467bd", "#17becf")
THESIS_COLORS = ("#d62728", "#ff7f0e", "#8c564b", "#e377c2")
IDEAL_COLOR = "#777777"


def thesis_overlay(data, scene, broadcast, idx, suffix):
    """(label, nodes, time, speedup or None, comm or None) of the thesis's measurements: from the
    file's thesis_* columns, else from the copied tables; None when neither applies."""
    nodes = data["nodes"][idx]
    if "thesis_s" in data and not np.isnan(data["thesis_s"][idx]).all():
        t_time = data["thesis_s"][idx]
        t_speedup = present(data, "thesis_speedup", idx)
        if t_speedup is None:
            t_speedup = t_time[0] / t_time
        return (f"thesis measured{suffix}", nodes, t_time, t_speedup, present(data, "thesis_comm_s", idx))
    curve = thesis_curve(scene, broadcast)
    if not curve:
        return None
    tn = np.array(sorted(curve["time"]), dtype=float)
    t_time = np.array([curve["time"][n] for n in tn])
    t_speedup = np.array([curve["speedup"].get(n, math.nan) for n in tn]) if curve["speedup"] else None
    t_comm = np.array([curve["comm"].get(n, math.nan) for n in tn]) if curve["comm"] else None
    return (curve["label"], tn, t_time, t_speedup, t_comm)


def ideal_speedup(data, nodes):
    """Linear speedup through the sweep's first point: n / n0 times that point's speedup (1, or n0
    when the table scales its first point to one node, as gcsim sweep raytrace does)."""
    first = int(np.argmin(data["nodes"]))
    n0 = data["nodes"][first]
    s0 = data["speedup"][first] if "speedup" in data and not math.isnan(data["speedup"][first]) else 1.0
    return np.asarray(nodes, dtype=float) * (s0 / n0)


def frame_log2(ax, values, axis):
    """Log 2 limits holding every value with a margin, ticks at the powers of two between."""
    values = np.asarray([v for v in values if np.isfinite(v) and v > 0])
    # A margin, widened to the powers of two beyond the extremes, so that both ends have a labelled tick.
    lo = min(values.min(), 2.0 ** math.floor(math.log2(values.min()))) / 1.15
    hi = max(values.max(), 2.0 ** math.ceil(math.log2(values.max()))) * 1.15
    ticks = [2.0 ** k for k in range(math.floor(math.log2(lo)), math.ceil(math.log2(hi)) + 1) if lo <= 2.0 ** k <= hi]
    labels = [f"{t:g}" for t in ticks]
    if axis == "y":
        ax.set_yscale("log", base=2)
        ax.set_ylim(lo, hi)
        ax.yaxis.set_major_locator(FixedLocator(ticks))
        ax.set_yticklabels(labels)
        ax.yaxis.set_minor_locator(NullLocator())
    return lo, hi


def draw_sweep(plt, path, title=None):
    """The figure and the overlays' names (for the caller to save and report)."""
    data = read_sweep(path)
    what, machine = describe_sweep(read_meta(path), path)
    fig, (ax_time, ax_speedup, ax_comm) = plt.subplots(1, 3, figsize=(17, 5.8), dpi=DPI)
    overlays, speedups, all_nodes = [], [], set(data["nodes"].tolist())
    for k, ((scene, broadcast), idx) in enumerate(series(data)):
        color, t_color = GCSIM_COLORS[k % len(GCSIM_COLORS)], THESIS_COLORS[k % len(THESIS_COLORS)]
        nodes, sim, comm = data["nodes"][idx], data["simulated_s"][idx], data["comm_s"][idx]
        name = " ".join(v for v in (scene, broadcast) if v)
        suffix = f" ({name})" if name else ""
        label = f"gcsim simulated{suffix}"
        ax_time.plot(nodes, sim, "o-", color=color, label=label)
        if "wall_s" in data:
            ax_time.plot(nodes, data["wall_s"][idx], "x:", color=color, alpha=0.7, label=f"host wall-clock{suffix}")
        speedup = present(data, "speedup", idx)
        if speedup is None:
            speedup = sim[0] / sim  # relative to the smallest node count of the series
        ax_speedup.plot(nodes, speedup, "o-", color=color, label=label)
        speedups.extend(speedup.tolist())
        waiting = present(data, "waiting_s", idx)
        if waiting is None:  # a CSV without the split: all the time blocked in calls
            ax_comm.plot(nodes, 100.0 * comm / sim, "o-", color=color, label=f"{label}: blocked in calls")
        else:
            ax_comm.plot(nodes, 100.0 * (comm - waiting) / sim, "o-", color=color, label=f"communicating{suffix}")
            ax_comm.plot(nodes, 100.0 * waiting / sim, "v:", color=color, alpha=0.8, label=f"waiting for a peer{suffix}")
        thesis = thesis_overlay(data, scene, broadcast, idx, suffix)
        if not thesis:
            continue
        label_t, tn, t_time, t_speedup, t_comm = thesis
        overlays.append(label_t)
        all_nodes |= set(float(n) for n in tn)
        style = dict(color=t_color, marker="s", linestyle="--", markerfacecolor="white", label=label_t)
        ax_time.plot(tn, t_time, **style)
        if t_speedup is not None:
            ax_speedup.plot(tn, t_speedup, **style)
            speedups.extend(t_speedup.tolist())
        if t_comm is not None:
            ax_comm.plot(tn, 100.0 * t_comm / t_time, **{**style, "label": f"{label_t}: in communication calls"})

    all_nodes = sorted(all_nodes)
    ideal = ideal_speedup(data, all_nodes)
    ax_speedup.plot(all_nodes, ideal, color=IDEAL_COLOR, linewidth=0.9, linestyle="-.", label="ideal (linear)")
    frame_log2(ax_speedup, speedups + ideal.tolist(), "y")
    frame_axes(data, all_nodes, ax_time, ax_speedup, ax_comm)
    note = "overlaid: " + "; ".join(overlays) if overlays else "no thesis table matches (no overlay)"
    fig.suptitle(f"{title or what}\n{machine}\n{note}", fontsize=11)
    fig.tight_layout()
    return fig, note


def frame_axes(data, all_nodes, ax_time, ax_speedup, ax_comm):
    lo, hi = all_nodes[0] / 1.3, all_nodes[-1] * 1.3
    for ax in (ax_time, ax_speedup, ax_comm):
        ax.set_xscale("log", base=2)
        ax.set_xlim(lo, hi)
        ax.xaxis.set_major_locator(FixedLocator(all_nodes))
        ax.set_xticklabels([f"{int(n)}" for n in all_nodes])
        ax.xaxis.set_minor_locator(NullLocator())
        ax.set_xlabel("nodes (log 2)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    values = data["simulated_s"][~np.isnan(data["simulated_s"])]
    if values.size and values.max() / max(values.min(), 1e-12) > 30:
        ax_time.set_yscale("log")
    ax_time.set_ylabel("time (s)")
    ax_time.set_title("simulated time against node count")
    ax_speedup.set_ylabel("speedup (log 2)")
    ax_speedup.set_title("speedup, log-log: ideal is the straight line")
    ax_comm.set_ylim(0, 105)
    if "waiting_s" in data and not np.isnan(data["waiting_s"]).all():
        ax_comm.set_ylabel("share of the simulated time (%, mean per node)")
        ax_comm.set_title("communicating (bytes moving, links set up) and waiting\nfor a peer to send or ask "
                          "(docs/run-records.md)", fontsize=9)
    else:
        ax_comm.set_ylabel("time blocked in communication calls (%)")
        ax_comm.set_title("comm_s / simulated_s: includes waiting for a peer (this CSV has no\nwaiting_s column; "
                          "gcsim plot TRACE splits it: utilization.png)", fontsize=9)


def plot_sweep(plt, path, out_path, title=None):
    fig, note = draw_sweep(plt, path, title)
    print(note)
    fig.savefig(out_path)
    plt.close(fig)
