#include <fmt/format.h>

#include "cvtmesh/report.hpp"

namespace cvtmesh {

std::string progress_line(const RemeshProgress& p) {
  const std::string phase = p.phase;
  if (phase == "topology")
    return fmt::format("  topology {:4d}  {} seeds now; {} triangles were at defects  {:7.2f}s\n",
                       p.iteration, p.seeds, p.defects, p.elapsed_seconds);
  if (phase == "redo")
    return fmt::format(
        "  redo     {:4d}  the output lost the input's topology: again{}, {}  {:7.2f}s\n",
        p.iteration, p.seeds > 0 ? fmt::format(" at {} vertices", p.seeds) : "", p.detail,
        p.elapsed_seconds);
  if (phase == "sheets")
    return fmt::format(
        "  sheets          the output joined sheets beside the edges where they meet, or lost "
        "the input's topology: again, each sheet apart  {:7.2f}s\n",
        p.elapsed_seconds);
  return fmt::format("  {} {:4d}  energy {:.9e}  |grad| {:.3e}  {:7.2f}s\n", p.phase, p.iteration,
                     p.energy, p.gradient_norm, p.elapsed_seconds);
}

}  // namespace cvtmesh
