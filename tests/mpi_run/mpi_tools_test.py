"""gcsim's tools on MPI programs, as a user runs them: a traced `gcsim mpirun` whose records name
the MPI calls (and whose trace is the same, byte for byte, when run again), `gcsim plot` and
`gcsim report` of it, and `gcsim sweep mpi` whose rows are the single runs' figures.

  mpi_tools_test.py trace|plot|sweep --gcsim G --mpicc CC --source S --work DIR [--configs DIR]

Exit status 0: passed; 77: skipped (no matplotlib for the plots); anything else: failed, with what
was expected on stderr."""

import argparse
import csv
import json
import os
import shutil
import subprocess
import sys

SKIP = 77
STATE_KINDS = ("compute", "send", "recv", "wait", "connect")


def fail(message):
    print(f"FAILED: {message}", file=sys.stderr)
    sys.exit(1)


def run(args, cwd, expect=0):
    p = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    if p.returncode != expect:
        fail(f"{' '.join(args)}: exit status {p.returncode}, expected {expect}\n{p.stdout}\n{p.stderr}")
    if "Traceback" in p.stderr:
        fail(f"{' '.join(args)} printed a Python traceback:\n{p.stderr}")
    return p.stdout


def build(a):
    if os.path.isdir(a.work):
        shutil.rmtree(a.work)
    os.makedirs(a.work)
    program = os.path.join(a.work, os.path.splitext(os.path.basename(a.source))[0])
    run([a.mpicc, "-O2", "-o", program, a.source, "-lm"], a.work)
    return program


