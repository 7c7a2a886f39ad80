// How a program that remeshes asks its memory allocator to keep freed memory.
#pragma once

namespace cvtmesh {

// Keeps freed blocks for reuse instead of returning them to the system at once (glibc's
// mallopt; elsewhere it does nothing). Every RVD evaluation allocates and frees buffers of the
// same sizes (polygons, integrals, neighbour lists); by default glibc maps the large ones fresh
// each time and trims its heap after each free, so every evaluation pays page faults again for
// memory it has just given back: the `cvtmesh` program, which calls this first, remeshes in
// 0.86-0.88 of the CPU time at the median with it (the shared meshes at 1k and 5k; 0.78 at best),
// the same outputs, its peak memory the same at the median and at most 1.10 times. It changes the
// whole process's allocator, so the library never calls it itself: call it at the start of a
// program, before any large allocation, if that suits the program.
void keep_freed_memory();

}  // namespace cvtmesh
