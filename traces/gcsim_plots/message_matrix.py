"""Plot 3: bytes sent from each processor (row) to each other processor (column)."""

import numpy as np
from matplotlib.colors import LogNorm
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from .style import DPI, human_bytes
from .trace_data import KIND_CODE


def plot_message_matrix(plt, trace, window, title, path):
    procs = window.procs
    n = len(procs)
    row_of = np.full(trace.processors, -1)
    row_of[procs] = np.arange(n)
    m = (trace.kind == KIND_CODE["message"]) & (trace.start >= window.t0) & (trace.start <= window.t1)
    m &= (trace.proc >= 0) & (trace.proc < trace.processors) & (trace.peer >= 0) & (trace.peer < trace.processors)
    src = row_of[np.clip(trace.proc[m], 0, trace.processors - 1)]
    dst = row_of[np.clip(trace.peer[m], 0, trace.processors - 1)]
    nbytes = trace.bytes[m].astype(np.float64)
    keep = (src >= 0) & (dst >= 0)
    src, dst, nbytes = src[keep], dst[keep], nbytes[keep]
    matrix = np.bincount(src * n + dst, weights=nbytes, minlength=n * n).reshape(n, n)
    counts = np.bincount(src * n + dst, minlength=n * n).reshape(n, n)

    side = min(11.0, max(5.0, 0.16 * n + 4.0))
    fig, ax = plt.subplots(figsize=(side + 1.6, side), dpi=DPI)
    import matplotlib
    cmap = matplotlib.colormaps["viridis"].copy()
    cmap.set_bad("white")
    shown = np.ma.masked_where(counts == 0, matplotlib_safe(matrix))
    positive = matrix[matrix > 0]
    lo, hi = (positive.min(), positive.max()) if positive.size else (1.0, 1.0)
    if hi < lo * 4:  # a narrow range still gets a readable colour bar of a few powers of two
        lo, hi = lo / 2, hi * 2
    norm = LogNorm(vmin=max(0.5, lo), vmax=hi)
    image = ax.imshow(shown, cmap=cmap, norm=norm, interpolation="nearest", origin="upper")
    cb = fig.colorbar(image, ax=ax, shrink=0.8)
    cb.set_label("bytes sent (log scale)")
    cb.ax.yaxis.set_major_locator(LogLocator(base=2 if hi / lo < 2 ** 12 else 16))
    cb.ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: human_bytes(v)))
    cb.ax.yaxis.set_minor_formatter(NullFormatter())
    if n <= 16:
        for (i, j), v in np.ndenumerate(matrix):
            if counts[i, j]:
                bright = norm(v) > 0.6 if positive.size else False
                text = f"{human_bytes(v)}\n{counts[i, j]} msg" if n <= 8 else human_bytes(v).replace(" ", "\n")
                ax.text(j, i, text, ha="center", va="center", fontsize=7 if n <= 8 else 6.5,
                        color="black" if bright else "white")
    step = max(1, int(np.ceil(n / 32)))
    ticks = np.arange(0, n, step)
    ax.set_xticks(ticks)
    ax.set_yticks(ticks)
    ax.set_xticklabels([f"P{procs[t]}" for t in ticks], rotation=90 if n > 16 else 0, fontsize=8)
    ax.set_yticklabels([f"P{procs[t]}" for t in ticks], fontsize=8)
    ax.set_xlabel("destination processor")
    ax.set_ylabel("source processor")
    fig.suptitle(f"{title}\nbytes sent between processors, messages sent {window.describe()}:\n"
                 f"{int(counts.sum())} messages, {human_bytes(matrix.sum())} in all; white: no message", fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def matplotlib_safe(matrix):
    """LogNorm cannot take zeros; the masked cells are drawn white anyway."""
    return np.where(matrix > 0, matrix, 1.0)
