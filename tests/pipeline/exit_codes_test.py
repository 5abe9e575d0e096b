#!/usr/bin/env python3
"""One way to fail: each kind of mistake gives one `gcsim: error: ...` line on stderr
and its documented exit status (README "Errors, exit codes and interrupted runs"), before any
simulation runs when the mistake is in the command line or an output path.

  exit_codes_test.py GCSIM WORKDIR
"""
import os
import subprocess
import sys

OK, RUN_FAILED, USAGE, FILE, DEADLOCK = 0, 1, 2, 3, 5

# (arguments, expected status, text the error must contain)
CASES = [
    (["--help"], OK, None),
    (["run", "radiosity", "--help"], OK, None),
    ([], USAGE, "subcommand"),
    (["run", "radiosity", "--no-such-option"], USAGE, "--no-such-option"),
    (["run", "radiosity", "--nodes", "65"], USAGE, "64 nodes"),
    (["run", "radiosity", "--nodes", "0"], USAGE, "--nodes"),
    (["run", "radiosity", "--nodes", "0x10"], USAGE, "decimal"),
    (["topo", "--nodes", "1e3"], USAGE, "decimal"),
    (["accuracy", "network", "--models", "analytic,bogus"], USAGE, "not a network model"),
    (["run", "radiosity", "--camera", "nan,0,0,0,0,1"], USAGE, "finite"),
    (["run", "radiosity", "--camera", "0,1,0,0,0,0"], USAGE, "parallel to the up direction"),
    (["run", "radiosity", "--camera", "0,0,0,0,0,0"], USAGE, "coincide"),
    (["run", "radiosity", "--camera", "0,0,5,0,0,0,180"], USAGE, "field of view"),
    (["run", "radiosity", "--camera", "0,0,5,0,0,0,1e-320"], USAGE, "--camera"),
    (["run", "radiosity", "--exposure", "-1"], USAGE, "--exposure"),
    (["run", "radiosity", "--energy", "inf"], USAGE, "--energy"),
    (["run", "radiosity", "--sort-until", "nan"], USAGE, "finite"),
    (["bench", "ring", "--size", "-1KB"], USAGE, "negative"),
    (["run", "radiosity", "--scene", "no/such.wld"], FILE, "does not exist"),
    (["run", "raytrace", "--scene", "no/such.obj"], FILE, "does not exist"),
    (["run", "raytrace", "--scene", "no-such-scene"], USAGE, "unknown scene"),
    (["run", "radiosity", "--scene", "no-such-scene"], USAGE, "unknown scene"),
    (["run", "radiosity", "--json", "no/such/dir/r.json"], FILE, "does not exist"),
    (["run", "radiosity", "--image", "no/such/dir/c.png"], FILE, "--image"),
    (["run", "radiosity", "--steps-csv", "{work}"], FILE, "is a directory"),
    (["run", "raytrace", "--image", "no/such/dir/t.png"], FILE, "--image"),
    (["sweep", "radiosity", "--csv", "no/such/dir/s.csv"], FILE, "--csv"),
    (["topo", "--json", "no/such/dir/t.json"], FILE, "--json"),
    (["run", "radiosity", "--scene", "cornell", "--hemicube", "16", "--max-steps", "3"], RUN_FAILED, "step limit"),
    (["demo", "deadlock"], DEADLOCK, "deadlock"),
]


def main(gcsim, work):
    os.makedirs(work, exist_ok=True)
    failures = []
    for args, status, text in CASES:
        args = [a.replace("{work}", work) for a in args]
        p = subprocess.run([gcsim, *args], capture_output=True, text=True, timeout=600, cwd=work)
        problems = []
        if p.returncode != status:
            problems.append(f"exit status {p.returncode}, expected {status}")
        if status != OK:
            if not p.stderr.startswith("gcsim: error: "):
                problems.append("stderr does not start with 'gcsim: error: '")
            if text and text.lower() not in p.stderr.lower():
                problems.append(f"stderr does not mention {text!r}")
        if status in (USAGE, FILE) and "simulated" in p.stdout:
            problems.append("a simulation ran before the error")
        if problems:
            failures.append(f"gcsim {' '.join(args)}: {'; '.join(problems)}\n  stderr: {p.stderr.strip()}")
        else:
            print(f"ok  {status:>3}  gcsim {' '.join(args)}")
    if failures:
        sys.exit("FAIL\n" + "\n".join(failures))


if __name__ == "__main__":
    main(*sys.argv[1:3])
