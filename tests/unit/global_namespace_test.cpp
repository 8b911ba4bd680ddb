// iecoop injects nothing into the global namespace: after including every header, the
// global namespace may declare all of iecoop's names for itself and use them unambiguously
// (a using-declaration would clash, a using-directive would make each use ambiguous).
#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>

#include <cstddef>

int BOOL = 1, BYTE = 2, WORD = 3, DWORD = 4, LWORD = 5, SINT = 6, INT = 7, DINT = 8, LINT = 9, USINT = 10, UINT = 11,
    UDINT = 12, ULINT = 13, REAL = 14, LREAL = 15, TIME = 16, LTIME = 17, STRING = 18, WSTRING = 19, TRUE = 20,
    FALSE = 21, LEN = 22, LEFT = 23, RIGHT = 24, MID = 25, CONCAT = 26, INSERT = 27, DELETE = 28, REPLACE = 29,
    FIND = 30, INT_TO_DINT = 31, TO_INT = 32, TRUNC = 33, convert = 34, fault = 35, parse_time = 36, integer = 37,
    basic_time = 38, iec_string = 39, conversion = 40, to_text = 41, parse_result = 42, AnyInt = 43, literals = 44,
    function_block = 45, extends = 46, program = 47, args = 48, pins = 49, local = 50, in_out = 51, output = 52,
    function = 53, run_fb_init = 54, reset = 55, online_change = 56, member_of = 57, internal_access = 58,
    block_access = 59, field_name = 60, param_name = 61, first_output_t = 62, inputs_of = 63, SUPER = 64, property = 65,
    interface_base = 66, implements = 67, itf = 68, query_interface = 69, query_pointer = 70, Implements = 71,
    Property = 72, monitoring = 73, owner_only_get = 74, owner_only_set = 75;
int operator""_iec(const char*, std::size_t) { return 76; }
int operator""_(const char*, std::size_t) { return 77; }

int sum_of_globals() {
  return BOOL + BYTE + WORD + DWORD + LWORD + SINT + INT + DINT + LINT + USINT + UINT + UDINT + ULINT + REAL + LREAL +
         TIME + LTIME + STRING + WSTRING + TRUE + FALSE + LEN + LEFT + RIGHT + MID + CONCAT + INSERT + DELETE +
         REPLACE + FIND + INT_TO_DINT + TO_INT + TRUNC + convert + fault + parse_time + integer + basic_time +
         iec_string + conversion + to_text + parse_result + AnyInt + literals + function_block + extends + program +
         args + pins + local + in_out + output + function + run_fb_init + reset + online_change + member_of +
         internal_access + block_access + field_name + param_name + first_output_t + inputs_of + SUPER + property +
         interface_base + implements + itf + query_interface + query_pointer + Implements + Property + monitoring +
         owner_only_get + owner_only_set + "x"_iec + "y"_;
}

#include "iecoop_test.hpp"

TEST_CASE("the global namespace keeps every IEC name for itself") { CHECK(sum_of_globals() == 77 * 78 / 2); }
