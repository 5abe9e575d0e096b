#!/usr/bin/env python3
"""gcsim's MPI layer against SimGrid's SMPI on the same machine: a ping-pong (0 B .. 1 MiB over 1,
2 and 6 hops of a 4x4 mesh) and a ring of MPI_Sendrecv (4 .. 64 ranks), the simulated times of
both and their difference, as a Markdown table (docs/mpi-vs-smpi.md).

    compare.py --gcsim build/release/apps/cli/gcsim --gcsim-mpicc build/release/apps/mpi/gcsim-mpicc

Every row runs under one protocol in both: up to gcsim's eager limit on the built-in calibrated
GC, above it on gc-all-eager.toml (the same machine, every message eager). Those rows must agree
within --tolerance (1 %); exit 1 if one does not. The rows "rendezvous" run the large messages on
the default machine, where the protocols differ: gcsim's rendezvous pays a request-to-send and a
clear-to-send, one latency T(h, 0) each, and o at both ends, which SMPI's blocking send of a large
message does not; there gcsim's round trip must exceed SMPI's by exactly 4 o + 4 T(h, 0).
"""
import argparse
import pathlib
import sys

import smpi_platform
from smpi_runs import ALL_EAGER_MACHINE, DEFAULT_MACHINE, RunError, Simulators, field

PINGPONG_SHAPE, PINGPONG_WIDTH = "4x4", 4
PINGPONG_PEERS = (1, 5, 15)  # 1, 2 and 6 hops from rank 0
EAGER_SIZES = (0, 1, 1024, 16384)
LARGE_SIZES = (16385, 65536, 1048576)
RING_SHAPES = ("2x2", "4x2", "4x4", "8x4", "8x8")
RING_SIZES = ((8, DEFAULT_MACHINE), (16384, DEFAULT_MACHINE), (262144, ALL_EAGER_MACHINE))
ROUND_TRIP = r"round_trip_s (\S+) failures 0"
STEP = r"step_s (\S+) checksum ok"


def hops(a, b, width):
    return abs(a % width - b % width) + abs(a // width - b // width)


class Comparison:
    def __init__(self, simulators, tolerance):
        self.sim, self.tolerance = simulators, tolerance
        self.rows, self.failures = [], []
        self.machine = smpi_platform.Machine(smpi_platform.load_machine(DEFAULT_MACHINE))

    def record(self, kind, size, hop_text, machine, ours, theirs, expected_excess=0.0):
        difference = (ours - theirs) / theirs
        label = "rendezvous (gcsim default)" if expected_excess else pathlib.Path(machine).stem
        self.rows.append((kind, size, hop_text, label, ours, theirs, difference))
        if expected_excess:
            # The protocols differ by a known amount: check it, to the simulators' rounding.
            if abs(ours - theirs - expected_excess) > 1e-9 + 1e-9 * theirs:
                self.failures.append(f"{kind} {size} B {hop_text}: gcsim - SMPI = {ours - theirs:.9e} s, "
                                     f"expected 4 o + 4 T(h, 0) = {expected_excess:.9e} s")
        elif abs(difference) > self.tolerance:
            self.failures.append(f"{kind} {size} B {hop_text} ({label}): {difference:+.3%} exceeds {self.tolerance:.1%}")

    def latency(self, h):
        m = self.machine
        return m.message_setup + m.network_latency + (h - 1) * m.hop_latency

    def pingpong(self, peer, size, machine, reps=3):
        (ours, _), (theirs, _) = self.sim.run_both("pingpong", 16, PINGPONG_SHAPE, machine, [peer, size, reps])
        return float(field(ours, ROUND_TRIP, "gcsim pingpong")), float(field(theirs, ROUND_TRIP, "SMPI pingpong"))

    def run_pingpongs(self):
        for peer in PINGPONG_PEERS:
            h = hops(0, peer, PINGPONG_WIDTH)
            for size in EAGER_SIZES:
                self.record("ping-pong", size, f"{h}", DEFAULT_MACHINE, *self.pingpong(peer, size, DEFAULT_MACHINE))
            for size in LARGE_SIZES:
                self.record("ping-pong", size, f"{h}", ALL_EAGER_MACHINE, *self.pingpong(peer, size, ALL_EAGER_MACHINE))
                excess = 4 * self.machine.call_overhead + 4 * self.latency(h)
                self.record("ping-pong", size, f"{h}", DEFAULT_MACHINE, *self.pingpong(peer, size, DEFAULT_MACHINE), excess)

    def run_rings(self):
        for shape in RING_SHAPES:
            width, height = smpi_platform.parse_shape(shape)
            n = width * height
            for size, machine in RING_SIZES:
                (ours, _), (theirs, _) = self.sim.run_both("sendrecv_ring", n, shape, machine, [size, 1])
                self.record(f"ring {n} ranks", size, f"{shape} mesh", machine,
                            float(field(ours, STEP, "gcsim ring")), float(field(theirs, STEP, "SMPI ring")))

    def table(self):
        lines = ["| program | bytes | hops or mesh | gcsim machine | gcsim (s) | SMPI (s) | difference |",
                 "|---|---:|---|---|---:|---:|---:|"]
        for kind, size, hop_text, label, ours, theirs, difference in self.rows:
            lines.append(f"| {kind} | {size} | {hop_text} | {label} | {ours:.6e} | {theirs:.6e} | {difference:+.4%} |")
        return "\n".join(lines)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gcsim", required=True, help="the gcsim executable")
    p.add_argument("--gcsim-mpicc", required=True, help="gcsim's compiler wrapper")
    p.add_argument("--work", default="smpi-compare", help="folder for the programs and platforms (default: smpi-compare)")
    p.add_argument("--tolerance", type=float, default=0.01, help="largest relative difference (default 0.01)")
    p.add_argument("--only", choices=("pingpong", "ring"), help="run one of the two programs")
    a = p.parse_args(argv)
    try:
        c = Comparison(Simulators(a.gcsim, a.gcsim_mpicc, a.work), a.tolerance)
        if a.only != "ring":
            c.run_pingpongs()
        if a.only != "pingpong":
            c.run_rings()
    except (RunError, smpi_platform.MachineError) as e:
        print(f"compare.py: {e}", file=sys.stderr)
        return 2
    print(c.table())
    for f in c.failures:
        print(f"DIFFERS: {f}")
    print(f"{len(c.rows)} rows, {len(c.failures)} outside the expected agreement")
    return 1 if c.failures else 0


if __name__ == "__main__":
    sys.exit(main())
