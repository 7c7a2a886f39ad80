"""A page to look at a remesh: `python3 -m cvtmesh.report IN OUT -o report.html`.

One self-contained HTML file (images inlined as PNG): the input and the output side by side
from the same camera, flat shaded, as wireframes and coloured by triangle quality Q with the
worst triangles marked; the histograms of their smallest angles; the quality table of
`cvtmesh quality --ref`; the input's corners that the output lost and its feature curves drawn
over the output; and, given the remesh's JSON report (`cvtmesh remesh ... --json`, or the dict
cvtmesh.remesh returns), the vertices that topology control added.

Drawn with matplotlib (mplot3d); faces turned away from the camera are culled on closed,
consistently oriented surfaces, which halves the drawing time without changing the picture.
"""

import argparse
import base64
import html
import io
import json
import os
import sys
import tempfile
import time

import numpy as np

import cvtmesh

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the non-interactive backend)
from matplotlib.colors import LightSource, Normalize  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

# Rows of the quality table: (key of the quality dict, label, format).
TABLE_ROWS = [
    ("vertices", "vertices", "{:d}"),
    ("faces", "triangles", "{:d}"),
    ("components", "components", "{:d}"),
    ("boundary_loops", "boundary loops", "{:d}"),
    ("euler_characteristic", "Euler characteristic", "{:d}"),
    ("genus", "genus", "{}"),
    ("nonmanifold_edges", "non-manifold edges", "{:d}"),
    ("q_min", "Qmin", "{:.4f}"),
    ("q_avg", "Qavg", "{:.4f}"),
    ("angle_min_deg", "θmin (°)", "{:.2f}"),
    ("angle_min_avg_deg", "θmin average (°)", "{:.2f}"),
    ("angle_max_deg", "θmax (°)", "{:.2f}"),
    ("pct_angle_below_30", "% triangles with θmin < 30°", "{:.2f}"),
    ("edge_length_mean", "mean edge length", "{:.6g}"),
]
# Rows that compare the output with the input (`quality OUT --ref IN`).
REFERENCE_ROWS = [
    ("hausdorff_max_pct", "Hausdorff max (% of diagonal)", "{:.5f}"),
    ("hausdorff_mean_pct", "Hausdorff mean (% of diagonal)", "{:.5f}"),
    ("same_topology", "same topology as the input", "{}"),
]
WORST_MARKED = 10  # the output's worst triangles, circled on its quality view
SURFACE = np.array([0.72, 0.76, 0.88])


class Camera:
    """One view for both meshes: matplotlib's elevation and azimuth (degrees) and a cube of
    axis limits around the input's bounding box, so that the two images line up."""

    def __init__(self, vertices, elevation=20.0, azimuth=-60.0):
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        self.center, self.radius = (lo + hi) / 2, max((hi - lo).max() / 2, 1e-300)
        self.elevation, self.azimuth = elevation, azimuth
        e, a = np.radians(elevation), np.radians(azimuth)
        self.toward_viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])

    def axes(self, figure):
        ax = figure.add_axes([0, 0, 1, 1], projection="3d")
        ax.view_init(elev=self.elevation, azim=self.azimuth)
        for set_limits, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), self.center):
            set_limits(c - self.radius, c + self.radius)
        ax.set_box_aspect((1, 1, 1), zoom=1.35)
        ax.set_axis_off()
        return ax


class Mesh:
    """A mesh and what the views need of it: corners per triangle, unit normals, shapes."""

    def __init__(self, V, F, quality):
        self.V, self.F, self.quality = V, F, quality
        self.corners = V[F]
        n = np.cross(self.corners[:, 1] - self.corners[:, 0], self.corners[:, 2] - self.corners[:, 0])
        length = np.linalg.norm(n, axis=1)
        self.normals = n / np.where(length > 0, length, 1)[:, None]
        self.shapes = cvtmesh.triangle_shapes(V, F)
        # Back faces can be left out only where none can be seen: a closed, oriented surface.
        self.cullable = (quality["boundary_loops"] == 0 and quality["nonmanifold_edges"] == 0
                         and quality["orientable"])

    def facing(self, camera):
        if not self.cullable:
            return np.ones(len(self.F), dtype=bool)
        return self.normals @ camera.toward_viewer >= 0


