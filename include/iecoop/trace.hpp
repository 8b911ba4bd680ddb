// SPDX-License-Identifier: MIT
// iecoop/trace.hpp — see what the controller does: a trace recorder for named values (pins,
// variables, PROPERTYs, located variables), sampled every cycle of a task or on change, with a
// trigger and a pre-trigger count (<iecoop/trace/recorder.hpp>), and its writers: VCD for
// GTKWave (<iecoop/trace/vcd.hpp>), CSV in iecoop-replay's format (<iecoop/trace/csv.hpp>)
// and a self-contained SVG timing chart (<iecoop/trace/svg.hpp>). No heap; the writers write
// through any `put(std::string_view)`, outside the cycle. docs/trace.md shows them all.
//
// The watch list for the real-time runner (<iecoop/trace/watch.hpp>) uses threads and is not
// included here.
#pragma once

#include <iecoop/trace/channels.hpp>
#include <iecoop/trace/csv.hpp>
#include <iecoop/trace/recorder.hpp>
#include <iecoop/trace/svg.hpp>
#include <iecoop/trace/vcd.hpp>
#include <iecoop/trace/view.hpp>
