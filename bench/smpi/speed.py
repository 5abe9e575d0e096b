#!/usr/bin/env python3
"""Simulation speed side by side: the 64-rank ring of MPI_Sendrecv (8-byte messages on the 8x8
calibrated GC) under `gcsim mpirun` and under `smpirun`, in messages per wall second, and the
ratio; the same program and machine as compare.py's ring rows.

    speed.py --gcsim build/release/apps/cli/gcsim --gcsim-mpicc build/release/apps/mpi/gcsim-mpicc

Each simulator runs the ring twice, with a short and a long count of rounds (one round: every
rank sends 64 messages); the rate is the extra messages of the long run over its extra wall time,
so that start-up (loading 64 copies of the program, reading the platform) does not count. Each
pair is repeated --repeat times and the best rate kept. Wall-clock figures: they depend on the
host and its load, and no test checks them.
"""
import argparse
import sys

from smpi_runs import DEFAULT_MACHINE, RunError, Simulators, field, run

RANKS, SHAPE, BYTES = 64, "8x8", 8


def rounds_pair(text):
    short, long = (int(v) for v in text.split(","))
    if not 0 < short < long:
        raise argparse.ArgumentTypeError(f"expected SHORT,LONG rounds with 0 < SHORT < LONG, got {text!r}")
    return short, long


def rate(command_of, rounds, repeat, run_one):
    """Best messages per wall second over repeat pairs of runs, and the long run's wall time."""
    best, long_wall = 0.0, 0.0
    short, long = rounds
    for _ in range(repeat):
        (_, short_wall), (out, long_wall) = run_one(command_of(short)), run_one(command_of(long))
        field(out, r"step_s (\S+) checksum ok", "ring")
        extra_messages = (long - short) * RANKS * RANKS
        best = max(best, extra_messages / max(long_wall - short_wall, 1e-9))
    return best, long_wall


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gcsim", required=True)
    p.add_argument("--gcsim-mpicc", required=True)
    p.add_argument("--work", default="smpi-speed")
    p.add_argument("--gcsim-rounds", type=rounds_pair, default=(20, 520), help="SHORT,LONG (default 20,520)")
    p.add_argument("--smpi-rounds", type=rounds_pair, default=(1, 6), help="SHORT,LONG (default 1,6)")
    p.add_argument("--repeat", type=int, default=2, help="pairs of runs per simulator; the best counts (default 2)")
    a = p.parse_args(argv)
    try:
        sim = Simulators(a.gcsim, a.gcsim_mpicc, a.work)
        def runner(what):
            return lambda command: run(command, what)

        ours = rate(lambda r: sim.gcsim_command("sendrecv_ring", RANKS, SHAPE, DEFAULT_MACHINE, [BYTES, r]),
                    a.gcsim_rounds, a.repeat, runner("gcsim mpirun"))
        theirs = rate(lambda r: sim.smpi_command("sendrecv_ring", RANKS, SHAPE, DEFAULT_MACHINE, [BYTES, r]),
                      a.smpi_rounds, a.repeat, runner("smpirun"))
    except RunError as e:
        print(f"speed.py: {e}", file=sys.stderr)
        return 2
    print(f"ring of MPI_Sendrecv, {RANKS} ranks, {BYTES}-byte messages, {SHAPE} calibrated GC")
    print(f"gcsim mpirun: {ours[0]:12.0f} messages per wall second ({a.gcsim_rounds[1]} rounds in {ours[1]:.2f} s)")
    print(f"smpirun:      {theirs[0]:12.0f} messages per wall second ({a.smpi_rounds[1]} rounds in {theirs[1]:.2f} s)")
    print(f"ratio gcsim / SMPI: {ours[0] / theirs[0]:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
