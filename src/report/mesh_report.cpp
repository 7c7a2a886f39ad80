#include "cvtmesh/report.hpp"

#include <optional>

#include <fmt/core.h>

namespace cvtmesh {

nlohmann::ordered_json mesh_json(const TopologyReport& t, const QualityReport& q) {
  nlohmann::ordered_json j;
  j["vertices"] = t.vertices;
  j["faces"] = t.triangles;
  j["edges"] = t.edges;
  j["components"] = t.components;
  j["boundary_loops"] = t.boundary_loops;
  j["nonmanifold_edges"] = t.nonmanifold_edges;
  j["nonmanifold_vertices"] = t.nonmanifold_vertices;
  j["unreferenced_vertices"] = t.unreferenced_vertices;
  j["orientable"] = t.orientable;
  j["euler_characteristic"] = t.euler_characteristic;
  j["genus"] = t.genus ? nlohmann::ordered_json(*t.genus) : nlohmann::ordered_json(nullptr);
  j["q_min"] = q.q_min;
  j["q_avg"] = q.q_avg;
  j["angle_min_deg"] = q.angle_min_deg;
  j["angle_min_avg_deg"] = q.angle_min_avg_deg;
  j["angle_max_deg"] = q.angle_max_deg;
  j["pct_angle_below_30"] = q.pct_angle_below_30;
  j["edge_length_mean"] = q.edge_length_mean;
  j["edge_length_std"] = q.edge_length_std;
  return j;
}

void add_reference_json(nlohmann::ordered_json& j, const HausdorffReport* h,
                        const TopologyReport& reference, bool same) {
  j["hausdorff_max_pct"] = h ? nlohmann::ordered_json(h->max_pct()) : nullptr;
  j["hausdorff_mean_pct"] = h ? nlohmann::ordered_json(h->mean_pct()) : nullptr;
  j["hausdorff_rms_pct"] = h ? nlohmann::ordered_json(h->rms_pct()) : nullptr;
  j["hausdorff_samples"] = h ? h->samples_per_surface : 0;
  const auto one_sided = [&](const OneSidedDistance& d) {
    return nlohmann::ordered_json{
        {"max_pct", h->pct(d.max)}, {"mean_pct", h->pct(d.mean)}, {"rms_pct", h->pct(d.rms)}};
  };
  j["hausdorff_to_reference"] = h ? one_sided(h->a_to_b) : nullptr;
  j["hausdorff_from_reference"] = h ? one_sided(h->b_to_a) : nullptr;
  j["same_topology"] = same;
  j["reference"] = {{"components", reference.components},
                    {"euler_characteristic", reference.euler_characteristic},
                    {"boundary_loops", reference.boundary_loops}};
}

std::string topology_line(const TopologyReport& t) {
  std::string s = fmt::format("{} vertices, {} triangles, {} component{}, ", t.vertices,
                              t.triangles, t.components, t.components == 1 ? "" : "s");
  s += t.is_closed()
           ? "closed"
           : fmt::format("{} boundary loop{}", t.boundary_loops, t.boundary_loops == 1 ? "" : "s");
  s += fmt::format(", Euler characteristic {}", t.euler_characteristic);
  if (t.genus) s += fmt::format(", genus {}", *t.genus);
  if (!t.is_manifold())
    s += fmt::format(", non-manifold ({} edges, {} vertices)", t.nonmanifold_edges,
                     t.nonmanifold_vertices);
  else if (!t.orientable)
    s += ", non-orientable";
  return s;
}

std::string quality_lines(const QualityReport& q) {
  return fmt::format(
      "  quality   Qmin {:.4f}   Qavg {:.4f}\n"
      "  angles    θmin {:.2f}°   θmin_ave {:.2f}°   θmax {:.2f}°   triangles with θmin < 30°: "
      "{:.2f}%\n"
      "  edges     mean length {:.6g}   std {:.6g}\n",
      q.q_min, q.q_avg, q.angle_min_deg, q.angle_min_avg_deg, q.angle_max_deg, q.pct_angle_below_30,
      q.edge_length_mean, q.edge_length_std);
}

std::string hausdorff_lines(const HausdorffReport* h, const TopologyReport& self,
                            const TopologyReport& reference) {
  std::string s =
      h ? fmt::format(
              "  hausdorff max {:.5f}%   mean {:.5f}%   rms {:.5f}% of the reference's bbox "
              "diagonal ({} samples per surface); mean to the reference {:.5f}%, from it "
              "{:.5f}%\n",
              h->max_pct(), h->mean_pct(), h->rms_pct(), h->samples_per_surface,
              h->pct(h->a_to_b.mean), h->pct(h->b_to_a.mean))
        : std::string("  hausdorff not measured\n");
  if (same_topology(self, reference)) return s + "  topology  same as the reference\n";
  return s + fmt::format(
                 "  topology  DIFFERS from the reference: components {} vs {}, Euler "
                 "characteristic {} vs {}, boundary loops {} vs {}\n",
                 self.components, reference.components, self.euler_characteristic,
                 reference.euler_characteristic, self.boundary_loops, reference.boundary_loops);
}

namespace {

void add_narrow_angle_json(nlohmann::ordered_json& j, const NarrowAngleQuality& n) {
  j["narrow_input_angles"] = n.narrow_angles;
  j["triangles_at_narrow_angles"] = n.triangles_at;
  j["angle_min_away_deg"] = n.angle_min_away_deg;
  j["q_min_away"] = n.q_min_away;
  j["narrow_angle_ratio_min"] =
      n.triangles_at > 0 ? nlohmann::ordered_json(n.ratio_at_min) : nlohmann::ordered_json(nullptr);
}

std::string narrow_angle_line(const NarrowAngleQuality& n) {
  if (n.narrow_angles == 0) return "";
  return fmt::format(
      "  narrow    {} input angle{} under {:.0f}° between features: θmin {:.2f}°, Qmin {:.3f} "
      "away from them; at them ({} triangles) the smallest angle is at least {:.2f} × the input "
      "angle\n",
      n.narrow_angles, n.narrow_angles == 1 ? "" : "s", kNarrowAngleDeg, n.angle_min_away_deg,
      n.q_min_away, n.triangles_at, n.ratio_at_min);
}

}  // namespace

MeshReport report_mesh(const std::string& name, const TriangleMesh& mesh,
                       const TriangleMesh* reference, const HausdorffReport* distance,
                       const TopologyReport* reference_topology,
                       const Features* reference_features) {
  MeshReport r;
  r.topology = analyze_topology(mesh);
  const QualityReport quality = measure_quality(mesh);
  r.json = mesh_json(r.topology, quality);
  r.text = fmt::format("{}: {}\n", name, topology_line(r.topology)) + quality_lines(quality);
  if (reference) {
    const TopologyReport ref_topology =
        reference_topology ? *reference_topology : analyze_topology(*reference);
    r.same_topology_as_reference = same_topology(r.topology, ref_topology);
    add_reference_json(r.json, distance, ref_topology, r.same_topology_as_reference);
    r.text += hausdorff_lines(distance, r.topology, ref_topology);
    const Features detected =
        reference_features ? Features{} : detect_features(*reference, FeatureSettings{});
    const NarrowAngleQuality narrow = measure_away_from(
        mesh, quality,
        narrow_feature_angles(*reference, reference_features ? *reference_features : detected,
                              kNarrowAngleDeg));
    add_narrow_angle_json(r.json, narrow);
    r.text += narrow_angle_line(narrow);
  }
  return r;
}

}  // namespace cvtmesh
