// The `run --json` writer alone: cost per block row in the document layout (array rows, file
// index) and the NDJSON layout (object rows), written to /dev/null. Row values vary like the
// G1 spiral's (times of a few ms, lengths 0.05..0.5 mm, feeds around 1500 mm/min).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "report/run_report_writer.hpp"

namespace {

using namespace drycut;

void run_report_rows(benchmark::State& state) {
  const auto layout = state.range(0) == 0 ? report::RunJsonLayout::Document : report::RunJsonLayout::Lines;
  std::FILE* out = std::fopen("/dev/null", "w");
  {
    report::RunReportWriter writer(out, layout, "/home/shop/programs/PART_4711.MPF", "MCV 1210");
    motion::BlockTiming t;
    t.source.file = intern_file_name("/home/shop/programs/PART_4711.MPF");
    t.label = "G1";
    t.limit = motion::Limit::ShortBlock;
    uint32_t line = 0;
    for (auto _ : state) {
      const double step = 0.05 + 0.45 * std::fmod(line * 0.6180339887, 1.0);
      t.source.line = ++line;
      t.length_mm = step;
      t.v_max_mm_s = 25.0 - 0.001 * (line % 97);
      t.v_min_mm_s = t.v_max_mm_s * 0.97;
      t.time_s = step / t.v_min_mm_s;
      writer.on_block(t);
    }
  }
  std::fclose(out);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(run_report_rows)->Arg(0)->Arg(1)->ArgName("ndjson");

}  // namespace
