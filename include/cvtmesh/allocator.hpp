// How a program that remeshes asks its memory allocator to keep freed memory.
#pragma once

namespace cvtmesh {

// Keeps freed blocks for reuse instead of returning them to the system at once (glibc's
// mallopt; elsewhere it does nothing). Every RVD evaluation allocates and frees buffers of the
// same sizes (polygons, integrals, neighbour lists); by default glibc maps the large ones fresh
// each time and trims its heap after each free, so every evaluation pays page faults again for
// memory it has just given back: the `cvtmesh` program, which calls this first, remeshes 14-20%
// faster with it (bunny, fandisk, man at 5k vertices; igea at 10k and 50k), its peak memory
// 1-10% higher. It changes the whole process's allocator, so the library never calls it itself:
// call it at the start of a program, before any large allocation, if that suits the program.
void keep_freed_memory();

}  // namespace cvtmesh
