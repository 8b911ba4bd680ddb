// SPDX-License-Identifier: MIT
// iecoop/testing.hpp — the test kit: unit tests of PLC designs on a PC, with doctest, in
// simulated time (docs/testing.md). Link the CMake target iecoop::testing, which brings
// doctest; in one source file of the test program define IECOOP_TESTING_MAIN before including
// this header (or link iecoop::testing_main) for a main().
//
//   testing::cycles<Body>         one block or program, called once per cycle (cycles.hpp)
//   testing::plc<Make>            a whole application, as a fixture (plc.hpp)
//     step(n), advance(T), run_until(condition, timeout), pulse(input, cycles)
//     force / write / release / forced (forcing.hpp)
//   testing::run_diagram, drive, expect, run_table     timing diagrams, CSV tables (diagram.hpp)
//   CHECK_FAULT, REQUIRE_FAULT, testing::expect_faults  faults (faults.hpp): any other fails the test case
//   readable IEC values in every failed check (values.hpp)
#pragma once

#include <doctest/doctest.h>

#include <iecoop/iecoop.hpp>
#include <iecoop/ostream.hpp>
#include <iecoop/testing/cycles.hpp>
#include <iecoop/testing/diagram.hpp>
#include <iecoop/testing/driver.hpp>
#include <iecoop/testing/faults.hpp>
#include <iecoop/testing/forcing.hpp>
#include <iecoop/testing/plc.hpp>
#include <iecoop/testing/values.hpp>

#if defined(IECOOP_TESTING_MAIN)
#include <iecoop/testing/main.hpp>
#endif
