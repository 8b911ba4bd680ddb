// The version in <iecoop/config.hpp> is the CMake project's version.
#include <iecoop/config.hpp>

static_assert(IECOOP_VERSION == EXPECTED_MAJOR * 10000 + EXPECTED_MINOR * 100 + EXPECTED_PATCH,
              "iecoop: IECOOP_VERSION_* in config.hpp differ from project(iecoop VERSION ...) in CMakeLists.txt");

int main() {
  return IECOOP_VERSION_MAJOR == EXPECTED_MAJOR && IECOOP_VERSION_MINOR == EXPECTED_MINOR &&
                 IECOOP_VERSION_PATCH == EXPECTED_PATCH
             ? 0
             : 1;
}
