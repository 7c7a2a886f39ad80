"""The `cvtmesh` module against the CLI it mirrors, and as a Python user meets it: arrays in and
out, errors, callbacks, threads, Ctrl-C. Needs PYTHONPATH to the built package and CVTMESH_CLI
to the `cvtmesh` program (CTest sets both)."""

import json
import os
import re
import signal
import subprocess
import tempfile
import threading
import time
import unittest
import warnings

import numpy as np

import cvtmesh
from shapes import cube, torus

CLI = os.environ.get("CVTMESH_CLI", "cvtmesh")
EXAMPLES = os.environ.get("CVTMESH_EXAMPLES", "examples")
# Keys whose values are times: they differ between any two runs.
TIMES = {"time_s", "timings"}


def cli_json(*args):
    out = subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


class RemeshTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.V, cls.F = torus()
        cls.V2, cls.F2, cls.report = cvtmesh.remesh(cls.V, cls.F, vertices=600, seed=3)

    def test_the_output_is_the_input_surface_remeshed(self):
        self.assertEqual(self.V2.shape, (600, 3))
        self.assertEqual(self.V2.dtype, np.float64)
        self.assertEqual(self.F2.dtype, np.int32)
        self.assertEqual(self.F2.shape[1], 3)
        self.assertTrue(self.report["same_topology"])
        self.assertEqual(self.report["nonmanifold_edges"], 0)
        self.assertEqual(self.report["faces"], len(self.F2))
        self.assertGreater(self.report["angle_min_deg"], 20)
        q = cvtmesh.quality(self.V2, self.F2)
        self.assertEqual(q["q_min"], self.report["q_min"])
        self.assertEqual(q["genus"], 1)

    def test_outputs_are_handed_over_without_a_copy(self):
        for array in (self.V2, self.F2):
            self.assertFalse(array.flags["OWNDATA"])
            self.assertEqual(type(array.base).__name__, "PyCapsule")

    def test_report_has_the_clis_keys_and_figures(self):
        with tempfile.TemporaryDirectory() as tmp:
            mesh = os.path.join(tmp, "torus.off")
            cvtmesh.write(mesh, self.V, self.F)
            cli = cli_json("remesh", mesh, os.path.join(tmp, "out.off"), "--vertices", "600",
                           "--seed", "3", "--quiet")
            V3, F3 = cvtmesh.read(os.path.join(tmp, "out.off"))
        self.assertEqual(list(cli), list(self.report))
        for key in cli.keys() - TIMES:
            self.assertEqual(cli[key], self.report[key], key)
        np.testing.assert_array_equal(F3, self.F2)
        np.testing.assert_allclose(V3, self.V2, rtol=0, atol=0)

    def test_every_cli_option_is_a_keyword_of_the_same_name(self):
        help_text = subprocess.run([CLI, "remesh", "--help"], check=True, capture_output=True,
                                   text=True).stdout
        options = set(re.findall(r"^\s+--([a-z-]+)", help_text, re.M)) - {"help", "json"}
        signature = cvtmesh.remesh.__doc__.splitlines()[0]
        self.assertGreater(len(options), 15)
        for option in options:
            self.assertIn(option.replace("-", "_") + ":", signature, option)

    def test_same_seed_same_output_on_any_thread_count(self):
        one = cvtmesh.remesh(self.V, self.F, vertices=600, seed=3, threads=1, no_hausdorff=True)
        np.testing.assert_array_equal(one[0], self.V2)
        np.testing.assert_array_equal(one[1], self.F2)

    def test_keeping_freed_memory_changes_no_output(self):
        cvtmesh.keep_freed_memory()  # from here on, for the whole process
        again = cvtmesh.remesh(self.V, self.F, vertices=600, seed=3, no_hausdorff=True)
        np.testing.assert_array_equal(again[0], self.V2)
        np.testing.assert_array_equal(again[1], self.F2)

    def test_sizes_and_options(self):
        h = 0.15
        V2, _, r = cvtmesh.remesh(self.V, self.F, edge_length=h, no_hausdorff=True,
                                  topology_rounds=0)
        self.assertAlmostEqual(r["edge_length_mean"] / h, 1, delta=0.15)
        self.assertIsNone(r["hausdorff_mean_pct"])
        seeds = self.V[::7] * 1.01
        V2, _, r = cvtmesh.remesh(self.V, self.F, seeds=seeds, iterations=0, polish_rounds=0,
                                  no_hausdorff=True)
        # One vertex a seed, but for crowded seeds that the last sweeps collapse (1% at most).
        self.assertEqual(len(V2) + r["short_edges_collapsed"], len(seeds))
        self.assertLessEqual(r["short_edges_collapsed"], len(seeds) // 100)
        _, _, r = cvtmesh.remesh(self.V, self.F, vertices=300, optimizer="lloyd", mode="rcvt",
                                 no_hausdorff=True)
        self.assertEqual(r["vertices"], 300)

    def test_sizing_and_adaptive(self):
        # Target lengths from a function of the position, as they are: followed at the median.
        _, _, r = cvtmesh.remesh(self.V, self.F, sizing=lambda p: 0.12 + 0.04 * p[0],
                                 no_hausdorff=True)
        self.assertAlmostEqual(r["edge_length_ratio"]["median"], 1, delta=0.2)
        # The same per vertex as an array, scaled to a vertex count.
        lengths = 0.12 + 0.04 * self.V[:, 0]
        V2, _, r = cvtmesh.remesh(self.V, self.F, 400, sizing=lengths, no_hausdorff=True)
        self.assertEqual(len(V2), 400)
        V2, _, r = cvtmesh.remesh(self.V, self.F, 400, adaptive=1.5, no_hausdorff=True)
        self.assertEqual(len(V2), 400)
        self.assertTrue(r["same_topology"])
        with self.assertRaisesRegex(ValueError, "sizing"):
            cvtmesh.remesh(self.V, self.F, sizing=lengths[1:])
        with self.assertRaisesRegex(ValueError, "exclude"):
            cvtmesh.remesh(self.V, self.F, 400, sizing=lengths, adaptive=2)

    def test_fill_holes_closes_the_inputs_small_holes_first(self):
        # The torus with three of its triangles removed, apart: three holes of one triangle.
        F = np.delete(self.F, [0, 700, 1400], axis=0)
        _, _, kept = cvtmesh.remesh(self.V, F, 600, no_hausdorff=True)
        self.assertEqual(kept["boundary_loops"], 3)
        self.assertEqual(kept["input_holes_filled"], 0)
        _, _, r = cvtmesh.remesh(self.V, F, 600, fill_holes=10, no_hausdorff=True)
        self.assertEqual(r["boundary_loops"], 0)
        self.assertEqual(r["genus"], 1)
        self.assertEqual(r["input_holes_filled"], 3)
        self.assertTrue(r["same_topology"])
        with self.assertRaisesRegex(ValueError, "fill_holes"):
            cvtmesh.remesh(self.V, F, 600, fill_holes=0)

    def test_progress_callback_sees_every_iteration(self):
        seen = []
        _, _, r = cvtmesh.remesh(self.V, self.F, vertices=300, progress=seen.append,
                                 no_hausdorff=True)
        self.assertEqual(len(seen), r["iterations"])
        # A feature-free surface spends both phases' iterations on RCVT (a creased one shows
        # "ccvt" too: Remesh.AFeatureFreeSurfaceSpendsBothPhasesOnRcvt in the C++ tests).
        self.assertEqual({p.phase for p in seen}, {"rcvt"})
        self.assertTrue(all(p.energy > 0 and p.elapsed_seconds >= 0 for p in seen))
        # Only a round of topology control ("topology") or a redo ("redo") fills these.
        self.assertTrue(all(p.seeds == 0 and p.defects == 0 and p.detail == "" for p in seen))

    def test_an_exception_in_the_callback_stops_the_remesh(self):
        def stop(p):
            raise RuntimeError(f"stop at {p.iteration}")

        with self.assertRaisesRegex(RuntimeError, "stop at"):
            cvtmesh.remesh(self.V, self.F, vertices=300, progress=stop)

    def test_the_gil_is_released_while_it_works(self):
        ticks = 0
        done = threading.Event()

        def work():
            cvtmesh.remesh(self.V, self.F, vertices=2000, no_hausdorff=True)
            done.set()

        thread = threading.Thread(target=work)
        thread.start()
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)
        thread.join()
        self.assertGreater(ticks, 20)

    def test_ctrl_c_interrupts_it(self):
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            cvtmesh.remesh(self.V, self.F, vertices=20000, no_hausdorff=True)
        self.assertLess(time.monotonic() - start, 5)

    def test_feature_edges_are_in_the_given_vertex_ids_through_the_repair(self):
        V = np.concatenate([[[5.0, 5.0, 5.0]], self.V])  # unreferenced: dropped by the repair
        F = self.F + 1
        edges = [[F[0][0], F[0][1]], [F[0][1], F[0][2]]]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            _, _, r = cvtmesh.remesh(V, F, vertices=300, no_features=True, feature_edges=edges,
                                     no_hausdorff=True)
        self.assertEqual(r["feature_edges_in"], 2)
        self.assertEqual(r["corners_in"], 3)  # the two ends, and the 120° turn between them

    def test_repairs_are_warned_about(self):
        F = np.concatenate([self.F, self.F[:1]])  # one duplicate triangle
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            cvtmesh.remesh(self.V, F, vertices=200, no_hausdorff=True)
        self.assertTrue(any("duplicate triangle" in str(w.message) for w in caught))


