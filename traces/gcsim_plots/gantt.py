"""Plot 1: timeline of every processor (Gantt chart), activities in colour, message arrows.

A window with few intervals is drawn interval by interval. One with many short intervals (a long
run: every interval narrower than a pixel) would be a barcode, so it is drawn as density, one cell
per processor and pixel column, with a second panel that zooms into a representative window where
every interval is drawn again."""

import copy

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from .binning import state_coverage
from .style import DPI, IDLE_COLOR, human_duration, MESSAGE_COLOR, STATE_COLORS, STATE_KINDS, STATE_LABELS
from .trace_data import KIND_CODE

# Above these counts the chart is drawn as density, and arrows would hide the activities.
EXACT_INTERVALS_MAX = 20000
ARROWS_MAX = 250
PIXEL_COLUMNS = 1500
ZOOM_INTERVALS = 800  # about how many intervals the zoomed panel shows
DENSITY_BINS = 400


def row_labels(trace, procs):
    return [f"P{p} ({trace.node_xy(p)[0]},{trace.node_xy(p)[1]})" for p in procs]


def state_mask(trace, window):
    """Processor intervals of the selected processors that meet the window."""
    states = window.overlapping(trace) & np.isin(trace.kind, [KIND_CODE[k] for k in STATE_KINDS])
    states &= (trace.proc >= 0) & (trace.proc < trace.processors)
    states &= window.selected[np.clip(trace.proc, 0, trace.processors - 1)]
    return states


def needs_density(trace, window, states):
    """Too many intervals to draw, or so many of them narrower than a pixel that they make a barcode."""
    count = int(states.sum())
    if count > EXACT_INTERVALS_MAX:
        return True
    if count < 2000:
        return False
    pixel = window.length / PIXEL_COLUMNS
    return float(np.median(trace.end[states] - trace.start[states])) < pixel


def zoom_window(trace, window, states):
    """A representative window: about ZOOM_INTERVALS intervals wide, centred on the median start of
    the intervals (the middle of the run's activity), inside the shown window."""
    count = max(1, int(states.sum()))
    width = window.length * min(0.1, ZOOM_INTERVALS / count)
    middle = float(np.median(trace.start[states]))
    t0 = min(max(window.t0, middle - width / 2), window.t1 - width)
    zoom = copy.copy(window)
    zoom.t0, zoom.t1 = t0, t0 + width
    return zoom


def draw_exact(ax, trace, window, states, row_of, factor):
    """Every interval a rectangle; the threads a processor spawned in the lower half of its row."""
    ax.set_facecolor(IDLE_COLOR)
    states = states & window.overlapping(trace)
    for kind, own in [(k, True) for k in STATE_KINDS] + [(k, False) for k in STATE_KINDS]:
        m = states & (trace.kind == KIND_CODE[kind]) & ((trace.thread == 0) if own else (trace.thread > 0))
        if not m.any():
            continue
        rows = row_of[trace.proc[m]]
        x0 = np.maximum(trace.start[m], window.t0) * factor
        x1 = np.minimum(trace.end[m], window.t1) * factor
        top = rows - 0.35 if own else rows + 0.02
        bottom = rows + 0.35
        verts = np.stack([np.column_stack((x0, top)), np.column_stack((x0, bottom)),
                          np.column_stack((x1, bottom)), np.column_stack((x1, top))], axis=1)
        ax.add_collection(PolyCollection(verts, facecolors=STATE_COLORS[kind], edgecolors=STATE_COLORS[kind],
                                         linewidths=0.3))  # hairline: sub-pixel intervals stay visible


def draw_density(ax, trace, window, n, factor):
    """Per processor row, the share of each activity in each of DENSITY_BINS columns, stacked in
    the row's band (compute at the bottom, idle the rest): what a barcode of short events averages to."""
    edges = np.linspace(window.t0, window.t1, DENSITY_BINS + 1)
    width = edges[1] - edges[0]
    cover = state_coverage(trace, window, edges) / width  # [row, kind, column], fractions
    # Threads may overlap their processor's intervals: keep each column's stack within the band.
    stacked = np.minimum(np.cumsum(cover, axis=1), 1.0)
    x = np.repeat(edges, 2)[1:-1] * factor  # steps: each column flat over its width
    ax.set_facecolor("white")
    for r in range(n):
        base = r + 0.4  # the band's bottom (rows grow downwards)
        below = np.zeros(DENSITY_BINS)
        ax.fill_between(x, base, base - 0.8, color=IDLE_COLOR, linewidth=0)
        for k, kind in enumerate(STATE_KINDS):
            top = stacked[r, k]
            if (top > below).any():
                ax.fill_between(x, base - 0.8 * np.repeat(below, 2), base - 0.8 * np.repeat(top, 2),
                                color=STATE_COLORS[kind], linewidth=0)
            below = top
    return width


def _rgb(hex_color):
    return np.array([int(hex_color[i:i + 2], 16) / 255.0 for i in (1, 3, 5)])


