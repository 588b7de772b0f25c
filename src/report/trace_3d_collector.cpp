#include "report/trace_3d_collector.hpp"

#include <algorithm>
#include <unordered_set>

namespace drycut::report {

Trace3dCollector::Trace3dCollector(size_t buckets) : points_(buckets), prune_at_(4 * points_.capacity()) {}

void Trace3dCollector::on_tool_centre(const interp::PathElement& e) {
  pending_.push_back(Pending{e.source.line, e.label, e.rapid ? 0.0 : e.feed_mm_s, e.rapid});
}

void Trace3dCollector::on_block(const motion::BlockTiming& timing) {
  // Elements the planner never timed (none known) are skipped, as the plot collector does.
  while (!pending_.empty() && (pending_.front().line != timing.source.line || pending_.front().label != timing.label))
    pending_.pop_front();
  if (!pending_.empty()) pending_.pop_front();
  ++block_seq_;
}

void Trace3dCollector::on_sample(const motion::TrajectorySample& sample) {
  // Node-based map: the current block's entry stays put when the map grows, and pruning keeps it.
  if (!current_ || current_seq_ != block_seq_) {
    TraceBlock b;
    if (sample.source) {
      b.file = sample.source->file;
      b.line = sample.source->line;
      b.text = sample.source->text;
    }
    if (!pending_.empty() && pending_.front().line == b.line) {
      b.feed_mm_s = pending_.front().feed_mm_s;
      b.rapid = pending_.front().rapid;
    }
    current_ = &blocks_.insert_or_assign(block_seq_, std::move(b)).first->second;
    current_seq_ = block_seq_;
  }
  TracePoint p;
  p.x = sample.position.x();
  p.y = sample.position.y();
  p.z = sample.position.z();
  p.t = sample.t_s;
  p.v = p.value = sample.v_mm_s;
  p.block = block_seq_;
  p.rapid = current_->rapid;
  points_.add(p);
  if (blocks_.size() > prune_at_) forget_unreferenced_blocks();
}

void Trace3dCollector::forget_unreferenced_blocks() {
  std::unordered_set<uint64_t> used;
  for (const auto& p : points_.points()) used.insert(p.block);
  used.insert(block_seq_);
  std::erase_if(blocks_, [&](const auto& entry) { return !used.contains(entry.first); });
  // At least three capacities of new blocks before the next pass: linear time overall.
  prune_at_ = blocks_.size() + 3 * points_.capacity();
}

Trace3d Trace3dCollector::trace() const {
  Trace3d out;
  out.points = points_.points();
  out.samples = points_.count();
  std::unordered_map<uint64_t, uint64_t> dense;  // sequence number -> index into out.blocks
  for (auto& p : out.points) {
    auto [it, fresh] = dense.emplace(p.block, out.blocks.size());
    if (fresh) {
      auto b = blocks_.find(p.block);
      out.blocks.push_back(b == blocks_.end() ? TraceBlock{} : b->second);
    }
    p.block = it->second;
  }
  return out;
}

}  // namespace drycut::report
