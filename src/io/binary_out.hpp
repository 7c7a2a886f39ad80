// Raw values into a binary file (binary PLY bodies), in the machine's byte order: little-endian
// on every platform cvtmesh targets.
#pragma once

#include <cstring>
#include <ostream>

namespace cvtmesh::io {

template <class T>
void put(std::ostream& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.write(bytes, sizeof(T));
}

}  // namespace cvtmesh::io
