"""Busy, communicating, waiting: what a processor's time went to, from the trace records.

The runtime's counters (the run JSON's compute_s and comm_s) put every blocked call under
communication, so a tile server blocked in recv until a worker asks for work counts as
"communicating" for the whole run. The trace says more: a message record gives the time its
sender called send, so the part of a receive spent before that call was waiting for the peer,
not moving bytes. The definitions (traces/README.md, "Busy, communicating, waiting"):

- busy: compute intervals (the node's CPU working, serving requests included);
- communicating: blocked while bytes move or a link is set up: a synchronous send until the
  message arrives, a receive or wait from the moment the peer sent what it then received, the
  set-up of a connection after both ends asked for it;
- waiting: blocked before the peer had sent (receive, wait) or asked for the link (connect):
  waiting for work or for a partner;
- idle: no interval (before the first call, after the program returned).
"""

import numpy as np

from .binning import coverage
from .trace_data import KIND_CODE

SHARES = ("busy", "communicating", "waiting")
BUSY, COMMUNICATING, WAITING = range(3)


def _latest_at_or_before(keys, times, query_keys, query_times):
    """For each query, the index of the record of the same key with the latest time <= the query's
    time (-1 when none): keys and times laid end to end on one sorted axis."""
    if len(keys) == 0 or len(query_keys) == 0:
        return np.full(len(query_keys), -1)
    span = float(max(times.max(), query_times.max())) + 1.0
    axis = keys * span + times
    order = np.argsort(axis, kind="stable")
    sorted_axis = axis[order]
    at = np.searchsorted(sorted_axis, query_keys * span + query_times, side="right") - 1
    found = at >= 0
    found[found] &= keys[order[at[found]]] == query_keys[found]
    return np.where(found, order[np.clip(at, 0, None)], -1)


def _peer_started(trace, kinds_of_intervals, partner_kind, match_on_start):
    """For each interval of kinds_of_intervals on P with peer Q, when Q's partner record (the message
    Q -> P it received, or Q's connect to P) began, or NaN when none meets the interval. The partner
    is the latest one that arrived (match on end) or asked (match on start) by the interval's end."""
    n = trace.processors
    rows = np.flatnonzero(np.isin(trace.kind, [KIND_CODE[k] for k in kinds_of_intervals]) & (trace.peer >= 0))
    started = np.full(len(rows), np.nan)
    partners = np.flatnonzero(trace.kind == KIND_CODE[partner_kind])
    if len(rows) == 0 or len(partners) == 0:
        return rows, started
    keys = trace.proc[partners].astype(np.int64) * n + trace.peer[partners]
    query = trace.peer[rows].astype(np.int64) * n + trace.proc[rows]
    times = trace.start[partners] if match_on_start else trace.end[partners]
    match = _latest_at_or_before(keys, times, query, trace.end[rows])
    ok = match >= 0
    hit = partners[match[ok]]
    inside = trace.end[hit] >= trace.start[rows[ok]]  # it belongs to this interval, not an earlier one
    started[ok] = np.where(inside, trace.start[hit], np.nan)
    return rows, started


def split_intervals(trace):
    """Every processor interval as (proc, start, end, share), blocked ones cut where the peer acted.
    Returns numpy arrays; share is BUSY, COMMUNICATING or WAITING."""
    procs, starts, ends, shares = [], [], [], []

    def add(rows, a, b, share):
        keep = b > a
        procs.append(trace.proc[rows][keep])
        starts.append(a[keep])
        ends.append(b[keep])
        shares.append(np.full(int(keep.sum()), share, dtype=np.int8))

    compute = np.flatnonzero(trace.kind == KIND_CODE["compute"])
    add(compute, trace.start[compute], trace.end[compute], BUSY)
    blocked = np.isin(trace.kind, [KIND_CODE[k] for k in ("recv", "wait", "connect")])
    sends = np.flatnonzero((trace.kind == KIND_CODE["send"]) | (blocked & (trace.peer < 0)))  # no partner to ask
    add(sends, trace.start[sends], trace.end[sends], COMMUNICATING)
    for kinds, partner, on_start in ((("recv", "wait"), "message", False), (("connect",), "connect", True)):
        rows, peer_start = _peer_started(trace, kinds, partner, on_start)
        a, b = trace.start[rows], trace.end[rows]
        cut = np.where(np.isnan(peer_start), a, np.clip(peer_start, a, b))
        add(rows, a, cut, WAITING)
        add(rows, cut, b, COMMUNICATING)
    return (np.concatenate(procs), np.concatenate(starts), np.concatenate(ends), np.concatenate(shares))


def share_coverage(trace, window, edges):
    """Array [processor in window.procs, share in SHARES, bin] of milliseconds. Where a processor's
    spawned threads overlap its own intervals, busy comes first, then communicating, then waiting,
    so that no processor has more than the bin's length."""
    proc, start, end, share = split_intervals(trace)
    start, end = np.maximum(start, window.t0), np.minimum(end, window.t1)
    keep = (end > start) & (proc >= 0) & (proc < trace.processors)
    keep[keep] &= window.selected[proc[keep]]
    row_of = np.full(trace.processors, -1)
    row_of[window.procs] = np.arange(len(window.procs))
    out = np.zeros((len(window.procs), len(SHARES), len(edges) - 1))
    for s in range(len(SHARES)):
        mask = keep & (share == s)
        rows = row_of[proc[mask]]
        a, b = start[mask], end[mask]
        order = np.argsort(rows, kind="stable")
        rows, a, b = rows[order], a[order], b[order]
        bounds = np.searchsorted(rows, np.arange(len(window.procs) + 1))
        for r in range(len(window.procs)):
            if bounds[r] < bounds[r + 1]:
                out[r, s] = coverage(a[bounds[r]:bounds[r + 1]], b[bounds[r]:bounds[r + 1]], edges)
    # A node whose CPU works is busy even while a thread of it waits: each share gets at most what
    # the shares before it in SHARES left of the bin.
    left = np.broadcast_to(np.diff(edges), out[:, 0].shape).copy()
    for s in range(len(SHARES)):
        out[:, s] = np.minimum(out[:, s], left)
        left -= out[:, s]
    return out


def mean_shares(cover, edges):
    """Percent of the window's processor time per share, and idle: they add up to 100."""
    time = (edges[-1] - edges[0]) * cover.shape[0]
    shares = 100.0 * cover.sum(axis=(0, 2)) / time
    return shares, 100.0 - shares.sum()
