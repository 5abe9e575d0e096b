#!/usr/bin/env python3
"""A SimGrid platform and SMPI options equivalent to a gcsim machine file, for comparing
`gcsim mpirun` with `smpirun` (docs/mpi-vs-smpi.md has the mapping and why).

    smpi_platform.py [--config FILE] --shape WxH --platform OUT.xml --hostfile OUT.txt
        writes the platform and the host file (rank r on node r), and prints the smpirun
        options, one per line (--cfg=...), for `smpirun $(cat options)`.

The machine file is read with its `base = "..."` chain as gcsim reads it (a base is a file
beside the one naming it, or builtin:NAME, configs/NAME.toml); without --config it is the built-in default, the calibrated GC
(configs/gc-powerplus-calibrated.toml). Only the mesh interconnect is mapped.
"""
import argparse
import pathlib
import sys
import tomllib

CONFIGS = pathlib.Path(__file__).resolve().parents[2] / "configs"
DEFAULT_MACHINE = CONFIGS / "gc-powerplus-calibrated.toml"


MAX_NODES = 256  # a Full zone's platform grows as n^2 routes: 64 nodes are 0.9 MB of XML
SMPI_ENVELOPE_BYTES = 16  # SimGrid's Request::start: payload = size + 16


class MachineError(Exception):
    pass


def merge(base, overlay):
    """A base table with a derived file's keys on top, sub-tables merged key by key."""
    out = dict(base)
    for key, value in overlay.items():
        if isinstance(value, dict) and isinstance(out.get(key), dict):
            out[key] = merge(out[key], value)
        else:
            out[key] = value
    return out


def load_machine(path, seen=()):
    path = pathlib.Path(path)
    if path.resolve() in seen:
        raise MachineError(f"{path}: base chain loops back to itself")
    try:
        table = tomllib.loads(path.read_text())
    except OSError as e:
        raise MachineError(f"{path}: cannot read it ({e.strerror})") from e
    except tomllib.TOMLDecodeError as e:
        raise MachineError(f"{path}: not TOML: {e}") from e
    base = table.pop("base", None)
    if base is None:
        return table
    if not isinstance(base, str):
        raise MachineError(f"{path}: 'base' must be a string, a machine file or builtin:NAME")
    # builtin:NAME is the file gcsim compiles in from configs/NAME.toml.
    base_path = CONFIGS / f"{base[len('builtin:'):]}.toml" if base.startswith("builtin:") else path.parent / base
    return merge(load_machine(base_path, seen + (path.resolve(),)), table)


def number(table, section, key, default=None):
    value = table.get(section, {}).get(key, default)
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise MachineError(f"[{section}] {key}: expected a number, got {value!r}")
    return float(value)


class Machine:
    """What the comparison needs of a gcsim machine, in SI units (seconds, bytes per second)."""

    def __init__(self, table):
        topology = table.get("topology", {})
        if topology.get("interconnect", "mesh") != "mesh":
            raise MachineError(f"[topology] interconnect: only the mesh is mapped, got {topology['interconnect']!r}")
        links = number(table, "node", "comm_processors") * number(table, "node", "links_per_comm_processor")
        # A channel is the node's links facing one of its 4 mesh neighbours (MachineConfig::channel_bandwidth).
        self.channel_bandwidth = number(table, "network", "link_bandwidth_mbps") * 1e6 * links / 4
        self.message_setup = number(table, "network", "message_setup_us") * 1e-6
        self.network_latency = number(table, "network", "network_latency_us") * 1e-6
        self.hop_latency = number(table, "network", "hop_latency_us") * 1e-6
        self.clock_hz = number(table, "node", "clock_mhz") * 1e6
        self.cpus = int(number(table, "node", "cpus"))
        # [mpi]'s defaults as machine/machine_config.cpp reads them.
        self.call_overhead = number(table, "mpi", "call_overhead_us", 5.0) * 1e-6
        self.seconds_per_byte = number(table, "mpi", "ns_per_byte", 0.0) * 1e-9
        self.eager_limit = int(number(table, "mpi", "eager_limit_bytes", 16384))


def parse_shape(text):
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise MachineError(f"--shape: expected WxH such as 8x8, got {text!r}") from None
    if width < 1 or height < 1:
        raise MachineError(f"--shape: expected positive sizes, got {text!r}")
    return width, height


def xy_route(src, dst, width):
    """The directed channels (from, to) of gcsim's mesh route: X first, then Y (machine/mesh.cpp)."""
    x, y = src % width, src // width
    tx, ty = dst % width, dst // width
    hops = []
    while x != tx:
        nx = x + (1 if tx > x else -1)
        hops.append((y * width + x, y * width + nx))
        x = nx
    while y != ty:
        ny = y + (1 if ty > y else -1)
        hops.append((y * width + x, ny * width + x))
        y = ny
    return hops


def mesh_channels(width, height):
    """Every directed channel between mesh neighbours, as (from, to)."""
    for node in range(width * height):
        x, y = node % width, node // width
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            if 0 <= x + dx < width and 0 <= y + dy < height:
                yield node, (y + dy) * width + x + dx


