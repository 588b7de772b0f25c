// Lexer and line parser on typical CAM blocks: the per-line cost of `drycut check`.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "parser/lexer.hpp"
#include "parser/line_parser.hpp"

namespace {

using namespace drycut::parser;

const std::vector<std::string>& cam_lines() {
  static const std::vector<std::string> lines = [] {
    std::vector<std::string> v;
    for (int i = 0; i < 1024; ++i)
      v.push_back("N" + std::to_string(i + 10) + " G1 X" + std::to_string(12.345 + i * 0.001) + " Y-" +
                  std::to_string(6.789 + i * 0.002) + " Z0.123 F1500");
    return v;
  }();
  return lines;
}

void BM_LexCamLine(benchmark::State& state) {
  Lexer lexer;
  std::vector<Token> tokens;
  const auto& lines = cam_lines();
  size_t i = 0;
  for (auto _ : state) {
    lexer.tokenize(lines[i++ & 1023], tokens);
    benchmark::DoNotOptimize(tokens.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LexCamLine);

void BM_ParseCamLine(benchmark::State& state) {
  LineParser parser;
  ParsedLine parsed;
  const auto& lines = cam_lines();
  size_t i = 0;
  for (auto _ : state) {
    parser.parse(lines[i++ & 1023], parsed);
    benchmark::DoNotOptimize(&parsed);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParseCamLine);

void BM_ParseExpressionLine(benchmark::State& state) {
  LineParser parser;
  ParsedLine parsed;
  const std::string line = "R1=SQRT(R2*R2+R3*R3)/2+SIN(R4*3.14159/180)*(R5-R6)";
  for (auto _ : state) {
    parser.parse(line, parsed);
    benchmark::DoNotOptimize(&parsed);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParseExpressionLine);

}  // namespace
