#pragma once
// Writes the path element stream as CSV samples every `step` mm of arc length:
// header `s_mm,x,y,z,element,file,line`. The first point of the path and the end of every
// element that ends the path are written too, so a path shorter than one step still shows.
#include <cstdio>
#include <string>

#include "interp/path_element.hpp"

namespace drycut::report {

class PathCsvWriter : public interp::ElementSink {
 public:
  // `out` stays owned by the caller; step must be > 0.
  PathCsvWriter(std::FILE* out, double step_mm);
  void consume(interp::PathElement&& element) override;
  void finish() override;

  double total_length_mm() const { return s_total_; }
  size_t samples_written() const { return samples_; }

 private:
  void write_row(double s, const geometry::Vec3& p, const interp::PathElement& e);

  std::FILE* out_;
  double step_;
  double s_total_ = 0.0;     // arc length at the start of the next element
  double next_sample_ = 0.0; // arc length of the next sample
  size_t samples_ = 0;
  bool have_last_ = false;
  interp::PathElement last_;  // the last motion element, for the closing sample
  double last_written_s_ = -1.0;
};

}  // namespace drycut::report
