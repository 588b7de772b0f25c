#pragma once
// The canonical element stream as text, one element per line: what the interpreter hands the
// planner. Used by `drycut path --elements` and the regression listings in tests/programs.
//   LINE    G1 (0.000 0.000 100.000) -> (0.000 0.000 10.000) L=90.000 F=25.500 | file:line
#include <cstdio>

#include "interp/path_element.hpp"

namespace drycut::report {

class ElementListingWriter : public interp::ElementSink {
 public:
  explicit ElementListingWriter(std::FILE* out) : out_(out) {}
  void consume(interp::PathElement&& element) override;
  void finish() override { std::fflush(out_); }

 private:
  std::FILE* out_;
};

}  // namespace drycut::report
