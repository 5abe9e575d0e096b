"""Loads a gcsim trace CSV (FILE.csv beside FILE.json) into numpy arrays, and selects a window
of time and a subset of processors. Format: traces/README.md."""

import json
import os
import re
import warnings

import numpy as np

from .errors import PlotError, UsageError, reads_file
from .style import time_unit

KINDS = ("compute", "send", "recv", "wait", "connect", "link", "message")
KIND_CODE = {k: i for i, k in enumerate(KINDS)}
COLUMNS = "kind,proc,peer,start_ps,end_ps,bytes,id,label,thread"
COLUMNS_WITHOUT_THREAD = "kind,proc,peer,start_ps,end_ps,bytes,id,label"  # traces written before threads were recorded
HEADER = re.compile(r"^# gcsim trace; level (\w+); (\d+) processors; mesh (\d+)x(\d+)")
# After "mesh WxH" (the grid of nodes) when the machine's interconnect is not the GC's mesh.
INTERCONNECT = re.compile(r"; interconnect ([\w.-]+)")
PS_PER_MS = 1e9
# A processor's track in the Chrome JSON: "P3 node (3,0)", the node's position by the interconnect's
# coordinates hook (machine/interconnect.hpp), written before any record.
NODE_LABEL = re.compile(r'"tid":(\d+),"name":"thread_name","args":\{"name":"P\d+ node \((-?\d+),(-?\d+)\)"\}')