class BadInputTest(unittest.TestCase):
    def test_bad_arrays_are_value_errors_naming_the_argument(self):
        V, F = cube()
        cases = {
            "V: expected shape": (V[:, :2], F),
            "V: row 3 has a non-finite": (np.where(np.arange(8)[:, None] == 3, np.nan, V), F),
            "F: row 0 has vertex index 8, out of range": (V, np.where(F == 0, 8, F)),
            "F: row 0 has vertex index -1": (V, np.where(F == 0, -1, F)),
            "F: expected integers": (V, F.astype(float)),
            "F: no triangles": (V, np.zeros((0, 3), int)),
            "V: expected numbers": (np.full((8, 3), "a"), F),
            "F: row 0 has vertex index -?[0-9]+, out of range": (V, F.astype(np.uint64) + 2**63),
        }
        for message, (bad_v, bad_f) in cases.items():
            with self.subTest(message):
                with self.assertRaisesRegex(ValueError, message):
                    cvtmesh.remesh(bad_v, bad_f, vertices=10)
                with self.assertRaisesRegex(ValueError, message):
                    cvtmesh.quality(bad_v, bad_f)

    def test_bad_settings_are_value_errors(self):
        V, F = cube()
        for kwargs in ({}, {"vertices": 10, "edge_length": 0.1}, {"vertices": 2},
                       {"vertices": 10, "optimizer": "newton"}, {"vertices": 10, "mode": "x"},
                       {"vertices": 10, "threads": -1}, {"edge_length": -1.0},
                       {"vertices": 10, "feature_angle": 30.0, "no_features": True},
                       {"vertices": 10, "feature_edges": [[0, 7]]}):
            with self.subTest(kwargs):
                with self.assertRaises(ValueError):
                    cvtmesh.remesh(V, F, **kwargs)
        with self.assertRaisesRegex(ValueError, "identical|same point"):
            cvtmesh.rvd(V, F, np.array([[0.5, 0.5, 0.0], [0.5, 0.5, 0.0]]))

    def test_files(self):
        V, F = cube()
        with tempfile.TemporaryDirectory() as tmp:
            with self.assertRaises(FileNotFoundError):
                cvtmesh.read(os.path.join(tmp, "missing.off"))
            with self.assertRaises(IsADirectoryError):
                cvtmesh.read(tmp)
            bad = os.path.join(tmp, "bad.off")
            with open(bad, "w") as f:
                f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n")
            with self.assertRaisesRegex(ValueError, "bad.off"):
                cvtmesh.read(bad)
            with self.assertRaisesRegex(ValueError, "extension"):
                cvtmesh.write(os.path.join(tmp, "cube.xyz"), V, F)
            with self.assertRaises(OSError):
                cvtmesh.write(os.path.join(tmp, "no", "such", "dir", "cube.off"), V, F)
            with self.assertRaisesRegex(OSError, "missing.txt: cannot open"):
                cvtmesh.remesh(V, F, seeds_file=os.path.join(tmp, "missing.txt"))
            with self.assertRaisesRegex(OSError, "missing.txt: cannot open"):
                cvtmesh.remesh(V, F, vertices=10, feature_edges=os.path.join(tmp, "missing.txt"))


