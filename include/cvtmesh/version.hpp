#pragma once

namespace cvtmesh {

// "MAJOR.MINOR.PATCH" of the library.
const char* version();

}  // namespace cvtmesh
