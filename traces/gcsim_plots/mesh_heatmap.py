"""Plot 2: the physical mesh, each directed channel coloured by the bytes it carried and by the
fraction of the window it was busy. Channel ids follow machine/mesh.hpp: node * 4 + direction
(0 east, 1 west, 2 north = +y, 3 south = -y). A trace of another interconnect (its CSV header says
"interconnect NAME") is drawn from its link records alone: each used channel as an arrow from its
source node towards its destination (away from the grid when it wraps around)."""

import numpy as np
from matplotlib.colors import Normalize
from matplotlib.patches import Rectangle
from matplotlib.ticker import FuncFormatter, MaxNLocator

from .binning import union_length
from .style import DPI, human_bytes
from .trace_data import KIND_CODE

STEP = {0: (1, 0), 1: (-1, 0), 2: (0, 1), 3: (0, -1)}


def is_mesh(trace):
    return getattr(trace, "interconnect", "mesh") == "mesh"


def channel_count(trace):
    nch = trace.mesh_width * trace.mesh_height * 4
    if not is_mesh(trace):
        links = (trace.kind == KIND_CODE["link"]) & (trace.id >= 0)
        if links.any():
            nch = max(nch, int(trace.id[links].max()) + 1)
    return nch


def channel_ends(trace):
    """Another interconnect's channels as its link records name them: id -> (source, destination)."""
    links = (trace.kind == KIND_CODE["link"]) & (trace.id >= 0) & (trace.proc >= 0) & (trace.peer >= 0)
    ids, first = np.unique(trace.id[links], return_index=True)
    return {int(c): (int(trace.proc[links][i]), int(trace.peer[links][i])) for c, i in zip(ids, first)}


