// Which blocks the NC block compressor may join, as the interpreter sees them
// (docs/compressor.md "Which blocks are compressed").
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {
namespace detail {

bool is_simple_block(const parser::Block& block, const ExtraAxes& extra_axes) {
  if (!block.m.empty() || !block.commands.empty() || !block.system_writes.empty() ||
      !block.axis_words.empty() || block.tool_name || block.modal_save != parser::ModalSave::None)
    return false;
  for (const auto& g : block.g)
    if (g.code != 1) return false;
  for (const auto& a : block.addresses) {
    const std::string_view n = a.name;  // compared with literals by length first, not a memcmp each
    // Positions of the geometry axes and of the machine's further path axes (rotary A/C of a
    // 5-axis machine: Job Planning lists `X Y Z A B C F` blocks as compressible).
    const bool allowed = n == "F" || axis_index(n) >= 0 || extra_axes.index(n) >= 0 || is_orientation_word(n);
    if (!allowed) return false;
    if (a.mode != parser::ValueMode::Default && a.mode != parser::ValueMode::Absolute &&
        a.mode != parser::ValueMode::Incremental)
      return false;
  }
  return true;
}

}  // namespace detail

void Interpreter::mark_for_compressor(const BlockContext& ctx, PathElement& element) {
  element.compressor = state_.compressor;
  if (state_.compressor == Compressor::Off) return;
  if (state_.compressor == Compressor::Compsurf)
    warn_once(ctx, "COMPSURF (Top Surface): planned as COMPCAD, its own surface smoothing is not published", 0);
  const bool compcad = state_.compressor == Compressor::Compcad || state_.compressor == Compressor::Compsurf;
  const int hundreds = profile_.compressor.mode / 100 % 10;
  if (element.kind == ElementKind::Arc && compcad && (hundreds == 1 || hundreds == 3))
    warn_once(ctx, "COMPCAD compression of circles (MD20482 hundreds digit 1/3): circle blocks stay circles", 0);
  if (element.rapid && (hundreds == 2 || hundreds == 3))
    warn_once(ctx, "compression of G0 blocks (MD20482 hundreds digit 2/3): G0 blocks stay lines", 0);
  if (element.kind != ElementKind::Line || element.rapid || state_.motion != MotionMode::Linear || !ctx.simple)
    return;
  element.compressible = true;
  element.follows_other_block = block_between_compressible_;
  block_between_compressible_ = false;
}

}  // namespace drycut::interp
