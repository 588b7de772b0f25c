#include "report/path_csv_writer.hpp"

#include <cmath>

namespace drycut::report {

PathCsvWriter::PathCsvWriter(std::FILE* out, double step_mm) : out_(out), step_(step_mm) {
  std::fputs("s_mm,x,y,z,element,file,line\n", out_);
}

void PathCsvWriter::write_row(double s, const geometry::Vec3& p, const interp::PathElement& e) {
  std::fprintf(out_, "%.6f,%.6f,%.6f,%.6f,%s,%s,%u\n", s, p.x(), p.y(), p.z(), e.label.c_str(),
               e.source.file_name().c_str(), e.source.line);
  ++samples_;
  last_written_s_ = s;
}

void PathCsvWriter::consume(interp::PathElement&& element) {
  if (!element.is_motion() || !element.curve) return;
  const double length = element.curve->length();
  const double end = s_total_ + length;
  // Samples at whole multiples of the step that fall inside this element (the start of the path
  // included); a sample on an element boundary belongs to the element that starts there.
  while (next_sample_ < end || (next_sample_ == 0.0 && samples_ == 0)) {
    const double local = std::max(0.0, next_sample_ - s_total_);
    write_row(next_sample_, element.curve->at(local).position, element);
    next_sample_ = step_ * std::floor(next_sample_ / step_ + 1.5);
    if (length == 0.0) break;
  }
  s_total_ = end;
  last_ = std::move(element);
  have_last_ = true;
}

void PathCsvWriter::finish() {
  if (have_last_ && last_written_s_ < s_total_ - 1e-9)
    write_row(s_total_, last_.curve->end(), last_);
  std::fflush(out_);
}

}  // namespace drycut::report