def lost_corners(V, corners, V2):
    """The input corners with no output vertex at their position: within a millionth of the
    input's diagonal, so that an output stored in float32 (STL) still shows them kept."""
    tolerance = 1e-6 * np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    lost = []
    for start in range(0, len(corners), 64):  # bounded memory: 64 corners x all vertices
        chunk = np.asarray(corners[start:start + 64])
        gaps = np.linalg.norm(V[chunk][:, None, :] - V2[None, :, :], axis=2).min(axis=1)
        lost += [int(c) for c, gap in zip(chunk, gaps) if gap > tolerance]
    return lost


def png(figure):
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    plt.close(figure)
    return buffer.getvalue()


def view(mesh, camera, style, marks=()):
    """One image of `mesh`: style "shaded", "wireframe" or "quality". `marks`: (points, colour,
    marker, label) drawn on top."""
    figure = plt.figure(figsize=(4.2, 4.2), dpi=100)
    ax = camera.axes(figure)
    keep = mesh.facing(camera)
    if style == "shaded":
        light = LightSource(azdeg=315, altdeg=45).shade_normals(mesh.normals[keep], fraction=1.0)
        colours = np.clip(0.25 + 0.75 * light[:, None], 0, 1) * SURFACE
        edges, width = "none", 0
    elif style == "wireframe":
        colours, edges, width = "white", (0.1, 0.1, 0.2), 0.25
    else:
        colours = plt.get_cmap("RdYlGn")(Normalize(0.3, 1.0)(mesh.shapes["q"][keep]))
        edges, width = (0.2, 0.2, 0.2, 0.4), 0.1
    ax.add_collection3d(Poly3DCollection(mesh.corners[keep], facecolors=colours,
                                         edgecolors=edges, linewidths=width))
    for item in marks:
        if isinstance(item, Line3DCollection):
            ax.add_collection3d(item)
            continue
        points, colour, marker, label = item
        if len(points):
            ax.scatter(*points.T, color=colour, marker=marker, s=40, depthshade=False,
                       label=label, zorder=10)
    if any(not isinstance(m, Line3DCollection) and len(m[0]) for m in marks):
        ax.legend(loc="lower left", fontsize=7, frameon=False)
    return png(figure)


def angle_histogram(input_mesh, output_mesh):
    figure, ax = plt.subplots(figsize=(6.4, 2.8), dpi=100)
    bins = np.linspace(0, 60, 61)
    for mesh, label, colour in ((input_mesh, "input", "#999999"), (output_mesh, "output", "#1f5fbf")):
        weights = np.full(len(mesh.F), 100.0 / len(mesh.F))
        ax.hist(mesh.shapes["min_angle_deg"], bins=bins, weights=weights, histtype="step",
                linewidth=1.6, color=colour, label=label)
    ax.axvline(30, color="#c03030", linestyle=":", linewidth=1)
    ax.set_xlabel("smallest angle of a triangle (°)")
    ax.set_ylabel("% of triangles")
    ax.legend(frameon=False)
    figure.tight_layout()
    return png(figure)


def image(data, alt):
    encoded = base64.b64encode(data).decode("ascii")
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{encoded}">'


def cell(value, form, key, which):
    text = "—" if value is None else form.format(value)
    return f'<td data-key="{key}" data-mesh="{which}">{html.escape(text)}</td>'


def quality_table(input_quality, output_quality):
    rows = [f"<tr><th>{html.escape(label)}</th>{cell(input_quality.get(key), form, key, 'input')}"
            f"{cell(output_quality.get(key), form, key, 'output')}</tr>"
            for key, label, form in TABLE_ROWS]
    rows += [f"<tr><th>{html.escape(label)}</th><td></td>"
             f"{cell(output_quality.get(key), form, key, 'output')}</tr>"
             for key, label, form in REFERENCE_ROWS]
    return ("<table><tr><th></th><th>input</th><th>output</th></tr>" + "".join(rows)
            + "</table>")


