#!/usr/bin/env python3
"""Interrupted runs lose nothing: sends SIGINT or SIGTERM to real gcsim processes and
checks what they leave behind.

  interrupt_test.py GCSIM WORKDIR sweep   SIGINT halfway through a sweep: exit 130, the CSV holds
                                          exactly the finished rows (complete lines), the JSON says
                                          interrupted and lists the same rows
  interrupt_test.py GCSIM WORKDIR run     SIGTERM during a traced run: exit 130, the trace JSON parses,
                                          the Paje file is written, every CSV line is complete, the
                                          --json says interrupted with the simulated time reached

The signal is sent once the run has visibly started (rows or trace records on disk), so the test
does not depend on the host's speed; the timeout only guards against a hang.
"""
import csv
import json
import os
import signal
import subprocess
import sys
import time

EXIT_INTERRUPTED = 130
TIMEOUT_S = 300


def fail(message, proc=None):
    if proc is not None:
        out, err = proc.communicate()
        message += f"\n--- stdout\n{out}\n--- stderr\n{err}"
    sys.exit(f"FAIL: {message}")


def wait_until(condition, proc, what):
    deadline = time.monotonic() + TIMEOUT_S
    while not condition():
        if proc.poll() is not None:
            fail(f"gcsim ended (status {proc.returncode}) before {what}", proc)
        if time.monotonic() > deadline:
            proc.kill()
            fail(f"timed out waiting for {what}", proc)
        time.sleep(0.02)


def data_lines(path):
    if not os.path.exists(path):
        return 0
    with open(path) as f:
        # minus the header; '#' rows say what was swept
        return max(0, sum(1 for line in f if line.endswith("\n") and not line.startswith("#")) - 1)


def finish(proc, sig):
    proc.send_signal(sig)
    try:
        out, err = proc.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        proc.kill()
        fail(f"gcsim did not stop after {sig.name}")
    if proc.returncode != EXIT_INTERRUPTED:
        fail(f"exit status {proc.returncode}, expected {EXIT_INTERRUPTED}\n--- stdout\n{out}\n--- stderr\n{err}")
    if "gcsim: error: interrupted" not in err:
        fail(f"stderr does not say it was interrupted:\n{err}")
    return out


def sweep(gcsim, work):
    counts = [1, 2, 4, 8, 16, 32, 64]
    csv_path, json_path = os.path.join(work, "sweep.csv"), os.path.join(work, "sweep.json")
    for p in (csv_path, json_path):
        if os.path.exists(p):
            os.remove(p)
    # Hemicube 128 to energy 0.999: every point takes a while, so the signal lands inside a point.
    proc = subprocess.Popen([gcsim, "sweep", "radiosity", "--scene", "cornell", "--hemicube", "128", "--energy", "0.999",
                             "--nodes", ",".join(map(str, counts)), "--jobs", "1", "--csv", csv_path, "--json", json_path],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_until(lambda: data_lines(csv_path) >= 2, proc, "two finished rows in the CSV")
    finish(proc, signal.SIGINT)
    with open(csv_path, newline="") as f:
        text = f.read()
    if not text.endswith("\n"):
        fail("the CSV's last line is incomplete")
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    nodes = [int(r["nodes"]) for r in rows]
    if len(nodes) < 2 or len(nodes) >= len(counts) or nodes != counts[:len(nodes)]:
        fail(f"CSV rows for nodes {nodes}: expected the first finished points of {counts}, not all of them")
    for r in rows:
        if any(v is None or v == "" for v in r.values()) or float(r["simulated_s"]) <= 0:
            fail(f"incomplete CSV row {r}")
    with open(json_path) as f:
        doc = json.load(f)
    if doc.get("interrupted") is not True:
        fail(f"--json does not say interrupted: {list(doc)}")
    if doc["finished_nodes"] != nodes or doc["interrupted_nodes"] != counts[len(nodes)]:
        fail(f"--json finished {doc['finished_nodes']}, interrupted at {doc['interrupted_nodes']}; CSV rows {nodes}")
    print(f"sweep: interrupted at the {doc['interrupted_nodes']}-node point; CSV and JSON hold the finished rows {nodes}")


def run(gcsim, work):
    trace, result = os.path.join(work, "run.json"), os.path.join(work, "result.json")
    base = trace[:-len(".json")]
    for p in (trace, result, base + ".csv", base + ".paje"):
        if os.path.exists(p):
            os.remove(p)
    proc = subprocess.Popen([gcsim, "run", "radiosity", "--scene", "room", "--nodes", "8", "--hemicube", "256",
                             "--energy", "0.9999", "--trace", trace, "--json", result],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_until(lambda: data_lines(base + ".csv") >= 100, proc, "trace records on disk")
    finish(proc, signal.SIGTERM)
    with open(trace) as f:
        events = json.load(f)  # the trace-event array, closed at the interruption
    if not isinstance(events, list) or not events:
        fail("the trace JSON is not a non-empty array")
    with open(base + ".csv", newline="") as f:
        text = f.read()
    if not text.endswith("\n"):
        fail("the trace CSV's last line is incomplete")
    lines = list(csv.reader(line for line in text.splitlines() if not line.startswith("#")))  # minus the comment
    if any(len(line) != len(lines[0]) for line in lines):
        fail("a trace CSV line has a different number of fields than the header")
    if os.path.getsize(base + ".paje") == 0:
        fail("the Paje file is empty")
    with open(result) as f:
        doc = json.load(f)
    if doc.get("interrupted") is not True or not doc["simulated"]["total_s"] > 0:
        fail(f"--json: interrupted={doc.get('interrupted')}, simulated={doc.get('simulated')}")
    reached = doc.get("reached", {})  # what the program finished: processor 0's loops
    if not (reached.get("loops", -1) >= 0 and 0 <= reached.get("shot_fraction", -1) < 1):
        fail(f"--json reached {reached}")
    print(f"run: stopped at simulated {doc['simulated']['total_s']:.6f} s; {len(events)} trace events, "
          f"{len(lines) - 1} CSV records, Paje written")


if __name__ == "__main__":
    gcsim, work, case = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    {"sweep": sweep, "run": run}[case](gcsim, work)
