"""Plot 4: share of processor time busy, communicating and waiting, over time (stacked, idle on
top). The means in the title come from the same bins as the plot, so with idle they add up to 100 %."""

import numpy as np
from matplotlib.patches import Patch

from .activity_split import SHARES, mean_shares, share_coverage
from .style import DPI, IDLE_COLOR, human_duration, SHARE_COLORS, SHARE_LABELS

BINS = 300


def utilization_shares(trace, window, bins=BINS):
    """(bin edges in ms, percent [share, bin], mean percent per share, mean idle percent)."""
    edges = np.linspace(window.t0, window.t1, bins + 1)
    cover = share_coverage(trace, window, edges)  # [processor, share, bin], at most the bin per processor
    share = 100.0 * cover.sum(axis=0) / (np.diff(edges) * len(window.procs))
    means, idle = mean_shares(cover, edges)
    return edges, share, means, idle


def summary_text(means, idle):
    parts = [f"{name} {m:.1f}%" for name, m in zip(SHARES, means)] + [f"idle {idle:.1f}%"]
    return ", ".join(parts)


def plot_utilization(plt, trace, window, title, path):
    edges, share, means, idle = utilization_shares(trace, window)
    factor, unit = window.unit()
    centers = 0.5 * (edges[:-1] + edges[1:]) * factor
    fig, ax = plt.subplots(figsize=(14, 5.2), dpi=DPI)
    ax.set_facecolor(IDLE_COLOR)
    ax.stackplot(centers, share, colors=[SHARE_COLORS[k] for k in SHARES], linewidth=0)
    ax.set_xlim(window.t0 * factor, window.t1 * factor)
    ax.set_ylim(0, 100)
    ax.set_xlabel(f"simulated time ({unit})")
    ax.set_ylabel("share of processor time (%)")
    ax.set_title(f"{title}\nutilization, {window.describe()}, bins of "
                 f"{human_duration(edges[1] - edges[0])}; mean: {summary_text(means, idle)}", fontsize=10)
    handles = [Patch(facecolor=SHARE_COLORS[k], label=SHARE_LABELS[k]) for k in SHARES]
    handles.append(Patch(facecolor=IDLE_COLOR, edgecolor="#bbbbbb", label="idle"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False, fontsize=9)
    ax.grid(color="white", linewidth=0.6, alpha=0.7)
    fig.tight_layout(rect=(0, 0.45 / 5.2, 1, 1))
    fig.savefig(path)
    plt.close(fig)
    return means, idle