def corner_list(lost, V):
    if not len(lost):
        return "<p>Every input corner is an output vertex.</p>"
    rows = "".join(f"<tr><td>{c}</td><td>{V[c][0]:.6g}</td><td>{V[c][1]:.6g}</td>"
                   f"<td>{V[c][2]:.6g}</td></tr>" for c in lost[:50])
    more = f"<p>… and {len(lost) - 50} more.</p>" if len(lost) > 50 else ""
    return ("<table><tr><th>input vertex</th><th>x</th><th>y</th><th>z</th></tr>" + rows
            + "</table>" + more)


def remesh_lines(remesh):
    """What the remesh's own report says about features and topology control."""
    if remesh is None:
        return ("<p>The remesh's JSON report was not given (<code>--remesh-json</code>): "
                "the seeds added by topology control are not shown.</p>")
    keys = ["feature_edges_in", "feature_edges_out", "feature_edges_missing",
            "feature_edges_dropped", "sizes_adapted", "count_grown", "corners_in",
            "corners_out", "feature_hausdorff_max_pct", "seeds_added", "islands_seeded",
            "seeds_refined", "links_mended", "triangles_removed", "holes_closed", "vertices_closing_holes", "input_crossing_triangles",
            "output_crossing_triangles", "vertices_guarded", "vertices_splitting_crossings",
            "flat_ears_removed", "flat_pairs_merged", "valence_three_removed", "obtuse_corners_split",
            "short_edges_collapsed",
            "mend_rounds", "time_s"]
    rows = "".join(f'<tr><th>{k}</th><td data-key="{k}" data-mesh="remesh">'
                   f"{html.escape(str(remesh.get(k)))}</td></tr>" for k in keys if k in remesh)
    return "<table>" + rows + "</table>"


STYLE = """
body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 1000px; }
h1 { font-size: 1.35em; } h2 { font-size: 1.1em; margin-top: 1.6em; }
.pair { display: grid; grid-template-columns: 1fr 1fr; gap: 0.5em; text-align: center; }
.pair img { width: 100%; max-width: 420px; border: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 0.9em; }
td, th { border-bottom: 1px solid #e4e4e4; padding: 0.2em 0.8em; text-align: right; }
th:first-child { text-align: left; font-weight: normal; }
.note { color: #666; font-size: 0.85em; }
"""
# Marks the page as checked once every image has decoded (read by the browser test).
CHECK_IMAGES = """
window.addEventListener("load", () => {
  const images = [...document.images];
  document.body.dataset.imagesDecoded =
      images.filter(i => i.complete && i.naturalWidth > 0).length + "/" + images.length;
});
"""


def build_page(input_path, output_path, V, F, V2, F2, remesh=None, feature_angle=60.0):
    """The HTML page as a string. `remesh`: the remesh's report dict, or None."""
    start = time.monotonic()
    input_quality = cvtmesh.quality(V, F)
    output_quality = cvtmesh.quality(V2, F2, (V, F))
    source, result = Mesh(V, F, input_quality), Mesh(V2, F2, output_quality)
    camera = Camera(V)

    # The input's features as remesh finds them by default: at the output's scale.
    found = cvtmesh.features(V, F, feature_angle, scale=output_quality["edge_length_mean"])
    lost = lost_corners(V, found["corners"], V2)
    feature_lines = Line3DCollection(V[found["edges"]], colors="#1f5fbf", linewidths=1.2)
    added = np.asarray(remesh.get("vertices_added", []) if remesh else [], dtype=int)
    worst = np.argsort(result.shapes["q"])[:WORST_MARKED]

    views = {
        "flat shaded": (view(source, camera, "shaded"),
                        view(result, camera, "shaded",
                             [feature_lines,
                              (V[lost], "#d02020", "x", "input corner lost"),
                              (V2[added], "#ff8c00", "o", "added by topology control")])),
        "wireframe": (view(source, camera, "wireframe"), view(result, camera, "wireframe")),
        "quality Q (red 0.3 or less, green 1)": (
            view(source, camera, "quality"),
            view(result, camera, "quality",
                 [(result.corners[worst].mean(axis=1), "#000000", "o",
                   f"{len(worst)} worst triangles")])),
    }
    sections = []
    for title, (left, right) in views.items():
        sections.append(f"<h2>{html.escape(title)}</h2><div class='pair'>"
                        f"<div>{image(left, 'input, ' + title)}<br>input</div>"
                        f"<div>{image(right, 'output, ' + title)}<br>output</div></div>")
    seconds = time.monotonic() - start
    name_in, name_out = html.escape(os.path.basename(input_path)), html.escape(
        os.path.basename(output_path))
    return f"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>cvtmesh report: {name_out}</title>
