// Whether a remesh fits in memory, checked before it starts (issue 22): a job that would exceed
// what the machine or its limits allow fails at once with a clear message, instead of being
// killed after minutes of work.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace cvtmesh {

// The peak memory of a remesh of `triangles` input triangles to `seeds` seeds, in bytes, as
// measured by bench/scale.py (rounded up; see the constants' comment).
std::uint64_t estimated_peak_bytes(std::size_t triangles, std::size_t seeds);

// What this process may still allocate: the least of the system's available memory
// (MemAvailable), its cgroup's limit less its usage, and its address-space limit less its size.
// nullopt when none of them can be read.
std::optional<std::uint64_t> available_memory_bytes();

// Throws ResourceError ("needs about X GiB of memory, Y GiB are available") when the estimate
// exceeds what is available.
void check_memory_for(std::size_t triangles, std::size_t seeds);

}  // namespace cvtmesh
