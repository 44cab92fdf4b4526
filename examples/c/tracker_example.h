/* The mptrack C API example (tracker_example.c): two targets in clutter,
 * tracked by MF-BP from static memory. It prints through a callback so the
 * same code runs on a host (main.c, stdio) and on a Cortex-M7 without
 * stdio (tests/baremetal/c_example_main.cpp, semihosting). */
#ifndef MPTRACK_EXAMPLE_TRACKER_EXAMPLE_H
#define MPTRACK_EXAMPLE_TRACKER_EXAMPLE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Writes one line (no trailing newline in line). */
typedef void (*mptrack_example_print)(const char* line);

/* Runs the example; 0 if every call succeeded and both targets were
 * confirmed, 1 otherwise. */
int mptrack_example_run(mptrack_example_print print);

#ifdef __cplusplus
}
#endif

#endif
