#pragma once
// `--trace`: one CSV row per IPO cycle, `t_s,x,y,z,v_mm_min,a_mm_s2,j_mm_s3,file,line`.
#include <cstdio>

#include "motion/plan_result.hpp"

namespace drycut::report {

class TraceCsvWriter : public motion::PlanObserver {
 public:
  explicit TraceCsvWriter(std::FILE* out) : out_(out) {
    std::fputs("t_s,x,y,z,v_mm_min,a_mm_s2,j_mm_s3,file,line\n", out_);
  }
  void on_sample(const motion::TrajectorySample& s) override {
    std::fprintf(out_, "%.4f,%.4f,%.4f,%.4f,%.2f,%.1f,%.0f,%s,%u\n", s.t_s, s.position.x(), s.position.y(),
                 s.position.z(), s.v_mm_s * 60.0, s.a_mm_s2, s.j_mm_s3,
                 s.source ? s.source->file_name().c_str() : "", s.source ? s.source->line : 0u);
  }

 private:
  std::FILE* out_;
};

// Hands every event to two observers (report and trace at once).
class PlanObserverPair : public motion::PlanObserver {
 public:
  PlanObserverPair(motion::PlanObserver& a, motion::PlanObserver& b) : a_(a), b_(b) {}
  void on_block(const motion::BlockTiming& t) override { a_.on_block(t); b_.on_block(t); }
  void on_sample(const motion::TrajectorySample& s) override { a_.on_sample(s); b_.on_sample(s); }

 private:
  motion::PlanObserver& a_;
  motion::PlanObserver& b_;
};

}  // namespace drycut::report
