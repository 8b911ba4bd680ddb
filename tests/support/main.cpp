// The doctest runner for iecoop's unit tests: the test kit's (<iecoop/testing/main.hpp>), which
// fails a run whose --test-case filter matches no test case (CTest splits names at ';').
#include <iecoop/testing/main.hpp>