def platform_xml(m, width, height):
    """Hosts node0..node{n-1}; per node a set-up link (the latency a message pays once) and a
    loopback; one link per directed mesh channel; a Full zone whose routes are the XY routes."""
    n = width * height
    # gcsim: latency(h) = setup + network_latency + (h - 1) hop_latency for h >= 1, latency(0) = setup.
    # SMPI sends every message with a 16-byte envelope (tag, source, communicator) that gcsim does
    # not model: the set-up link is shorter by the envelope's time on a channel, so that a message
    # alone on the network takes what gcsim's does.
    first_link_extra = m.message_setup + m.network_latency - m.hop_latency - SMPI_ENVELOPE_BYTES / m.channel_bandwidth
    if first_link_extra < 0:
        raise MachineError("[network] latencies shorter than SMPI's 16-byte envelope on a channel: cannot be matched")
    bw = f"{m.channel_bandwidth:.12g}Bps"
    if n > MAX_NODES:
        raise MachineError(f"--shape {width}x{height}: {n} nodes; a Full zone lists all n (n - 1) routes, "
                           f"at most {MAX_NODES} nodes here")
    lines = ["<?xml version='1.0'?>", '<!DOCTYPE platform SYSTEM "https://simgrid.org/simgrid.dtd">',
             '<platform version="4.1">', '<zone id="gc" routing="Full">']
    for node in range(n):
        lines.append(f'  <host id="node{node}" speed="{m.clock_hz:.12g}f" core="{m.cpus}"/>')
    for node in range(n):
        lines.append(f'  <link id="setup{node}" bandwidth="{bw}" latency="{first_link_extra:.12g}s" sharing_policy="FATPIPE"/>')
        lines.append(f'  <link id="loop{node}" bandwidth="1e18Bps" latency="{m.message_setup:.12g}s" sharing_policy="FATPIPE"/>')
    for a, b in mesh_channels(width, height):
        lines.append(f'  <link id="c{a}-{b}" bandwidth="{bw}" latency="{m.hop_latency:.12g}s"/>')
    for s in range(n):
        lines.append(f'  <route src="node{s}" dst="node{s}"><link_ctn id="loop{s}"/></route>')
        for d in range(n):
            if s == d:
                continue
            links = "".join(f'<link_ctn id="c{a}-{b}"/>' for a, b in xy_route(s, d, width))
            lines.append(f'  <route src="node{s}" dst="node{d}" symmetrical="NO"><link_ctn id="setup{s}"/>{links}</route>')
    lines += ["</zone>", "</platform>"]
    return "\n".join(lines) + "\n"


def smpi_options(m):
    """smpirun's --cfg options that make SMPI cost a message as gcsim's [mpi] layer does."""
    eager = m.eager_limit
    overhead = f"0:{m.call_overhead:.12g}:{m.seconds_per_byte:.12g}"
    return [
        "--cfg=network/model:CM02",          # max-min sharing only, no TCP factors (LV08/SMPI models)
        "--cfg=network/crosstraffic:0",      # no acknowledgement flows on the reverse route
        "--cfg=network/TCP-gamma:1e30",      # no window bound on a flow's rate
        "--cfg=smpi/bw-factor:1",            # SMPI's piecewise correction factors off
        "--cfg=smpi/lat-factor:1",
        f"--cfg=smpi/send-is-detached-thresh:{eager + 1}",  # eager up to the limit: the send returns
        f"--cfg=smpi/async-small-thresh:{eager + 1}",       # and the data leaves before the receive
        f"--cfg=smpi/os:{overhead}", f"--cfg=smpi/ois:{overhead}", f"--cfg=smpi/or:{overhead}",
        # gcsim charges o for a failed test or probe too; SMPI's sleep there, not grown per failure
        # (neither program of the comparison tests or probes).
        f"--cfg=smpi/test:{m.call_overhead:.12g}", f"--cfg=smpi/iprobe:{m.call_overhead:.12g}",
        "--cfg=smpi/grow-injected-times:no",
        f"--cfg=smpi/host-speed:{m.clock_hz:.12g}f",
        "--cfg=smpi/simulate-computation:no",  # gcsim --compute none/annotated: code between calls is free
        "--cfg=smpi/wtime:0", "--cfg=smpi/init:0",
    ]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--config", default=str(DEFAULT_MACHINE), help="gcsim machine file (default: the calibrated GC)")
    p.add_argument("--shape", required=True, help="the sub-mesh the ranks occupy, WxH (as gcsim mpirun --shape)")
    p.add_argument("--platform", required=True, help="platform XML to write")
    p.add_argument("--hostfile", required=True, help="host file to write (rank r on node r)")
    a = p.parse_args(argv)
    try:
        m = Machine(load_machine(a.config))
        width, height = parse_shape(a.shape)
        xml = platform_xml(m, width, height)
    except MachineError as e:
        print(f"smpi_platform.py: {e}", file=sys.stderr)
        return 2
    pathlib.Path(a.platform).write_text(xml)
    pathlib.Path(a.hostfile).write_text("".join(f"node{r}\n" for r in range(width * height)))
    print("\n".join(smpi_options(m)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
