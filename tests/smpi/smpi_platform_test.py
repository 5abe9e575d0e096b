#!/usr/bin/env python3
"""bench/smpi/smpi_platform.py: the SimGrid platform it writes for a gcsim machine has gcsim's
routes (X then Y, one directed channel per hop) and, on every route, gcsim's uncontended
latency less SMPI's envelope; bad machine files and shapes are refused by name."""
import pathlib
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "bench" / "smpi"))
import smpi_platform  # noqa: E402


def seconds(text):
    assert text.endswith("s"), text
    return float(text[:-1])


class PlatformOfTheCalibratedGC(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.m = smpi_platform.Machine(smpi_platform.load_machine(smpi_platform.DEFAULT_MACHINE))
        cls.root = ET.fromstring(smpi_platform.platform_xml(cls.m, 4, 3).split("\n", 2)[2])
        cls.links = {l.get("id"): l for l in cls.root.iter("link")}

    def test_the_calibrated_machines_figures(self):
        # configs/gc-powerplus-calibrated.toml: 1.82134 MB/s per link, 16 links over 4 directions.
        self.assertAlmostEqual(self.m.channel_bandwidth, 1.82134e6 * 4, places=3)
        self.assertAlmostEqual(self.m.message_setup + self.m.network_latency, 65e-6, places=12)
        self.assertAlmostEqual(self.m.hop_latency, 2e-6, places=12)
        self.assertAlmostEqual(self.m.call_overhead, 5e-6, places=15)  # [mpi]'s defaults
        self.assertEqual(self.m.eager_limit, 16384)

    def test_every_route_is_gcsims_xy_route_with_its_latency(self):
        width = 4
        routes = self.root.iter("route")
        count = 0
        for r in routes:
            s, d = int(r.get("src")[4:]), int(r.get("dst")[4:])
            ids = [l.get("id") for l in r.iter("link_ctn")]
            latency = sum(seconds(self.links[i].get("latency")) for i in ids)
            if s == d:
                self.assertEqual(ids, [f"loop{s}"])
                self.assertAlmostEqual(latency, self.m.message_setup, places=12)
                continue
            count += 1
            h = abs(s % width - d % width) + abs(s // width - d // width)
            self.assertEqual(ids[0], f"setup{s}")
            self.assertEqual(len(ids), h + 1)
            # The channels chain from s to d, X first: no Y step before the last X step.
            at, moved_y = s, False
            for link in ids[1:]:
                a, b = (int(v) for v in link[1:].split("-"))
                self.assertEqual(a, at)
                self.assertIn(abs(a - b), (1, width))
                if abs(a - b) == width:
                    moved_y = True
                else:
                    self.assertFalse(moved_y, f"route {s}->{d} steps in X after Y")
                at = b
            self.assertEqual(at, d)
            envelope = smpi_platform.SMPI_ENVELOPE_BYTES / self.m.channel_bandwidth
            expected = self.m.message_setup + self.m.network_latency + (h - 1) * self.m.hop_latency - envelope
            self.assertAlmostEqual(latency, expected, places=12)
        self.assertEqual(count, 12 * 11)

    def test_options_follow_the_mpi_table(self):
        options = smpi_platform.smpi_options(self.m)
        self.assertIn("--cfg=smpi/send-is-detached-thresh:16385", options)
        self.assertIn("--cfg=smpi/async-small-thresh:16385", options)
        self.assertIn("--cfg=smpi/os:0:5e-06:0", options)
        self.assertIn("--cfg=network/model:CM02", options)


class BadInput(unittest.TestCase):
    def machine_file(self, text):
        d = tempfile.TemporaryDirectory()
        self.addCleanup(d.cleanup)
        path = pathlib.Path(d.name) / "m.toml"
        path.write_text(text)
        return path

    def test_a_missing_file_is_named(self):
        with self.assertRaisesRegex(smpi_platform.MachineError, "nope.toml: cannot read it"):
            smpi_platform.load_machine("nope.toml")

    def test_bad_toml_names_the_file_and_line(self):
        path = self.machine_file('base = "builtin:gc-powerplus-calibrated"\n[mpi\n')
        with self.assertRaisesRegex(smpi_platform.MachineError, r"m\.toml: not TOML: .*line 2"):
            smpi_platform.load_machine(path)

    def test_another_interconnect_is_refused(self):
        path = self.machine_file('base = "builtin:gc-powerplus-calibrated"\n[topology]\ninterconnect = "torus"\n')
        with self.assertRaisesRegex(smpi_platform.MachineError, "only the mesh is mapped, got 'torus'"):
            smpi_platform.Machine(smpi_platform.load_machine(path))

    def test_a_derived_file_overrides_its_base(self):
        path = self.machine_file('base = "builtin:gc-powerplus-calibrated"\n[mpi]\neager_limit_bytes = 100\n')
        m = smpi_platform.Machine(smpi_platform.load_machine(path))
        self.assertEqual(m.eager_limit, 100)
        self.assertIn("--cfg=smpi/send-is-detached-thresh:101", smpi_platform.smpi_options(m))

    def test_a_shape_too_large_for_a_full_zone_is_refused(self):
        m = smpi_platform.Machine(smpi_platform.load_machine(smpi_platform.DEFAULT_MACHINE))
        with self.assertRaisesRegex(smpi_platform.MachineError, "--shape 32x32: 1024 nodes"):
            smpi_platform.platform_xml(m, 32, 32)

    def test_bad_shapes(self):
        for text in ("8", "0x4", "axb"):
            with self.assertRaisesRegex(smpi_platform.MachineError, "--shape"):
                smpi_platform.parse_shape(text)


if __name__ == "__main__":
    unittest.main()
