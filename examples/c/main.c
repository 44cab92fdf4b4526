/* Host entry point of the C API example: lines go to stdout. */
#include <stdio.h>

#include "tracker_example.h"

static void print_line(const char* line) { puts(line); }

int main(void) { return mptrack_example_run(print_line); }
