#include "parser/loop_guard.hpp"

namespace drycut::parser {

LoopGuard::Repeat LoopGuard::repeats(uint64_t site, const std::string& state, const Visit& v) {
  constexpr size_t kMaxSites = 4096;  // bounded memory for programs with very many loops
  auto it = sites_.find(site);
  if (it == sites_.end()) {
    if (sites_.size() >= kMaxSites) return Repeat::No;
    it = sites_.emplace(site, Record{}).first;
  }
  Record& r = it->second;
  // A wait on an input is a wait whatever else the stretch read: the input (or a synchronized
  // action's variable) is what ends it on the machine.
  if (r.visits > 0 && r.state == state && r.input_reads != v.input_reads && r.last_clock_reads == v.clock_reads)
    return Repeat::WaitsOnInput;
  // A wait with a timeout beside the input: the pass dwelled or polled a timer, did no work and
  // polled no process value (that loop waits for the process).
  const bool waited = (r.last_dwell_blocks != v.dwell_blocks || r.last_clock_reads != v.clock_reads) &&
                      r.last_process_reads == v.process_reads;
  if (v.decided_by_input && r.visits > 0 && r.last_work_blocks == v.work_blocks && waited &&
      r.last_input_reads != v.input_reads)
    return Repeat::WaitsOnInput;
  if (r.visits > 0 && r.reads == v.reads && r.state == state) return Repeat::Endless;
  const bool polled_input = !v.decided_by_input && r.visits > 0 && r.last_work_blocks == v.work_blocks && waited &&
                            r.last_input_reads != v.input_reads && v.clock_s - r.last_clock_s <= kMaxPollPassS;
  r.last_work_blocks = v.work_blocks;
  r.last_dwell_blocks = v.dwell_blocks;
  r.last_clock_reads = v.clock_reads;
  r.last_input_reads = v.input_reads;
  r.last_process_reads = v.process_reads;
  r.last_clock_s = v.clock_s;
  if (++r.visits == r.next_save) {
    r.state = state;
    r.reads = v.reads;
    r.input_reads = v.input_reads;
    r.next_save *= 2;
  }
  return polled_input ? Repeat::PollsInputWithTimeout : Repeat::No;
}

}  // namespace drycut::parser
