// iecoop-check fixture, the clean twin of var_written_outside.cpp: a block's VAR written by the
// block itself and by the blocks that extend it, read from everywhere.
#include <array>

#include <iecoop/iecoop.hpp>

using namespace iecoop;

struct ST_Pos {
  INT x;
  INT y;
};

// FUNCTION_BLOCK FB_Axis
struct FB_Axis : function_block<FB_Axis> {
  BOOL bEnable;
  using VAR_INPUT = pins<&FB_Axis::bEnable>;
  var<INT> nMoves;
  var<BOOL> bDone;
  var<ST_Pos> stPos;
  var<std::array<INT, 4>> aSteps;
  TON tmrDone;
  virtual void body() {
    nMoves = nMoves + 1;
    nMoves += 1;
    ++nMoves;
    stPos->x = 1;
    stPos.ref().y = 2;
    aSteps[0] = 3;
    tmrDone("IN"_ = bEnable, "Q"_ >> bDone);
    const auto reset = [this] { nMoves = 0; };  // a lambda in the block's code is the block's code
    if (nMoves > 100) reset();
  }
  void Reset();
};

// METHOD Reset, defined outside the class: still FB_Axis's code.
void FB_Axis::Reset() { nMoves = 0; }

// FUNCTION_BLOCK FB_FastAxis EXTENDS FB_Axis: a derived block writes its base's VAR.
struct FB_FastAxis : extends<FB_FastAxis, FB_Axis> {
  var<INT> nBoosts;
  void body() override {
    SUPER::body();
    nMoves = nMoves + 10;
    this->nBoosts += 1;
  }
  void Copy(FB_FastAxis& other) { other.nMoves = nMoves; }  // code of the block (as CODESYS, by type)
};

// PROGRAM PLC_PRG: reads the blocks' VARs, writes only its own and the inputs.
struct PLC_PRG : program<PLC_PRG> {
  FB_FastAxis fbAxis;
  var<INT> nSeen;
  void body() {
    fbAxis.bEnable = TRUE;
    fbAxis();
    nSeen = fbAxis.nMoves + fbAxis.aSteps[0];
    if (fbAxis.bDone) nSeen = nSeen + fbAxis.stPos->x;
  }
};

INT Total(const FB_Axis& fb) { return fb.nMoves + fb.stPos->y; }
