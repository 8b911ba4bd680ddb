// The micro-benchmarks' kernels: each iecoop construct beside its hand-written equivalent,
// as one step that the Google Benchmark loop (micro_bench.cpp) and the instruction counter
// (count_main.cpp, run under callgrind) both repeat. The objects live in memory that the
// compiler must assume is read elsewhere (benchmark::ClobberMemory / an asm barrier after
// each step), so every step does its loads and stores.
#pragma once

#include <iecoop/iecoop.hpp>

namespace kernels {

using namespace iecoop;

// --- PROPERTY vs a member -----------------------------------------------------------------

// FUNCTION_BLOCK FB_Prop  VAR iValue : INT; END_VAR
// PROPERTY P_Value : INT  (Get: P_Value := iValue;  Set: iValue := P_Value;)
struct FB_Prop : function_block<FB_Prop> {
  INT iValue;
  INT P_Value_Get() { return iValue; }
  void P_Value_Set(INT value) { iValue = value; }
  [[no_unique_address]] property<INT, &FB_Prop::P_Value_Get, &FB_Prop::P_Value_Set> P_Value{this};
  void body() {}
};
struct plain_prop {
  INT iValue;
};
// fb.P_Value := fb.P_Value + 1;
inline void property_iecoop(FB_Prop& fb) { fb.P_Value = fb.P_Value + 1; }
inline void property_handwritten(plain_prop& s) { s.iValue = s.iValue + 1; }

// --- METHOD with named arguments vs a member function ---------------------------------

struct M_Scale_vars {
  DINT diValue;
  DINT diFactor = 1;
  DINT diOffset;
};
// METHOD M_Scale : DINT  VAR_INPUT diValue, diFactor, diOffset : DINT; END_VAR
struct FB_Scale : function_block<FB_Scale> {
  DINT diTotal;
  DINT M_Scale(args<M_Scale_vars> in) {
    diTotal = diTotal + in.diValue * in.diFactor + in.diOffset;
    return diTotal;
  }
  void body() {}
};
struct plain_scale {
  DINT diTotal;
  DINT scale(DINT value, DINT factor, DINT offset) {
    diTotal = diTotal + value * factor + offset;
    return diTotal;
  }
};
// fb.M_Scale(diOffset := 3, diValue := 7, diFactor := 2);
inline DINT method_iecoop(FB_Scale& fb) { return fb.M_Scale({"diOffset"_ = 3, "diValue"_ = 7, "diFactor"_ = 2}); }
inline DINT method_handwritten(plain_scale& s) { return s.scale(7, 2, 3); }

// --- FB call with parameter assignment vs assigning members ----------------------------

// FUNCTION_BLOCK FB_Add  VAR_INPUT a, b : INT; END_VAR  VAR_OUTPUT sum : INT; END_VAR
struct FB_Add : function_block<FB_Add> {
  INT a;
  INT b;
  INT sum;
  using VAR_INPUT = pins<&FB_Add::a, &FB_Add::b>;
  using VAR_OUTPUT = pins<&FB_Add::sum>;
  void body() { sum = a + b; }
};
struct plain_add {
  INT a;
  INT b;
  INT sum;
  void body() { sum = a + b; }
};
// fbAdd(a := x, b := 2, sum => result);
inline INT fbcall_iecoop(FB_Add& fb, INT x) {
  INT result;
  fb("a"_ = x, "b"_ = INT(2), "sum"_ >> result);
  return result;
}
inline INT fbcall_handwritten(plain_add& s, INT x) {
  s.a = x;
  s.b = INT(2);
  s.body();
  return s.sum;
}

// --- INTERFACE call vs a plain virtual call vs a direct call -------------------------

struct M_Add_vars {
  REAL rVal;
};
// INTERFACE I_Math  METHOD M_Add : REAL  VAR_INPUT rVal : REAL; END_VAR
struct I_Math : interface_base<I_Math> {
  virtual REAL M_Add(args<M_Add_vars> in) = 0;
};
// FUNCTION_BLOCK FB_MathMen IMPLEMENTS I_Math
struct FB_MathMen : function_block<FB_MathMen, implements<I_Math>> {
  REAL rSum;
  REAL M_Add(args<M_Add_vars> in) override {
    rSum += in.rVal;
    return rSum;
  }
  void body() {}
};
struct plain_math_base {
  plain_math_base() = default;
  plain_math_base(const plain_math_base&) = delete;
  plain_math_base& operator=(const plain_math_base&) = delete;
  virtual float add(float value) = 0;

 protected:
  ~plain_math_base() = default;
};
struct plain_math final : plain_math_base {
  float sum = 0;
  float add(float value) override {
    sum += value;
    return sum;
  }
  float add_direct(float value) {
    sum += value;
    return sum;
  }
};
// ipMath := fbMath;  ipMath.M_Add(1.5);   (the interface variable assigned elsewhere)
inline REAL interface_iecoop(const itf<I_Math>& ip) { return ip->M_Add(1.5f); }
inline float interface_virtual(plain_math_base& b) { return b.add(1.5f); }
inline float interface_direct(plain_math& m) { return m.add_direct(1.5f); }

// --- ARRAY with and without CheckBounds vs a C array --------------------------------------

// VAR aValues : ARRAY[1..64] OF DINT; iNext : DINT := 1; diSum : DINT; END_VAR
template <array_check Check>
struct ring {
  basic_array<Check, DINT, 1, 64> aValues;
  DINT iNext = 1;
  DINT diSum;
};
struct plain_ring {
  std::int32_t aValues[64]{};
  std::int32_t iNext = 1;
  std::int32_t diSum = 0;
};
// aValues[iNext] := aValues[iNext] + 1;  iNext := iNext MOD 64 + 1;   (an index from a variable)
template <array_check Check>
inline void array_index_iecoop(ring<Check>& r) {
  r.aValues[r.iNext] = r.aValues[r.iNext] + 1;
  r.iNext = r.iNext % 64 + 1;
}
inline void array_index_handwritten(plain_ring& r) {
  r.aValues[r.iNext - 1] = r.aValues[r.iNext - 1] + 1;
  r.iNext = r.iNext % 64 + 1;
}
// diSum := 0;  FOR i := 1 TO 64 DO diSum := diSum + aValues[i]; END_FOR   (bounds the compiler knows)
template <array_check Check>
inline void array_loop_iecoop(ring<Check>& r) {
  r.diSum = 0;
  for (DINT i = 1; i <= 64; i = i + 1) r.diSum = r.diSum + r.aValues[i];
}
inline void array_loop_handwritten(plain_ring& r) {
  std::uint32_t sum = 0;  // wrapping, as DINT's sum
  for (int i = 1; i <= 64; ++i) sum += static_cast<std::uint32_t>(r.aValues[i - 1]);
  r.diSum = static_cast<std::int32_t>(sum);
}

}  // namespace kernels
