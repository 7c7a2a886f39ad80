// Ctrl-C (SIGINT) and SIGTERM during a long run: the first asks the work to stop (the library
// polls interrupt_requested through its cancel callback, and nothing is written); a second
// one kills the program at once, as if no handler were installed.
#pragma once

namespace cvtmesh::cli {

void install_interrupt_handler();
bool interrupt_requested();

}  // namespace cvtmesh::cli
