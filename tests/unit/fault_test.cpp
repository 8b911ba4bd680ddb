// The fault path: handlers are installed, restored and called with the fault's kind and
// message; a returning handler lets the operation finish with its documented result.
#include "iecoop_test.hpp"

#include <string_view>

using namespace iecoop;

namespace {
int calls = 0;
fault_kind seen_kind{};
std::string_view seen_message;
void remember(const fault_info& fault) {
  ++calls;
  seen_kind = fault.kind;
  seen_message = fault.message;
}
}  // namespace

TEST_SUITE("fault path") {
  // The test kit installs its handler for each test case (faults fail the case) over the
  // one installed before: at start-up, the default handler.
  TEST_CASE("the default handler is installed at start-up") {
    CHECK((iecoop::testing::detail::kit.previous == &default_fault_handler));
    CHECK((get_fault_handler() == &iecoop::testing::detail::kit_fault_handler));
  }

  TEST_CASE("an installed handler receives every fault, and the previous one comes back") {
    calls = 0;
    const fault_handler previous = set_fault_handler(&remember);
    CHECK((previous == &iecoop::testing::detail::kit_fault_handler));
    CHECK((get_fault_handler() == &remember));
    fault(fault_kind::user, "conveyor jammed");
    CHECK(calls == 1);
    CHECK(seen_kind == fault_kind::user);
    CHECK(seen_message == "conveyor jammed");
    const DINT result = iecoop_test::opaque(DINT(5)) % iecoop_test::opaque(DINT(0));
    CHECK(result == 0);
    CHECK(calls == 2);
    CHECK(seen_kind == fault_kind::division_by_zero);
    CHECK((set_fault_handler(previous) == &remember));
    CHECK((get_fault_handler() == &iecoop::testing::detail::kit_fault_handler));
  }

  TEST_CASE("installing nullptr restores the default handler") {
    set_fault_handler(&remember);
    set_fault_handler(nullptr);
    CHECK((get_fault_handler() == &default_fault_handler));
  }

  TEST_CASE("every fault kind has a name") {
    CHECK(std::string_view(to_string(fault_kind::division_by_zero)) == "division by zero");
    CHECK(std::string_view(to_string(fault_kind::invalid_value)) == "invalid value");
    CHECK(std::string_view(to_string(fault_kind::unbound_in_out)) == "unbound VAR_IN_OUT");
    CHECK(std::string_view(to_string(fault_kind::unassigned_interface)) == "call through unassigned interface");
    CHECK(std::string_view(to_string(fault_kind::watchdog)) == "watchdog");
    CHECK(std::string_view(to_string(fault_kind::user)) == "user fault");
    CHECK(std::string_view(to_string(fault_kind::array_bounds)) == "array index out of bounds");
    CHECK(std::string_view(to_string(fault_kind::out_of_range)) == "value out of subrange");
    CHECK(std::string_view(to_string(fault_kind::null_pointer)) == "null pointer dereferenced");
  }
}
