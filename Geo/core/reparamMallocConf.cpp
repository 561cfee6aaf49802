// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// jemalloc's options, for the gmsh executable CMakeLists.txt links with it:
// the pages freed are kept for the next allocations ("muzzy" pages never
// purged) instead of going back to the system after a delay. The layout
// factorizes a Laplacian per part and takes new pages for each; their
// faults were 11.6 % of the samples on the largest segmentation, and
// keeping them takes 5-10 % off the CPU time for 5-14 % more peak memory
// (bench/README.md, "The allocator"). jemalloc reads this symbol when it
// starts (its own is weak); another allocator ignores it.

extern "C" {
extern const char *malloc_conf;
const char *malloc_conf = "muzzy_decay_ms:-1";
}
