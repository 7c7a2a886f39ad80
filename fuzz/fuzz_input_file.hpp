// The fuzzed bytes as a file, for the readers that take a path: written to a file of this
// process's own (in /dev/shm when it exists, else the temporary folder), with the extension that
// picks the reader, and overwritten by the next input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace cvtmesh::fuzz {

std::filesystem::path as_file(const std::uint8_t* data, std::size_t size, const char* extension);

}  // namespace cvtmesh::fuzz
