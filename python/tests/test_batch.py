"""`python3 -m cvtmesh.batch`: a folder remeshed on the local process pool and on a Dask cluster
of 2 workers that the test starts on the loopback address; failures recorded, reruns resumed.
The corpus case (../shared/data/corpus) interrupts a batch and finishes it on Dask; it skips
without the shared data."""

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

import cvtmesh
from shapes import cube, torus

SHARED = os.environ.get("CVTMESH_SHARED_DATA", "")
CORPUS = os.path.join(SHARED, "corpus")


def batch(*args, **kwargs):
    return subprocess.run([sys.executable, "-m", "cvtmesh.batch", *args], capture_output=True,
                          text=True, **kwargs)


def rows(folder):
    with open(os.path.join(folder, "cvtmesh-batch.jsonl"), encoding="utf-8") as f:
        return [json.loads(line) for line in f]


def local_dask_cluster():
    from distributed import LocalCluster

    return LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                        dashboard_address=None)


class GeneratedFolderTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.source, self.target = os.path.join(self.tmp, "in"), os.path.join(self.tmp, "out")
        os.makedirs(self.source)
        cvtmesh.write(os.path.join(self.source, "torus.off"), *torus())
        cvtmesh.write(os.path.join(self.source, "fat-torus.ply"), *torus(r=0.7))
        V, F = cube()
        cvtmesh.write(os.path.join(self.source, "cube.obj"), V, F)
        with open(os.path.join(self.source, "broken.off"), "w") as f:
            f.write("OFF\n3 1 0\n0 0 0\n")
        with open(os.path.join(self.source, "notes.txt"), "w") as f:
            f.write("not a mesh\n")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def check_rows(self, run):
        self.assertEqual(run.returncode, 2, run.stderr)  # one mesh failed
        found = {row["mesh"]: row for row in rows(self.target)}
        self.assertEqual(sorted(found), ["broken.off", "cube.obj", "fat-torus.ply", "torus.off"])
        for name in ("cube.obj", "fat-torus.ply", "torus.off"):
            row = found[name]
            self.assertEqual(row["status"], "ok", row["error"])
            self.assertEqual(row["report"]["vertices"], 300)
            self.assertTrue(row["report"]["same_topology"])
            self.assertGreater(row["seconds"], 0)
            V, F = cvtmesh.read(os.path.join(self.target, name))
            self.assertEqual(len(V), 300)
        self.assertEqual(found["broken.off"]["status"], "error")
        self.assertIn("broken.off", found["broken.off"]["error"])
        self.assertIn("broken.off", run.stderr)

    def test_local_pool_records_failures_and_resumes(self):
        self.check_rows(batch(self.source, self.target, "--vertices", "300", "--jobs", "2"))
        first = {row["mesh"]: row for row in rows(self.target)}
        again = batch(self.source, self.target, "--vertices", "300", "--jobs", "2")
        self.assertIn("3 of 4 meshes done before, skipped", again.stderr)
        self.check_rows(again)
        for row in rows(self.target):
            if row["status"] == "ok":  # not redone
                self.assertEqual(row, first[row["mesh"]])
        # Other settings: every mesh is done again.
        other = batch(self.source, self.target, "--vertices", "200", "--jobs", "2")
        self.assertNotIn("done before", other.stderr)
        self.assertEqual({row["mesh"]: row["report"]["vertices"] for row in rows(self.target)
                          if row["status"] == "ok"},
                         {"cube.obj": 200, "fat-torus.ply": 200, "torus.off": 200})

    def test_options_reach_each_remesh(self):
        # A torus with two one-triangle holes: kept by default, filled with --fill-holes.
        V, F = torus()
        cvtmesh.write(os.path.join(self.source, "holed.off"), V, np.delete(F, [0, 500], axis=0))
        batch(self.source, self.target, "--vertices", "300", "--jobs", "2", "--fill-holes")
        found = {row["mesh"]: row for row in rows(self.target)}
        self.assertEqual(found["holed.off"]["report"]["input_holes_filled"], 2)
        self.assertEqual(found["holed.off"]["report"]["boundary_loops"], 0)
        self.assertEqual(found["holed.off"]["settings"]["fill_holes"], 10)

    def test_dask_cluster(self):
        with local_dask_cluster() as cluster:
            run = batch(self.source, self.target, "--vertices", "300", "--scheduler",
                        cluster.scheduler_address)
        self.check_rows(run)

    def test_bad_folders_fail_cleanly(self):
        run = batch(os.path.join(self.tmp, "missing"), self.target, "--vertices", "300")
        self.assertEqual(run.returncode, 1)
        self.assertRegex(run.stderr, r"missing: not a folder")
        run = batch(self.source, self.source, "--vertices", "300")
        self.assertEqual(run.returncode, 1)
        self.assertRegex(run.stderr, r"is the input folder")


@unittest.skipUnless(os.path.isdir(CORPUS), f"no shared corpus at {CORPUS}")
class CorpusTest(unittest.TestCase):
    def test_interrupted_batch_finishes_on_dask(self):
        meshes = sorted(n for n in os.listdir(CORPUS) if n.endswith(".off"))
        with tempfile.TemporaryDirectory() as target:
            options = ["--vertices", "300", "--no-hausdorff", "--quiet"]
            first = subprocess.Popen([sys.executable, "-m", "cvtmesh.batch", CORPUS, target,
                                      "--jobs", "2", *options], stderr=subprocess.PIPE,
                                     text=True, start_new_session=True)
            path = os.path.join(target, "cvtmesh-batch.jsonl")
            deadline = time.monotonic() + 300
            while time.monotonic() < deadline and first.poll() is None:
                if os.path.exists(path) and len(rows(target)) >= 5:
                    break
                time.sleep(0.1)
            first.send_signal(signal.SIGINT)  # Ctrl-C
            _, err = first.communicate(timeout=120)
            self.assertEqual(first.returncode, 130, err)
            self.assertIn("interrupted", err)
            before = {row["mesh"]: row for row in rows(target)}
            self.assertGreaterEqual(len(before), 5)
            self.assertLess(len(before), len(meshes))

            with local_dask_cluster() as cluster:
                run = batch(CORPUS, target, "--scheduler", cluster.scheduler_address, *options,
                            timeout=1200)
            self.assertEqual(run.returncode, 0, run.stderr)
            after = {row["mesh"]: row for row in rows(target)}
            self.assertEqual(sorted(after), meshes)
            self.assertEqual(len(rows(target)), len(meshes))  # one row per mesh
            for name, row in after.items():
                self.assertEqual(row["status"], "ok", f"{name}: {row['error']}")
                self.assertTrue(os.path.exists(os.path.join(target, name)))
            for name, row in before.items():
                if row["status"] == "ok":
                    self.assertEqual(after[name], row)  # finished ones were not redone
            seconds = np.array([row["seconds"] for row in after.values()])
            print(f"\n{len(after)} corpus meshes at 300 vertices: {seconds.sum():.1f} s of work",
                  file=sys.stderr)


if __name__ == "__main__":
    unittest.main()
