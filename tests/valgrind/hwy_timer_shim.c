/* Preloaded by memcheck.py under valgrind only. libhwy 1.0.3 (Highway; OpenImageIO -> libjxl ->
 * libhwy on Debian 12) runs RDTSCP in hwy::platform::TimerResolution() from a static
 * initializer, an instruction valgrind 3.19 does not know: every program linking libthinlight
 * died of SIGILL before main. This definition of the same (C++-mangled) function takes the
 * place of libhwy's, which calls it through its PLT; it returns a plausible resolution in ticks.
 * Nothing of thinlight is replaced or hidden. */
#include <stdint.h>

uint64_t _ZN3hwy8platform15TimerResolutionEv(void);
uint64_t _ZN3hwy8platform15TimerResolutionEv(void) { return 32; }
