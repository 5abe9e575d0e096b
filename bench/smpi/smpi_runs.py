"""One MPI program built twice, with gcsim-mpicc and with SimGrid's smpicc, and run under
`gcsim mpirun` and `smpirun` on the same machine (smpi_platform.py makes SMPI's side of it).
compare.py and speed.py use it."""
import pathlib
import re
import resource
import shutil
import subprocess
import time

import smpi_platform

HERE = pathlib.Path(__file__).resolve().parent
PROGRAMS = {"pingpong": HERE / "pingpong.c", "sendrecv_ring": HERE / "sendrecv_ring.c"}
DEFAULT_MACHINE = smpi_platform.DEFAULT_MACHINE
ALL_EAGER_MACHINE = HERE / "gc-all-eager.toml"


class RunError(Exception):
    pass


def children_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(command, what):
    """Runs a command; its stdout and the wall seconds it took, or a RunError with its output."""
    return run_timed(command, what)[:2]


def run_timed(command, what):
    """Runs a command: its stdout, the wall seconds and the CPU seconds (user + system, its
    processes and theirs) it took, or a RunError with its output."""
    cpu, start = children_cpu_seconds(), time.perf_counter()
    p = subprocess.run([str(c) for c in command], capture_output=True, text=True)
    wall, cpu = time.perf_counter() - start, children_cpu_seconds() - cpu
    if p.returncode != 0:
        raise RunError(f"{what} failed (exit {p.returncode}): {' '.join(map(str, command))}\n{p.stdout}{p.stderr}")
    return p.stdout, wall, cpu


def field(output, pattern, what):
    """The first group of pattern in a program's output (its rank 0 line)."""
    m = re.search(pattern, output)
    if not m:
        raise RunError(f"{what}: no line matching {pattern!r} in its output:\n{output}")
    return m.group(1)


class Simulators:
    """The two simulators, the programs built for each, and SMPI's platforms made once per
    (machine, shape) in the work folder."""

    def __init__(self, gcsim, gcsim_mpicc, work, smpicc=None, smpirun=None):
        self.gcsim, self.gcsim_mpicc = pathlib.Path(gcsim), pathlib.Path(gcsim_mpicc)
        self.smpicc = smpicc or shutil.which("smpicc")
        self.smpirun = smpirun or shutil.which("smpirun")
        if not self.smpicc or not self.smpirun:
            raise RunError("SimGrid's smpicc and smpirun are not installed (Debian: libsimgrid-dev)")
        self.work = pathlib.Path(work)
        self.work.mkdir(parents=True, exist_ok=True)
        self.platforms = {}
        self.built = {}

    def build(self, program):
        """The program compiled by both wrappers from the same source, unchanged."""
        if program not in self.built:
            source = PROGRAMS[program]
            ours, theirs = self.work / f"{program}.gcsim", self.work / f"{program}.smpi"
            run([self.gcsim_mpicc, "-O2", "-o", ours, source], f"gcsim-mpicc {source.name}")
            run([self.smpicc, "-O2", "-o", theirs, source], f"smpicc {source.name}")
            self.built[program] = (ours, theirs)
        return self.built[program]

    def platform(self, machine, shape):
        key = (str(machine), shape)
        if key not in self.platforms:
            m = smpi_platform.Machine(smpi_platform.load_machine(machine))
            width, height = smpi_platform.parse_shape(shape)
            stem = self.work / f"{pathlib.Path(machine).stem}-{shape}"
            xml, hosts = stem.with_suffix(".xml"), stem.with_suffix(".hosts")
            xml.write_text(smpi_platform.platform_xml(m, width, height))
            hosts.write_text("".join(f"node{r}\n" for r in range(width * height)))
            self.platforms[key] = (xml, hosts, smpi_platform.smpi_options(m))
        return self.platforms[key]

    def gcsim_command(self, program, np, shape, machine, args):
        ours, _ = self.build(program)
        return [self.gcsim, "mpirun", "-np", np, "--config", machine, "--shape", shape, "--compute", "none", ours, *args]

    def smpi_command(self, program, np, shape, machine, args):
        _, theirs = self.build(program)
        xml, hosts, options = self.platform(machine, shape)
        return [self.smpirun, "-np", np, "-platform", xml, "-hostfile", hosts, *options,
                "--log=root.thres:warning", theirs, *args]

    def run_both(self, program, np, shape, machine, args):
        """(gcsim's output, wall s), (SMPI's output, wall s)."""
        what = f"{program} -np {np} {' '.join(map(str, args))}"
        return (run(self.gcsim_command(program, np, shape, machine, args), f"gcsim mpirun {what}"),
                run(self.smpi_command(program, np, shape, machine, args), f"smpirun {what}"))
