#!/usr/bin/env python3
"""`gcsim help COMMAND...` prints what `gcsim COMMAND... --help` prints, for every command.

Walks the command tree from `gcsim --help` (each help's "Subcommands:" list), compares the two
outputs of every command byte for byte, and checks that an unknown word is a usage error (exit 2)
that names the command's real subcommands.

usage: help_command_test.py GCSIM
"""
import subprocess
import sys


def run(gcsim, *args):
    return subprocess.run([gcsim, *args], capture_output=True, text=True, timeout=60)


def subcommands(help_text):
    names, inside = [], False
    for line in help_text.splitlines():
        if line.startswith("Subcommands:"):
            inside = True
        elif inside and line.startswith("  ") and line.split():
            names.append(line.split()[0])
        elif inside:
            inside = False
    return [n for n in names if n != "help"]


def main():
    gcsim = sys.argv[1]
    failed, checked, todo = 0, 0, [[]]
    while todo:
        path = todo.pop()
        by_flag, by_help = run(gcsim, *path, "--help"), run(gcsim, "help", *path)
        checked += 1
        if by_flag.returncode != 0 or by_help.returncode != 0 or by_flag.stdout != by_help.stdout:
            failed += 1
            print(f"differs: gcsim help {' '.join(path)} (exit {by_help.returncode} / {by_flag.returncode})")
        todo.extend(path + [name] for name in subcommands(by_flag.stdout))
    bogus = run(gcsim, "help", "run", "no-such-app")
    if bogus.returncode != 2 or "radiosity" not in bogus.stderr:
        failed += 1
        print(f"unknown command: exit {bogus.returncode}, stderr {bogus.stderr!r}")
    print(f"{checked + 1 - failed} passed, {failed} failed")
    return 1 if failed or checked < 20 else 0


if __name__ == "__main__":
    sys.exit(main())
