// Seed: "面向对象的方法" (Chinese OOP page), "相关案例" (the worked case) — INTERFACE I_Math with
// the method M_Add, the property P_Result (and the method M_Mul MAIN calls), two function
// blocks implementing it, FB_MathMen and FB_MethErase, and the PROGRAM MAIN that points the
// interface variable at one or the other.
//
// The seed shows the declarations of M_Add and P_Result and the code of MAIN, not the bodies
// of the blocks (its step E: "define the algorithm and the property in the blocks' methods").
// We fill them in the obvious way: M_Mul is declared like M_Add; FB_MathMen ("memory")
// keeps its result, so each method works on the result of the one before; FB_MethErase
// ("erase") computes the same result but erases its memory after each method call.
//
// The POUs are in this header so that one source serves the host's tests
// (i_math_interface.cpp) and the firmware example (embedded/examples/i_math_interface.cpp).
#pragma once

#include <iecoop/iecoop.hpp>

namespace seed_i_math {

using namespace iecoop;

// INTERFACE I_Math
struct I_Math : interface_base<I_Math> {
  // METHOD M_Add : REAL
  // VAR_INPUT
  //     rVal : REAL;
  // END_VAR
  struct M_Add_vars {
    REAL rVal;
  };
  virtual REAL M_Add(args<M_Add_vars> in) = 0;

  // METHOD M_Mul : REAL             (declared like M_Add; the seed only calls it)
  // VAR_INPUT
  //     rVal : REAL;
  // END_VAR
  struct M_Mul_vars {
    REAL rVal;
  };
  virtual REAL M_Mul(args<M_Mul_vars> in) = 0;

  // PROPERTY P_Result : REAL
  virtual REAL P_Result_Get() = 0;
  virtual void P_Result_Set(REAL value) = 0;
  [[no_unique_address]] property<REAL, &I_Math::P_Result_Get, &I_Math::P_Result_Set> P_Result{this};
};

// FUNCTION_BLOCK FB_MathMen IMPLEMENTS I_Math      (bodies ours: keeps its result)
struct FB_MathMen : function_block<FB_MathMen, implements<I_Math>> {
  // VAR rMem : REAL; END_VAR
  var<REAL> rMem;

  REAL M_Add(args<M_Add_vars> in) override {
    rMem = rMem + in.rVal;  // rMem := rMem + rVal;
    return rMem;            // M_Add := rMem;
  }
  REAL M_Mul(args<M_Mul_vars> in) override {
    rMem = rMem * in.rVal;  // rMem := rMem * rVal;
    return rMem;            // M_Mul := rMem;
  }
  REAL P_Result_Get() override { return rMem; }          // P_Result := rMem;
  void P_Result_Set(REAL value) override { rMem = value; }  // rMem := P_Result;
};

// FUNCTION_BLOCK FB_MethErase IMPLEMENTS I_Math    (bodies ours: forgets after each method)
struct FB_MethErase : function_block<FB_MethErase, implements<I_Math>> {
  // VAR rMem : REAL; END_VAR
  var<REAL> rMem;

  REAL M_Add(args<M_Add_vars> in) override {
    const REAL rResult = rMem + in.rVal;  // M_Add := rMem + rVal;
    rMem = 0.0f;                          // rMem := 0;
    return rResult;
  }
  REAL M_Mul(args<M_Mul_vars> in) override {
    const REAL rResult = rMem * in.rVal;  // M_Mul := rMem * rVal;
    rMem = 0.0f;                          // rMem := 0;
    return rResult;
  }
  REAL P_Result_Get() override { return rMem; }
  void P_Result_Set(REAL value) override { rMem = value; }
};

// PROGRAM MAIN
struct MAIN : program<MAIN> {
  // VAR_INPUT
  itf<I_Math> ipInterface;         // ipInterface : I_Math;            // the interface variable
  FB_MathMen fbMemInstance;        // fbMemInstance : FB_MathMen;      // one block
  FB_MethErase fbEraseInstance;    // fbEraseInstance : FB_MethErase;  // the other
  // END_VAR
  using VAR_INPUT = pins<&MAIN::ipInterface, &MAIN::fbMemInstance, &MAIN::fbEraseInstance>;
  // VAR
  var<REAL> rResultInterface;  // rResultInterface : REAL;
  BOOL bUseMemInstance;        // bUseMemInstance : BOOL;   (a plain member: the test sets it,
                               //  as a watch-list write would)
  var<REAL> AddResult;         // AddResult : REAL;
  // END_VAR

  void body() {
    if (bUseMemInstance) {                        // IF bUseMemInstance THEN
      ipInterface = fbMemInstance;                //     ipInterface := fbMemInstance;    // to block 1
    } else {                                      // ELSE
      ipInterface = fbEraseInstance;              //     ipInterface := fbEraseInstance;  // to block 2
    }                                             // END_IF
    ipInterface->P_Result = 2.0f;                 // ipInterface.P_Result := 2;           // write the property
    AddResult = ipInterface->M_Add(3.0f);         // AddResult := ipInterface.M_Add(3);   // call a method
    ipInterface->M_Mul(3.0f);                     // ipInterface.M_Mul(3);
    rResultInterface = ipInterface->P_Result;     // rResultInterface := ipInterface.P_Result;  // read it
  }
};

}  // namespace seed_i_math