def records(csv_path):
    with open(csv_path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def check_names_calls(rows, ranks):
    """Every interval on a rank's track names the MPI call it belongs to; the halo exchange's waits
    name MPI_Sendrecv, its peer and its bytes; the residual's name MPI_Allreduce."""
    states = [r for r in rows if r["kind"] in STATE_KINDS]
    if not states:
        fail("the trace has no interval on any rank's track")
    labels = {r["label"] for r in states}
    unnamed = sorted(x for x in labels if not x.startswith("MPI_") and x != "gcsim_mpi_compute")
    if unnamed:
        fail(f"intervals not named by their MPI call: {unnamed} (labels: {sorted(labels)})")
    for call in ("MPI_Sendrecv", "MPI_Allreduce"):
        if not any(r["label"] == call for r in states):
            fail(f"no interval names {call} (labels: {sorted(labels)})")
    halo = [r for r in states if r["label"] == "MPI_Sendrecv" and r["kind"] == "wait"]
    if not halo:
        fail("no MPI_Sendrecv wait: the halo exchange never blocked")
    for r in halo:
        proc, peer = int(r["proc"]), int(r["peer"])
        if not (0 <= peer < ranks and peer != proc and int(r["bytes"]) > 0):
            fail(f"an MPI_Sendrecv wait without its peer and bytes: {r}")
    messages = [r for r in rows if r["kind"] == "message"]
    if not messages:
        fail("the trace has no message records (the network's own)")


def check_no_overlap(rows):
    """The intervals of one track follow each other (Perfetto needs them nested; the plots count them once)."""
    tracks = {}
    for r in rows:
        if r["kind"] in STATE_KINDS:
            tracks.setdefault((r["proc"], r["thread"]), []).append((int(r["start_ps"]), int(r["end_ps"]), r["label"]))
    for track, spans in tracks.items():
        spans.sort()
        for (a0, a1, la), (b0, b1, lb) in zip(spans, spans[1:]):
            if b0 < a1:
                fail(f"track {track}: {la} [{a0}, {a1}] overlaps {lb} [{b0}, {b1}] ps")


def traced_run(a, program, name, ranks, args):
    run([a.gcsim, "mpirun", "-np", str(ranks), "--compute", "annotated", "--trace", f"{name}.json", "--json", f"{name}_run.json", program] + args,
        a.work)
    return os.path.join(a.work, name)


def test_trace(a):
    program = build(a)
    ranks, args = 6, ["24", "30"]
    first = traced_run(a, program, "t", ranks, args)
    again = traced_run(a, program, "again", ranks, args)
    for ext in (".json", ".csv", ".paje"):
        with open(first + ext, "rb") as f, open(again + ext, "rb") as g:
            if f.read() != g.read():
                fail(f"the trace's {ext} differs between two identical runs")
    with open(first + ".json") as f:
        events = json.load(f)  # the Chrome trace is whole JSON once the run closed it
    named = {e["name"] for e in events if e.get("ph") == "X" and e.get("cat") in STATE_KINDS}
    if "MPI_Sendrecv" not in named or "MPI_Allreduce" not in named:
        fail(f"the Chrome trace's slices do not name the calls: {sorted(named)}")
    rows = records(first + ".csv")
    check_names_calls(rows, ranks)
    check_no_overlap(rows)
    with open(os.path.join(a.work, "t_run.json")) as f:
        doc = json.load(f)
    for key in ("simulated", "wall", "nodes", "model", "machine", "provenance", "program", "arguments", "trace_files"):
        if key not in doc:
            fail(f"the run JSON lacks '{key}' (keys: {sorted(doc)})")
    if doc["arguments"] != args or doc["nodes"] != ranks or len(doc["trace_files"]) != 3:
        fail(f"the run JSON's program, nodes or trace files are not the run's: {doc['arguments']}, {doc['nodes']}, "
             f"{doc['trace_files']}")


def has_matplotlib(a):
    python = os.environ.get("GCSIM_PYTHON", "/usr/bin/python3")
    return subprocess.run([python, "-c", "import matplotlib, numpy"], capture_output=True).returncode == 0


def expect_png(path):
    if not os.path.isfile(path):
        fail(f"{path} was not written")
    with open(path, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            fail(f"{path} is not a PNG")
    if os.path.getsize(path) < 10000:
        fail(f"{path} is suspiciously small ({os.path.getsize(path)} bytes)")


def test_plot(a):
    if not has_matplotlib(a):
        print("skipped: python3-matplotlib and python3-numpy are not installed")
        return SKIP
    program = build(a)
    traced_run(a, program, "t", 16, ["24", "30"])
    run([a.gcsim, "plot", "t.json", "--out", "plots"], a.work)
    for png in ("gantt", "utilization", "mesh_heatmap", "message_matrix"):
        expect_png(os.path.join(a.work, "plots", f"{png}.png"))
    run([a.gcsim, "report", "t_run.json", "--out", "rep"], a.work)
    with open(os.path.join(a.work, "rep", "index.html")) as f:
        page = f.read()
    for text in ("mpi", os.path.basename(program), "plots/gantt.png", "t.csv", "t.paje"):
        if text not in page:
            fail(f"the report of the MPI run does not show '{text}'")
    return 0


def simulated_of(a, program, ranks, args, config):
    options = ["--config", config] if config else []
    out = os.path.join(a.work, f"single_{ranks}_{'published' if config else 'calibrated'}.json")
    run([a.gcsim, "mpirun", "-np", str(ranks), "--compute", "annotated"] + options + ["--json", out, program] + args,
        a.work)
    with open(out) as f:
        return json.load(f)["simulated"]["total_s"]


def test_sweep(a):
    program = build(a)
    args, counts = ["0.5", "10"], [1, 2, 4]
    # --compute after the program's arguments, as --nodes: both are the sweep's, not the program's
    run([a.gcsim, "sweep", "mpi", "--csv", "sweep.csv", "--json", "sweep.json", program] + args +
        ["--nodes", ",".join(map(str, counts)), "--compute", "annotated"], a.work)
    rows = records(os.path.join(a.work, "sweep.csv"))
    published = os.path.join(a.configs, "gc-powerplus.toml")
    for machine, config in (("calibrated", None), ("published", published)):
        mine = [r for r in rows if r["machine"] == machine]
        if [int(r["nodes"]) for r in mine] != counts:
            fail(f"the {machine} rows are not one per node count {counts}: {mine}")
        first = float(mine[0]["simulated_s"])
        if float(mine[0]["speedup"]) != 1.0:
            fail(f"speedup at 1 node on the {machine} machine is {mine[0]['speedup']}, not 1")
        for r in mine:
            n, t = int(r["nodes"]), float(r["simulated_s"])
            single = simulated_of(a, program, n, args, config)
            if abs(t - single) > 1e-9 * max(1.0, single):
                fail(f"{machine}, {n} nodes: the sweep says {t} s, gcsim mpirun -np {n} says {single} s")
            if abs(float(r["speedup"]) - first / t) > 1e-6 or abs(float(r["efficiency"]) - first / t / n) > 1e-6:
                fail(f"{machine}, {n} nodes: speedup {r['speedup']} or efficiency {r['efficiency']} is not "
                     f"{first / t} / {first / t / n}")
            waiting, communicating, comm = (float(r[k]) for k in ("waiting_s", "communicating_s", "comm_s"))
            if n > 1 and not 1 < float(r["speedup"]) <= n:
                fail(f"{machine}, {n} nodes: speedup {r['speedup']} outside (1, {n}] for work that divides evenly")
            if abs(waiting + communicating - comm) > 1e-8:
                fail(f"{machine}, {n} nodes: communicating {communicating} + waiting {waiting} != comm {comm}")
    if has_matplotlib(a):
        run([a.gcsim, "plot", "--sweep", "sweep.csv", "--out", "sweep_plot"], a.work)
        expect_png(os.path.join(a.work, "sweep_plot", "sweep_sweep.png"))
    return 0


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=("trace", "plot", "sweep"))
    p.add_argument("--gcsim", required=True)
    p.add_argument("--mpicc", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--configs", default="")
    a = p.parse_args()
    status = {"trace": test_trace, "plot": test_plot, "sweep": test_sweep}[a.test](a)
    sys.exit(status or 0)


if __name__ == "__main__":
    main()
