#!/usr/bin/env python3
"""The README's commands, run as a newcomer pastes them, so the front door never goes stale.

Every line of README.md's ```sh blocks that starts with `gcsim` runs with the built binary, in
order, in a scratch folder where `scenes/` is the source tree's: each must exit 0. The long runs
get smaller sizes appended (SMALLER below), so the test stays a few seconds; the options are
still the README's. The set-up commands (the first block: CI runs them) and the install commands
(CTest install_and_build_example runs those) are not repeated here.

usage: readme_commands_test.py GCSIM README.md WORK_DIR
"""
import os
import re
import shlex
import shutil
import subprocess
import sys

# (pattern matched against the command, arguments appended): fewer nodes, loops or pixels.
SMALLER = [
    (r"^sweep radiosity", ["--nodes", "1,2,4", "--energy", "0.95", "--hemicube", "32"]),
    (r"^run radiosity", ["--energy", "0.95", "--hemicube", "32"]),
    (r"^run media --scene exp1", ["--width", "64", "--height", "48", "--photons", "20000"]),
    (r"^render ", ["--photons", "20000"]),
]
# Commands whose success is another exit status: the MPI tour's deadlocking pair (README says exit 5).
EXPECTED_STATUS = [(r"^mpirun -np 2 \./deadlock", 5)]
# The build tree's MPI compiler wrapper, as the README names it (build/release/...): run from the
# build directory under test, and the examples/ it compiles from the source tree.
WRAPPER = "build/release/apps/mpi/gcsim-mpicc"


def readme_commands(readme):
    """The gcsim command lines of the README's sh blocks, comments stripped."""
    commands, in_block = [], False
    with open(readme, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_block = line.strip() == "```sh"
                continue
            if in_block and line.startswith("gcsim "):
                commands.append(shlex.split(line, comments=True)[1:])
            elif in_block and line.startswith(WRAPPER + " "):
                commands.append(["@wrapper", *shlex.split(line, comments=True)[1:]])
    return commands


def compile_command(gcsim, readme, args):
    """A gcsim-mpicc line: the wrapper of the build gcsim is in, sources from the source tree."""
    build = os.path.dirname(os.path.dirname(os.path.dirname(gcsim)))
    source = os.path.dirname(os.path.abspath(readme))
    wrapper = os.path.join(build, "apps", "mpi", "gcsim-mpicc")
    return [wrapper, *[os.path.join(source, a) if a.startswith("examples/") else a for a in args]]


def main():
    gcsim, readme, work = (os.path.abspath(a) for a in sys.argv[1:4])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    os.symlink(os.path.join(os.path.dirname(os.path.abspath(readme)), "scenes"), os.path.join(work, "scenes"))
    commands = readme_commands(readme)
    if len(commands) < 5:
        print(f"expected the README's tour, found {len(commands)} gcsim commands in {readme}")
        return 1
    failed = 0
    for args in commands:
        line = " ".join(args)
        extra = [a for pattern, more in SMALLER if re.search(pattern, line) for a in more]
        command = compile_command(gcsim, readme, args[1:]) if args[0] == "@wrapper" else [gcsim, *args, *extra]
        expected = next((code for pattern, code in EXPECTED_STATUS if re.search(pattern, line)), 0)
        run = subprocess.run(command, cwd=work, capture_output=True, text=True, timeout=600)
        status = "ok" if run.returncode == expected else f"FAILED (exit {run.returncode}, expected {expected})"
        print(f"{status}: gcsim {line}{' + ' + ' '.join(extra) if extra else ''}")
        if run.returncode != expected:
            failed += 1
            print(run.stderr[-2000:])
    print(f"{len(commands) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
