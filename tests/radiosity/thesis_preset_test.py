#!/usr/bin/env python3
"""The thesis's program on the built-in default machine predicts the thesis's tables.

    thesis_preset_test.py GCSIM NODES [--bcast tree]

Runs `gcsim sweep radiosity --scene cornell --preset thesis --nodes NODES` with no --config (the
default machine: the GC as measured) and checks that every node count's simulated time is within
25 % of the thesis's figure the sweep prints beside it (table 4.3, or 4.8 with --bcast tree), that
the header names the machine and the preset, and that the JSON rows say the preset.
"""
import csv
import json
import pathlib
import subprocess
import sys
import tempfile

TOLERANCE = 0.25


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    gcsim, nodes, extra = sys.argv[1], sys.argv[2], sys.argv[3:]
    with tempfile.TemporaryDirectory() as tmp:
        out_csv, out_json = pathlib.Path(tmp) / "s.csv", pathlib.Path(tmp) / "s.json"
        cmd = [gcsim, "sweep", "radiosity", "--scene", "cornell", "--preset", "thesis", "--nodes", nodes,
               "--jobs", "2", "--csv", str(out_csv), "--json", str(out_json), *extra]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        print(proc.stdout)
        if proc.returncode != 0:
            sys.exit(f"{' '.join(cmd)} exited {proc.returncode}:\n{proc.stderr}")
        rows = list(csv.DictReader(line for line in out_csv.open() if not line.startswith("#")))
        doc = json.loads(out_json.read_text())
    failures = []
    if "calibrated" not in proc.stdout.split("\n", 1)[0]:
        failures.append("the first line does not name the default (calibrated) machine")
    if "program   --preset thesis" not in proc.stdout:
        failures.append("the header does not say the preset")
    json_rows = doc["rows"] if isinstance(doc, dict) else doc
    if any(r["radiosity"]["preset"] != "thesis" for r in json_rows):
        failures.append("a JSON row does not say preset thesis")
    for row in rows:
        ours, theirs = float(row["simulated_s"]), float(row["thesis_s"])
        error = ours / theirs - 1
        print(f"{row['nodes']:>3} nodes: {ours:8.1f} s against {theirs:5.0f} s ({100 * error:+.1f} %)")
        if abs(error) > TOLERANCE:
            failures.append(f"{row['nodes']} nodes: {100 * error:+.1f} % (tolerance {100 * TOLERANCE:.0f} %)")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
