#!/usr/bin/env python3
"""Hostile input: every reproducer a hostile user found gives its documented exit status and one
clear `gcsim: error:` message, with no crash, no hang and no lost file. Every command with each of
its output options pointed at /dev/full must fail with status 3 naming /dev/full; two outputs (or
an output and an input) naming one file must be refused before any work, the input untouched.

  hostile_input_test.py GCSIM SOURCE_DIR WORKDIR
"""
import hashlib
import os
import shutil
import subprocess
import sys

OK, RUN_FAILED, USAGE, FILE, RESOURCE = 0, 1, 2, 3, 4


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def make_inputs(work, source):
    """The hostile files, built in the work directory; returns the names the cases use."""
    deep = "[" + ".".join(["a"] * 50000) + "]\n"
    write(os.path.join(work, "deep.toml"), deep)
    fifo = os.path.join(work, "fifo.obj")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
    os.makedirs(os.path.join(work, "adir"), exist_ok=True)
    write(os.path.join(work, "base_dir.toml"), 'base = "adir"\n')
    write(os.path.join(work, "base_zero.toml"), 'base = "/dev/zero"\n')
    write(os.path.join(work, "wrap.toml"), 'base = "builtin:gc-powerplus"\n[topology]\nnodes = 2\nmesh = [4294967298, 1]\n')
    if not os.path.lexists(os.path.join(work, "random.obj")):
        os.symlink("/dev/urandom", os.path.join(work, "random.obj"))
    faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 4\nf 1 3 4\nf 2 3 4\n" + "f 1 2 3\n" * 500
    write(os.path.join(work, "tetrahedron.obj"), faces)
    # The example scene with its tetrahedron replaced by the repeated-face one, for gcsim render.
    scene_dir = os.path.join(work, "repeated")
    shutil.copytree(os.path.join(source, "scenes"), scene_dir, dirs_exist_ok=True)
    write(os.path.join(scene_dir, "meshes", "tetrahedron.obj"), faces)
    with open(os.path.join(source, "scenes", "cornell-fog.toml")) as f:
        fog = f.read()
    write(os.path.join(work, "huge-image.toml"),
          fog.replace("width = 256", "width = 16384").replace("height = 256", "height = 16384"))
    placement = "< 1.0 1.0 1.0 >\n< 0.0 0.0 0.0 >\n< 0.0 0.0 0.0 >\nEND_FILE\n"
    write(os.path.join(work, "zero.wld"), "WORLD zero\n/dev/zero\n" + placement)
    write(os.path.join(work, "fifo.wld"), "WORLD fifo\nfifo.obj\n" + placement)
    write(os.path.join(work, "overflow.json"), '{"simulated": {"s": 1e309}, "wall": 1}')


# (arguments, expected status, text the error must contain); {work} and {src} are substituted.
CASES = [
    # Crashes: a 50,000-part TOML header; a face repeated 500 times (the BVH stays shallow).
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "deep.toml"], FILE, "deep.toml:1"),
    (["plan", "deep.toml", "--sample-loops", "0"], FILE, "more than 64 parts"),
    (["run", "raytrace", "--scene", "tetrahedron.obj", "--nodes", "1", "--size", "8"], OK, None),
    (["render", "repeated/example.toml", "--nodes", "2"], OK, None),
    # Hangs and unbounded reads: devices, FIFOs and directories are named as what they are.
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "/dev/zero"], FILE, "device"),
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "fifo.obj"], FILE, "FIFO"),
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "base_dir.toml"], FILE, "is a directory"),
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "base_zero.toml"], FILE, "device"),
    (["run", "raytrace", "--scene", "fifo.obj", "--nodes", "1", "--size", "8"], FILE, "FIFO"),
    (["run", "raytrace", "--scene", "random.obj", "--nodes", "1", "--size", "8"], FILE, "device"),
    (["run", "radiosity", "--scene", "zero.wld", "--nodes", "1"], FILE, "zero.wld:2"),
    (["run", "radiosity", "--scene", "fifo.wld", "--nodes", "1"], FILE, "FIFO"),
    (["plot", "--sweep", "/dev/zero", "--out", "plots"], FILE, "device"),
    (["plot", "--sweep", "fifo.obj", "--out", "plots"], FILE, "FIFO"),
    (["report", "/dev/urandom", "--out", "report"], FILE, "device"),
    # Sizes checked before allocating: exit 4 at once.
    (["run", "media", "--b", "2147483648", "--nodes", "2"], RESOURCE, "node memory"),
    (["run", "media", "--b", "1e300", "--nodes", "2"], RESOURCE, "node memory"),
    (["run", "media", "--photons", "2147483647", "--nodes", "2"], RESOURCE, "photon maps"),
    (["bench", "ring", "--size", "2147483648"], RESOURCE, "node memory"),
    (["plan", "huge-image.toml", "--sample-loops", "0"], RESOURCE, "image"),
    # Integers: in range before narrowing, decimal, an explicit value never read as "default".
    (["bcast", "--nodes", "2", "--size", "1KB", "--config", "wrap.toml"], FILE, "4294967298"),
    (["bcast", "--nodes", "0x10", "--size", "1KB"], USAGE, "decimal"),
    (["bench", "ring", "--nodes", "2", "--iterations", "0x10"], USAGE, "decimal"),
    (["run", "media", "--photons", "-1", "--nodes", "2"], USAGE, "--photons"),
    (["run", "media", "--width", "", "--nodes", "2"], USAGE, "empty value"),
    (["run", "media", "--k", "", "--nodes", "2"], USAGE, "empty value"),
    (["run", "media", "--b", "-1", "--nodes", "2"], USAGE, "--b"),
    # One code per kind of failure.
    (["bcast", "--nodes", "8", "--shape", "3x3", "--size", "1KB"], USAGE, "--shape 3x3"),
    (["paje", "no-such-trace.csv"], FILE, "does not exist"),
    (["report", "overflow.json", "--out", "report"], FILE, "overflow.json"),
    (["bcast", "--nodes", "1" * 100000], USAGE, "(100000 characters)"),
]

