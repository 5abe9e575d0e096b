#!/usr/bin/env python3
"""One --model for every command: `gcsim plan` refuses an unknown model as a usage error naming
the valid ones, as `gcsim run` does, and the --model help of run, plan, calibrate and validate lists
the same models, each with its summary, as `gcsim run radiosity --help` does.

  model_option_test.py GCSIM SCENE.toml
"""
import re
import subprocess
import sys

USAGE = 2


def gcsim(binary, *args):
    return subprocess.run([binary, *args], capture_output=True, text=True, timeout=300)


def model_line(binary, *command):
    """The --model line of `gcsim COMMAND --help`: its set of names and its description."""
    p = gcsim(binary, *command, "--help")
    if p.returncode != 0:
        sys.exit(f"gcsim {' '.join(command)} --help: exit status {p.returncode}\n{p.stderr}")
    lines = p.stdout.splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"\s*--model\s+TEXT:\{([^}]*)\}\s*(.*)", line)
        if m:  # a long type name puts the description on the next line
            text = m.group(2) or (lines[i + 1].strip() if i + 1 < len(lines) else "")
            return m.group(1).split(","), text
    sys.exit(f"gcsim {' '.join(command)} --help: no --model line\n{p.stdout}")


def main(binary, scene):
    failures = []
    models, run_help = model_line(binary, "run", "radiosity")
    # "name: summary" for every model, as run's help gives them.
    found = re.findall(r"(?:^|; )([a-z-]+: [^;]*)", run_help.split(": ", 1)[1])
    summaries = [s for s in found if s.split(":")[0] in models]  # not "default: ..."
    if sorted(s.split(":")[0] for s in summaries) != sorted(models):
        failures.append(f"run radiosity --model: summaries {summaries} do not match the models {models}")
    for command in (["plan"], ["calibrate"], ["validate"], ["sweep", "radiosity"], ["accuracy", "network"]):
        names, text = model_line(binary, *command)
        if names != models:
            failures.append(f"{' '.join(command)} --model accepts {names}, run radiosity {models}")
        for s in summaries:
            if s.rstrip(". ") not in text:
                failures.append(f"{' '.join(command)} --model help does not give {s!r}: {text}")

    p = gcsim(binary, "plan", scene, "--model", "bogus")
    if p.returncode != USAGE:
        failures.append(f"plan --model bogus: exit status {p.returncode}, expected {USAGE}")
    if not p.stderr.startswith("gcsim: error: "):
        failures.append(f"plan --model bogus: stderr does not start with 'gcsim: error: ': {p.stderr!r}")
    for name in models:
        if name not in p.stderr:
            failures.append(f"plan --model bogus: the error does not name the model {name!r}: {p.stderr!r}")
    if "simulated" in p.stdout or p.stdout.strip():
        failures.append(f"plan --model bogus: work was done before the error: {p.stdout!r}")

    if failures:
        sys.exit("FAIL\n" + "\n".join(failures))
    print(f"ok  models {', '.join(models)}: the same --model in every command; plan --model bogus exits {USAGE}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
