#pragma once
// Lets the report watch the element stream between two pipeline stages without changing it:
// every element goes to the watcher, then on to the downstream sink unchanged.
#include <functional>
#include <utility>

#include "interp/path_element.hpp"

namespace drycut::report {

class ElementTap : public interp::ElementSink {
 public:
  using Watcher = std::function<void(const interp::PathElement&)>;
  ElementTap(interp::ElementSink& downstream, Watcher watcher)
      : downstream_(downstream), watcher_(std::move(watcher)) {}
  void consume(interp::PathElement&& element) override {
    watcher_(element);
    downstream_.consume(std::move(element));
  }
  void finish() override { downstream_.finish(); }

 private:
  interp::ElementSink& downstream_;
  Watcher watcher_;
};

}  // namespace drycut::report
