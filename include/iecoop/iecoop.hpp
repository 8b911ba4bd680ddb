// SPDX-License-Identifier: MIT
// iecoop/iecoop.hpp — everything iecoop offers, in one include. (The optional integrations
// <iecoop/fmt.hpp> and <iecoop/ostream.hpp> are not included: they pull in fmt and
// <ostream>, which the core never needs; nor are the POSIX real-time runner
// <iecoop/runtime/realtime.hpp> and the watch list <iecoop/trace/watch.hpp>, which use threads,
// and the RETAIN image in a file, <iecoop/runtime/file_storage.hpp>, which uses POSIX files.)
#pragma once

// IWYU pragma: begin_exports
#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

// types/: the elementary data types, their literals and conversions (IEC 61131-3 6.3, 6.4)
// (the elementary types' headers, then enumeration.hpp and initial_value.hpp, first: a refused
// conversion, operation or start value is then reported one include deep, which keeps the
// user's own line within the first lines of the compiler's report)
#include <iecoop/types/detail/elementary_traits.hpp>  // IWYU pragma: keep

#include <iecoop/types/bool.hpp>

#include <iecoop/types/integer.hpp>

#include <iecoop/types/real.hpp>

#include <iecoop/types/enumeration.hpp>

#include <iecoop/types/detail/initial_value.hpp>  // IWYU pragma: keep

#include <iecoop/types/array.hpp>
#include <iecoop/types/bit_access.hpp>
#include <iecoop/types/convert.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/literals.hpp>
#include <iecoop/types/pointer.hpp>
#include <iecoop/types/string.hpp>
#include <iecoop/types/subrange.hpp>
#include <iecoop/types/time.hpp>

// pou/: program organisation units and the object-oriented extensions (6.5, 6.6)
// (function_block.hpp, then lifecycle.hpp, first: the diagnostics of a call, an assignment or an
// FB_Init of a block stay near the top of the compiler's output)
#include <iecoop/pou/function_block.hpp>

#include <iecoop/pou/lifecycle.hpp>

#include <iecoop/pou/access.hpp>
#include <iecoop/pou/attributes.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/extends.hpp>
#include <iecoop/pou/global_variables.hpp>
#include <iecoop/pou/interface.hpp>
#include <iecoop/pou/lifecycle.hpp>
#include <iecoop/pou/method.hpp>
#include <iecoop/pou/named_arguments.hpp>
#include <iecoop/pou/program.hpp>
#include <iecoop/pou/property.hpp>
#include <iecoop/pou/reference.hpp>
#include <iecoop/pou/variables.hpp>

// standard/: the standard functions and function blocks (6.6.2, 6.6.3)
#include <iecoop/standard/arithmetic_functions.hpp>
#include <iecoop/standard/bistables.hpp>
#include <iecoop/standard/bit_functions.hpp>
#include <iecoop/standard/comparison_functions.hpp>
#include <iecoop/standard/conversion_functions.hpp>
#include <iecoop/standard/counters.hpp>
#include <iecoop/standard/cycle_clock.hpp>
#include <iecoop/standard/dialect.hpp>
#include <iecoop/standard/edges.hpp>
#include <iecoop/standard/numeric_functions.hpp>
#include <iecoop/standard/selection_functions.hpp>
#include <iecoop/standard/string_functions.hpp>
#include <iecoop/standard/time_functions.hpp>
#include <iecoop/standard/timers.hpp>

// sfc/: Sequential Function Charts, the language of steps and transitions (6.7)
#include <iecoop/sfc/elements.hpp>  // before chart.hpp: a refused TRANSITION is two includes deep

#include <iecoop/sfc/chart.hpp>
#include <iecoop/sfc/step.hpp>

// util/: the CODESYS Util library — PID, ramps, generators, monitors, BCD and bits (docs/util.md)
#include <iecoop/util/util.hpp>

// io/: direct addresses, the process image, located variables, I/O drivers (6.5.5)
#include <iecoop/io/address.hpp>
#include <iecoop/io/driver.hpp>
#include <iecoop/io/located.hpp>
#include <iecoop/io/process_image.hpp>

// runtime/: tasks, the scheduler, the application, RETAIN (6.8)
#include <iecoop/runtime/application.hpp>
#include <iecoop/runtime/configuration.hpp>
#include <iecoop/runtime/retain.hpp>
#include <iecoop/runtime/retain_storage.hpp>
#include <iecoop/runtime/scheduler.hpp>
#include <iecoop/runtime/task.hpp>
#include <iecoop/runtime/task_info.hpp>

// trace/: the trace recorder and its VCD, CSV and SVG writers (CODESYS Trace)
#include <iecoop/trace.hpp>
// IWYU pragma: end_exports
