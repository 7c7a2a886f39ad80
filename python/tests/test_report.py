"""`python3 -m cvtmesh.report`, checked in a real browser: headless Chromium loads the page,
every image must decode, and the numbers shown must be the report's. The screenshot is kept
in the build tree (CVTMESH_REPORT_SCREENSHOT) for people to look at."""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

import cvtmesh
from shapes import torus

CHROMIUM = shutil.which("chromium")
SCREENSHOT = os.environ.get("CVTMESH_REPORT_SCREENSHOT")


def chromium(*args):
    return subprocess.run([CHROMIUM, "--headless=new", "--no-sandbox", "--disable-gpu",
                           "--hide-scrollbars", *args], check=True, capture_output=True,
                          text=True, timeout=120)


class ReportTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp()
        V, F = torus(nu=40, nv=16)
        cls.V, cls.F = V, F
        cls.V2, cls.F2, cls.remesh = cvtmesh.remesh(V, F, vertices=10000, seed=2)
        cls.paths = {name: os.path.join(cls.tmp, name)
                     for name in ("in.off", "out.ply", "remesh.json", "report.html")}
        cvtmesh.write(cls.paths["in.off"], V, F)
        cvtmesh.write(cls.paths["out.ply"], cls.V2, cls.F2)
        with open(cls.paths["remesh.json"], "w") as f:
            json.dump(cls.remesh, f)
        start = time.monotonic()
        cls.process = subprocess.run(
            [sys.executable, "-m", "cvtmesh.report", cls.paths["in.off"], cls.paths["out.ply"],
             "-o", cls.paths["report.html"], "--remesh-json", cls.paths["remesh.json"]],
            capture_output=True, text=True)
        cls.seconds = time.monotonic() - start
        with open(cls.paths["report.html"], encoding="utf-8") as f:
            cls.page = f.read()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def test_it_writes_a_self_contained_page(self):
        self.assertEqual(self.process.returncode, 0, self.process.stderr)
        self.assertEqual(len(re.findall(r'<img [^>]*src="data:image/png;base64,', self.page)), 7)
        self.assertNotRegex(self.page, r'src="(https?:|file:|/)')
        print(f"\nreport of a {len(self.F2)}-triangle output: {self.seconds:.2f} s", file=sys.stderr)

    def test_its_numbers_are_the_reports(self):
        shown = dict(re.findall(r'data-key="(\w+)" data-mesh="output">([^<]*)<', self.page))
        quality = cvtmesh.quality(self.V2, self.F2, (self.V, self.F))
        self.assertEqual(int(shown["faces"]), self.remesh["faces"])
        self.assertEqual(int(shown["vertices"]), self.remesh["vertices"])
        self.assertAlmostEqual(float(shown["q_min"]), self.remesh["q_min"], delta=5e-5)
        self.assertAlmostEqual(float(shown["angle_min_deg"]), self.remesh["angle_min_deg"],
                               delta=5e-3)
        self.assertAlmostEqual(float(shown["hausdorff_max_pct"]), quality["hausdorff_max_pct"],
                               delta=5e-6)
        self.assertEqual(shown["same_topology"], "True")
        remesh = dict(re.findall(r'data-key="(\w+)" data-mesh="remesh">([^<]*)<', self.page))
        self.assertEqual(int(remesh["seeds_added"]), self.remesh["seeds_added"])

    def test_bad_input_is_one_line_and_a_non_zero_exit(self):
        missing = os.path.join(self.tmp, "missing.off")
        run = subprocess.run([sys.executable, "-m", "cvtmesh.report", missing,
                              self.paths["out.ply"], "-o", os.path.join(self.tmp, "x.html")],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 1)
        self.assertRegex(run.stderr, r"^cvtmesh.report: error: .*missing.off.*\n$")
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "x.html")))

    def test_corners_kept_through_float32_and_lost_when_moved(self):
        from cvtmesh.report import lost_corners

        V = self.V
        stored = V.astype(np.float32).astype(np.float64)  # as an STL output keeps them
        self.assertEqual(lost_corners(V, [0, 5, 9], stored), [])
        moved = stored.copy()
        moved[5] += 1e-3
        self.assertEqual(lost_corners(V, [0, 5, 9], moved), [5])

    @unittest.skipUnless(CHROMIUM, "chromium is not installed (scripts/deps installs it)")
    def test_a_browser_loads_it_and_decodes_every_image(self):
        url = "file://" + self.paths["report.html"]
        dom = chromium("--dump-dom", "--virtual-time-budget=10000", url).stdout
        self.assertIn('data-images-decoded="7/7"', dom)
        # The browser's DOM shows the numbers the page was written with.
        self.assertRegex(dom, r'data-key="q_min" data-mesh="output">%.4f<' % self.remesh["q_min"])
        shot = SCREENSHOT or os.path.join(self.tmp, "report.png")
        chromium(f"--screenshot={shot}", "--window-size=1000,2600", url)
        import matplotlib.image
        pixels = matplotlib.image.imread(shot)
        self.assertEqual(pixels.shape[:2], (2600, 1000))
        # Not a blank page: the views put many distinct colours on it.
        colours = np.unique((pixels[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0)
        self.assertGreater(len(colours), 500)


if __name__ == "__main__":
    unittest.main()
