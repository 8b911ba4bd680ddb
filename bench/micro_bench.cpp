// Micro-benchmarks: each iecoop construct against its hand-written equivalent, in the same
// run (the report compares their figures). Every object's address escapes first, so that
// both sides keep it in memory, as a block instance is. The kernels are in kernels.hpp; the instruction
// counts of the same kernels come from count_main.cpp under callgrind.
//
//   BM_Property_iecoop / _handwritten        fb.P_Value := fb.P_Value + 1 vs s.iValue + 1
//   BM_Method_iecoop / _handwritten          a method with named arguments vs a member function
//   BM_FbCall_iecoop / _handwritten          fb(a := x, b := 2, sum => r) vs assigning members
//   BM_Interface_iecoop / _virtual / _direct a call through an interface variable vs a plain
//                                            virtual call vs a direct call
#include <benchmark/benchmark.h>

#include "kernels.hpp"

namespace {

using namespace kernels;

void BM_Property_iecoop(benchmark::State& state) {
  FB_Prop fb;
  benchmark::DoNotOptimize(&fb);  // in memory, as a block instance is
  for (auto _ : state) {
    property_iecoop(fb);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(fb.iValue);
}
void BM_Property_handwritten(benchmark::State& state) {
  plain_prop s;
  benchmark::DoNotOptimize(&s);  // in memory, as a block instance is
  for (auto _ : state) {
    property_handwritten(s);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(s.iValue);
}
BENCHMARK(BM_Property_iecoop);
BENCHMARK(BM_Property_handwritten);

void BM_Method_iecoop(benchmark::State& state) {
  FB_Scale fb;
  benchmark::DoNotOptimize(&fb);  // in memory, as a block instance is
  for (auto _ : state) {
    benchmark::DoNotOptimize(method_iecoop(fb));
    benchmark::ClobberMemory();
  }
}
void BM_Method_handwritten(benchmark::State& state) {
  plain_scale s;
  benchmark::DoNotOptimize(&s);  // in memory, as a block instance is
  for (auto _ : state) {
    benchmark::DoNotOptimize(method_handwritten(s));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_Method_iecoop);
BENCHMARK(BM_Method_handwritten);

void BM_FbCall_iecoop(benchmark::State& state) {
  FB_Add fb;
  benchmark::DoNotOptimize(&fb);  // in memory, as a block instance is
  INT x = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(fbcall_iecoop(fb, x));
    benchmark::ClobberMemory();
  }
}
void BM_FbCall_handwritten(benchmark::State& state) {
  plain_add s;
  benchmark::DoNotOptimize(&s);  // in memory, as a block instance is
  INT x = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(fbcall_handwritten(s, x));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_FbCall_iecoop);
BENCHMARK(BM_FbCall_handwritten);

// The callee is hidden from the optimiser each iteration, so that each call dispatches.
void BM_Interface_iecoop(benchmark::State& state) {
  FB_MathMen fb;
  itf<I_Math> ip = fb;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ip);
    benchmark::DoNotOptimize(interface_iecoop(ip));
  }
}
void BM_Interface_virtual(benchmark::State& state) {
  plain_math m;
  plain_math_base* b = &m;
  for (auto _ : state) {
    benchmark::DoNotOptimize(b);
    benchmark::DoNotOptimize(interface_virtual(*b));
  }
}
void BM_Interface_direct(benchmark::State& state) {
  plain_math m;
  plain_math* p = &m;
  for (auto _ : state) {
    benchmark::DoNotOptimize(p);
    benchmark::DoNotOptimize(interface_direct(*p));
  }
}
BENCHMARK(BM_Interface_iecoop);
BENCHMARK(BM_Interface_virtual);
BENCHMARK(BM_Interface_direct);

}  // namespace

// The index comes from memory each iteration: the check stays in the loop.
template <class Object, void (*Step)(Object&)>
void BM_Array(benchmark::State& state) {
  Object r;
  benchmark::DoNotOptimize(&r);  // in memory, as a block instance is
  for (auto _ : state) {
    Step(r);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(r.iNext);
}
BENCHMARK(BM_Array<ring<array_check::bounds>, array_index_iecoop<array_check::bounds>>)->Name("BM_ArrayIndex_checked");
BENCHMARK(BM_Array<ring<array_check::none>, array_index_iecoop<array_check::none>>)->Name("BM_ArrayIndex_unchecked");
BENCHMARK(BM_Array<plain_ring, array_index_handwritten>)->Name("BM_ArrayIndex_handwritten");
BENCHMARK(BM_Array<ring<array_check::bounds>, array_loop_iecoop<array_check::bounds>>)->Name("BM_ArrayLoop_checked");
BENCHMARK(BM_Array<ring<array_check::none>, array_loop_iecoop<array_check::none>>)->Name("BM_ArrayLoop_unchecked");
BENCHMARK(BM_Array<plain_ring, array_loop_handwritten>)->Name("BM_ArrayLoop_handwritten");
