"""Plot 1: timeline of every processor (Gantt chart), activities in colour, message arrows."""

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from .binning import state_coverage
from .style import DPI, IDLE_COLOR, human_duration, MESSAGE_COLOR, STATE_COLORS, STATE_KINDS, STATE_LABELS
from .trace_data import KIND_CODE

# Above these counts the chart is drawn per pixel column, and arrows would hide the activities.
EXACT_INTERVALS_MAX = 20000
ARROWS_MAX = 250
PIXEL_COLUMNS = 1500


def row_labels(trace, procs):
    return [f"P{p} ({p % trace.mesh_width},{p // trace.mesh_width})" for p in procs]


def plot_gantt(plt, trace, window, title, path):
    procs = window.procs
    n = len(procs)
    height = min(12.0, max(3.4, 0.24 * n + 2.2))
    fig, ax = plt.subplots(figsize=(14, height), dpi=DPI)
    row_of = np.full(trace.processors, -1)
    row_of[procs] = np.arange(n)

    in_window = window.overlapping(trace)
    states = in_window & np.isin(trace.kind, [KIND_CODE[k] for k in STATE_KINDS])
    states &= (trace.proc >= 0) & (trace.proc < trace.processors)
    states &= window.selected[np.clip(trace.proc, 0, trace.processors - 1)]
    exact = states.sum() <= EXACT_INTERVALS_MAX
    threads = bool((states & (trace.thread > 0)).any())
    if exact:
        mode = "every interval drawn"
        if threads:
            mode += "; lower half of a row: threads the processor spawned (they run beside it)"
        ax.set_facecolor(IDLE_COLOR)
        # The processor's own intervals fill the row; its threads' intervals go on top, in the lower half.
        for kind, own in [(k, True) for k in STATE_KINDS] + [(k, False) for k in STATE_KINDS]:
            m = states & (trace.kind == KIND_CODE[kind]) & ((trace.thread == 0) if own else (trace.thread > 0))
            if not m.any():
                continue
            rows = row_of[trace.proc[m]]
            x0 = np.maximum(trace.start[m], window.t0)
            x1 = np.minimum(trace.end[m], window.t1)
            top = rows - 0.35 if own else rows + 0.02
            bottom = rows + 0.35
            verts = np.stack([np.column_stack((x0, top)), np.column_stack((x0, bottom)),
                              np.column_stack((x1, bottom)), np.column_stack((x1, top))], axis=1)
            ax.add_collection(PolyCollection(verts, facecolors=STATE_COLORS[kind], edgecolors=STATE_COLORS[kind],
                                             linewidths=0.3))  # hairline: sub-pixel intervals stay visible
    else:
        # One cell per processor and pixel column, coloured by the activity that filled most of it
        # (idle included), so that a million intervals cost one image.
        edges = np.linspace(window.t0, window.t1, PIXEL_COLUMNS + 1)
        cover = state_coverage(trace, window, edges)
        idle = (edges[1] - edges[0]) - cover.sum(axis=1, keepdims=True)
        dominant = np.concatenate((np.clip(idle, 0, None), cover), axis=1).argmax(axis=1)
        cmap = ListedColormap([IDLE_COLOR] + [STATE_COLORS[k] for k in STATE_KINDS])
        ax.imshow(dominant, cmap=cmap, vmin=-0.5, vmax=len(STATE_KINDS) + 0.5, aspect="auto", interpolation="nearest",
                  extent=(window.t0, window.t1, n - 0.5, -0.5))
        mode = f"each pixel column shows the activity that filled most of its {human_duration(edges[1] - edges[0])}"

    messages = in_window & (trace.kind == KIND_CODE["message"])
    messages &= (trace.proc >= 0) & (trace.proc < trace.processors) & (trace.peer >= 0) & (trace.peer < trace.processors)
    if messages.any():
        messages &= window.selected[np.clip(trace.proc, 0, trace.processors - 1)]
        messages &= window.selected[np.clip(trace.peer, 0, trace.processors - 1)]
    count = int(messages.sum())
    arrows = 0 < count <= ARROWS_MAX
    if arrows:
        for i in np.flatnonzero(messages):
            ax.annotate("", xy=(trace.end[i], row_of[trace.peer[i]]), xytext=(trace.start[i], row_of[trace.proc[i]]),
                        arrowprops=dict(arrowstyle="-|>", color=MESSAGE_COLOR, lw=0.7, alpha=0.75, shrinkA=0,
                                        shrinkB=0, mutation_scale=7))
    elif count:
        mode += f"; {count} message arrows left out (over {ARROWS_MAX}: narrow --from-ms/--to-ms or --procs)"

    ax.set_xlim(window.t0, window.t1)
    ax.set_ylim(n - 0.5, -0.5)
    step = max(1, int(np.ceil(n / 40)))
    ticks = np.arange(0, n, step)
    ax.set_yticks(ticks)
    ax.set_yticklabels([row_labels(trace, procs)[t] for t in ticks], fontsize=8 if n > 16 else 9)
    ax.set_xlabel("simulated time (ms)")
    ax.set_ylabel("processor (mesh x,y)")
    ax.set_title(f"{title}\nprocessor timeline, {window.describe()}, {n} of {trace.processors} processors\n{mode}",
                 fontsize=10)
    ax.grid(axis="x", color="white", linewidth=0.6, alpha=0.8)

    handles = [Patch(facecolor=STATE_COLORS[k], label=STATE_LABELS[k]) for k in STATE_KINDS]
    handles.append(Patch(facecolor=IDLE_COLOR, edgecolor="#bbbbbb", label="idle"))
    if arrows:
        handles.append(Line2D([0], [0], color=MESSAGE_COLOR, lw=1, marker=">", markersize=5, label="message (send \u2192 arrival)"))
    # The legend gets its own strip under the axis label, whatever the figure's height.
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False, fontsize=9)
    fig.tight_layout(rect=(0, 0.45 / height, 1, 1))
    fig.savefig(path)
    plt.close(fig)
