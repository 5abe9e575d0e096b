"""The thesis's measured node-count tables (copies in traces/thesis/, taken from the thesis's
chapter 4), for overlaying on a sweep that reproduces one of them."""

import csv
import os

HERE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "thesis")

# broadcast -> (time table, speedup table or None, communication table or None)
TABLES = {
    "sequential": ("thesis_table_4_3_time_vs_nodes.csv", "thesis_table_4_4_speedup.csv",
                   "thesis_table_4_5_comm_time.csv"),
    "tree": ("thesis_table_4_8_time_vs_nodes_tree_broadcast.csv", None, None),
}
TABLE_NAMES = {"sequential": "tables 4.3-4.5 (sequential broadcast)", "tree": "table 4.8 (tree broadcast)"}
SCENES = ("ROOM", "PICROOM", "CORNELL")


def read_table(name):
    """{scene: {nodes: value}} from one of the copied CSVs (lines starting with # are comments)."""
    with open(os.path.join(HERE, name), newline="") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    header, body = rows[0], rows[1:]
    table = {scene: {} for scene in header[1:]}
    for r in body:
        for scene, v in zip(header[1:], r[1:]):
            table[scene][int(r[0])] = float(v)
    return table


def thesis_curve(scene, broadcast):
    """{'label', 'time': {nodes: s}, 'speedup': {nodes: ratio}, 'comm': {nodes: s} or None} or None."""
    scene = (scene or "").upper()
    broadcast = (broadcast or "").lower()
    broadcast = "tree" if "tree" in broadcast else "sequential" if "seq" in broadcast else broadcast
    if scene not in SCENES or broadcast not in TABLES:
        return None
    time_name, speedup_name, comm_name = TABLES[broadcast]
    time = read_table(time_name)[scene]
    if speedup_name:
        speedup = {n: v / 100.0 for n, v in read_table(speedup_name)[scene].items()}  # the thesis gives percent
    else:
        speedup = {n: time[1] / t for n, t in time.items()} if 1 in time else None
    if speedup is not None and 1 in time:
        speedup.setdefault(1, 1.0)
    comm = read_table(comm_name)[scene] if comm_name else None
    return {"label": f"thesis {TABLE_NAMES[broadcast]}, {scene}", "time": time, "speedup": speedup, "comm": comm}
