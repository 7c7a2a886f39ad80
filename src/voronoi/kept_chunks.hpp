// For sinks that keep their chunks from one traversal to the next (PolygonSink::begin_kept).
#pragma once

#include <cstddef>
#include <vector>

namespace cvtmesh {

// Whether every chunk is kept: what a sink holds is as it was.
inline bool all_kept(const std::vector<char>& kept) {
  for (const char k : kept)
    if (!k) return false;
  return true;
}

// Each of `chunked` (one vector per chunk) sized to the chunks of `kept`, and the chunks not kept
// emptied: what a sink holds of those comes again.
template <class... Chunked>
void keep_only(const std::vector<char>& kept, Chunked&... chunked) {
  (chunked.resize(kept.size()), ...);
  for (std::size_t c = 0; c < kept.size(); ++c)
    if (!kept[c]) ((chunked[c] = {}), ...);
}

}  // namespace cvtmesh
