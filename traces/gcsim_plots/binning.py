"""Time covered by intervals in each bin of a time axis, without drawing (or looping over) the
intervals: a million records reduce to one number per processor, activity and pixel column."""

import numpy as np

from .style import STATE_KINDS
from .trace_data import KIND_CODE


def coverage(starts, ends, edges):
    """Time of each bin [edges[i], edges[i+1]] covered by the intervals [starts, ends].

    The covered time up to t is F(t) = sum(max(0, min(t, end) - start)), which sorted starts and
    ends with their prefix sums give for every edge at once; a bin's coverage is F's difference."""
    if len(starts) == 0:
        return np.zeros(len(edges) - 1)
    origin = edges[0]
    s = np.sort(starts - origin)
    e = np.sort(ends - origin)
    t = edges - origin
    cs = np.concatenate(([0.0], np.cumsum(s)))
    ce = np.concatenate(([0.0], np.cumsum(e)))
    k = np.searchsorted(s, t, side="right")
    j = np.searchsorted(e, t, side="right")
    covered = (k * t - cs[k]) - (j * t - ce[j])
    return np.clip(np.diff(covered), 0.0, None)


def state_coverage(trace, window, edges):
    """Array [processor in window.procs, activity in STATE_KINDS, bin] of covered milliseconds."""
    out = np.zeros((len(window.procs), len(STATE_KINDS), len(edges) - 1))
    keep = window.overlapping(trace) & window.selected[np.clip(trace.proc, 0, trace.processors - 1)]
    keep &= (trace.proc >= 0) & (trace.proc < trace.processors)
    row_of = np.full(trace.processors, -1)
    row_of[window.procs] = np.arange(len(window.procs))
    for ki, kind in enumerate(STATE_KINDS):
        mask = keep & (trace.kind == KIND_CODE[kind])
        if not mask.any():
            continue
        rows = row_of[trace.proc[mask]]
        starts = trace.start[mask]
        ends = trace.end[mask]
        order = np.argsort(rows, kind="stable")
        rows, starts, ends = rows[order], starts[order], ends[order]
        bounds = np.searchsorted(rows, np.arange(len(window.procs) + 1))
        for r in range(len(window.procs)):
            a, b = bounds[r], bounds[r + 1]
            if a < b:
                out[r, ki] = coverage(starts[a:b], ends[a:b], edges)
    return out


def union_length(group, starts, ends, groups):
    """Length of the union of the intervals of each group (0..groups-1): how long a channel was busy,
    counting overlapping transfers once. Vectorised: groups are laid end to end on one axis."""
    if len(starts) == 0:
        return np.zeros(groups)
    span = float(max(ends.max(), starts.max()) - min(starts.min(), 0.0)) + 1.0
    s = starts + group * span
    e = ends + group * span
    order = np.lexsort((s, group))
    s, e, g = s[order], e[order], group[order]
    reach = np.maximum.accumulate(e)
    new_segment = np.ones(len(s), dtype=bool)
    new_segment[1:] = s[1:] > reach[:-1]
    first = np.flatnonzero(new_segment)
    last = np.concatenate((first[1:] - 1, [len(s) - 1]))
    lengths = reach[last] - s[first]
    return np.bincount(g[first], weights=lengths, minlength=groups)
