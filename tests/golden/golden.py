#!/usr/bin/env python3
"""Golden runs: simulated figures that must not change by accident.

    golden.py check GCSIM     rerun every run in runs.txt and compare with expected/
    golden.py record GCSIM    (re)write expected/ from the current binary

A run's record is its --json output without host-dependent fields (wall time, file paths) plus the
SHA-256 of its trace CSV (trace level 'messages'): simulated times of every message, byte for byte.
"""
import hashlib
import json
import pathlib
import shlex
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parent.parent  # runs start here, so that `--config configs/...` names the shipped files
HOST_FIELDS = {"wall", "trace", "trace_level", "image", "json", "provenance"}  # provenance: argv, paths, hashes


def runs():
    for line in (HERE / "runs.txt").read_text().splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            name, args = line.split(None, 1)
            yield name, shlex.split(args)


def strip_host(value):
    if isinstance(value, dict):
        return {k: strip_host(v) for k, v in value.items() if k not in HOST_FIELDS}
    if isinstance(value, list):
        return [strip_host(v) for v in value]
    return value


def record_of(gcsim, args, work):
    trace, out = work / "t.json", work / "r.json"
    cmd = [gcsim, *args, "--json", str(out), "--trace", str(trace), "--trace-level", "messages"]
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}:\n{proc.stderr}")
    rec = strip_host(json.loads(out.read_text()))
    rec["trace_csv_sha256"] = hashlib.sha256((work / "t.csv").read_bytes()).hexdigest()
    return rec


def diff(expected, actual, path=""):
    if type(expected) is not type(actual):
        return [f"{path}: {expected!r} -> {actual!r}"]
    if isinstance(expected, dict):
        out = []
        for k in sorted(set(expected) | set(actual)):
            if k not in actual or k not in expected:
                out.append(f"{path}/{k}: {'missing' if k not in actual else 'new'}")
            else:
                out += diff(expected[k], actual[k], f"{path}/{k}")
        return out
    if isinstance(expected, list) and len(expected) == len(actual):
        return [d for i, (e, a) in enumerate(zip(expected, actual)) for d in diff(e, a, f"{path}[{i}]")]
    return [] if expected == actual else [f"{path}: {expected!r} -> {actual!r}"]


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("check", "record"):
        sys.exit(__doc__)
    mode, gcsim = sys.argv[1], str(pathlib.Path(sys.argv[2]).resolve())
    expected_dir = HERE / "expected"
    expected_dir.mkdir(exist_ok=True)
    failures = 0
    for name, args in runs():
        with tempfile.TemporaryDirectory() as tmp:
            rec = record_of(gcsim, args, pathlib.Path(tmp))
        path = expected_dir / f"{name}.json"
        if mode == "record":
            path.write_text(json.dumps(rec, indent=1, sort_keys=True) + "\n")
            print(f"recorded {name}")
            continue
        problems = diff(json.loads(path.read_text()), rec)
        status = "same" if not problems else "CHANGED"
        print(f"{name:20} {status}")
        for p in problems[:20]:
            print(f"    {p}")
        failures += bool(problems)
    if failures:
        sys.exit(f"{failures} golden run(s) changed their simulated figures")


if __name__ == "__main__":
    main()
