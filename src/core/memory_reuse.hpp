// How the process takes memory: a render fills buffers of tens of megabytes
// (a large image, a million triangles on the screen), each of which would
// otherwise be a fresh mapping whose every page the kernel faults in and
// clears, and which is handed back when freed. Kept instead, the memory
// that loading a scene frees, and each render's, serves the next buffers
// as they are. A process's peak use is unchanged; it is kept to the end.
#pragma once

namespace rise {

// Called once, first thing in a program's main().
void keepFreedMemoryForReuse();

}  // namespace rise
