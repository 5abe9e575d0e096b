"""Colours and labels shared by every plot (and by the Paje export in machine/paje_writer.cpp)."""
import textwrap

# Activity kinds of a processor, in the order they are stacked and listed in legends.
STATE_KINDS = ("compute", "send", "recv", "wait", "connect")
STATE_LABELS = {
    "compute": "compute",
    "send": "send",
    "recv": "receive",
    "wait": "wait",
    "connect": "connect (open link)",
}
# ColorBrewer Set1: distinct for the common colour-vision deficiencies and in greyscale by lightness.
STATE_COLORS = {
    "compute": "#4daf4a",
    "send": "#377eb8",
    "recv": "#ff7f00",
    "wait": "#e41a1c",
    "connect": "#984ea3",
}
IDLE_COLOR = "#f0f0f0"
# Busy, communicating, waiting (gcsim_plots/activity_split.py): a palette of their own, so that they
# are not read as the activity kinds above.
SHARE_COLORS = {"busy": "#1b9e77", "communicating": "#386cb0", "waiting": "#f0a30a"}
SHARE_LABELS = {"busy": "busy (compute)", "communicating": "communicating (bytes moving, link set-up)",
                "waiting": "waiting (for a peer to send or connect)"}
# Markers and line styles told apart without colour: gcsim's own series, then overlays.
SERIES_MARKERS = ("o", "D", "^", "v", "P", "X")
MESSAGE_COLOR = "#222222"

DPI = 120
# Characters in a line of a subtitle: what the narrowest figure (the message matrix) holds at its font size.
SUBTITLE_WIDTH = 100


def human_bytes(n):
    """4096 -> '4.0 KB': bytes read at a glance."""
    n = float(n)
    for unit in ("B", "KB", "MB", "GB", "TB"):
        if abs(n) < 1024 or unit == "TB":
            return f"{n:.0f} {unit}" if unit == "B" else f"{n:.1f} {unit}"
        n /= 1024
    return f"{n:.1f} TB"


def human_duration(ms):
    """A duration given in ms, in the unit that reads best: '303 \u00b5s', '42.4 ms', '2.1 s'."""
    if ms >= 1000:
        return f"{ms / 1000:.3g} s"
    if ms >= 1:
        return f"{ms:.3g} ms"
    if ms >= 1e-3:
        return f"{ms * 1e3:.3g} \u00b5s"
    return f"{ms * 1e6:.3g} ns"


def time_unit(span_ms, end_ms=0.0):
    """The unit a time axis of this span (ending at end_ms) reads best in: (factor from ms, unit
    name). A short window late in a long run goes up a unit rather than print 40,000 ms."""
    units = ((1e3, "\u00b5s"), (1.0, "ms"), (1e-3, "s"))
    i = 0 if span_ms < 2.0 else 1 if span_ms < 2000.0 else 2
    while i < 2 and end_ms * units[i][0] >= 1e4:
        i += 1
    return units[i]


def machine_line(trace, shown=None):
    """'Parsytec GC-PowerPlus ..., 8 nodes, network model analytic': for every plot's subtitle."""
    nodes = f"{trace.processors} nodes (mesh {trace.mesh_width}x{trace.mesh_height})"
    if shown is not None and shown != trace.processors:
        nodes += f", {shown} shown"
    line = f"{trace.machine}; {nodes}" if trace.machine else f"{nodes}; machine and network model not recorded in this trace"
    # Wrapped, so the narrower figures (the message matrix, the mesh heatmap) do not cut it off.
    return textwrap.fill(line, width=SUBTITLE_WIDTH, break_on_hyphens=False)
