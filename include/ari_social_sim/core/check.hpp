#pragma once

#include <cstdio>
#include <cstdlib>

// Two strengths of internal check (input from callers is validated with exceptions instead):
//  - ARI_CHECK: an invariant that must hold in every build; failing it is a bug, so abort loudly.
//  - ARI_DCHECK: an assumption on a hot path, checked in debug builds only.
#define ARI_CHECK(condition)                                                                 \
  do {                                                                                       \
    if (!(condition)) {                                                                      \
      std::fprintf(stderr, "%s:%d: ARI_CHECK(%s) failed\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                          \
    }                                                                                        \
  } while (false)

#ifdef NDEBUG
#define ARI_DCHECK(condition) \
  do {                        \
  } while (false)
#else
#define ARI_DCHECK(condition) ARI_CHECK(condition)
#endif