<style>{STYLE}</style><script>{CHECK_IMAGES}</script></head>
<body>
<h1>cvtmesh report: {name_in} → {name_out}</h1>
<p>{input_quality['faces']} → {output_quality['faces']} triangles;
Qmin {input_quality['q_min']:.3f} → {output_quality['q_min']:.3f};
θmin {input_quality['angle_min_deg']:.1f}° → {output_quality['angle_min_deg']:.1f}°;
topology {'kept' if output_quality['same_topology'] else '<b>changed</b>'}.</p>
{''.join(sections[:1])}
<p class="note">Over the output: the input's feature curves (blue; detected at {feature_angle:g}°
at the output's scale, as remesh does), input corners the output lost (red ×) and vertices
that topology control added (orange).</p>
{''.join(sections[1:])}
<p class="note">Circled: the output's {len(worst)} triangles of lowest Q.</p>
<h2>Smallest angles</h2>{image(angle_histogram(source, result), 'smallest-angle histogram')}
<h2>Quality (<code>cvtmesh quality OUT --ref IN</code>)</h2>
{quality_table(input_quality, output_quality)}
<h2>Features</h2>
<p>{len(found['edges'])} feature edges in {len(found['curves'])} curves,
{len(found['corners'])} corners; {len(found['corners']) - len(lost)} corners kept,
{len(lost)} lost:</p>{corner_list(lost, V)}
<h2>The remesh's report</h2>{remesh_lines(remesh)}
<p class="note">Made by cvtmesh {cvtmesh.__version__} in {seconds:.1f} s.</p>
</body></html>
"""


def write_atomically(path, text):
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".report-", suffix=".html")
    umask = os.umask(0)
    os.umask(umask)
    try:
        os.chmod(temporary, 0o666 & ~umask)  # as a file opened for writing would be
        with os.fdopen(handle, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m cvtmesh.report",
        description="Write an HTML page comparing a mesh (IN) and its remesh (OUT).")
    parser.add_argument("input", metavar="IN", help="the input mesh")
    parser.add_argument("output", metavar="OUT", help="its remesh")
    parser.add_argument("-o", "--html", required=True, help="the page to write")
    parser.add_argument("--remesh-json", help="the remesh's report (cvtmesh remesh --json)")
    parser.add_argument("--feature-angle", type=float, default=60.0,
                        help="feature detection angle, as given to remesh (default 60)")
    args = parser.parse_args(argv)
    try:
        if os.path.abspath(args.html) in (os.path.abspath(args.input),
                                          os.path.abspath(args.output)):
            raise ValueError(f"{args.html}: would write over a mesh")
        remesh = None
        if args.remesh_json:
            with open(args.remesh_json, encoding="utf-8") as f:
                remesh = json.load(f)
        V, F = cvtmesh.read(args.input)
        V2, F2 = cvtmesh.read(args.output)
        page = build_page(args.input, args.output, V, F, V2, F2, remesh, args.feature_angle)
        write_atomically(args.html, page)
    except (OSError, ValueError) as e:
        print(f"cvtmesh.report: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