# Every command with each output option at /dev/full: status 3 naming /dev/full.
FULL = "/dev/full"
COMMANDS_WITH_OUTPUTS = [
    (["bcast", "--nodes", "2", "--size", "1KB"], ["--json"]),
    (["bench", "ring", "--nodes", "2", "--iterations", "2"], ["--json"]),
    (["topo", "--nodes", "4"], ["--json"]),
    (["run", "raytrace", "--scene", "cornell", "--nodes", "2", "--size", "8"], ["--json", "--image"]),
    (["run", "radiosity", "--scene", "cornell", "--nodes", "2", "--hemicube", "16", "--energy", "0.5"],
     ["--json", "--image", "--steps-csv", "--radiosities"]),
    (["run", "media", "--nodes", "2", "--width", "8", "--height", "8", "--photons", "500"], ["--json", "--image"]),
    (["sweep", "raytrace", "--scene", "cornell", "--size", "8", "--nodes", "1,2"], ["--csv", "--json"]),
    (["paje", "{src}/traces/samples/bcast16_tree.csv"], ["--out"]),
    (["plan", "{src}/scenes/cornell-fog.toml", "--sample-loops", "0", "--sample-photons", "0", "--sample-tiles", "0"],
     ["--json"]),
]


def run(gcsim, args, work, env=None):
    return subprocess.run([gcsim, *args], capture_output=True, text=True, timeout=120, cwd=work, env=env)


def check(gcsim, work, args, status, text):
    p = run(gcsim, args, work)
    shown = " ".join(a if len(a) < 60 else a[:20] + "..." for a in args)
    problems = []
    if p.returncode != status:
        problems.append(f"exit status {p.returncode}, expected {status}")
    if status != OK:
        lines = p.stderr.strip().splitlines()
        if not p.stderr.startswith("gcsim: error: ") and not p.stderr.startswith("gcsim plot: error: "):
            problems.append("stderr does not start with 'gcsim: error: '")
        if len(lines) > 3 or len(p.stderr) > 600:
            problems.append(f"the error is {len(lines)} lines, {len(p.stderr)} characters (expected a line or two)")
        if text and text not in p.stderr:
            problems.append(f"stderr lacks {text!r}")
    return [f"gcsim {shown}: {x}\n  stderr: {p.stderr[:300]!r}" for x in problems]


def same_file_checks(gcsim, work):
    """Two outputs, or an output and the input, naming one file: refused, nothing touched."""
    failures = []
    scene = os.path.join(work, "tetrahedron.obj")
    with open(scene, "rb") as f:
        before = hashlib.sha256(f.read()).hexdigest()
    for args, text in [
        (["run", "raytrace", "--scene", scene, "--nodes", "1", "--size", "8", "--json", scene], "--scene"),
        (["bcast", "--nodes", "2", "--size", "1KB", "--json", "x.json", "--trace", "x.json"], "--trace x.json"),
        (["bcast", "--nodes", "2", "--size", "1KB", "--json", "x.csv", "--trace", "x.json"], "x.csv"),
        (["bcast", "--nodes", "2", "--size", "1KB", "--trace", FULL], "--trace /dev/full"),
    ]:
        failures += check(gcsim, work, args, FILE, text)
    with open(scene, "rb") as f:
        if hashlib.sha256(f.read()).hexdigest() != before:
            failures.append("the --scene OBJ was changed by a refused --json")
    for derived in ("/dev/full.csv", "/dev/full.paje"):
        if os.path.exists(derived) and os.path.getmtime(derived) > os.path.getmtime(scene):
            failures.append(f"{derived} was created beside the device")
    return failures


def full_disk_checks(gcsim, work, source):
    failures = []
    for base, outputs in COMMANDS_WITH_OUTPUTS:
        base = [a.replace("{src}", source) for a in base]
        for option in outputs:
            failures += check(gcsim, work, base + [option, FULL], FILE, FULL)
    return failures


def main(gcsim, source, work):
    os.makedirs(work, exist_ok=True)
    make_inputs(work, source)
    failures = []
    for args, status, text in CASES:
        failures += check(gcsim, work, args, status, text)
    nodes = run(gcsim, ["bcast", "--nodes", "010", "--size", "1KB"], work)
    if nodes.returncode != 0 or "10 nodes" not in nodes.stdout:
        failures.append(f"--nodes 010 should run 10 nodes (decimal), got status {nodes.returncode}: {nodes.stdout[-200:]!r}")
    silent = run(gcsim, ["plot", "--sweep", "overflow.json"], work, env={**os.environ, "GCSIM_PYTHON": "/bin/false"})
    if silent.returncode != RUN_FAILED or "GCSIM_PYTHON" not in silent.stderr:
        failures.append(f"GCSIM_PYTHON=/bin/false: status {silent.returncode}, stderr {silent.stderr!r}")
    failures += same_file_checks(gcsim, work)
    failures += full_disk_checks(gcsim, work, source)
    for f in failures:
        print("FAIL", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
