/* The conformance programs' check: counts every check and reports a failed one on stderr with its
 * rank and line, so the program can exit 1 at the end. The including file declares `rank`. */
#ifndef GCSIM_CONFORMANCE_CHECK_H
#define GCSIM_CONFORMANCE_CHECK_H
#include <stdio.h>

static int failures = 0, checks = 0;
#define CHECK(cond)                                                                  \
  do {                                                                               \
    ++checks;                                                                        \
    if (!(cond)) {                                                                   \
      ++failures;                                                                    \
      fprintf(stderr, "rank %d: check failed line %d: %s\n", rank, __LINE__, #cond); \
    }                                                                                \
  } while (0)

#endif
