// Code-generation checks (see cmake/check_codegen.cmake): a RETAIN or PERSISTENT variable is
// read and written like the plain variable it holds; only its construction and destruction
// touch the list of remanent variables.
#include <iecoop/iecoop.hpp>
#include <iecoop/runtime/retain.hpp>

using namespace iecoop;

namespace {

struct Retained {
  retain<INT> iCount;
};
// The plain variable, followed by as many bytes as the list's links take (so that the
// compiler may load as widely as it does for the retain<> variable).
struct Plain {
  INT iCount;
  detail::retained_node links;
};
static_assert(sizeof(Plain) == sizeof(Retained));
struct RetainedReal {
  persistent<REAL> rOffset;
};
struct PlainReal {
  REAL rOffset;
  detail::retained_node links;
};
static_assert(sizeof(PlainReal) == sizeof(RetainedReal));

}  // namespace

extern "C" {

// `iCount := iCount + 1;`
void iecoop_same_retain_increment_a(Retained& r) { r.iCount = r.iCount + 1; }
void iecoop_same_retain_increment_b(Plain& p) { p.iCount = p.iCount + 1; }

// `iCount := iCount * 3 - 7;`
void iecoop_same_retain_expression_a(Retained& r) { r.iCount = r.iCount * 3 - 7; }
void iecoop_same_retain_expression_b(Plain& p) { p.iCount = p.iCount * 3 - 7; }

// `rOffset := rOffset * 2.0 + 0.5;`
void iecoop_same_persistent_real_a(RetainedReal& r) { r.rOffset = r.rOffset * 2.0f + 0.5f; }
void iecoop_same_persistent_real_b(PlainReal& p) { p.rOffset = p.rOffset * 2.0f + 0.5f; }

// A read of the value.
short iecoop_same_retain_read_a(const Retained& r) { return r.iCount.get().value(); }
short iecoop_same_retain_read_b(const Plain& p) { return p.iCount.value(); }

// A test of the value.
bool iecoop_same_retain_compare_a(const Retained& r) { return r.iCount > 500; }
bool iecoop_same_retain_compare_b(const Plain& p) { return p.iCount > 500; }

}  // extern "C"