class Trace:
    """Columns of the records, one numpy array each; times in simulated milliseconds."""

    def __init__(self, path, level, processors, mesh_width, mesh_height, kind, proc, peer, start_ps, end_ps, nbytes, ident,
                 thread, interconnect="mesh"):
        self.path = path
        self.interconnect = interconnect  # "mesh": the GC's, whose channels and routes the plots know
        self.level = level
        self.processors = processors
        self.mesh_width = mesh_width
        self.mesh_height = mesh_height
        self.kind = kind
        self.proc = proc
        self.peer = peer
        self.start = start_ps / PS_PER_MS
        self.end = end_ps / PS_PER_MS
        self.bytes = nbytes
        self.id = ident
        self.thread = thread  # 0: the processor itself; 1, 2, ...: threads it spawned
        self.machine = machine_of(path)  # "" when the trace does not say
        self.node_positions = node_positions_of(path)  # node -> (x, y); empty: row by row

    def __len__(self):
        return len(self.kind)

    def span_ms(self):
        return (0.0, float(self.end.max()) if len(self) else 0.0)

    def of_kind(self, *names):
        codes = [KIND_CODE[n] for n in names]
        return np.isin(self.kind, codes)

    def node_xy(self, node):
        """Where the trace put the node (the interconnect's coordinates), else row-major on the mesh
        (traces written before the positions were read from the trace)."""
        at = self.node_positions.get(int(node))
        return at if at is not None else (node % self.mesh_width, node // self.mesh_width)


def csv_path_for(path):
    """gcsim writes FILE.json, FILE.csv and FILE.paje; any of them (or FILE) names the trace."""
    stem, ext = os.path.splitext(path)
    if ext == ".csv":
        return path
    if ext in (".json", ".paje"):
        return stem + ".csv"
    return path + ".csv" if not os.path.exists(path) else path


def node_positions_of(csv):
    """Each node's (x, y) from the processors' track names at the head of the Chrome JSON beside the
    CSV (metadata events come first, so reading stops at the first record). {} when absent."""
    path = os.path.splitext(csv)[0] + ".json"
    positions = {}
    try:
        with open(path, "r", encoding="utf-8", errors="replace") as f:
            for n, line in enumerate(f):
                if n > 0 and '"ph":"M"' not in line:
                    break
                m = NODE_LABEL.search(line)
                if m:
                    positions[int(m.group(1))] = (int(m.group(2)), int(m.group(3)))
    except OSError:
        return {}
    return positions


MACHINE_EVENT = re.compile(r'^,?(\{"ph":"M","pid":0,"name":"process_labels".*\}),?$')


def machine_of(csv):
    """The machine and network model, from the Chrome JSON beside the CSV: its metadata event
    process_labels (Perfetto shows it on the processors' track group). "" when absent."""
    path = os.path.splitext(csv)[0] + ".json"
    if not os.path.isfile(path):  # a FIFO or device beside the CSV would block or never end
        return ""
    try:
        with open(path, "r", encoding="utf-8", errors="replace") as f:
            head = [f.readline() for _ in range(6)]  # it follows the two process events
    except OSError:
        return ""
    for line in head:
        m = MACHINE_EVENT.match(line.strip())
        if m:
            try:
                return str(json.loads(m.group(1))["args"]["labels"])
            except (ValueError, KeyError, TypeError):
                return ""
    return ""


@reads_file("gcsim trace CSV")
def load_trace(path):
    csv = csv_path_for(path)
    if not os.path.exists(csv):
        if csv != path:
            raise PlotError(f"{path}: the trace CSV {csv} beside it does not exist "
                            "(gcsim --trace FILE.json writes FILE.csv next to it; plots are drawn from the CSV)")
        raise PlotError(f"{path}: no such file (expected a gcsim trace: FILE.json with FILE.csv beside it)")
    try:
        with open(csv, "r", encoding="utf-8", errors="replace") as f:
            first = f.readline()
            second = f.readline().strip()
            rest = f.read(4096)
    except OSError as e:
        raise PlotError(f"{csv}: cannot read: {e.strerror}")
    m = HEADER.match(first)
    if not m:
        raise PlotError(f"{csv}: not a gcsim trace CSV (expected a first line '# gcsim trace; level L; "
                        f"N processors; mesh WxH; ...', found {ascii(first.strip()[:40])})")
    if second not in (COLUMNS, COLUMNS_WITHOUT_THREAD):
        raise PlotError(f"{csv}: expected the column line '{COLUMNS}', found {second[:60]!r}")
    level, processors, width, height = m.group(1), int(m.group(2)), int(m.group(3)), int(m.group(4))
    # The bounds gcsim's own trace reader (machine/trace_csv.cpp) holds a header to.
    if not 1 <= processors <= 1 << 20 or not 1 <= width * height <= 1 << 24 or width < 1 or height < 1:
        raise PlotError(f"{csv}:1: {processors} processors on a {width}x{height} mesh; expected 1..{1 << 20} "
                        f"processors on at most {1 << 24} nodes")
    wiring = INTERCONNECT.search(first)
    interconnect = wiring.group(1) if wiring else "mesh"
    if not rest.strip():
        why = (" (level summary keeps totals only: rerun with --trace-level messages or full)"
               if level == "summary" else "")
        raise PlotError(f"{csv}: the trace has no records{why}")
    # One pass of numpy's C reader; the kind column is mapped to its code on the way (-1: unknown).
    codes = {**KIND_CODE, **{k.encode(): v for k, v in KIND_CODE.items()}}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            columns = (0, 1, 2, 3, 4, 5, 6, 8) if second == COLUMNS else (0, 1, 2, 3, 4, 5, 6)
            table = np.loadtxt(csv, delimiter=",", skiprows=2, usecols=columns, dtype=np.int64,
                               ndmin=2, converters={0: lambda s: codes.get(s, -1)})
    except ValueError as e:
        raise PlotError(f"{csv}: not a gcsim trace CSV: {str(e).splitlines()[0]} (rows counted from 0 after the "
                        f"two header lines; expected {COLUMNS})")
    kind = table[:, 0].astype(np.int8)
    if (kind < 0).any():
        row = int(np.flatnonzero(kind < 0)[0])
        raise PlotError(f"{csv}:{row + 3}: unknown record kind (expected one of {', '.join(KINDS)})")
    numbers = table[:, 1:]
    check_records(csv, numbers, processors)
    thread = table[:, 7].astype(np.int32) if table.shape[1] > 7 else np.zeros(len(table), dtype=np.int32)
    return Trace(csv, level, processors, width, height, kind, numbers[:, 0].astype(np.int32),
                 numbers[:, 1].astype(np.int32), numbers[:, 2].astype(np.float64), numbers[:, 3].astype(np.float64),
                 numbers[:, 4], numbers[:, 5], thread, interconnect)


def check_records(csv, numbers, processors):
    """Processors and peers inside the machine, intervals that do not end before they start."""
    proc, peer, start, end = numbers[:, 0], numbers[:, 1], numbers[:, 2], numbers[:, 3]
    bad = (proc < 0) | (proc >= processors) | (peer < -1) | (peer >= processors) | (start < 0) | (end < start)
    if bad.any():
        row = int(np.flatnonzero(bad)[0])
        raise PlotError(f"{csv}:{row + 3}: record outside the trace (proc {proc[row]}, peer {peer[row]}, "
                        f"{start[row]}..{end[row]} ps; expected processors 0-{processors - 1}, peer -1 or a "
                        "processor, and end_ps >= start_ps >= 0)")


def parse_procs(spec, processors, where):
    """'0-7,12' -> [0..7, 12]; every processor when spec is empty."""
    if not spec:
        return np.arange(processors)
    chosen = []
    for part in spec.split(","):
        part = part.strip()
        m = re.fullmatch(r"(\d+)(?:-(\d+))?", part)
        if not m:
            raise UsageError(f"--procs {spec!r}: expected processor numbers and ranges such as 0-7,12 "
                            f"(the trace {where} has processors 0-{processors - 1})")
        lo = int(m.group(1))
        hi = int(m.group(2)) if m.group(2) else lo
        if lo > hi or hi >= processors:
            raise UsageError(f"--procs {spec!r}: {part} is outside 0-{processors - 1}, "
                            f"the processors of the trace {where}")
        chosen.extend(range(lo, hi + 1))
    return np.unique(np.array(chosen, dtype=np.int64))


class Window:
    """The time window [t0, t1] in ms that the plots show, and the processors they show."""

    def __init__(self, trace, from_ms, to_ms, procs_spec):
        span0, span1 = trace.span_ms()
        self.t0 = span0 if from_ms is None else float(from_ms)
        self.t1 = span1 if to_ms is None else float(to_ms)
        if self.t1 <= self.t0:
            if from_ms is None and to_ms is None:
                raise PlotError(f"{trace.path}: every record has zero length; nothing to plot")
            raise UsageError(f"--from-ms {self.t0:g} --to-ms {self.t1:g}: the window is empty "
                            f"(the trace {trace.path} spans {span0:g} to {span1:g} ms)")
        if self.t0 >= span1 or self.t1 <= span0:
            raise UsageError(f"--from-ms {self.t0:g} --to-ms {self.t1:g}: no records in that window "
                            f"(the trace {trace.path} spans {span0:g} to {span1:g} ms)")
        self.procs = parse_procs(procs_spec, trace.processors, trace.path)
        self.subset = procs_spec is not None and procs_spec != ""
        self.selected = np.zeros(trace.processors, dtype=bool)
        self.selected[self.procs] = True

    @property
    def length(self):
        return self.t1 - self.t0

    def overlapping(self, trace):
        """Records whose interval meets the window."""
        return (trace.end >= self.t0) & (trace.start <= self.t1)

    def unit(self):
        """(factor from ms, unit name) of this window's time axis."""
        return time_unit(self.length, self.t1)

    def describe(self):
        factor, unit = self.unit()
        return f"{self.t0 * factor:.4g} to {self.t1 * factor:.4g} {unit}"
