"""Plot 4: share of processor time spent in each activity, over time (stacked, idle on top)."""

import numpy as np
from matplotlib.patches import Patch

from .binning import state_coverage
from .style import DPI, IDLE_COLOR, human_duration, STATE_COLORS, STATE_KINDS, STATE_LABELS

BINS = 300


def plot_utilization(plt, trace, window, title, path):
    edges = np.linspace(window.t0, window.t1, BINS + 1)
    width = edges[1] - edges[0]
    cover = state_coverage(trace, window, edges).sum(axis=0)  # [activity, bin]
    share = 100.0 * cover / (width * len(window.procs))
    share = np.minimum(share, 100.0)  # threads on one node may overlap their processor's intervals
    centers = 0.5 * (edges[:-1] + edges[1:])
    fig, ax = plt.subplots(figsize=(14, 5), dpi=DPI)
    ax.set_facecolor(IDLE_COLOR)
    ax.stackplot(centers, share, colors=[STATE_COLORS[k] for k in STATE_KINDS], linewidth=0, step=None)
    busy = share.sum(axis=0)
    ax.plot(centers, busy, color="#333333", linewidth=0.8)
    ax.set_xlim(window.t0, window.t1)
    ax.set_ylim(0, 100)
    ax.set_xlabel("simulated time (ms)")
    ax.set_ylabel("share of processor time (%)")
    mean = cover.sum(axis=1) / (window.length * len(window.procs)) * 100.0
    summary = ", ".join(f"{STATE_LABELS[k].split(' ')[0]} {m:.1f}%" for k, m in zip(STATE_KINDS, mean))
    ax.set_title(f"{title}\nutilization of {len(window.procs)} processors, {window.describe()}, bins of "
                 f"{human_duration(width)}; mean: {summary}", fontsize=10)
    handles = [Patch(facecolor=STATE_COLORS[k], label=STATE_LABELS[k]) for k in STATE_KINDS]
    handles.append(Patch(facecolor=IDLE_COLOR, edgecolor="#bbbbbb", label="idle"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False, fontsize=9)
    ax.grid(color="white", linewidth=0.6, alpha=0.7)
    fig.tight_layout(rect=(0, 0.45 / 5.0, 1, 1))
    fig.savefig(path)
    plt.close(fig)