class ReadWriteTest(unittest.TestCase):
    def test_every_format_round_trips(self):
        V, F = torus(nu=12, nv=6)
        with tempfile.TemporaryDirectory() as tmp:
            for ext in ("obj", "off", "ply", "stl"):
                with self.subTest(ext):
                    path = os.path.join(tmp, "t." + ext)
                    cvtmesh.write(path, V, F)
                    V2, F2 = cvtmesh.read(path)
                    expected = V.astype(np.float32) if ext == "stl" else V  # STL: float32
                    np.testing.assert_array_equal(V2[F2], expected[F])

    def test_reads_a_shipped_example(self):
        V, F = cvtmesh.read(os.path.join(EXAMPLES, "knot1.off"))
        cli = cli_json("quality", os.path.join(EXAMPLES, "knot1.off"))
        self.assertEqual((len(V), len(F)), (cli["vertices"], cli["faces"]))
        self.assertEqual(cvtmesh.quality(V, F), cli)


class MeasureTest(unittest.TestCase):
    def test_quality_against_a_reference_is_the_clis(self):
        V, F = torus()
        V2, F2, _ = cvtmesh.remesh(V, F, vertices=400, no_hausdorff=True)
        with tempfile.TemporaryDirectory() as tmp:
            a, b = os.path.join(tmp, "a.ply"), os.path.join(tmp, "b.ply")
            cvtmesh.write(a, V2, F2)
            cvtmesh.write(b, V, F)
            cli = cli_json("quality", a, "--ref", b, "--samples", "5000")
        self.assertEqual(cvtmesh.quality(V2, F2, (V, F), samples=5000), cli)

    def test_triangle_shapes_are_the_quality_reports(self):
        V, F = torus()
        shapes = cvtmesh.triangle_shapes(V, F)
        q = cvtmesh.quality(V, F)
        self.assertEqual(shapes["q"].min(), q["q_min"])
        self.assertEqual(shapes["min_angle_deg"].min(), q["angle_min_deg"])
        self.assertEqual(shapes["max_angle_deg"].max(), q["angle_max_deg"])
        equilateral = cvtmesh.triangle_shapes([[0, 0, 0], [1, 0, 0], [0.5, 3**0.5 / 2, 0]],
                                              [[0, 1, 2]])
        self.assertAlmostEqual(equilateral["q"][0], 1, delta=1e-12)

    def test_features_of_a_cube(self):
        V, F = cube()
        f = cvtmesh.features(V, F)
        self.assertEqual(f["edges"].shape, (12, 2))
        self.assertEqual(sorted(f["corners"]), list(range(8)))
        self.assertEqual(len(f["curves"]), 12)
        self.assertEqual(f["closed"], [False] * 12)
        self.assertAlmostEqual(f["narrowest_sector_deg"], 90)
        self.assertEqual(len(cvtmesh.features(V, F, angle=120)["edges"]), 0)
        # At the scale of a remesh with edges longer than half the cube's, its edges are no
        # features any more (each curve is shorter than twice the edge length).
        self.assertEqual(len(cvtmesh.features(V, F, scale=0.1)["edges"]), 12)
        self.assertEqual(len(cvtmesh.features(V, F, scale=0.6)["edges"]), 0)

    def test_lfs_of_a_torus_is_its_tube_radius_and_the_clis(self):
        V, F = torus(R=1.0, r=0.3, nu=96, nv=32)
        sizes = cvtmesh.lfs(V, F, gradation=0)
        self.assertEqual(sizes.shape, (len(V),))
        np.testing.assert_allclose(sizes, 0.3, rtol=0.1)
        with tempfile.TemporaryDirectory() as tmp:
            cvtmesh.write(os.path.join(tmp, "t.off"), V, F)
            cli = cli_json("lfs", os.path.join(tmp, "t.off"), os.path.join(tmp, "t.ply"))
        graded = cvtmesh.lfs(V, F)
        self.assertEqual(cli["lfs_min"], graded.min())
        self.assertEqual(cli["lfs_max"], graded.max())

    def test_lfs_narrows_to_the_gap_between_boundaries(self):
        # A flat strip 6 x 1: no poles (its lfs is its diagonal) but its sides are 1 apart.
        u, v = np.meshgrid(np.linspace(0, 6, 61), np.linspace(0, 1, 7))
        V = np.column_stack([u.ravel(), v.ravel(), np.zeros(u.size)])
        idx = np.arange(u.size).reshape(u.shape)
        a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, 1:], idx[1:, :-1]
        F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                            np.stack([a, c, d], -1).reshape(-1, 3)])
        for sharp in (True, False):
            sizes = cvtmesh.lfs(V, F, gradation=0, features=sharp)
            self.assertAlmostEqual(sizes.min(), 1.0, places=9)
            self.assertGreater(sizes.max(), 6.0)

    def test_rvd_cells_tile_the_surface(self):
        V, F = torus()
        rng = np.random.default_rng(1)
        seeds = V[rng.choice(len(V), 300, replace=False)] * 1.001
        d = cvtmesh.rvd(V, F, seeds, rdt=True)
        self.assertEqual(d["areas"].shape, (300,))
        self.assertEqual(d["centroids"].shape, (300, 3))
        self.assertAlmostEqual(d["areas"].sum() / d["surface_area"], 1, delta=1e-12)
        self.assertAlmostEqual(d["energies"].sum() / d["energy"], 1, delta=1e-12)
        self.assertEqual(d["rdt"].shape[1], 3)
        self.assertLess(d["rdt"].max(), 300)
        # The same figures at any scale, scaled back (the library works at unit size).
        big = cvtmesh.rvd(V * 2.0**40, F, seeds * 2.0**40)
        np.testing.assert_array_equal(big["areas"], d["areas"] * 2.0**80)


if __name__ == "__main__":
    unittest.main()
