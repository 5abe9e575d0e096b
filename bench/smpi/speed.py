#!/usr/bin/env python3
"""Simulation speed side by side: the 64-rank ring of MPI_Sendrecv (8-byte messages on the 8x8
calibrated GC) under `gcsim mpirun` and under `smpirun`, in messages per wall second and per CPU
second, and the ratios; the same program and machine as compare.py's ring rows.

    speed.py --gcsim build/release/apps/cli/gcsim --gcsim-mpicc build/release/apps/mpi/gcsim-mpicc

Each simulator runs the ring twice, with a short and a long count of rounds (one round: every
rank sends 64 messages); a rate is the long run's extra messages over its extra time, so that
start-up (loading 64 copies of the program, reading the platform) does not count. Each pair is
repeated --repeat times and the best rate kept. The CPU rate (user + system time of the
simulator's processes) is the one a loaded host changes least. These are measurements of the
host: no test checks them.
"""
import argparse
import statistics
import sys

from smpi_runs import DEFAULT_MACHINE, RunError, Simulators, field, run_timed

RANKS, SHAPE, BYTES = 64, "8x8", 8


def rounds_pair(text):
    try:
        short, long = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected SHORT,LONG such as 1,6, got {text!r}") from None
    if not 0 < short < long:
        raise argparse.ArgumentTypeError(f"expected SHORT,LONG rounds with 0 < SHORT < LONG, got {text!r}")
    return short, long


def rates(command_of, rounds, repeat, what):
    """The best messages per wall second and per CPU second over `repeat` pairs of runs, and
    the long run's wall seconds."""
    best_wall = best_cpu = long_wall = 0.0
    short, long = rounds
    extra_messages = (long - short) * RANKS * RANKS
    for _ in range(repeat):
        _, short_wall, short_cpu = run_timed(command_of(short), what)
        out, long_wall, long_cpu = run_timed(command_of(long), what)
        field(out, r"step_s (\S+) checksum ok", what)
        best_wall = max(best_wall, extra_messages / max(long_wall - short_wall, 1e-9))
        best_cpu = max(best_cpu, extra_messages / max(long_cpu - short_cpu, 1e-9))
    return best_wall, best_cpu, long_wall


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gcsim", required=True, help="the gcsim executable")
    p.add_argument("--gcsim-mpicc", required=True, help="gcsim's compiler wrapper")
    p.add_argument("--work", default="smpi-speed", help="folder for the programs and platform (default: smpi-speed)")
    p.add_argument("--gcsim-rounds", type=rounds_pair, default=(20, 520), help="SHORT,LONG (default 20,520)")
    p.add_argument("--smpi-rounds", type=rounds_pair, default=(1, 6), help="SHORT,LONG (default 1,6)")
    p.add_argument("--repeat", type=int, default=2, help="pairs of runs per simulator; the best counts (default 2)")
    p.add_argument("--alternate", type=int, default=1,
                   help="measure both simulators this many times in turn and print the median ratio "
                        "(a busy host moves each simulator's rate by a quarter; default 1)")
    a = p.parse_args(argv)
    if a.repeat < 1 or a.alternate < 1:
        p.error("--repeat and --alternate take a count of at least 1")
    print(f"ring of MPI_Sendrecv, {RANKS} ranks, {BYTES}-byte messages, {SHAPE} calibrated GC")
    print(f"{'':14}{'msgs/wall s':>14}{'msgs/CPU s':>14}  long run")
    wall_ratios, cpu_ratios = [], []
    try:
        sim = Simulators(a.gcsim, a.gcsim_mpicc, a.work)
        for _ in range(a.alternate):
            ours = rates(lambda r: sim.gcsim_command("sendrecv_ring", RANKS, SHAPE, DEFAULT_MACHINE, [BYTES, r]),
                         a.gcsim_rounds, a.repeat, "gcsim mpirun ring")
            theirs = rates(lambda r: sim.smpi_command("sendrecv_ring", RANKS, SHAPE, DEFAULT_MACHINE, [BYTES, r]),
                           a.smpi_rounds, a.repeat, "smpirun ring")
            for name, (wall, cpu, seconds), rounds in (("gcsim mpirun", ours, a.gcsim_rounds), ("smpirun", theirs, a.smpi_rounds)):
                print(f"{name:14}{wall:14.0f}{cpu:14.0f}  {rounds[1]} rounds, {rounds[1] * RANKS * RANKS} messages, {seconds:.2f} s")
            wall_ratios.append(ours[0] / theirs[0])
            cpu_ratios.append(ours[1] / theirs[1])
            print(f"ratio gcsim / SMPI: {wall_ratios[-1]:.1f} per wall second, {cpu_ratios[-1]:.1f} per CPU second")
    except RunError as e:
        print(f"speed.py: {e}", file=sys.stderr)
        return 2
    if a.alternate > 1:
        print(f"median of {a.alternate} ratios: {statistics.median(wall_ratios):.1f} per wall second "
              f"({min(wall_ratios):.1f}-{max(wall_ratios):.1f}), {statistics.median(cpu_ratios):.1f} per CPU second "
              f"({min(cpu_ratios):.1f}-{max(cpu_ratios):.1f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
