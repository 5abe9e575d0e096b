#!/usr/bin/env python3
"""Interrupted long commands besides run and sweep: SIGINT to a real gcsim process once
it has visibly finished part of its work, then what it leaves behind.

  interrupt_commands_test.py GCSIM WORKDIR CASE

  accuracy_radiosity  during table 3: exit 130, --json holds tables 1 and 2 whole, table 3 cut
                      short, "interrupted": true and the table that was running
  accuracy_media      after the first of four scenes: --json and --csv hold that scene only
  validate            after the first simulated runs: --json and --csv hold the cells whose runs
                      finished (some, not all), marked interrupted
  calibrate           after two trials of the fit: --json has the trials done and the best so far,
                      --out is a machine file (marked interrupted) that gcsim loads
  render              during a traced `run render`: trace JSON closed, Paje written, --json marked

Progress lines (GCSIM_PROGRESS=1) or rows on stdout say when part of the work is done, so the
test does not depend on the host's speed; what remains after the signal is many seconds of work,
and the timeouts only guard against a hang.
"""
import csv
import json
import math
import os
import re
import signal
import subprocess
import sys

from interrupt_test import EXIT_INTERRUPTED, TIMEOUT_S, data_lines, fail, wait_until

SOURCE = os.path.dirname(os.path.abspath(__file__))


def start(args, progress=False):
    env = dict(os.environ, GCSIM_PROGRESS="1" if progress else "0")
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)


def read_until(proc, stream, pattern, what):
    """Reads stream (raw, unbuffered) until pattern matches what was read; returns the text."""
    seen = b""
    rx = re.compile(pattern)
    while not rx.search(seen.decode(errors="replace")):
        chunk = os.read(stream.fileno(), 4096)  # a hang here ends at ctest's own timeout
        if not chunk:
            proc.wait()
            fail(f"gcsim ended (status {proc.returncode}) before {what}:\n{seen.decode(errors='replace')}")
        seen += chunk
    return seen.decode(errors="replace")


def interrupt(proc):
    """SIGINT; checks the exit status and the error line; returns stdout."""
    proc.send_signal(signal.SIGINT)
    try:
        out, err = proc.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        proc.kill()
        fail("gcsim did not stop after SIGINT")
    out, err = out.decode(errors="replace"), err.decode(errors="replace")
    if proc.returncode != EXIT_INTERRUPTED:
        fail(f"exit status {proc.returncode}, expected {EXIT_INTERRUPTED}\n--- stdout\n{out}\n--- stderr\n{err}")
    if "gcsim: error: interrupted" not in err:
        fail(f"stderr does not say it was interrupted:\n{err}")
    return out


def load_json(path):
    with open(path) as f:
        doc = json.load(f)
    if doc.get("interrupted") is not True:
        fail(f"{path} does not say interrupted: {sorted(doc)}")
    return doc


def fresh(work, *names):
    paths = [os.path.join(work, n) for n in names]
    for p in paths:
        if os.path.exists(p):
            os.remove(p)
    return paths


def accuracy_radiosity(gcsim, work):
    (out,) = fresh(work, "accuracy.json")
    # Table 3 with four levels at hemicube 256 takes many seconds; tables 1 and 2 are small.
    proc = start([gcsim, "accuracy", "radiosity", "--resolutions", "16,32", "--thresholds", "0.9,0.99", "--levels", "1,2,3,4",
                  "--hierarchical-hemicube", "256", "--json", out])
    read_until(proc, proc.stdout, r"\n3\. ", "table 3 started")
    text = interrupt(proc)
    if "interrupted during the hierarchical table" not in text:
        fail(f"stdout does not say where it stopped:\n{text}")
    doc = load_json(out)
    if doc["interrupted_table"] != "hierarchical":
        fail(f"interrupted_table {doc['interrupted_table']}")
    if len(doc["form_factors"]) != 3 * 2 or len(doc["energy"]) != 2:
        fail(f"tables 1 and 2 not whole: {len(doc['form_factors'])} and {len(doc['energy'])} rows")
    if len(doc.get("hierarchical", [])) >= 5:
        fail("table 3 finished: the interruption came too late to test anything")
    if any(not r["simulated_s"] > 0 for r in doc["form_factors"] + doc["energy"]):
        fail("a finished row has no simulated time")
    print(f"accuracy radiosity: tables 1 and 2 whole, {len(doc.get('hierarchical', []))} of 5 rows of table 3")


