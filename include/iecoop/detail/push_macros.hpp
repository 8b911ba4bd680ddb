// SPDX-License-Identifier: MIT
// iecoop/detail/push_macros.hpp — saves and removes macros that collide with IEC names.
//
// Deliberately without include guard: every public iecoop header includes this file after
// its standard includes and <iecoop/detail/pop_macros.hpp> at its end. <windows.h> and
// friends define IN, OUT, TRUE, FALSE, DELETE, ERROR, interface, min and max as macros,
// glibc's <sys/param.h> MIN and MAX; a user may have defined BOOL, WORD or ABS. Inside iecoop's headers they are
// undefined; after the header the user's definitions are back exactly as they were.
// IWYU pragma: private
#pragma push_macro("IN")
#undef IN
#pragma push_macro("OUT")
#undef OUT
#pragma push_macro("OPTIONAL")
#undef OPTIONAL
#pragma push_macro("CONST")
#undef CONST
#pragma push_macro("TRUE")
#undef TRUE
#pragma push_macro("FALSE")
#undef FALSE
#pragma push_macro("ERROR")
#undef ERROR
#pragma push_macro("interface")
#undef interface
#pragma push_macro("min")
#undef min
#pragma push_macro("max")
#undef max
#pragma push_macro("MIN")
#undef MIN
#pragma push_macro("MAX")
#undef MAX
#pragma push_macro("ABS")
#undef ABS
#pragma push_macro("BOOL")
#undef BOOL
#pragma push_macro("BYTE")
#undef BYTE
#pragma push_macro("WORD")
#undef WORD
#pragma push_macro("DWORD")
#undef DWORD
#pragma push_macro("LWORD")
#undef LWORD
#pragma push_macro("SINT")
#undef SINT
#pragma push_macro("INT")
#undef INT
#pragma push_macro("DINT")
#undef DINT
#pragma push_macro("LINT")
#undef LINT
#pragma push_macro("USINT")
#undef USINT
#pragma push_macro("UINT")
#undef UINT
#pragma push_macro("UDINT")
#undef UDINT
#pragma push_macro("ULINT")
#undef ULINT
#pragma push_macro("REAL")
#undef REAL
#pragma push_macro("LREAL")
#undef LREAL
#pragma push_macro("TIME")
#undef TIME
#pragma push_macro("LTIME")
#undef LTIME
#pragma push_macro("STRING")
#undef STRING
#pragma push_macro("WSTRING")
#undef WSTRING
#pragma push_macro("LEN")
#undef LEN
#pragma push_macro("LEFT")
#undef LEFT
#pragma push_macro("RIGHT")
#undef RIGHT
#pragma push_macro("MID")
#undef MID
#pragma push_macro("CONCAT")
#undef CONCAT
#pragma push_macro("INSERT")
#undef INSERT
#pragma push_macro("DELETE")
#undef DELETE
#pragma push_macro("REPLACE")
#undef REPLACE
#pragma push_macro("FIND")
#undef FIND