def message_mask(trace, window):
    m = window.overlapping(trace) & (trace.kind == KIND_CODE["message"])
    m &= (trace.proc >= 0) & (trace.proc < trace.processors) & (trace.peer >= 0) & (trace.peer < trace.processors)
    if m.any():
        m &= window.selected[np.clip(trace.proc, 0, trace.processors - 1)]
        m &= window.selected[np.clip(trace.peer, 0, trace.processors - 1)]
    return m


def draw_arrows(ax, trace, messages, row_of, factor):
    for i in np.flatnonzero(messages):
        ax.annotate("", xy=(trace.end[i] * factor, row_of[trace.peer[i]]),
                    xytext=(trace.start[i] * factor, row_of[trace.proc[i]]),
                    arrowprops=dict(arrowstyle="-|>", color=MESSAGE_COLOR, lw=0.7, alpha=0.75, shrinkA=0, shrinkB=0,
                                    mutation_scale=7))


def style_rows(ax, trace, procs, window, factor, unit):
    n = len(procs)
    ax.set_xlim(window.t0 * factor, window.t1 * factor)
    ax.set_ylim(n - 0.5, -0.5)
    step = max(1, int(np.ceil(n / 40)))
    ticks = np.arange(0, n, step)
    ax.set_yticks(ticks)
    ax.set_yticklabels([row_labels(trace, procs)[t] for t in ticks], fontsize=8 if n > 16 else 9)
    ax.set_xlabel(f"simulated time ({unit})")
    ax.set_ylabel("processor (mesh x,y)")
    ax.grid(axis="x", color="white", linewidth=0.6, alpha=0.8)


def arrows_or_note(ax, trace, window, row_of, factor):
    """Draws the window's message arrows when there are few; else returns a note saying why not."""
    messages = message_mask(trace, window)
    count = int(messages.sum())
    if 0 < count <= ARROWS_MAX:
        draw_arrows(ax, trace, messages, row_of, factor)
        return True, ""
    if count:
        return False, f"; {count} message arrows left out (over {ARROWS_MAX}: narrow --from-ms/--to-ms or --procs)"
    return False, ""


def plot_gantt(plt, trace, window, title, path):
    procs = window.procs
    n = len(procs)
    row_of = np.full(trace.processors, -1)
    row_of[procs] = np.arange(n)
    states = state_mask(trace, window)
    dense = needs_density(trace, window, states)
    row_height = min(12.0, max(2.6, 0.24 * n + 1.4))
    height = row_height * (2 if dense else 1) + 1.4
    fig, axes = plt.subplots(2 if dense else 1, 1, figsize=(14, height), dpi=DPI, squeeze=False)
    ax = axes[0, 0]
    factor, unit = window.unit()
    if dense:
        column = draw_density(ax, trace, window, n, factor)
        arrows = False
        zoom = zoom_window(trace, window, states)
        ax.add_patch(Rectangle((zoom.t0 * factor, -0.5), (zoom.t1 - zoom.t0) * factor, n, fill=False,
                               edgecolor="#000000", linewidth=1.2))
        mode = (f"overview: share of each activity per {human_duration(column)} in each processor's band (too many "
                f"short intervals to draw one by one); framed: the window zoomed in below")
        zax = axes[1, 0]
        zfactor, zunit = zoom.unit()
        draw_exact(zax, trace, zoom, states, row_of, zfactor)
        arrows, note = arrows_or_note(zax, trace, zoom, row_of, zfactor)
        style_rows(zax, trace, procs, zoom, zfactor, zunit)
        zax.set_title(f"zoomed in: {zoom.describe()} ({human_duration(zoom.length)}, around the median interval start), "
                      f"every interval drawn{note}", fontsize=10)
    else:
        draw_exact(ax, trace, window, states, row_of, factor)
        mode = "every interval drawn"
        if bool((states & (trace.thread > 0)).any()):
            mode += "; lower half of a row: threads the processor spawned (they run beside it)"
        arrows, note = arrows_or_note(ax, trace, window, row_of, factor)
        mode += note
    style_rows(ax, trace, procs, window, factor, unit)
    ax.set_title(f"{title}\nprocessor timeline, {window.describe()}, {n} of {trace.processors} processors\n{mode}",
                 fontsize=10)

    handles = [Patch(facecolor=STATE_COLORS[k], label=STATE_LABELS[k]) for k in STATE_KINDS]
    handles.append(Patch(facecolor=IDLE_COLOR, edgecolor="#bbbbbb", label="idle"))
    if arrows:
        handles.append(Line2D([0], [0], color=MESSAGE_COLOR, lw=1, marker=">", markersize=5,
                              label="message (send \u2192 arrival)"))
    # The legend gets its own strip under the axis label, whatever the figure's height.
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False, fontsize=9)
    fig.tight_layout(rect=(0, 0.45 / height, 1, 1))
    fig.savefig(path)
    plt.close(fig)
    return {"dense": dense, "unit": unit, "zoom": (zoom.t0, zoom.t1) if dense else None}
