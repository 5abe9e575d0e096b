"""Colours and labels shared by every plot (and by the Paje export in machine/paje_writer.cpp)."""

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
MESSAGE_COLOR = "#222222"

DPI = 120


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
