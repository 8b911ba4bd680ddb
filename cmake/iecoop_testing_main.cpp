// The main() of a test program linked with iecoop::testing_main: doctest's runner, which
// fails a run whose --test-case filter matches no test case (docs/testing.md).
#include <iecoop/testing/main.hpp>