def channel_step(trace, ch, ends):
    """(source x, y) and the unit step (dx, dy) of the arrow of channel ch, or None if it is not drawn."""
    if is_mesh(trace):
        if channel_target(trace, ch) is None:
            return None
        return trace.node_xy(ch // 4), STEP[ch % 4]
    if ch not in ends:
        return None
    (x, y), (tx, ty) = trace.node_xy(ends[ch][0]), trace.node_xy(ends[ch][1])
    # A hop of more than one cell wraps around the grid: the arrow points off its edge.
    step = [int(np.sign(d)) if abs(d) <= 1 else -int(np.sign(d)) for d in (tx - x, ty - y)]
    return (x, y), tuple(step)


def channel_target(trace, ch):
    node, d = divmod(int(ch), 4)
    x, y = trace.node_xy(node)
    dx, dy = STEP[d]
    tx, ty = x + dx, y + dy
    if not (0 <= tx < trace.mesh_width and 0 <= ty < trace.mesh_height):
        return None
    return tx, ty


def route_messages(trace, src, dst):
    """Channels of the X-then-Y routes of the messages (as machine/mesh.cpp routes them):
    pairs (channel, message index)."""
    w = trace.mesh_width
    x, y = src % w, src // w
    tx, ty = dst % w, dst // w
    channels, owners = [], []
    index = np.arange(len(src))
    for _ in range(trace.mesh_width + trace.mesh_height):
        move_x = x != tx
        move_y = ~move_x & (y != ty)
        if not (move_x.any() or move_y.any()):
            break
        east = move_x & (tx > x)
        west = move_x & (tx < x)
        north = move_y & (ty > y)
        south = move_y & (ty < y)
        node = y * w + x
        for mask, d in ((east, 0), (west, 1), (north, 2), (south, 3)):
            channels.append(node[mask] * 4 + d)
            owners.append(index[mask])
        x = x + east - west
        y = y + north - south
    if not channels:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    return np.concatenate(channels), np.concatenate(owners)


def channel_load(trace, window):
    """Bytes and busy milliseconds per channel id in the window, and where they came from."""
    nch = channel_count(trace)
    in_window = window.overlapping(trace)
    links = in_window & (trace.kind == KIND_CODE["link"]) & (trace.id >= 0) & (trace.id < nch)
    if links.any():
        ch = trace.id[links]
        starts = np.maximum(trace.start[links], window.t0)
        ends = np.minimum(trace.end[links], window.t1)
        source = "link records (trace level full)"
        nbytes = trace.bytes[links]
    elif not is_mesh(trace):
        # Only gcsim knows another interconnect's routes: without link records there is nothing to draw.
        zero = np.zeros(nch)
        return zero, zero, f"no link records (rerun with --trace-level full to see the {trace.interconnect}'s channels)"
    else:
        msgs = in_window & (trace.kind == KIND_CODE["message"])
        msgs &= (trace.proc >= 0) & (trace.peer >= 0)
        msgs &= (trace.proc < trace.mesh_width * trace.mesh_height) & (trace.peer < trace.mesh_width * trace.mesh_height)
        ch, owner = route_messages(trace, trace.proc[msgs].astype(np.int64), trace.peer[msgs].astype(np.int64))
        starts = np.maximum(trace.start[msgs][owner], window.t0)
        ends = np.minimum(trace.end[msgs][owner], window.t1)
        nbytes = trace.bytes[msgs][owner]
        source = ("messages routed X then Y (no link records at this trace level: busy is an upper bound, "
                  "send to arrival)")
    total = np.bincount(ch, weights=nbytes.astype(np.float64), minlength=nch)
    busy = union_length(ch, starts, ends, nch)
    return total, busy / window.length, source


def draw_mesh(ax, trace, window, values, norm, cmap, lw):
    # add_artist, not add_patch: the limits are set below, and updating them per arrow is the slow part.
    w, h = trace.mesh_width, trace.mesh_height
    label_nodes = w * h <= 64
    # On big meshes the node boxes would hide the channels: only the selected nodes get a dot.
    big = w * h > 256
    for node in range(w * h):
        if big:
            if window.subset and node < trace.processors and window.selected[node]:
                ax.plot(*trace.node_xy(node), "s", color="#222222", markersize=3, zorder=3)
            continue
        x, y = trace.node_xy(node)
        chosen = node < trace.processors and window.selected[node]
        ax.add_artist(Rectangle((x - 0.17, y - 0.17), 0.34, 0.34, facecolor="white",
                               edgecolor="#222222" if chosen else "#bbbbbb", linewidth=1.4 if chosen else 0.6, zorder=3))
        if label_nodes:
            ax.text(x, y, f"P{node}", ha="center", va="center", fontsize=7 if w * h > 16 else 9, zorder=4,
                    color="#222222" if chosen else "#999999")
    # One quiver per panel (used channels coloured, unused grey): hundreds of arrows cost one artist.
    used, unused = [], []
    ends = {} if is_mesh(trace) else channel_ends(trace)
    for ch in range(len(values)):
        drawn = channel_step(trace, ch, ends)
        if drawn is None:
            continue
        (x, y), (dx, dy) = drawn
        ox, oy = dy * 0.1, -dx * 0.1  # keep right: the two directions of a pair side by side
        (used if values[ch] > 0 else unused).append((x + 0.2 * dx + ox, y + 0.2 * dy + oy, 0.6 * dx, 0.6 * dy, values[ch]))
    for arrows, width in ((unused, lw / 3), (used, lw if not big else 6.0)):
        if not arrows:
            continue
        a = np.array(arrows)
        style = dict(angles="xy", scale_units="xy", scale=1, units="xy", width=0.018 * width, headwidth=2.6,
                     headlength=2.2, headaxislength=2.0, zorder=2)
        if arrows is used:
            ax.quiver(a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4], cmap=cmap, norm=norm, **style)
        else:
            ax.quiver(a[:, 0], a[:, 1], a[:, 2], a[:, 3], color="#dddddd", **style)
    ax.set_xlim(-0.6, w - 0.4)
    ax.set_ylim(-0.6, h - 0.4)
    ax.set_aspect("equal")
    ax.set_xticks(range(0, w, max(1, w // 16)))
    ax.set_yticks(range(0, h, max(1, h // 16)))
    ax.set_xlabel(f"{getattr(trace, 'interconnect', 'mesh')} x (east \u2192)")
    ax.set_ylabel(f"{getattr(trace, 'interconnect', 'mesh')} y (north \u2192)")


def plot_mesh_heatmap(plt, trace, window, title, path):
    total, busy, source = channel_load(trace, window)
    w, h = trace.mesh_width, trace.mesh_height
    panel = min(7.0, max(4.0, 0.9 * max(w, h) + 1.5))
    fig, axes = plt.subplots(1, 2, figsize=(2 * panel + 2.2, panel * h / max(w, h) + 1.8), dpi=DPI)
    lw = max(0.8, min(5.0, 32.0 / max(w, h)))
    import matplotlib
    bytes_cmap = matplotlib.colormaps["viridis"]
    busy_cmap = matplotlib.colormaps["plasma"]  # low to high as the bytes panel (and the message matrix): dark to bright
    bytes_norm = Normalize(0, max(1.0, total.max()))
    # Scaled to the busiest channel (a nice round share), so that light load still shows contrast.
    busy_top = next((v for v in (0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 0.75, 1.0) if busy.max() <= v), max(1.0, busy.max()))
    busy_norm = Normalize(0, busy_top)
    draw_mesh(axes[0], trace, window, total, bytes_norm, bytes_cmap, lw)
    draw_mesh(axes[1], trace, window, busy, busy_norm, busy_cmap, lw)
    axes[0].set_title(f"bytes carried per channel (max {human_bytes(total.max())})", fontsize=10)
    # Shares below 10 % get a decimal, so that the ticks of a lightly loaded mesh differ.
    share = (lambda v: f"{v:.1%}") if busy_top <= 0.1 else (lambda v: f"{v:.0%}")
    axes[1].set_title(f"busy fraction per channel (max {share(busy.max())})", fontsize=10)
    cb = fig.colorbar(matplotlib.cm.ScalarMappable(norm=bytes_norm, cmap=bytes_cmap), ax=axes[0], shrink=0.8)
    cb.set_label("bytes in window")
    # Ticks at round numbers of the unit the maximum is shown in (KB, MB), not of bytes.
    unit = 1024 ** max(0, min(4, int(np.log(max(total.max(), 1.0)) / np.log(1024))))
    cb.set_ticks(unit * MaxNLocator(6).tick_values(0, bytes_norm.vmax / unit))
    cb.ax.set_ylim(0, bytes_norm.vmax)
    cb.ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: human_bytes(v)))
    cb = fig.colorbar(matplotlib.cm.ScalarMappable(norm=busy_norm, cmap=busy_cmap), ax=axes[1], shrink=0.8)
    cb.set_label("busy fraction of the window")
    cb.ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: share(v)))
    subset = "; outlined: the selected processors" if window.subset else ""
    fig.suptitle(f"{title}\n{getattr(trace, 'interconnect', 'mesh')} channels {w}x{h}, {window.describe()}; from {source}; grey: unused{subset}",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
