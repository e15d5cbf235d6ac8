// How the process takes memory. A render fills buffers of tens of megabytes
// (a large image, a million triangles on the screen), and the kernel faults
// in and clears every page the first time it is touched: 4 KiB at a time,
// at a cost that a virtual machine multiplies (10 microseconds a page was
// measured on one, a third of a 1080p render). Two things cut the faults:
//  - memory freed is kept, not handed back, so that the memory that
//    loading a scene frees, and each render's, serves the next buffers as
//    they are (a process's peak use is unchanged; it is kept to the end);
//  - the heap's first gigabyte asks for transparent huge pages, so that one
//    fault brings in 2 MiB, 512 pages at once. This is what glibc's own
//    setting (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) does, which glibc reads
//    only from the environment a program starts with. The gigabyte is
//    address space only until it is used; a process under an address-space
//    limit (ulimit -v) keeps its room and is not given it.
#pragma once

namespace rise {

// Called once, first thing in a program's main().
void setUpProcessMemory();

}  // namespace rise
