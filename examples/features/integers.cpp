// One feature: IEC integer arithmetic. An expression is computed in the PLC's register and cut
// to the variable's width when assigned; it wraps and is never undefined behaviour; types
// widen implicitly as in ST and narrow only through a conversion; division by zero is a fault.
#include <fmt/core.h>

#include <iecoop/fmt.hpp>
#include <iecoop/iecoop.hpp>

using namespace iecoop;

int main() {
  // VAR wVar1, wVar2, wVar3 : WORD; iVar : INT; dVar : DINT; siVar : SINT; dwVar : DWORD; END_VAR
  WORD wVar1 = 65535, wVar2 = 0, wVar3;
  INT iVar = 32767;
  DINT dVar;
  SINT siVar;
  DWORD dwVar;

  dwVar = wVar1 + 1;  // dwVar := wVar1 + 1;              the register holds 65536
  fmt::print("dwVar := wVar1 + 1             {}\n", dwVar);
  wVar3 = wVar1 + 1;  // wVar3 := wVar1 + 1;              cut to WORD
  fmt::print("wVar3 := wVar1 + 1             {}\n", wVar3);
  fmt::print("(wVar1 + 1) = wVar2            {}\n", (wVar1 + 1) == wVar2);
  fmt::print("TO_WORD(wVar1 + 1) = wVar2     {}\n", TO_WORD(wVar1 + 1) == wVar2);

  dVar = iVar + 1;  // dVar := iVar + 1;                  INT widens to DINT: no overflow
  fmt::print("dVar := iVar + 1               {}\n", dVar);
  iVar = iVar + 1;  // iVar := iVar + 1;                  wraps to -32768, defined
  fmt::print("iVar := iVar + 1               {}\n", iVar);
  iVar = 32767;
  iVar = (iVar + 10) / 2;  // iVar := (iVar + 10) / 2;    16388, not -16374
  fmt::print("iVar := (32767 + 10) / 2       {}\n", iVar);

  // siVar := dVar;  does not compile: a DINT narrows only through a conversion
  siVar = DINT_TO_SINT(dVar);  // siVar := DINT_TO_SINT(dVar);   keeps the low byte
  fmt::print("DINT_TO_SINT(32768)            {}\n", siVar);
  fmt::print("REAL_TO_INT(2.5)               {}\n", REAL_TO_INT(REAL(2.5f)));
  fmt::print("REAL_TO_INT(-1.5)              {}\n", REAL_TO_INT(REAL(-1.5f)));
  fmt::print("16#FF AND BYTE#2#1010_0101     {}\n", BYTE(0xFF) & "BYTE#2#1010_0101"_iec);
  fmt::print("INT + UINT is a DINT:          {}\n", INT(-1) + UINT(65535));

  // A division by zero goes to the fault handler, and the result is 0.
  set_fault_handler([](const fault_info& f) { fmt::print("fault handler: {}: {}\n", to_string(f.kind), f.message); });
  INT iZero = 0;
  iVar = iVar / iZero;  // iVar := iVar / iZero;
  fmt::print("iVar / 0                       {}\n", iVar);
}
