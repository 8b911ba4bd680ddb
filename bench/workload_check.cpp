// CTest's check of the standard workload (no timing): each implementation reproduces the
// cross-check figures of workload.hpp over 100000 scans.
#include <cstdio>

#include "workload.hpp"

int main() {
  using namespace workload;
  const bool iecoop = cross_check(iecoop_side::reset, iecoop_side::scan, iecoop_side::read);
  const bool handwritten = cross_check(handwritten_side::reset, handwritten_side::scan, handwritten_side::read);
  const bool minimal = cross_check(minimal_side::reset, minimal_side::scan, minimal_side::read);
  std::printf("workload cross-check: iecoop %s, handwritten %s, handwritten_minimal %s\n", iecoop ? "ok" : "WRONG",
              handwritten ? "ok" : "WRONG", minimal ? "ok" : "WRONG");
  return iecoop && handwritten && minimal ? 0 : 1;
}
