// Deliberately allocates: the no-heap check must reject this library
// (test core_library_no_heap_detects_canary, WILL_FAIL), proving the check can fail.
#include <cstdlib>
#include <new>

int* heap_canary_new() { return new int(1); }
void* heap_canary_malloc() { return std::malloc(16); }
