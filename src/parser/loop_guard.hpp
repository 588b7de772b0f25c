#pragma once
// Finds endless loops without running them to the step limit. Only a backward jump (GOTOB,
// GOTO/GOTOC backwards, ENDWHILE, ENDFOR, UNTIL, ENDLOOP, a REPEAT section) can make a program
// run forever, and the loader's future depends only on its own state (position, call stack,
// open structures, variables, R parameters, written system variables) and on what it reads of
// the interpreter's state. So when a backward jump arrives at the same place with the same
// loader state, and nothing was read from the interpreter in between, the program repeats
// itself for ever: that is reported at once (alarm 990004) instead of after 10^8 lines.
//
// Algorithm (Brent's cycle detection, per jump site): every visit compares the state with the
// one saved at that site; the saved state is renewed at the 1st, 2nd, 4th, 8th ... visit, so a
// cycle of any length L through the site is found within about 2L visits, with one saved state
// per site. States are compared byte for byte (no hash collisions).
//
// A loop whose repeating stretch read a digital/analog input or PLC datum ($A_IN, $A_DBB ...)
// is not endless on the machine: it waits for the PLC or the process to change that signal
// (WHILE $A_IN[3]==0 ENDWHILE). The guard tells such a wait apart (Repeat::WaitsOnInput) by
// the count of input reads between the saved visit and this one, also when the stretch read
// the interpreter's state besides (R20=$P_F in a loop polling a synchronized action's $R10:
// before 2026-11-27 any such read made the guard give up, and the wait ran to the step limit).
//
// A wait with a timeout changes state on every pass (W1: G4 F0.5 / R10=R10+1 / IF R10>20
// SETAL(65020) / IF $A_IN[7]==0 GOTOB W1), so it never repeats: it ran into its own timeout
// alarm (before 2026-11-28). So a jump back whose condition read an input (Visit::
// decided_by_input: IF ... GOTOB, WHILE, UNTIL, or the IF block around a GOTOB) is a wait too
// when the pass since the last visit dwelled (G4, or a stop M0/M1 for the operator) and did
// nothing else a block carries (no axis, no other M function, no S): on the machine the signal
// ends it. A loop that computes without
// dwelling (counting set inputs, testing bits of $A_DBB) or works (cuts, spindle steps of a
// warm-up with an abort input) runs its passes. A pass that polled a timer and the input and
// did nothing else (WHILE ($A_IN[9]==0) AND ($AC_TIMER[1]<10) ENDWHILE) is the same wait with its
// timeout on the clock: it ends the same way (before 2026-11-28 it waited its full timeout and a
// check after it stopped the run). A pass that polled a process value (the spindle's actual
// speed: WHILE ($AA_S<7900) AND ($A_IN[3]==0)) waits for that process: it runs on until the
// value ends it, the input being the abort.
//
// A wait whose own jump back is decided by a counter, not by the input (TUER: IF $A_IN[1]==1
// GOTOF OFFEN / G4 F0.5 / _TRY=_TRY+1 / IF _TRY<20 GOTOB TUER / SETAL(65201)), changes state on
// every pass and leaves by a jump forward when the input comes: when the pass since the last
// visit read an input, did no work and only dwelled or polled a timer, for at most
// kMaxPollPassS seconds, it is such a wait (Repeat::PollsInputWithTimeout): the loader lets the
// input come and the loop leaves on its next pass instead of running into its timeout alarm
// (before 2026-11-29). A pass that dwells longer (a warm-up's G4 F60 beside an abort input) is
// no poll: its passes run.
#include <cstdint>
#include <string>
#include <unordered_map>

namespace drycut::parser {

class LoopGuard {
 public:
  enum class Repeat : uint8_t { No, Endless, WaitsOnInput, PollsInputWithTimeout };
  // The longest pass of a poll (G4 between two reads of the input) [I]: door, clamp and pallet
  // waits poll every 0.1..1 s; a warm-up dwells for tens of seconds per step.
  static constexpr double kMaxPollPassS = 2.0;
  struct Visit {
    uint64_t reads = 0;          // running count of reads of the interpreter's state
    uint64_t input_reads = 0;    // running count of input and PLC reads
    uint64_t work_blocks = 0;    // running count of blocks that move axes, program M or S
    uint64_t dwell_blocks = 0;   // running count of G4 blocks
    uint64_t clock_reads = 0;    // running count of reads that let the clock run ($AC_TIMER, $AA_S)
    uint64_t process_reads = 0;  // of those, reads of a process value ($AA_S), not of a timer
    bool decided_by_input = false;
    double clock_s = 0;          // the interpreter's clock
  };
  // WaitsOnInput when `state` at `site` equals the saved one and inputs were read since, or
  // when the jump was decided by an input and the pass since the last visit only dwelled; else Endless
  // when the state equals the saved one and no interpreter state was read since.
  Repeat repeats(uint64_t site, const std::string& state, const Visit& visit);

 private:
  struct Record {
    std::string state;
    uint64_t reads = 0;
    uint64_t input_reads = 0;
    uint64_t visits = 0;
    uint64_t next_save = 1;
    uint64_t last_work_blocks = 0;  // at the last visit (not only the saved one)
    uint64_t last_dwell_blocks = 0;
    uint64_t last_clock_reads = 0;
    uint64_t last_input_reads = 0;
    uint64_t last_process_reads = 0;
    double last_clock_s = 0;
  };
  std::unordered_map<uint64_t, Record> sites_;
};

}  // namespace drycut::parser