def accuracy_media(gcsim, work):
    out, table = fresh(work, "media.json", "media.csv")
    # Small images; a large reference makes the three scenes after the first take seconds.
    proc = start([gcsim, "accuracy", "media", "--scenes", "small,exp1,exp2,fog", "--estimators", "uniform,transmittance",
                  "--width", "32", "--height", "24", "--photons", "5000", "--budgets", "1,2", "--repeats", "2",
                  "--reference-factor", "16", "--photon-fractions", "", "--json", out, "--csv", table])
    read_until(proc, proc.stdout, r"== small", "the first scene's table")
    interrupt(proc)
    doc = load_json(out)
    if [s["scene"] for s in doc["scenes"]] != ["small"] or doc["interrupted_at"].startswith("small"):
        fail(f"scenes {[s['scene'] for s in doc['scenes']]}, interrupted at {doc['interrupted_at']!r}")
    with open(table, newline="") as f:  # the first row, '# gcsim accuracy media; machine ...', is a comment
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows or any(r["scene"] != "small" for r in rows) or len(rows) != sum(r["fits"] for r in doc["scenes"][0]["rows"]):
        fail(f"CSV rows {[(r['scene'], r['estimator'], r['budget']) for r in rows]}")
    print(f"accuracy media: scene small kept ({len(rows)} rows), stopped at {doc['interrupted_at']}")


def validate(gcsim, work):
    out, table = fresh(work, "validate.json", "validate.csv")
    proc = start([gcsim, "validate", "--tables", "4.3", "--hemicube", "32", "--energy", "0.9", "--jobs", "1",
                  "--json", out, "--csv", table], progress=True)
    read_until(proc, proc.stderr, r"[1-9][0-9]*/[0-9]+ simulated runs", "a finished run")
    interrupt(proc)
    doc = load_json(out)
    cells = doc.get("cells", [])
    if not 1 <= len(cells) < 21:
        fail(f"{len(cells)} cells predicted of table 4.3's 21")
    if any(not (isinstance(c["predicted"], float) and math.isfinite(c["predicted"]) and c["predicted"] > 0) for c in cells):
        fail(f"a kept cell has no prediction: {cells}")
    if data_lines(table) != len(cells):
        fail(f"CSV has {data_lines(table)} rows, JSON {len(cells)} cells")
    print(f"validate: {len(cells)} of 21 cells kept")


def calibrate(gcsim, work):
    fitted, out = fresh(work, "fitted.toml", "calibrate.json")
    proc = start([gcsim, "calibrate", "--fit", "4.3@4+8", "--free", "network.connect_base_us", "--hemicube", "32",
                  "--energy", "0.9", "--jobs", "1", "--out", fitted, "--json", out], progress=True)
    read_until(proc, proc.stderr, r"trial 3:", "two finished trials")
    interrupt(proc)
    doc = load_json(out)
    if doc["converged"] is not False or doc["trials"] < 2 or not 1 <= doc["best"]["trial"] <= doc["trials"]:
        fail(f"--json {doc}")
    if [p["key"] for p in doc["parameters"]] != ["network.connect_base_us"] or not doc["parameters"][0]["value"] > 0:
        fail(f"parameters {doc['parameters']}")
    with open(fitted) as f:
        text = f.read()
    if "INTERRUPTED" not in text or "[calibration]" in text:
        fail(f"--out is not marked as an interrupted fit:\n{text}")
    check = subprocess.run([gcsim, "validate", "--config", fitted, "--tables", "4.6", "--jobs", "1"], capture_output=True,
                           text=True, timeout=TIMEOUT_S)
    if check.returncode != 0:
        fail(f"gcsim cannot use the interrupted --out as a machine file:\n{check.stderr}")
    print(f"calibrate: {doc['trials']} trials, best {doc['best']}; {fitted} loads")


def render(gcsim, work):
    trace, result = fresh(work, "render.json", "result.json")
    base = trace[:-len(".json")]
    fresh(work, "render.csv", "render.paje")
    proc = start([gcsim, "run", "render", "--scene", os.path.join(SOURCE, "..", "..", "scenes", "cornell.toml"),
                  "--nodes", "8", "--trace", trace, "--json", result])
    wait_until(lambda: data_lines(base + ".csv") >= 100, proc, "trace records on disk")
    interrupt(proc)
    with open(trace) as f:
        events = json.load(f)
    if not isinstance(events, list) or not events or os.path.getsize(base + ".paje") == 0:
        fail("the trace JSON is empty or the Paje file is")
    doc = load_json(result)
    reached = doc.get("reached", {})
    if not doc["simulated"]["total_s"] > 0 or not 0 <= reached.get("radiosity_shot_fraction", -1) < 1:
        fail(f"--json simulated {doc['simulated']}, reached {reached}")
    print(f"render: stopped at simulated {doc['simulated']['total_s']:.6f} s; {len(events)} trace events, Paje written")


if __name__ == "__main__":
    gcsim, work, case = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    {"accuracy_radiosity": accuracy_radiosity, "accuracy_media": accuracy_media, "validate": validate,
     "calibrate": calibrate, "render": render}[case](gcsim, work)
